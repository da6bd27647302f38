#pragma once
// Where mass scaling adds mass: a sliver-rich mesh (e.g. of a dense scan's hull) can add
// several times the rock's mass, which changes its inertia and the run's dynamics.
#include <cstddef>
#include <string>

#include "core/vec3.hpp"

namespace rockfrac::fem {

class FemModel;

struct AddedMassSummary {
    double fraction = 0.0;            // added mass / physical mass
    std::size_t elements = 0;         // all elements
    std::size_t scaledElements = 0;   // elements whose density was raised
    Vec3 centroid;                    // centroid of the added mass (m)
    double surfaceShare = 0.0;        // share of the added mass in elements with a face on the surface
    Vec3 smallestAt;                  // centroid of the element of the smallest altitude (m)
    double smallestHeight = 0.0;      // smallest altitude of any element (m)
    double medianHeight = 0.0;        // median of the elements' smallest altitudes (m)
    double scaledMedianHeight = 0.0;  // the same over the scaled elements (m)
};

// From the model's element densities against the physical density `density` (kg/m^3).
AddedMassSummary summariseAddedMass(const FemModel& model, double density);

// The one-line warning when mass scaling adds more than `limit` of the mass (empty
// otherwise): the added percentage, how many elements and where, their size against the
// median, and what to do (a coarser mesh, a simplified surface, a smaller step target).
std::string addedMassWarning(const AddedMassSummary& summary, double massScalingTimeStep,
                             double limit = 0.10);

}  // namespace rockfrac::fem
