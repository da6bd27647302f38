// DemModel: cells leaving (discharge), arrays shrunk to size, memory accounting.
#include <cstddef>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dem/demModel.hpp"

namespace rockfrac {

namespace {

template <class T>
std::size_t bytes(const std::vector<T>& v)
{
    return v.capacity() * sizeof(T);
}

void requireCount(std::size_t got, int expected)
{
    if (static_cast<int>(got) != expected)
        throw UserError("removeCells: the mask has " + std::to_string(got) + " entries for " +
                        std::to_string(expected) + " cells");
}

// Keep the entries whose flag is set, in order.
template <class T>
void keepFlagged(std::vector<T>& v, const std::vector<char>& keep)
{
    std::size_t out = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (keep[i]) v[out++] = v[i];
    v.resize(out);
}

// Keep the CSR ranges [offset[i], offset[i+1]) whose flag is set, in order.
template <class T>
void keepFlaggedRanges(std::vector<int>& offset, std::vector<T>& values, const std::vector<char>& keep)
{
    std::vector<int> kept_offset(1, 0);
    std::vector<T> kept;
    for (std::size_t i = 0; i + 1 < offset.size(); ++i) {
        if (!keep[i]) continue;
        kept.insert(kept.end(), values.begin() + offset[i], values.begin() + offset[i + 1]);
        kept_offset.push_back(static_cast<int>(kept.size()));
    }
    offset = std::move(kept_offset);
    values = std::move(kept);
}

}  // namespace

std::vector<int> DemModel::removeCells(const std::vector<char>& remove)
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
    const double energy_before = energies_.kinetic() + energies_.stored();

    // Cells, with their core vertex and anchor node ranges.
    CellArrays& c = cells_;
    keepFlaggedRanges(c.core_vertex_offset, c.core_vertices, keep_cell);
    keepFlaggedRanges(c.core_edge_offset, c.core_edges, keep_cell);
    keepFlaggedRanges(c.core_plane_offset, c.core_planes, keep_cell);
    keepFlaggedRanges(c.anchor_node_offset, c.anchor_nodes, keep_cell);
    keepFlagged(c.position, keep_cell);
    keepFlagged(c.velocity, keep_cell);
    keepFlagged(c.orientation, keep_cell);
    keepFlagged(c.angular_velocity, keep_cell);
    keepFlagged(c.force, keep_cell);
    keepFlagged(c.torque, keep_cell);
    keepFlagged(c.mass, keep_cell);
    keepFlagged(c.principal_inertia, keep_cell);
    keepFlagged(c.dilation_radius, keep_cell);
    keepFlagged(c.bounding_radius, keep_cell);
    keepFlagged(c.initial_bond_count, keep_cell);

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
    keepFlagged(f.cell_i, keep_face);
    keepFlagged(f.cell_j, keep_face);
    keepFlagged(f.intact_bonds, keep_face);
    keepFlagged(f.normal_i, keep_face);
    keepFlagged(f.normal_j, keep_face);
    keepFlagged(f.length_i, keep_face);
    keepFlagged(f.length_j, keep_face);
    keepFlagged(f.bond_area, keep_face);
    keepFlagged(f.damping_beta, keep_face);
    if (!f.strength_scale.empty()) keepFlagged(f.strength_scale, keep_face);
    keepFlagged(f.force_on_i, keep_face);
    keepFlagged(f.torque_on_i, keep_face);
    keepFlagged(f.torque_on_j, keep_face);
    BondStorage& b = bonds_;
    keepFlagged(b.node_i, keep_bond);
    keepFlagged(b.node_j, keep_bond);
    keepFlagged(b.stage, keep_bond);
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
    keepFlagged(p.cell_a, keep_pair);
    keepFlagged(p.cell_b, keep_pair);
    keepFlagged(p.interface, keep_pair);
    keepFlagged(p.tangential_spring, keep_pair);
    keepFlagged(p.last_normal, keep_pair);
    keepFlagged(p.separation_margin, keep_pair);
    keepFlagged(p.seat, keep_pair);
    keepFlagged(p.force_on_b, keep_pair);
    keepFlagged(p.point_or_torque, keep_pair);
    keepFlagged(p.status, keep_pair);
    keepFlagged(p.stiffness, keep_pair);
    WallContactArrays& w = wall_items_;
    std::vector<char> keep_item(w.size());
    std::vector<int> triangle_offset(1, 0), triangles;
    for (int k = 0; k < w.size(); ++k) {
        keep_item[k] = keep_cell[w.cell[k]];
        if (!keep_item[k]) continue;
        w.cell[k] = new_index[w.cell[k]];
        triangles.insert(triangles.end(), w.triangles.begin() + w.triangle_offset[k],
                         w.triangles.begin() + w.triangle_offset[k + 1]);
        triangle_offset.push_back(static_cast<int>(triangles.size()));
    }
    w.triangle_offset = std::move(triangle_offset);
    w.triangles = std::move(triangles);
    keepFlagged(w.cell, keep_item);
    keepFlagged(w.wall, keep_item);
    keepFlagged(w.tangential_spring, keep_item);
    keepFlagged(w.last_normal, keep_item);
    keepFlagged(w.force_on_cell, keep_item);
    keepFlagged(w.torque_on_cell, keep_item);
    keepFlagged(w.elastic_energy, keep_item);
    keepFlagged(w.damping_power, keep_item);
    keepFlagged(w.friction_dissipation, keep_item);
    keepFlagged(w.wall_power, keep_item);
    keepFlagged(w.status, keep_item);
    keepFlagged(w.stiffness, keep_item);

    buildIncidence();
    energy_floor_ = 0.0;
    lists_valid_ = false;
    // Forces of the remaining cells without the removed ones; the energy that left
    // is what the kinetic and stored energies lost.
    computeForces(0.0);
    measureCells(last_dt_);
    energies_.exchanged += energy_before - (energies_.kinetic() + energies_.stored());
    updateStatus(-1);
    return new_index;
}

void DemModel::shrinkToFit()
{
    CellArrays& c = cells_;
    c.core_vertices.shrink_to_fit();
    c.core_vertex_offset.shrink_to_fit();
    c.core_edges.shrink_to_fit();
    c.core_edge_offset.shrink_to_fit();
    c.core_planes.shrink_to_fit();
    c.core_plane_offset.shrink_to_fit();
    InterfaceArrays& f = interfaces_;
    for (auto* v : {&f.cell_i, &f.cell_j, &f.bond_offset, &f.intact_bonds}) v->shrink_to_fit();
    for (auto* v : {&f.normal_i, &f.normal_j}) v->shrink_to_fit();
    for (auto* v : {&f.length_i, &f.length_j, &f.bond_area, &f.damping_beta}) v->shrink_to_fit();
    f.softening_slot.shrink_to_fit();
    c.anchor_node_offset.shrink_to_fit();
    c.anchor_nodes.shrink_to_fit();
    bonds_.node_i.shrink_to_fit();
    bonds_.node_j.shrink_to_fit();
    bonds_.stage.shrink_to_fit();
}

DemMemoryBytes DemModel::memoryUse() const
{
    DemMemoryBytes m;
    const CellArrays& c = cells_;
    m.cells = bytes(c.position) + bytes(c.velocity) + bytes(c.orientation) + bytes(c.angular_velocity) +
              bytes(c.force) + bytes(c.torque) + bytes(c.mass) + bytes(c.principal_inertia) +
              bytes(c.dilation_radius) + bytes(c.bounding_radius) + bytes(c.initial_bond_count) +
              bytes(rotation_) + bytes(angular_velocity_world_) + bytes(position_at_build_);
    m.cores = bytes(c.core_vertex_offset) + bytes(c.core_vertices) + bytes(c.core_edge_offset) +
              bytes(c.core_edges) + bytes(c.core_plane_offset) + bytes(c.core_planes);
    m.anchor_nodes = bytes(c.anchor_node_offset) + bytes(c.anchor_nodes);
    const InterfaceArrays& f = interfaces_;
    m.interfaces = bytes(f.cell_i) + bytes(f.cell_j) + bytes(f.bond_offset) + bytes(f.intact_bonds) +
                   bytes(f.normal_i) + bytes(f.normal_j) + bytes(f.length_i) + bytes(f.length_j) +
                   bytes(f.bond_area) + bytes(f.damping_beta) + bytes(f.strength_scale) +
                   bytes(f.force_on_i) + bytes(f.torque_on_i) + bytes(f.torque_on_j) +
                   bytes(f.softening_slot);
    const BondStorage& b = bonds_;
    m.bonds = bytes(b.node_i) + bytes(b.node_j) + bytes(b.stage);
    m.softening = bytes(b.softening);
    const ContactPairArrays& p = pairs_;
    m.pairs = bytes(p.cell_a) + bytes(p.cell_b) + bytes(p.interface) + bytes(p.tangential_spring) +
              bytes(p.last_normal) + bytes(p.separation_margin) + bytes(p.seat) + bytes(p.force_on_b) +
              bytes(p.point_or_torque) + bytes(p.status) + bytes(p.stiffness);
    const WallContactArrays& w = wall_items_;
    m.wall_items = bytes(w.cell) + bytes(w.wall) + bytes(w.triangle_offset) + bytes(w.triangles) +
                   bytes(w.tangential_spring) + bytes(w.last_normal) + bytes(w.force_on_cell) +
                   bytes(w.torque_on_cell) + bytes(w.elastic_energy) + bytes(w.damping_power) +
                   bytes(w.friction_dissipation) + bytes(w.wall_power) + bytes(w.status) +
                   bytes(w.stiffness) + bytes(contact_frequency2_) + bytes(triangle_vertices_) +
                   bytes(triangle_features_);
    m.lists = bytes(cell_interface_offset_) + bytes(cell_interfaces_) + bytes(cell_pair_offset_) +
              bytes(cell_pairs_) + bytes(cell_wall_item_offset_) + bytes(neighbour_interface_);
    return m;
}

}  // namespace rockfrac
