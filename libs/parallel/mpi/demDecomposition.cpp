// decomposeDemModel: a whole DemModel cut down to one rank's cells and ghosts
// (parallel/mpi/demExchange.hpp).
#include <algorithm>
#include <cstdio>

#include "core/error.hpp"
#include "parallel/mpi/demExchange.hpp"
#include "parallel/mpi/haloExchange.hpp"

namespace rockfrac::mpi {

std::unique_ptr<MpiDemExchange> decomposeDemModel(DemModel& model, const DecomposeParameters& parameters,
                                                  MPI_Comm comm, std::unique_ptr<DemModel>* whole)
{
    const int n_ranks = size(comm), me = rank(comm);
    if (parameters.n_subdomains != n_ranks)
        throw UserError("numberOfSubdomains is " + std::to_string(parameters.n_subdomains) +
                        " but the run has " + std::to_string(n_ranks) + " ranks: give mpirun -np " +
                        std::to_string(parameters.n_subdomains) + " or change numberOfSubdomains");
    const CellArrays& cells = model.cells();
    const int n = cells.size();
    const std::vector<Vec3> centroids(cells.position.begin(), cells.position.end());
    const std::vector<double> reach(cells.bounding_radius.begin(), cells.bounding_radius.end());
    // Any cell may move by the largest cell's reach before the layer must be rebuilt.
    const double allowance = n > 0 ? *std::max_element(reach.begin(), reach.end()) : 0.0;
    const double margin = model.skin() + 2.0 * allowance;
    // A model with fewer cells than ranks (a crusher filling up) leaves the last ranks idle.
    const int parts = std::min(n_ranks, n);
    const std::vector<int> part_of =
        parts == 0 ? std::vector<int>{}
                   : parameters.method->decompose(
                         centroids, parameters.cost_weights ? model.cellCosts() : std::vector<double>(n, 1.0),
                         parts);

    // Every rank's cells and ghosts, worked out alike on every rank (so the lists of what to
    // send need no message): held[q][c] when rank q keeps cell c.
    std::vector<std::vector<char>> held(n_ranks, std::vector<char>(n, 0));
    for (int q = 0; q < n_ranks; ++q) {
        std::vector<Vec3> own_c, other_c;
        std::vector<double> own_r, other_r;
        std::vector<int> other;
        for (int c = 0; c < n; ++c) {
            if (part_of[c] == q) {
                held[q][c] = 1;
                own_c.push_back(centroids[c]);
                own_r.push_back(reach[c]);
            } else {
                other.push_back(c);
                other_c.push_back(centroids[c]);
                other_r.push_back(reach[c]);
            }
        }
        const std::vector<bool> near = withinReach(own_c, own_r, other_c, other_r, margin);
        for (std::size_t i = 0; i < other.size(); ++i)
            if (near[i]) held[q][other[i]] = 1;
    }

    std::vector<char> remove(n);
    for (int c = 0; c < n; ++c) remove[c] = !held[me][c];
    // removeCellsOnly keeps the forces of a restored state (the next step continues from them,
    // as the serial run does), the step check's bound and the histories as they are.
    if (whole) *whole = std::make_unique<DemModel>(model);
    const DemEnergies energies = model.energies();
    const DemCounters counters = model.counters();
    const DemForceRates rates = model.forceRates();
    std::vector<int> global_interface;
    const InterfaceArrays& f = model.interfaces();
    for (int k = 0; k < f.size(); ++k)
        if (held[me][f.cell_i[k]] && held[me][f.cell_j[k]]) global_interface.push_back(k);

    const std::vector<int> local = model.removeCellsOnly(remove);
    std::vector<std::int64_t> global_cell;
    std::vector<char> owned;
    for (int c = 0; c < n; ++c)
        if (local[c] >= 0) {
            global_cell.push_back(c);
            owned.push_back(part_of[c] == me);
        }
    std::vector<MpiDemExchange::Neighbour> neighbours;
    for (int q = 0; q < n_ranks; ++q) {
        if (q == me) continue;
        MpiDemExchange::Neighbour nb;
        nb.rank = q;
        for (int c = 0; c < n; ++c) {
            if (part_of[c] == me && held[q][c]) nb.send.push_back(local[c]);
            if (part_of[c] == q && held[me][c]) nb.recv.push_back(local[c]);
        }
        if (!nb.send.empty() || !nb.recv.empty()) neighbours.push_back(std::move(nb));
    }
    const CellArrays& mine = model.cells();
    std::vector<Vec3> start(mine.position.begin(), mine.position.end());
    auto exchange =
        std::make_unique<MpiDemExchange>(comm, std::move(global_cell), std::move(global_interface), owned,
                                         std::move(neighbours), std::move(start), allowance);
    exchange->interfacesDecomposed(model.interfaces());
    exchange->setImbalanceTolerance(parameters.imbalance_tolerance);
    model.decompose(exchange.get(), owned, energies, counters, rates);
    return exchange;
}

std::string describeDecomposition(const MpiDemExchange& exchange, const DecomposeParameters& parameters,
                                  MPI_Comm comm)
{
    long sums[2] = {exchange.ghostCells(), static_cast<long>(exchange.bytesPerStep())};
    int most[3] = {exchange.ownedCells(), exchange.ghostCells(), exchange.neighbourRanks()};
    int least = exchange.ownedCells();
    MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_LONG, MPI_SUM, comm);
    MPI_Allreduce(MPI_IN_PLACE, most, 3, MPI_INT, MPI_MAX, comm);
    MPI_Allreduce(MPI_IN_PLACE, &least, 1, MPI_INT, MPI_MIN, comm);
    char line[400];
    std::snprintf(
        line, sizeof(line),
        "Decomposition: %d ranks (%s, %s weights): %d-%d cells per rank; %ld ghost cells in all (at most "
        "%d on a rank, at most %d neighbour ranks); %.4g kB of ghost states and item results sent per step "
        "in all; cells may "
        "move %.4g mm before the ghost layer must be rebuilt",
        size(comm), parameters.method->type(), parameters.cost_weights ? "cost" : "uniform", least, most[0],
        sums[0], most[1], most[2], 1e-3 * static_cast<double>(sums[1]), 1e3 * exchange.allowance());
    return line;
}

}  // namespace rockfrac::mpi
