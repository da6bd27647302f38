#pragma once
// A DemModel decomposed over MPI ranks (dem/demExchange.hpp says what the model asks).
//
// Every rank starts from the same whole model (read from the same case), cuts it by the
// decomposition of system/decomposeParDict into its own cells and their ghosts, and keeps
// from then on only those: the cells of another rank whose centroids lie within
// reach_i + reach_j + margin of one of its own, margin = the lists' skin + twice the
// allowance (the distance any cell may move from where it was at the decomposition before
// the ghost layer no longer holds every cell within contact reach; checked at every list
// build). Before each force evaluation each owner sends its neighbours the state of the
// cells they hold as ghosts (13 doubles per cell); an interface or contact pair across two
// ranks is computed on the rank of its first cell, which sends its results (10 doubles per
// interface, 7 per pair) to the rank of the second.
//
//     std::unique_ptr<MpiDemExchange> exchange = decomposeDemModel(model, parameters, comm);
//     // model now holds this rank's cells and ghosts; step it as before
#include <mpi.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dem/demExchange.hpp"
#include "dem/demModel.hpp"
#include "parallel/decomposition.hpp"

namespace rockfrac::mpi {

class MpiDemExchange final : public DemExchange {
public:
    struct Neighbour {
        int rank = 0;
        std::vector<int> send;  // my own cells it holds as ghosts (local indices, global order)
        std::vector<int> recv;  // my ghosts it owns (local indices, global order)
    };
    MpiDemExchange(MPI_Comm comm, std::vector<std::int64_t> global_cell, std::vector<int> global_interface,
                   std::vector<char> owned, std::vector<Neighbour> neighbours,
                   std::vector<Vec3> start_position, double allowance);

    int rank() const override { return rank_; }
    void refreshGhosts(CellArrays& cells) override;
    bool anyRank(bool mine) override;
    double maxOverRanks(double mine) override;
    void sumOverRanks(std::vector<double>& values) override;
    std::vector<WallItemTerm> mergeWallTerms(const std::vector<WallItemTerm>& mine) override;
    void checkGhostReach(const CellArrays& cells, double cost) override;
    void returnInterfaceResults(InterfaceArrays& interfaces) override;
    void returnPairResults(ContactPairArrays& pairs) override;
    void pairListsBuilt(const ContactPairArrays& pairs) override;
    // Which interfaces go where (they do not change during a run): once, after the cut.
    void interfacesDecomposed(const InterfaceArrays& interfaces);
    std::int64_t globalCell(int c) const override { return global_cell_[c]; }
    int globalInterface(int k) const { return global_interface_[k]; }
    bool owns(int c) const { return owned_[c] != 0; }
    MPI_Comm comm() const { return comm_; }

    // For the log and the benchmarks.
    int ownedCells() const;
    int ghostCells() const { return static_cast<int>(global_cell_.size()) - ownedCells(); }
    int neighbourRanks() const { return static_cast<int>(neighbours_.size()); }
    std::uint64_t bytesPerStep()
        const;  // ghost states and item results sent per force evaluation (current lists)
    double allowance() const { return allowance_; }
    // Why the cells should be cut anew (empty when they need not): at the last list build a
    // cell had moved more than half the allowance since this cut, or the ranks' cost imbalance
    // (largest / mean - 1) exceeded the one measured at the first build after this cut by more
    // than the tolerance (decomposeParDict imbalanceTolerance). The same on every rank.
    std::string redistributionDue() const;
    void setImbalanceTolerance(double tolerance) { imbalance_tolerance_ = tolerance; }
    double imbalance() const { return imbalance_; }
    // Wall-clock seconds this rank spent in the exchange's calls (messages, collectives and the
    // waiting for slower ranks in them), and how many calls, since the start.
    double exchangeSeconds() const { return exchange_seconds_; }
    long exchangeCalls() const { return exchange_calls_; }

private:
    MPI_Comm comm_;
    int rank_ = 0, size_ = 1;
    std::vector<std::int64_t> global_cell_;
    std::vector<int> global_interface_;
    std::vector<char> owned_;
    std::vector<Neighbour> neighbours_;
    std::vector<Vec3> start_position_;
    double allowance_ = 0.0;
    double moved_ = 0.0, imbalance_ = 0.0, baseline_imbalance_ = -1.0, imbalance_tolerance_ = 0.2;
    std::vector<std::vector<double>> send_buffer_, recv_buffer_;
    std::vector<int> owner_;  // per local cell: the rank owning it
    // Per neighbour (as neighbours_): the items whose results go there (first cell mine, second
    // its) and come from there (first cell its, second mine), local indices in global order.
    std::vector<std::vector<int>> ghost_send_, ghost_recv_;  // cells, as Neighbour's lists
    std::vector<std::vector<int>> interface_send_, interface_recv_, pair_send_, pair_recv_;
    // Items by the pair of owners of their two cells, into per-neighbour lists.
    template <class CellOf>
    void sortItems(int n, CellOf&& first_and_second, std::vector<std::vector<int>>& send,
                   std::vector<std::vector<int>>& recv) const;
    // Send each neighbour its items' values (per_item doubles packed by pack(i, out)) and unpack
    // what comes back (unpack(i, in)).
    template <class Pack, class Unpack>
    void exchangeItems(const std::vector<std::vector<int>>& send, const std::vector<std::vector<int>>& recv,
                       int per_item, int tag, Pack&& pack, Unpack&& unpack);
    double exchange_seconds_ = 0.0;
    long exchange_calls_ = 0;
    class Timed;  // adds a call's wall time to exchange_seconds_
};

// Cuts `model` (the same whole model on every rank) down to this rank's cells and ghosts and
// connects it to the others; numberOfSubdomains must equal the number of ranks (UserError).
// A model restored from a state file keeps its forces (the next step continues bitwise).
// `whole`, when given, gets on every rank a copy of the whole model to gather into
// (gatherModel). The cost weights are DemModel::cellCosts (the items as last listed).
// Collective. The returned exchange must outlive the model's steps. Called again on a model
// copied from a gathered whole model, it cuts the cells anew (migration and re-balancing).
std::unique_ptr<MpiDemExchange> decomposeDemModel(DemModel& model, const DecomposeParameters& parameters,
                                                  MPI_Comm comm, std::unique_ptr<DemModel>* whole = nullptr);

// The state of every rank's cells, bonds, contacts and walls, the clock, counters, energies and
// force rates, set into rank 0's copy of the whole model (the arrays a state file and the VTK
// frames are written from: <time>/demState as the serial run writes it), or with `everywhere`
// into every rank's copy (to cut anew from). Collective; `whole` is used on rank 0 only unless
// everywhere.
// Returns the bytes this rank received (the whole state's size where it was gathered, else 0).
std::size_t gatherModel(const DemModel& local, MpiDemExchange& exchange, DemModel* whole,
                        bool everywhere = false);

// One line for the log: the rank's cells, ghosts, neighbours, bytes per step and the allowance.
std::string describeDecomposition(const MpiDemExchange& exchange, const DecomposeParameters& parameters,
                                  MPI_Comm comm);

}  // namespace rockfrac::mpi
