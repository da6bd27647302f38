// DemModel: one force evaluation: kinematic caches, bond and contact kernels, the gather.
#include <algorithm>
#include <vector>

#include "core/parallel.hpp"
#include "dem/cellKernels.hpp"
#include "dem/demModel.hpp"

namespace rockfrac {

void DemModel::refreshKinematicCaches()
{
    const int n = cells_.size();
#pragma omp parallel for schedule(static) if (n >= parallelMinimumItems())
    for (int c = 0; c < n; ++c)
        refreshCellKinematics(cells_.orientation.data(), cells_.angular_velocity.data(), rotation_.data(),
                              angular_velocity_world_.data(), c);
    wall_poses_.clear();
    for (const WallState& w : walls_) wall_poses_.push_back(wallPose(w));
}

BondKernelArgs DemModel::bondArgs()
{
    BondKernelArgs a;
    a.n_interfaces = interfaces_.size();
    a.position = cells_.position.data();
    a.velocity = cells_.velocity.data();
    a.angular_velocity_world = angular_velocity_world_.data();
    a.rotation = rotation_.data();
    a.cell_i = interfaces_.cell_i.data();
    a.cell_j = interfaces_.cell_j.data();
    a.bond_offset = interfaces_.bond_offset.data();
    a.normal_i_body = interfaces_.normal_i.data();
    a.normal_j_body = interfaces_.normal_j.data();
    a.length_i = interfaces_.length_i.data();
    a.length_j = interfaces_.length_j.data();
    a.bond_area = interfaces_.bond_area.data();
    a.damping_beta = interfaces_.damping_beta.data();
    a.strength_scale = interfaces_.strength_scale.empty() ? nullptr : interfaces_.strength_scale.data();
    a.softening_slot = interfaces_.softening_slot.data();
    a.intact_bonds = interfaces_.intact_bonds.data();
    a.force_on_i = interfaces_.force_on_i.data();
    a.torque_on_i = interfaces_.torque_on_i.data();
    a.torque_on_j = interfaces_.torque_on_j.data();
    a.anchor_node_offset = cells_.anchor_node_offset.data();
    a.anchor_nodes = cells_.anchor_nodes.data();
    a.node_i = bonds_.node_i.data();
    a.node_j = bonds_.node_j.data();
    a.stage = bonds_.stage.data();
    a.softening = bonds_.softening.data();
    bond_block_sums_.resize((a.n_interfaces + a.block_size - 1) / a.block_size);
    a.block_sums = bond_block_sums_.data();
    return a;
}

CellContactView DemModel::cellView() const
{
    CellContactView v;
    v.position = cells_.position.data();
    v.velocity = cells_.velocity.data();
    v.angular_velocity_world = angular_velocity_world_.data();
    v.rotation = rotation_.data();
    v.mass = cells_.mass.data();
    v.dilation_radius = cells_.dilation_radius.data();
    v.bounding_radius = cells_.bounding_radius.data();
    v.core_vertex_offset = cells_.core_vertex_offset.data();
    v.core_vertices = cells_.core_vertices.data();
    v.core_edge_offset = cells_.core_edge_offset.data();
    v.core_edges = cells_.core_edges.data();
    v.core_plane_offset = cells_.core_plane_offset.data();
    v.core_planes = cells_.core_planes.data();
    return v;
}

void DemModel::runBondKernel(double dt)
{
    parameters_.bond_law->run(bondArgs());
    // Interfaces whose first onset found no softening slot: claimed in interface order
    // (deterministic whatever the thread count), then evaluated again, now stored.
    int pending = 0;
    for (const BondBlockSums& s : bond_block_sums_) pending += s.pending_onsets;
    if (pending > 0) {
        std::vector<int> onsets;
        for (int k = 0; k < interfaces_.size(); ++k)
            if (interfaces_.intact_bonds[k] == bondOnsetPending) {
                claimSofteningSlot(k);
                onsets.push_back(k);
            }
        BondKernelArgs again = bondArgs();
        again.only_interfaces = onsets.data();
        again.n_only = static_cast<int>(onsets.size());
        parameters_.bond_law->run(again);
    }
    double strain = 0.0;
    force_rates_.bond_damping = 0.0;
    for (const BondBlockSums& s : bond_block_sums_) {
        strain += s.strain_energy;
        force_rates_.bond_damping += s.damping_power;
        energies_.fracture += s.fracture_dissipation;
    }
    // These forces act over the second half kick of this step (the first half kick of the
    // next one is booked by step(), see bookFirstHalfKick).
    energies_.bond_damping += force_rates_.bond_damping * 0.5 * dt;
    energies_.bond_strain = strain;
    int broken = 0, open = 0, cracked = 0;
    for (int k = 0; k < interfaces_.size(); ++k) {
        const int broken_here =
            interfaces_.bond_offset[k + 1] - interfaces_.bond_offset[k] - interfaces_.intact_bonds[k];
        broken += broken_here;
        open += interfaces_.intact_bonds[k] == 0;
        cracked += broken_here > 0;
    }
    counters_.bonds_broken = broken;
    counters_.interfaces_open = open;
    counters_.interfaces_cracked = cracked;
}

namespace {

template <class Arrays>
ContactItemOutputs itemOutputs(Arrays& items)
{
    ContactItemOutputs o;
    o.tangential_spring = items.tangential_spring.data();
    o.last_normal = items.last_normal.data();
    o.elastic_energy = items.elastic_energy.data();
    o.damping_power = items.damping_power.data();
    o.friction_dissipation = items.friction_dissipation.data();
    o.status = items.status.data();
    o.stiffness = items.stiffness.data();
    return o;
}

// Sums over contact items in item order (deterministic); returns the active count.
template <class Arrays>
int sumContactEnergies(const Arrays& items, DemEnergies& energies, double& damping_power, int& intersections)
{
    int active = 0;
    for (int i = 0; i < items.size(); ++i) {
        if (items.status[i] == contactNone) continue;
        ++active;
        intersections += items.status[i] == contactCoresIntersect;
        energies.contact_elastic += items.elastic_energy[i];
        damping_power += items.damping_power[i];
        energies.friction += items.friction_dissipation[i];
    }
    return active;
}

}  // namespace

void DemModel::runContactKernels(double dt)
{
    PairKernelArgs pa;
    pa.constants = rock_rock_;
    pa.dt = dt;
    pa.n_pairs = pairs_.size();
    pa.cells = cellView();
    pa.intact_bonds = interfaces_.intact_bonds.data();
    pa.bond_offset = interfaces_.bond_offset.data();
    pa.cell_a = pairs_.cell_a.data();
    pa.cell_b = pairs_.cell_b.data();
    pa.interface = pairs_.interface.data();
    pa.separation_margin = pairs_.separation_margin.data();
    pa.seat = pairs_.seat.data();
    pa.items.tangential_spring = pairs_.tangential_spring.data();
    pa.items.last_normal = pairs_.last_normal.data();
    pa.items.status = pairs_.status.data();  // energies: block sums
    pa.items.stiffness = pairs_.stiffness.data();
    pa.force_on_b = pairs_.force_on_b.data();
    pa.point_or_torque = pairs_.point_or_torque.data();
    pa.patch = parameters_.cell_contact_patch;
    pair_block_sums_.assign((pa.n_pairs + pa.block_size - 1) / pa.block_size, ContactBlockSums{});
    pa.block_sums = pair_block_sums_.data();
    parameters_.contact_law->runPairs(pa);

    WallKernelArgs wa;
    wa.constants = rock_steel_;
    wa.dt = dt;
    wa.n_items = wall_items_.size();
    wa.cells = pa.cells;
    wa.walls = wall_poses_.data();
    wa.triangle_vertices = triangle_vertices_.data();
    wa.triangle_features = triangle_features_.data();
    wa.item_cell = wall_items_.cell.data();
    wa.item_wall = wall_items_.wall.data();
    wa.item_triangle_offset = wall_items_.triangle_offset.data();
    wa.item_triangles = wall_items_.triangles.data();
    wa.items = itemOutputs(wall_items_);
    wa.force_on_cell = wall_items_.force_on_cell.data();
    wa.torque_on_cell = wall_items_.torque_on_cell.data();
    wa.wall_power = wall_items_.wall_power.data();
    parameters_.contact_law->runWalls(wa);

    energies_.contact_elastic = 0.0;
    counters_.core_intersections = 0;
    counters_.contacts_active = 0;
    force_rates_.contact_damping = 0.0;
    for (const ContactBlockSums& s : pair_block_sums_) {
        energies_.contact_elastic += s.elastic_energy;
        force_rates_.contact_damping += s.damping_power;
        energies_.friction += s.friction_dissipation;
        counters_.contacts_active += s.active;
        counters_.core_intersections += s.cores_intersect;
    }
    counters_.pair_core_intersections = counters_.core_intersections;
    counters_.wall_contacts_active = sumContactEnergies(wall_items_, energies_, force_rates_.contact_damping,
                                                        counters_.core_intersections);
    energies_.contact_damping += force_rates_.contact_damping * 0.5 * dt;  // second half kick
    for (WallState& w : walls_) {
        w.reaction = w.reaction_torque = Vec3{};
        w.power = 0.0;
    }
    for (int i = 0; i < wall_items_.size(); ++i) {
        WallState& w = walls_[wall_items_.wall[i]];
        const Vec3 force = wall_items_.force_on_cell[i];
        w.reaction -= force;
        // Torque on the wall about its origin: minus the cell's force system moved there.
        w.reaction_torque -=
            cross(cells_.position[wall_items_.cell[i]] - w.origin, force) + wall_items_.torque_on_cell[i];
        w.power += wall_items_.wall_power[i];
    }
    for (WallState& w : walls_) {  // second half kick
        w.work += w.power * 0.5 * dt;
        energies_.wall_work += w.power * 0.5 * dt;
    }
}

GatherArgs DemModel::gatherArgs()
{
    GatherArgs a;
    a.gravity = parameters_.gravity;
    a.mass = cells_.mass.data();
    a.interface_offset = cell_interface_offset_.data();
    a.interface_entries = cell_interfaces_.data();
    a.interface_force_on_i = interfaces_.force_on_i.data();
    a.interface_torque_on_i = interfaces_.torque_on_i.data();
    a.interface_torque_on_j = interfaces_.torque_on_j.data();
    a.pair_offset = cell_pair_offset_.data();
    a.pair_entries = cell_pairs_.data();
    a.pair_force_on_b = pairs_.force_on_b.data();
    a.pair_point_or_torque = pairs_.point_or_torque.data();
    a.pair_torques = parameters_.cell_contact_patch;
    a.pair_cell_b = pairs_.cell_b.data();
    a.position = cells_.position.data();
    a.wall_item_offset = cell_wall_item_offset_.data();
    a.wall_force_on_cell = wall_items_.force_on_cell.data();
    a.wall_torque_on_cell = wall_items_.torque_on_cell.data();
    a.force = cells_.force.data();
    a.torque = cells_.torque.data();
    a.pair_stiffness = pairs_.stiffness.data();
    a.wall_stiffness = wall_items_.stiffness.data();
    a.principal_inertia = cells_.principal_inertia.data();
    a.bounding_radius = cells_.bounding_radius.data();
    contact_frequency2_.resize(cells_.size());
    a.contact_frequency2 = contact_frequency2_.data();
    return a;
}

// Each cell sums the items it takes part in, in a fixed order (cellKernels.hpp).
void DemModel::gatherForces()
{
    const int n = cells_.size();
    const GatherArgs a = gatherArgs();
#pragma omp parallel for schedule(static) if (n >= parallelMinimumItems())
    for (int c = 0; c < n; ++c) gatherCellForces(a, c);
    float largest = 0.0f;  // a maximum: the same whatever the thread count
#pragma omp parallel for schedule(static) reduction(max : largest) if (n >= parallelMinimumItems())
    for (int c = 0; c < n; ++c) largest = std::max(largest, contact_frequency2_[c]);
    max_contact_frequency2_ = largest;
}

void DemModel::computeForces(double dt)
{
    refreshKinematicCaches();
    runBondKernel(dt);
    // Moved too far, or an interface lost its first bond (its pair must enter the list).
    if (neighbourListsStale() || counters_.interfaces_cracked != interfaces_cracked_at_build_)
        rebuildNeighbourLists();
    runContactKernels(dt);
    gatherForces();
    forces_valid_ = true;
}

void DemModel::evaluateForces(double dt)
{
    computeForces(dt);
    measureCells(0.0);
}

}  // namespace rockfrac
