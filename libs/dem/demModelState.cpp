// DemModel: state access for output, restart and imposed kinematics.
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dem/demModel.hpp"

namespace rockfrac {

namespace {

void requireSize(std::size_t got, int expected, const std::string& what)
{
    if (static_cast<int>(got) != expected) {
        std::ostringstream message;
        message << "restart data does not match the model: " << what << " has " << got
                << " entries, expected " << expected;
        throw UserError(message.str());
    }
}

}  // namespace

void DemModel::setCellState(const std::vector<Vec3>& position, const std::vector<Vec3>& velocity,
                            const std::vector<Quat>& orientation, const std::vector<Vec3>& angular_velocity)
{
    const int n = cells_.size();
    requireSize(position.size(), n, "cell positions");
    requireSize(velocity.size(), n, "cell velocities");
    requireSize(orientation.size(), n, "cell orientations");
    requireSize(angular_velocity.size(), n, "cell angular velocities");
    cells_.position = position;
    cells_.velocity = velocity;
    cells_.orientation = orientation;
    cells_.angular_velocity = angular_velocity;
    lists_valid_ = forces_valid_ = false;
    rebase_energy_ = true;
}

void DemModel::setCellForces(const std::vector<Vec3>& force, const std::vector<Vec3>& torque)
{
    requireSize(force.size(), cells_.size(), "cell forces");
    requireSize(torque.size(), cells_.size(), "cell torques");
    cells_.force = force;
    cells_.torque = torque;
    forces_valid_ = true;
}

void DemModel::setCellState(const CellArrays& state)
{
    forEachField<restartField, derivedField>(
        [&](const auto& field, auto& mine, const auto& given) {
            requireSize(given.size(), cells_.size(), entryName<CellArrays>(field));
            mine = given;
        },
        cells_, state);
    lists_valid_ = forces_valid_ = false;
    rebase_energy_ = true;
}

void DemModel::setCellForces(const CellArrays& state)
{
    bool given = false;  // none given: nothing to set; some: each must match
    forEachField<restartField | derivedField>(
        [&](const auto&, const auto& v) { given = given || !v.empty(); }, state);
    if (!given) return;
    forEachField<restartField | derivedField>(
        [&](const auto& field, auto& mine, const auto& v) {
            requireSize(v.size(), cells_.size(), entryName<CellArrays>(field));
            mine = v;
        },
        cells_, state);
    forces_valid_ = true;
}

void DemModel::setBondHistory(const BondArrays& history)
{
    const int n = bonds_.size();
    forEachField<restartField>(
        [&](const auto& field, const auto& v) { requireSize(v.size(), n, entryName<BondArrays>(field)); },
        history);
    bonds_.stage = history.stage;
    std::vector<BondSoftening> per_bond(n);
    for (int b = 0; b < n; ++b) {
        per_bond[b].onset_displacement = history.onset_displacement[b];
        per_bond[b].onset_stress = history.onset_stress[b];
        per_bond[b].rupture_displacement = history.rupture_displacement[b];
        per_bond[b].max_displacement = history.max_displacement[b];
        per_bond[b].damage = history.damage[b];
    }
    setSofteningPerBond(per_bond);
    for (int k = 0; k < interfaces_.size(); ++k) {
        int intact = 0;
        for (int b = interfaces_.bond_offset[k]; b < interfaces_.bond_offset[k + 1]; ++b)
            intact += bonds_.stage[b] != bondBroken;
        interfaces_.intact_bonds[k] = intact;
    }
    forces_valid_ = false;
}

BondArrays DemModel::bonds() const
{
    BondArrays out;
    const int n = bonds_.size();
    out.anchor_i.resize(n);
    out.anchor_j.resize(n);
    for (int k = 0; k < interfaces_.size(); ++k) {
        const Vec3* nodes_i = cells_.anchor_nodes.data() + cells_.anchor_node_offset[interfaces_.cell_i[k]];
        const Vec3* nodes_j = cells_.anchor_nodes.data() + cells_.anchor_node_offset[interfaces_.cell_j[k]];
        for (int b = interfaces_.bond_offset[k]; b < interfaces_.bond_offset[k + 1]; ++b) {
            out.anchor_i[b] = nodes_i[bonds_.node_i[b]];
            out.anchor_j[b] = nodes_j[bonds_.node_j[b]];
        }
    }
    out.stage = bonds_.stage;
    const std::vector<BondSoftening> per_bond = softeningPerBond();
    out.onset_displacement.resize(n);
    out.onset_stress.resize(n);
    out.rupture_displacement.resize(n);
    out.max_displacement.resize(n);
    out.damage.resize(n);
    for (int b = 0; b < n; ++b) {
        out.onset_displacement[b] = per_bond[b].onset_displacement;
        out.onset_stress[b] = per_bond[b].onset_stress;
        out.rupture_displacement[b] = per_bond[b].rupture_displacement;
        out.max_displacement[b] = per_bond[b].max_displacement;
        out.damage[b] = per_bond[b].damage;
    }
    return out;
}

std::vector<BondSoftening> DemModel::softeningPerBond() const
{
    std::vector<BondSoftening> per_bond(bonds_.size());
    for (int k = 0; k < interfaces_.size(); ++k) {
        const int slot = interfaces_.softening_slot[k];
        if (slot < 0) continue;
        const int first = interfaces_.bond_offset[k];
        for (int b = first; b < interfaces_.bond_offset[k + 1]; ++b)
            per_bond[b] = bonds_.softening[slot + (b - first)];
    }
    return per_bond;
}

void DemModel::setSofteningPerBond(const std::vector<BondSoftening>& per_bond)
{
    requireSize(per_bond.size(), bonds_.size(), "bond softening histories");
    // Slots for the interfaces with a bond past its onset, in interface order.
    bonds_.softening.clear();
    for (int k = 0; k < interfaces_.size(); ++k) {
        const int first = interfaces_.bond_offset[k], last = interfaces_.bond_offset[k + 1];
        bool softened = false;
        for (int b = first; b < last; ++b) softened = softened || bonds_.stage[b] != bondElastic;
        interfaces_.softening_slot[k] = softened ? static_cast<int>(bonds_.softening.size()) : -1;
        if (softened)
            bonds_.softening.insert(bonds_.softening.end(), per_bond.begin() + first,
                                    per_bond.begin() + last);
    }
}

void DemModel::claimSofteningSlot(int k)
{
    if (interfaces_.softening_slot[k] >= 0) return;
    interfaces_.softening_slot[k] = static_cast<int>(bonds_.softening.size());
    bonds_.softening.resize(bonds_.softening.size() +
                            (interfaces_.bond_offset[k + 1] - interfaces_.bond_offset[k]));
}

void DemModel::setContactHistory(const ContactPairArrays& pairs, const WallContactArrays& wall_items)
{
    // Only keys and springs matter: the next rebuild carries them into fresh lists.
    pairs_ = pairs;
    if (!parameters_.cell_contact_patch) pairs_.seat.clear();  // point contacts keep no seats
    wall_items_ = wall_items;
    lists_valid_ = forces_valid_ = false;
}

void DemModel::setClock(double time, long steps, const DemEnergies& energies, double initial_balance)
{
    time_ = time;
    counters_.steps = steps;
    energies_ = energies;
    initial_balance_ = initial_balance;
    rebase_energy_ = false;
}

void DemModel::setCellPose(int cell, const Vec3& position, const Quat& orientation)
{
    cells_.position.at(cell) = position;
    cells_.orientation.at(cell) = normalised(orientation);
    lists_valid_ = forces_valid_ = false;  // a jump: GJK margins no longer hold
    rebase_energy_ = true;
}

void DemModel::setCellVelocity(int cell, const Vec3& velocity, const Vec3& angular_velocity_body)
{
    cells_.velocity.at(cell) = velocity;
    cells_.angular_velocity.at(cell) = angular_velocity_body;
    forces_valid_ = false;
    rebase_energy_ = true;
}

std::vector<double> DemModel::cellDamage() const
{
    std::vector<int> broken(cells_.size(), 0);
    for (int k = 0; k < interfaces_.size(); ++k) {
        const int n_broken =
            interfaces_.bond_offset[k + 1] - interfaces_.bond_offset[k] - interfaces_.intact_bonds[k];
        broken[interfaces_.cell_i[k]] += n_broken;
        broken[interfaces_.cell_j[k]] += n_broken;
    }
    std::vector<double> damage(cells_.size(), 0.0);
    for (int c = 0; c < cells_.size(); ++c)
        if (cells_.initial_bond_count[c] > 0) damage[c] = double(broken[c]) / cells_.initial_bond_count[c];
    return damage;
}

Vec3 DemModel::angularMomentum(int c) const
{
    const Vec3 w = cells_.angular_velocity[c], inertia = cells_.principal_inertia[c];
    return rotationMatrix(cells_.orientation[c]) * Vec3{inertia.x * w.x, inertia.y * w.y, inertia.z * w.z};
}

}  // namespace rockfrac
