// DemModel in a decomposed run (dem/demExchange.hpp): which items this rank counts, the sums
// over the ranks, and the walls' reactions summed in the serial model's order.
#include <string>

#include "core/error.hpp"
#include "dem/demExchange.hpp"
#include "dem/demModel.hpp"

namespace rockfrac {

void DemModel::decompose(DemExchange* exchange, const std::vector<char>& owned,
                         const DemEnergies& whole_energies, const DemCounters& whole_counters,
                         const DemForceRates& whole_rates)
{
    if (static_cast<int>(owned.size()) != cells_.size())
        throw UserError("DemModel::decompose: " + std::to_string(owned.size()) + " ownership flags for " +
                        std::to_string(cells_.size()) + " cells");
    exchange_ = exchange;
    owned_cell_.assign(owned.begin(), owned.end());
    for (unsigned char& o : owned_cell_) o = o != 0;
    counted_interface_.resize(interfaces_.size());
    for (int k = 0; k < interfaces_.size(); ++k) counted_interface_[k] = owned_cell_[interfaces_.cell_i[k]];
    countPairs();
    countInterfaces();
    // The whole model built its lists, or builds them, at its next force evaluation: so do
    // the ranks (the lists cut down by removeCells were built where the whole model's were not).
    interfaces_cracked_at_build_ = counters_.interfaces_cracked;
    lists_valid_ = false;
    // The cumulative energies and the powers the next half kick books stay with rank 0; the
    // others add from zero. The walls' work is booked alike on every rank (from the merged
    // wall powers) and counted on rank 0 only (reduceOverRanks).
    const bool first = exchange_->rank() == 0;
    energies_ = whole_energies;
    if (!first)
        for (double* e : {&energies_.bond_damping, &energies_.contact_damping, &energies_.friction,
                          &energies_.fracture, &energies_.gravity_work, &energies_.exchanged})
            *e = 0.0;
    force_rates_ = first ? whole_rates : DemForceRates{};
    global_energies_ = whole_energies;
    global_counters_ = whole_counters;
    energy_floor_ = 0.0;
}

// Interfaces: the bonds, broken bonds, open and cracked interfaces this rank counts.
void DemModel::countInterfaces()
{
    int bonds = 0, broken = 0, open = 0, cracked = 0;
    for (int k = 0; k < interfaces_.size(); ++k) {
        if (!counted(counted_interface_, k)) continue;
        const int n = interfaces_.bond_offset[k + 1] - interfaces_.bond_offset[k];
        bonds += n;
        broken += n - interfaces_.intact_bonds[k];
        open += interfaces_.intact_bonds[k] == 0;
        cracked += n - interfaces_.intact_bonds[k] > 0;
    }
    counters_.bonds = bonds;
    counters_.bonds_broken = broken;
    counters_.interfaces_open = open;
    counters_.interfaces_cracked = cracked;
}

// A pair is counted where its first cell is owned.
void DemModel::countPairs()
{
    counted_pair_.resize(pairs_.size());
    int listed = 0;
    for (int p = 0; p < pairs_.size(); ++p) {
        counted_pair_[p] = owned_cell_[pairs_.cell_a[p]];
        listed += counted_pair_[p];
    }
    counters_.contact_pairs_listed = listed;
}

int DemModel::reduceOverRanks(int non_finite_cell)
{
    const DemEnergies& e = energies_;
    const DemCounters& c = counters_;
    std::vector<double> v = {e.kinetic_translation,
                             e.kinetic_rotation,
                             e.bond_strain,
                             e.contact_elastic,
                             e.bond_damping,
                             e.contact_damping,
                             e.friction,
                             e.fracture,
                             exchange_->rank() == 0 ? e.wall_work : 0.0,
                             e.gravity_work,
                             e.exchanged,
                             static_cast<double>(c.bonds),
                             static_cast<double>(c.bonds_broken),
                             static_cast<double>(c.interfaces_open),
                             static_cast<double>(c.interfaces_cracked),
                             static_cast<double>(c.contact_pairs_listed),
                             static_cast<double>(c.contacts_active),
                             static_cast<double>(c.wall_contacts_active),
                             static_cast<double>(c.core_intersections),
                             static_cast<double>(c.pair_core_intersections),
                             static_cast<double>(c.shrunk_cores),
                             static_cast<double>(c.own_radius_cells)};
    exchange_->sumOverRanks(v);
    DemEnergies& g = global_energies_;
    g.kinetic_translation = v[0];
    g.kinetic_rotation = v[1];
    g.bond_strain = v[2];
    g.contact_elastic = v[3];
    g.bond_damping = v[4];
    g.contact_damping = v[5];
    g.friction = v[6];
    g.fracture = v[7];
    g.wall_work = v[8];
    g.gravity_work = v[9];
    g.exchanged = v[10];
    // Steps, rebuilds and the step check's splits are taken together: the same on every rank.
    global_counters_ = counters_;
    int* const summed[] = {&global_counters_.bonds,
                           &global_counters_.bonds_broken,
                           &global_counters_.interfaces_open,
                           &global_counters_.interfaces_cracked,
                           &global_counters_.contact_pairs_listed,
                           &global_counters_.contacts_active,
                           &global_counters_.wall_contacts_active,
                           &global_counters_.core_intersections,
                           &global_counters_.pair_core_intersections,
                           &global_counters_.shrunk_cores,
                           &global_counters_.own_radius_cells};
    for (int i = 0; i < 11; ++i) *summed[i] = static_cast<int>(v[11 + i]);
    // The first non-finite cell by global id, or -1.
    const double mine =
        non_finite_cell >= 0 ? -static_cast<double>(exchange_->globalCell(non_finite_cell)) : -1e300;
    const double first = exchange_->maxOverRanks(mine);
    return first > -1e300 ? static_cast<int>(-first) : -1;
}

// The serial model sums its wall items in (cell, wall) order; each rank sends the terms of its
// own cells' items and every rank adds the merged list in that order.
void DemModel::sumWallReactionsOverRanks()
{
    std::vector<WallItemTerm> mine;
    for (int i = 0; i < wall_items_.size(); ++i) {
        const int c = wall_items_.cell[i];
        if (!owned_cell_[c]) continue;
        WallItemTerm t;
        t.cell = exchange_->globalCell(c);
        t.wall = wall_items_.wall[i];
        t.force = wall_items_.force_on_cell[i];
        t.torque = cross(cells_.position[c] - walls_[t.wall].origin, t.force) + wall_items_.torque_on_cell[i];
        t.power = wall_items_.wall_power[i];
        mine.push_back(t);
    }
    for (const WallItemTerm& t : exchange_->mergeWallTerms(mine)) {
        WallState& w = walls_[t.wall];
        w.reaction -= t.force;
        w.reaction_torque -= t.torque;
        w.power += t.power;
    }
}

}  // namespace rockfrac
