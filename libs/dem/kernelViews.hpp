#pragma once
// The kernels' raw-pointer views of the array groups (demState.hpp). Each builder takes
// the groups of the host (std::vector) or of a device mirror (libs/demCuda: DeviceArray)
// alike, so the OpenMP path and the CUDA backend hand the kernels the same arrays. The
// builders set the arrays only; counts of blocks, block sums and the laws' constants
// are the caller's.
#include "dem/bondLaw.hpp"
#include "dem/cellKernels.hpp"
#include "dem/pairContact.hpp"
#include "dem/wallContact.hpp"

namespace rockfrac {

// An optional array (demFields.hpp: empty = neutral): null when empty.
template <class Array>
auto* optionalData(Array& array)
{
    return array.size() > 0 ? array.data() : nullptr;
}

// Cells as the contact kernels see them (rotation and world angular velocity: the
// per-cell caches refreshed at each evaluation).
template <class Cells, class Rotations, class Vectors>
CellContactView cellContactView(Cells& c, Rotations& rotation, Vectors& angular_velocity_world)
{
    CellContactView v;
    v.position = c.position.data();
    v.velocity = c.velocity.data();
    v.angular_velocity_world = angular_velocity_world.data();
    v.rotation = rotation.data();
    v.mass = c.mass.data();
    v.dilation_radius = c.dilation_radius.data();
    v.bounding_radius = c.bounding_radius.data();
    v.core_vertex_offset = c.core_vertex_offset.data();
    v.core_vertices = c.core_vertices.data();
    v.core_edge_offset = c.core_edge_offset.data();
    v.core_edges = c.core_edges.data();
    v.core_plane_offset = c.core_plane_offset.data();
    v.core_planes = c.core_planes.data();
    return v;
}

// Interfaces, their bonds and their cells (softening: the host's pool, or a device's
// entries per bond with each interface's slot at its first bond).
template <class Cells, class Interfaces, class Bonds, class Rotations, class Vectors>
void viewBondArrays(BondKernelArgs& a, Cells& c, Interfaces& f, Bonds& b, Rotations& rotation,
                    Vectors& angular_velocity_world)
{
    a.n_interfaces = f.size();
    a.position = c.position.data();
    a.velocity = c.velocity.data();
    a.angular_velocity_world = angular_velocity_world.data();
    a.rotation = rotation.data();
    a.cell_i = f.cell_i.data();
    a.cell_j = f.cell_j.data();
    a.bond_offset = f.bond_offset.data();
    a.normal_i_body = f.normal_i.data();
    a.normal_j_body = f.normal_j.data();
    a.length_i = f.length_i.data();
    a.length_j = f.length_j.data();
    a.bond_area = f.bond_area.data();
    a.damping_beta = f.damping_beta.data();
    a.strength_scale = optionalData(f.strength_scale);
    a.softening_slot = f.softening_slot.data();
    a.intact_bonds = f.intact_bonds.data();
    a.force_on_i = f.force_on_i.data();
    a.torque_on_i = f.torque_on_i.data();
    a.torque_on_j = f.torque_on_j.data();
    a.anchor_node_offset = c.anchor_node_offset.data();
    a.anchor_nodes = c.anchor_nodes.data();
    a.node_i = b.node_i.data();
    a.node_j = b.node_j.data();
    a.stage = b.stage.data();
    a.softening = b.softening.data();
}

// Cell–cell pairs (energies are summed per block, not stored per pair).
template <class Interfaces, class Pairs>
void viewPairArrays(PairKernelArgs& a, Interfaces& f, Pairs& p)
{
    a.n_pairs = p.size();
    a.intact_bonds = f.intact_bonds.data();
    a.bond_offset = f.bond_offset.data();
    a.cell_a = p.cell_a.data();
    a.cell_b = p.cell_b.data();
    a.interface = p.interface.data();
    a.separation_margin = p.separation_margin.data();
    a.seat = p.seat.data();
    a.items.tangential_spring = p.tangential_spring.data();
    a.items.last_normal = p.last_normal.data();
    a.items.status = p.status.data();
    a.items.stiffness = p.stiffness.data();
    a.force_on_b = p.force_on_b.data();
    a.point_or_torque = p.point_or_torque.data();
}

// Cell–wall items (the walls and their triangles are the caller's).
template <class Items>
void viewWallItemArrays(WallKernelArgs& a, Items& w)
{
    a.n_items = w.size();
    a.item_cell = w.cell.data();
    a.item_wall = w.wall.data();
    a.item_triangle_offset = w.triangle_offset.data();
    a.item_triangles = w.triangles.data();
    a.item_centre_at_build = w.centre_at_build.data();
    a.item_clearance_at_build = w.clearance_at_build.data();
    a.items.tangential_spring = w.tangential_spring.data();
    a.items.last_normal = w.last_normal.data();
    a.items.elastic_energy = w.elastic_energy.data();
    a.items.damping_power = w.damping_power.data();
    a.items.friction_dissipation = w.friction_dissipation.data();
    a.items.status = w.status.data();
    a.items.stiffness = w.stiffness.data();
    a.force_on_cell = w.force_on_cell.data();
    a.torque_on_cell = w.torque_on_cell.data();
    a.wall_power = w.wall_power.data();
}

// Each cell's sum over its items. lists: interface_offset, interfaces, pair_offset, pairs
// and wall_item_offset (DemModel::GatherLists or a device's copy).
template <class Cells, class Interfaces, class Pairs, class Items, class Lists, class Floats>
void viewGatherArrays(GatherArgs& a, Cells& c, Interfaces& f, Pairs& p, Items& w, Lists& lists,
                      Floats& contact_frequency2)
{
    a.mass = c.mass.data();
    a.interface_offset = lists.interface_offset.data();
    a.interface_entries = lists.interfaces.data();
    a.interface_force_on_i = f.force_on_i.data();
    a.interface_torque_on_i = f.torque_on_i.data();
    a.interface_torque_on_j = f.torque_on_j.data();
    a.pair_offset = lists.pair_offset.data();
    a.pair_entries = lists.pairs.data();
    a.pair_force_on_b = p.force_on_b.data();
    a.pair_point_or_torque = p.point_or_torque.data();
    a.pair_cell_b = p.cell_b.data();
    a.position = c.position.data();
    a.wall_item_offset = lists.wall_item_offset.data();
    a.wall_force_on_cell = w.force_on_cell.data();
    a.wall_torque_on_cell = w.torque_on_cell.data();
    a.force = c.force.data();
    a.torque = c.torque.data();
    a.pair_stiffness = p.stiffness.data();
    a.wall_stiffness = w.stiffness.data();
    a.principal_inertia = c.principal_inertia.data();
    a.bounding_radius = c.bounding_radius.data();
    a.contact_frequency2 = contact_frequency2.data();
}

// The integrator's cells (rotation: of the last force evaluation).
template <class Cells, class Rotations>
IntegrationArgs integrationView(Cells& c, Rotations& rotation, const Vec3& gravity)
{
    IntegrationArgs a;
    a.gravity = gravity;
    a.mass = c.mass.data();
    a.principal_inertia = c.principal_inertia.data();
    a.force = c.force.data();
    a.torque = c.torque.data();
    a.rotation = rotation.data();
    a.position = c.position.data();
    a.velocity = c.velocity.data();
    a.orientation = c.orientation.data();
    a.angular_velocity = c.angular_velocity.data();
    return a;
}

}  // namespace rockfrac
