// DemModel: one force evaluation: kinematic caches, bond and contact kernels, the gather.
#include <algorithm>
#include <vector>

#include "core/parallel.hpp"
#include "dem/cellKernels.hpp"
#include "dem/demExchange.hpp"
#include "dem/demModel.hpp"
#include "dem/kernelViews.hpp"

namespace rockfrac {

void DemModel::refreshKinematicCaches()
{
    const int n = cells_.size();
#pragma omp parallel for schedule(static) if (n >= parallelMinimumItems())
    for (int c = 0; c < n; ++c)
        refreshCellKinematics(cells_.orientation.data(), cells_.angular_velocity.data(), rotation_.data(),
                              angular_velocity_world_.data(), c);
    refreshWallPoses();
}

void DemModel::refreshWallPoses()
{
    wall_poses_.clear();
    for (const WallState& w : walls_) wall_poses_.push_back(wallPose(w));
}

BondKernelArgs DemModel::bondArgs()
{
    BondKernelArgs a;
    viewBondArrays(a, cells_, interfaces_, bonds_, rotation_, angular_velocity_world_);
    bond_block_sums_.resize((a.n_interfaces + a.block_size - 1) / a.block_size);
    a.block_sums = bond_block_sums_.data();
    a.counted = counted_interface_.empty() ? nullptr : counted_interface_.data();
    return a;
}

CellContactView DemModel::cellView() const
{
    return cellContactView(cells_, rotation_, angular_velocity_world_);
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
        if (!counted(counted_interface_, k)) continue;
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

// Sums over contact items in item order (deterministic); returns the active count.
// A decomposed model counts the items of its own cells only (owned_cell empty: every item).
template <class Arrays>
int sumContactEnergies(const Arrays& items, const std::vector<unsigned char>& owned_cell,
                       DemEnergies& energies, double& damping_power, int& intersections)
{
    int active = 0;
    for (int i = 0; i < items.size(); ++i) {
        if (items.status[i] == contactNone) continue;
        if (!owned_cell.empty() && !owned_cell[items.cell[i]]) continue;
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
    pa.cells = cellView();
    viewPairArrays(pa, interfaces_, pairs_);
    pa.patch = parameters_.cell_contact_patch;
    pair_block_sums_.assign((pa.n_pairs + pa.block_size - 1) / pa.block_size, ContactBlockSums{});
    pa.block_sums = pair_block_sums_.data();
    pa.counted = counted_pair_.empty() ? nullptr : counted_pair_.data();
    parameters_.contact_law->runPairs(pa);

    WallKernelArgs wa;
    wa.constants = rock_steel_;
    wa.dt = dt;
    wa.cells = pa.cells;
    wa.walls = wall_poses_.data();
    wa.triangle_vertices = triangle_vertices_.data();
    wa.triangle_features = triangle_features_.data();
    wa.triangle_prisms = triangle_prisms_.data();
    viewWallItemArrays(wa, wall_items_);
    wa.owned_cell = owned_cell_.empty() ? nullptr : owned_cell_.data();
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
    counters_.wall_contacts_active = sumContactEnergies(
        wall_items_, owned_cell_, energies_, force_rates_.contact_damping, counters_.core_intersections);
    energies_.contact_damping += force_rates_.contact_damping * 0.5 * dt;  // second half kick
    for (WallState& w : walls_) {
        w.reaction = w.reaction_torque = Vec3{};
        w.power = 0.0;
    }
    if (exchange_)
        sumWallReactionsOverRanks();
    else
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
    a.pair_torques = parameters_.cell_contact_patch;
    contact_frequency2_.resize(cells_.size());
    const GatherLists lists = gatherLists();
    viewGatherArrays(a, cells_, interfaces_, pairs_, wall_items_, lists, contact_frequency2_);
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
    for (int c = 0; c < n; ++c)
        if (counted(owned_cell_, c)) largest = std::max(largest, contact_frequency2_[c]);
    max_contact_frequency2_ = exchange_ ? exchange_->maxOverRanks(largest) : largest;
}

void DemModel::computeForces(double dt)
{
    // Decomposed: the ghosts as their owners have them (after a drift, or after a kick when a
    // moved wall makes the step start with an evaluation), bitwise.
    if (exchange_) exchange_->refreshGhosts(cells_);
    refreshKinematicCaches();
    runBondKernel(dt);
    // Decomposed: the interfaces another rank computed (their first cell is its), before the
    // lists are judged (a pair whose bonds are intact is left out).
    if (exchange_) exchange_->returnInterfaceResults(interfaces_);
    // Moved too far, or an interface lost its first bond (its pair must enter the list).
    bool rebuild = neighbourListsStale() || counters_.interfaces_cracked != interfaces_cracked_at_build_;
    if (exchange_) rebuild = exchange_->anyRank(rebuild);  // every rank when one must: the serial moments
    if (rebuild) rebuildNeighbourLists();
    runContactKernels(dt);
    if (exchange_) exchange_->returnPairResults(pairs_);
    gatherForces();
    forces_valid_ = true;
}

void DemModel::evaluateForces(double dt)
{
    computeForces(dt);
    measureCells(0.0);
}

}  // namespace rockfrac
