// DemModel: cells leaving (discharge), arrays shrunk to size, memory accounting.
#include <cstddef>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dem/demModel.hpp"

namespace rockfrac {

namespace {

void requireCount(std::size_t got, int expected)
{
    if (static_cast<int>(got) != expected)
        throw UserError("removeCells: the mask has " + std::to_string(got) + " entries for " +
                        std::to_string(expected) + " cells");
}

}  // namespace

std::vector<int> DemModel::removeCells(const std::vector<char>& remove)
{
    const double energy_before = energies_.kinetic() + energies_.stored();
    std::vector<int> new_index = removeCellsOnly(remove);
    if (static_cast<int>(new_index.size()) == cells_.size()) return new_index;  // none removed
    // Forces of the remaining cells without the removed ones; the energy that left
    // is what the kinetic and stored energies lost.
    computeForces(0.0);
    measureCells(last_dt_);
    energies_.exchanged += energy_before - (energies_.kinetic() + energies_.stored());
    updateStatus(-1);
    return new_index;
}

std::vector<int> DemModel::removeCellsOnly(const std::vector<char>& remove)
{
    const int n = cells_.size();
    requireCount(remove.size(), n);
    std::vector<int> new_index(n, -1);
    std::vector<char> keep_cell(n);
    int kept = 0;
    for (int c = 0; c < n; ++c) {
        keep_cell[c] = !remove[c];
        if (keep_cell[c]) new_index[c] = kept++;
    }
    if (kept == n) return new_index;

    // Cells, with their core vertex and anchor node ranges.
    keepFlaggedFields(cells_, keep_cell);

    // Interfaces and their bonds: kept when both cells stay (a bond to a removed cell
    // goes with it). Monotone renumbering keeps the (cell_i, cell_j) order.
    InterfaceArrays& f = interfaces_;
    std::vector<char> keep_face(f.size()), keep_bond(bonds_.size(), 0);
    std::vector<int> bond_offset(1, 0);
    std::vector<BondSoftening> softening;  // the pool, compacted in interface order
    for (int k = 0; k < f.size(); ++k) {
        keep_face[k] = keep_cell[f.cell_i[k]] && keep_cell[f.cell_j[k]];
        if (!keep_face[k]) continue;
        f.cell_i[k] = new_index[f.cell_i[k]];
        f.cell_j[k] = new_index[f.cell_j[k]];
        const int n_bonds = f.bond_offset[k + 1] - f.bond_offset[k];
        for (int b = f.bond_offset[k]; b < f.bond_offset[k + 1]; ++b) keep_bond[b] = 1;
        bond_offset.push_back(bond_offset.back() + n_bonds);
        if (f.softening_slot[k] >= 0) {
            const int slot = static_cast<int>(softening.size());
            softening.insert(softening.end(), bonds_.softening.begin() + f.softening_slot[k],
                             bonds_.softening.begin() + f.softening_slot[k] + n_bonds);
            f.softening_slot[k] = slot;
        }
    }
    f.bond_offset = std::move(bond_offset);
    bonds_.softening = std::move(softening);
    keepFlagged(f.softening_slot, keep_face);
    keepFlaggedFields(f, keep_face);
    BondStorage& b = bonds_;
    keepFlaggedFields(b, keep_bond);
    counters_.bonds = b.size();

    // Contact histories: pairs and wall items of remaining cells, renumbered (the
    // keys stay sorted); the interface of a kept pair is renumbered too.
    std::vector<int> new_face(keep_face.size(), -1);
    for (int k = 0, next = 0; k < static_cast<int>(keep_face.size()); ++k)
        if (keep_face[k]) new_face[k] = next++;
    ContactPairArrays& p = pairs_;
    std::vector<char> keep_pair(p.size());
    for (int k = 0; k < p.size(); ++k) {
        keep_pair[k] = keep_cell[p.cell_a[k]] && keep_cell[p.cell_b[k]];
        if (!keep_pair[k]) continue;
        p.cell_a[k] = new_index[p.cell_a[k]];
        p.cell_b[k] = new_index[p.cell_b[k]];
        if (p.interface[k] >= 0) p.interface[k] = new_face[p.interface[k]];
    }
    keepFlaggedFields(p, keep_pair);
    WallContactArrays& w = wall_items_;
    std::vector<char> keep_item(w.size());
    for (int k = 0; k < w.size(); ++k) {
        keep_item[k] = keep_cell[w.cell[k]];
        if (keep_item[k]) w.cell[k] = new_index[w.cell[k]];
    }
    keepFlaggedFields(w, keep_item);

    buildIncidence();
    energy_floor_ = 0.0;
    lists_valid_ = false;
    return new_index;
}

void DemModel::shrinkToFit()
{
    shrinkFields(cells_);
    shrinkFields(interfaces_);
    shrinkFields(bonds_);
}

DemMemoryBytes DemModel::memoryUse() const
{
    DemMemoryBytes m;
    m.anchor_nodes = capacityBytes(ranged(cells_.anchor_node_offset, cells_.anchor_nodes));
    m.cores = fieldBytes<rangedField>(cells_) - m.anchor_nodes;
    m.cells = fieldBytes<0u, rangedField>(cells_) + capacityBytes(rotation_) +
              capacityBytes(angular_velocity_world_) + capacityBytes(position_at_build_);
    m.interfaces = fieldBytes(interfaces_);
    m.bonds = fieldBytes<0u, poolField>(bonds_);
    m.softening = fieldBytes<poolField>(bonds_);
    m.pairs = fieldBytes(pairs_);
    // Wall items, and the walls: states, poses, triangles, grids and what the last list
    // build saw of them.
    m.wall_items = fieldBytes(wall_items_) + capacityBytes(contact_frequency2_) +
                   capacityBytes(triangle_vertices_) + capacityBytes(triangle_features_) +
                   capacityBytes(triangle_prisms_) + capacityBytes(walls_) + capacityBytes(wall_poses_) +
                   capacityBytes(triangle_grids_) + capacityBytes(wall_origin_at_build_) +
                   capacityBytes(wall_orientation_at_build_) + capacityBytes(wall_extent_);
    for (const TriangleGrid& grid : triangle_grids_) m.wall_items += grid.memoryBytes();
    // Gather and neighbour lists, and the per-block partial sums.
    m.lists = capacityBytes(cell_interface_offset_) + capacityBytes(cell_interfaces_) +
              capacityBytes(cell_pair_offset_) + capacityBytes(cell_pairs_) +
              capacityBytes(cell_wall_item_offset_) + capacityBytes(neighbour_interface_) +
              capacityBytes(bond_block_sums_) + capacityBytes(pair_block_sums_) +
              capacityBytes(cell_block_sums_);
    return m;
}

}  // namespace rockfrac
