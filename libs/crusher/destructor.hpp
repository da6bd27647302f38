#pragma once
// The destructor below the discharge (docs/theory-crusher.md, "Discharge record").
//
// When a cell's centroid is below the destructor level, the fragment it belongs to
// (cells joined by intact bonds, by union-find as in libs/fragments) leaves the model
// whole, at once: every cell of it is removed and the fragment is recorded with its
// mass, volume and sizes at that moment. A fragment can only reach the destructor
// through the discharge gap, so what is recorded is what the crusher produced; the
// discharge PSD is the mass-weighted distribution of these records.
#include <vector>

#include "dem/demModel.hpp"

namespace rockfrac {

struct DischargedFragment {
    double time = 0.0;
    int n_cells = 0;
    double mass = 0.0;                 // [kg]
    double volume = 0.0;               // mass / rock density [m^3]
    double equivalent_diameter = 0.0;  // (6 V / pi)^(1/3) [m]
    double sieve_size = 0.0;           // intermediate principal extent of the dilated cores [m]
};

struct DestructorResult {
    std::vector<DischargedFragment> fragments;
    std::vector<int> new_index;  // old cell -> new cell, -1 removed (empty when nothing left)
    double mass = 0.0;           // removed this call [kg]
};

// Remove every fragment with a cell below z = below; nothing happens when none is.
DestructorResult destroyBelow(DemModel& model, double below);

// Sizes of a set of cells as one fragment: principal extents of their dilated cores
// (world frame), descending; the sieve size is the middle one.
Vec3 principalExtents(const DemModel& model, const std::vector<int>& cells);

}  // namespace rockfrac
