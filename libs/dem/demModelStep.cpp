// DemModel: the explicit step (velocity Verlet), energy measurement and the status check.
#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"
#include "dem/cellKernels.hpp"
#include "dem/demExchange.hpp"
#include "dem/demModel.hpp"
#include "dem/demModelDetail.hpp"
#include "dem/kernelViews.hpp"

namespace rockfrac {

using demDetail::cell_block_size;

IntegrationArgs DemModel::integrationArgs()
{
    return integrationView(cells_, rotation_, parameters_.gravity);
}

// First half kick, drift and rotation update (kickDriftCell), gravity's work summed per block.
void DemModel::kickDrift(double dt)
{
    const int n = cells_.size();
    const int n_blocks = (n + cell_block_size - 1) / cell_block_size;
    cell_block_sums_.assign(n_blocks, CellBlockSums{});
    const IntegrationArgs a = integrationArgs();
#pragma omp parallel for schedule(static) if (n_blocks > 1)
    for (int block = 0; block < n_blocks; ++block) {
        double gravity_work = 0.0;
        for (int c = block * cell_block_size; c < std::min(n, (block + 1) * cell_block_size); ++c) {
            const double work = kickDriftCell(a, c, dt);
            if (counted(owned_cell_, c)) gravity_work += work;
        }
        cell_block_sums_[block].gravity_work = gravity_work;
    }
    for (const CellBlockSums& s : cell_block_sums_) energies_.gravity_work += s.gravity_work;
}

// Second half kick (kickCell).
void DemModel::kick(double dt)
{
    const int n = cells_.size();
    const IntegrationArgs a = integrationArgs();
#pragma omp parallel for schedule(static) if (n >= parallelMinimumItems())
    for (int c = 0; c < n; ++c) kickCell(a, c, dt);
}

// Kinetic energy and the finiteness check, summed per block in a fixed order.
void DemModel::measureCells(double sync_dt)
{
    const int n = cells_.size();
    const int n_blocks = (n + cell_block_size - 1) / cell_block_size;
    cell_block_sums_.assign(n_blocks, CellBlockSums{});
    const IntegrationArgs a = integrationArgs();
#pragma omp parallel for schedule(static) if (n_blocks > 1)
    for (int block = 0; block < n_blocks; ++block) {
        CellBlockSums s;
        for (int c = block * cell_block_size; c < std::min(n, (block + 1) * cell_block_size); ++c) {
            const CellEnergyTerms t = measureCell(a, c, sync_dt);
            if (!counted(owned_cell_, c)) continue;  // a ghost: its owner counts it
            s.kinetic_translation += t.kinetic_translation;
            s.kinetic_rotation += t.kinetic_rotation;
            if (!t.finite && s.non_finite_cell < 0) s.non_finite_cell = c;
        }
        cell_block_sums_[block] = s;
    }
    energies_.kinetic_translation = energies_.kinetic_rotation = 0.0;
    int non_finite = -1;
    for (const CellBlockSums& s : cell_block_sums_) {
        energies_.kinetic_translation += s.kinetic_translation;
        energies_.kinetic_rotation += s.kinetic_rotation;
        if (non_finite < 0) non_finite = s.non_finite_cell;
    }
    finishMeasurement(energies_.kinetic_translation, energies_.kinetic_rotation, non_finite);
}

// The kinetic energies are known: rebase the balance if asked, then check the state.
void DemModel::finishMeasurement(double kinetic_translation, double kinetic_rotation, int non_finite_cell)
{
    energies_.kinetic_translation = kinetic_translation;
    energies_.kinetic_rotation = kinetic_rotation;
    if (exchange_) non_finite_cell = reduceOverRanks(non_finite_cell);
    // A state set by the caller is an energy input: the balance is measured from here.
    if (rebase_energy_) {
        initial_balance_ = energies().balance();
        energy_scale_ = 0.0;
        rebase_energy_ = false;
    }
    updateStatus(non_finite_cell);
}

void DemModel::updateStatus(int non_finite_cell)
{
    status_ = DemStatus{};
    status_.step = counters_.steps;
    status_.time = time_;
    status_.cell = non_finite_cell;
    const DemEnergies& e = energies();
    energy_scale_ = std::max(energy_scale_, e.kinetic() + e.stored() + e.dissipated() +
                                                std::fabs(e.wall_work) + std::fabs(e.gravity_work));
    status_.energy_scale = energy_scale_;
    status_.energy_error = e.balance() - initial_balance_;
    // Below the energy one average bond releases when it breaks the balance is round-off
    // (a plate that has just touched a vertex): the growth check starts above it.
    if (energy_floor_ == 0.0) {
        double area = 0.0, length = 0.0;
        for (int k = 0; k < interfaces_.size(); ++k) {
            if (!counted(counted_interface_, k)) continue;
            const int n = interfaces_.bond_offset[k + 1] - interfaces_.bond_offset[k];
            area += interfaces_.bond_area[k] * n;
            length += (interfaces_.length_i[k] + interfaces_.length_j[k]) * n;
        }
        int n_bonds = std::max(1, bonds_.size());
        if (exchange_) {  // of the whole model
            std::vector<double> sums = {area, length};
            exchange_->sumOverRanks(sums);
            area = sums[0];
            length = sums[1];
            n_bonds = std::max(1, global_counters_.bonds);
        }
        energy_floor_ = std::max(1e-300, parameters_.bond_law->energyFloor(area, n_bonds, length / n_bonds));
    }
    if (non_finite_cell >= 0 || !std::isfinite(status_.energy_error))
        status_.code = DemStatusCode::nonFiniteState;
    else if (status_.energy_error >
                 parameters_.energy_growth_tolerance * std::max(energy_scale_, energy_floor_) &&
             status_.energy_error > 0.0)
        status_.code = DemStatusCode::energyGrowth;
}

// The power of the velocity-dependent forces (dashpots) and of the walls is booked half a
// step at a time, with the forces of the half kick it acts in: the first half kick of a
// step uses the forces of the last evaluation, which the previous step booked for its own
// second half only, or a re-evaluation after the caller changed a wall's motion (with the
// velocities after the kick and the new wall velocity: a crusher re-evaluates every step,
// and booking the step's own evaluation over the whole step left a quarter of the liners'
// dashpot losses out).
void DemModel::bookFirstHalfKick(double dt)
{
    energies_.bond_damping += force_rates_.bond_damping * 0.5 * dt;
    energies_.contact_damping += force_rates_.contact_damping * 0.5 * dt;
    for (WallState& w : walls_) {
        w.work += w.power * 0.5 * dt;
        energies_.wall_work += w.power * 0.5 * dt;
    }
}

double DemModel::step(double dt)
{
    if (!forces_valid_) computeForces(0.0);
    return stepInParts(dt, [this](double part) { singleStep(part); });
}

// Velocity Verlet over dt (forces valid at the start).
void DemModel::singleStep(double dt)
{
    last_dt_ = dt;
    bookFirstHalfKick(dt);
    kickDrift(dt);
    moveWalls(dt);
    computeForces(dt);
    kick(dt);
    time_ += dt;
    ++counters_.steps;
    measureCells(dt);
}

}  // namespace rockfrac
