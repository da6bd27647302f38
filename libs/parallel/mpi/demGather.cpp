// gatherModel: every rank's share of a decomposed DemModel set into rank 0's whole model, the
// arrays a state file and the VTK frames are written from (parallel/mpi/demExchange.hpp).
#include <algorithm>
#include <numeric>

#include "dem/demFields.hpp"
#include "parallel/mpi/demExchange.hpp"
#include "parallel/mpi/haloExchange.hpp"

namespace rockfrac::mpi {

namespace {

using fieldDetail::put;
using fieldDetail::take;

// Every rank's bytes on rank 0, or on every rank (indexed by rank; empty elsewhere).
std::vector<std::vector<unsigned char>> gatherBytes(const std::vector<unsigned char>& mine, MPI_Comm comm,
                                                    bool everywhere)
{
    const int n_ranks = size(comm), me = rank(comm);
    const bool receives = everywhere || me == 0;
    const int bytes = static_cast<int>(mine.size());
    std::vector<int> counts(n_ranks), offsets(n_ranks + 1, 0);
    if (everywhere)
        MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
    else
        MPI_Gather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
    for (int r = 0; r < n_ranks; ++r) offsets[r + 1] = offsets[r] + counts[r];
    std::vector<unsigned char> all(receives ? offsets[n_ranks] : 0);
    if (everywhere)
        MPI_Allgatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE,
                       comm);
    else
        MPI_Gatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, 0,
                    comm);
    std::vector<std::vector<unsigned char>> out(receives ? n_ranks : 0);
    for (int r = 0; receives && r < n_ranks; ++r)
        out[r].assign(all.begin() + offsets[r], all.begin() + offsets[r + 1]);
    return out;
}

// The counted entities of a contact group (pairs by their first cell, wall items by their
// cell), their cells (and a pair's interface) renumbered to the whole model's.
template <class Group, class Renumber>
std::vector<unsigned char> packCounted(const Group& group, const std::vector<int>& cell_of,
                                       const MpiDemExchange& ex, Renumber&& renumber)
{
    std::vector<char> keep(group.size());
    for (int i = 0; i < group.size(); ++i) keep[i] = ex.owns(cell_of[i]);
    Group mine = group;
    keepFlaggedFields(mine, keep);
    renumber(mine);
    std::vector<unsigned char> out;
    put(out, static_cast<std::int64_t>(mine.size()));
    for (int i = 0; i < mine.size(); ++i) packEntity(mine, i, out);
    return out;
}

// Rank 0: every rank's entities of a group, merged in the order of `key` (the serial order).
template <class Group, class Key>
Group mergeCounted(const std::vector<std::vector<unsigned char>>& from, Key&& key)
{
    Group all;
    for (const auto& in : from) {
        std::size_t at = 0;
        const auto n = take<std::int64_t>(in, at);
        for (std::int64_t i = 0; i < n; ++i) at = unpackEntity(all, in, at);
    }
    std::vector<int> order(all.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(all, a) < key(all, b); });
    Group sorted;
    std::vector<unsigned char> bytes;
    for (int i : order) {
        bytes.clear();
        packEntity(all, i, bytes);
        unpackEntity(sorted, bytes, 0);
    }
    return sorted;
}

}  // namespace

std::size_t gatherModel(const DemModel& local, MpiDemExchange& ex, DemModel* whole, bool everywhere)
{
    const MPI_Comm comm = ex.comm();
    const bool root = everywhere || rank(comm) == 0;
    // Cells: the state and the forces of the last step, by global id.
    const CellArrays& cells = local.cells();
    std::vector<unsigned char> cell_bytes;
    for (int c = 0; c < cells.size(); ++c) {
        if (!ex.owns(c)) continue;
        put(cell_bytes, ex.globalCell(c));
        for (const Vec3& v : {cells.position[c], cells.velocity[c], cells.angular_velocity[c], cells.force[c],
                              cells.torque[c]})
            put(cell_bytes, v);
        put(cell_bytes, cells.orientation[c]);
    }
    // Bonds: each counted interface's stages and softening, by global interface.
    const InterfaceArrays& faces = local.interfaces();
    const std::vector<BondSoftening> softening = local.softeningPerBond();
    const auto& stage = local.bondStorage().stage;
    std::vector<unsigned char> bond_bytes;
    for (int k = 0; k < faces.size(); ++k) {
        if (!ex.owns(faces.cell_i[k])) continue;
        put(bond_bytes, ex.globalInterface(k));
        for (int b = faces.bond_offset[k]; b < faces.bond_offset[k + 1]; ++b) {
            put(bond_bytes, stage[b]);
            put(bond_bytes, softening[b]);
        }
    }
    const ContactPairArrays& pairs = local.contactPairs();
    const std::vector<int> pair_cell(pairs.cell_a.begin(), pairs.cell_a.end());
    const auto pair_bytes = packCounted(pairs, pair_cell, ex, [&](ContactPairArrays& p) {
        for (int i = 0; i < p.size(); ++i) {
            p.cell_a[i] = static_cast<int>(ex.globalCell(p.cell_a[i]));
            p.cell_b[i] = static_cast<int>(ex.globalCell(p.cell_b[i]));
            if (p.interface[i] >= 0) p.interface[i] = ex.globalInterface(p.interface[i]);
        }
    });
    const WallContactArrays& items = local.wallContacts();
    const std::vector<int> item_cell(items.cell.begin(), items.cell.end());
    const auto item_bytes = packCounted(items, item_cell, ex, [&](WallContactArrays& w) {
        for (int i = 0; i < w.size(); ++i) w.cell[i] = static_cast<int>(ex.globalCell(w.cell[i]));
    });
    // The powers the next half kick books: summed over the ranks (each holds its items' share).
    std::vector<double> rates = {local.forceRates().bond_damping, local.forceRates().contact_damping};
    ex.sumOverRanks(rates);

    const auto cell_from = gatherBytes(cell_bytes, comm, everywhere);
    const auto bond_from = gatherBytes(bond_bytes, comm, everywhere);
    const auto pair_from = gatherBytes(pair_bytes, comm, everywhere);
    const auto item_from = gatherBytes(item_bytes, comm, everywhere);
    if (!root || !whole) return 0;
    std::size_t received = 0;
    for (const auto* from : {&cell_from, &bond_from, &pair_from, &item_from})
        for (const auto& in : *from) received += in.size();

    CellArrays state = whole->cells();
    for (const auto& in : cell_from)
        for (std::size_t at = 0; at < in.size();) {
            const auto c = take<std::int64_t>(in, at);
            for (Vec3* v : {&state.position[c], &state.velocity[c], &state.angular_velocity[c],
                            &state.force[c], &state.torque[c]})
                *v = take<Vec3>(in, at);
            state.orientation[c] = take<Quat>(in, at);
        }
    BondArrays bonds = whole->bonds();
    const InterfaceArrays& all_faces = whole->interfaces();
    for (const auto& in : bond_from)
        for (std::size_t at = 0; at < in.size();) {
            const int k = take<int>(in, at);
            for (int b = all_faces.bond_offset[k]; b < all_faces.bond_offset[k + 1]; ++b) {
                bonds.stage[b] = take<unsigned char>(in, at);
                const auto s = take<BondSoftening>(in, at);
                bonds.onset_displacement[b] = s.onset_displacement;
                bonds.onset_stress[b] = s.onset_stress;
                bonds.rupture_displacement[b] = s.rupture_displacement;
                bonds.max_displacement[b] = s.max_displacement;
                bonds.damage[b] = s.damage;
            }
        }
    const auto all_pairs = mergeCounted<ContactPairArrays>(pair_from, [](const ContactPairArrays& p, int i) {
        return std::make_pair(p.cell_a[i], p.cell_b[i]);
    });
    const auto all_items = mergeCounted<WallContactArrays>(
        item_from, [](const WallContactArrays& w, int i) { return std::make_pair(w.cell[i], w.wall[i]); });

    // In readDemState's order: the state, histories, walls, clock, then the forces.
    whole->setCellState(state);
    whole->setBondHistory(bonds);
    whole->setContactHistory(all_pairs, all_items);
    for (int w = 0; w < local.nWalls(); ++w) whole->setWallState(w, local.wall(w));
    whole->setForceRates({rates[0], rates[1]});
    whole->setClock(local.time(), local.counters().steps, local.energies(), local.initialBalance());
    whole->setCounters(local.counters());
    whole->setCellForces(state);
    whole->setContactFrequencyBound(local.contactFrequencyBound());
    return received;
}

}  // namespace rockfrac::mpi
