#pragma once
// The intact bonded block of benchDem and benchDemMpi (docs/benchmarks.md): the BDT's cell size
// (meso constant 7.25e-8 m^3), seeds pruned at 0.6 of the spacing, bonds that never break, no
// gravity, small random velocities (seed 3) so that every bond works.
#include <cmath>
#include <memory>

#include "core/random.hpp"
#include "dem/demModel.hpp"
#include "dem/voronoiQnscBond.hpp"
#include "voronoi/domain.hpp"
#include "voronoi/tessellation.hpp"

namespace rockfrac {

inline VoronoiMesh benchBlockMesh(int nCells, CellOrder order)
{
    const double volume = nCells * 7.25e-8;
    const double side = std::cbrt(volume / 2.0);
    const Domain domain = Domain::box({0, 0, 0}, {2 * side, side, side});
    const double spacing = std::cbrt(7.25e-8);
    // Cells numbered along a Morton curve (voronoiMeshDict cellOrder morton), as a large
    // mesh should be; CellOrder::seeding keeps the random order of the seeds.
    return generateVoronoiMesh(domain, nCells, 0.6 * spacing, 7, 0.1, order);
}

inline DemParameters benchBlockParameters()
{
    DemParameters p;
    VoronoiQnscBondLaw::Parameters q;
    q.tensile_strength = 1e12;  // intact: no bond ever breaks
    q.cohesion = 1.5e12;
    p.bond_law = std::make_shared<VoronoiQnscBondLaw>(q);
    p.gravity = {0, 0, 0};
    p.damping_reading = DampingReading::criticalFraction;
    p.bond_damping = 0.05;
    return p;
}

inline void setBenchBlockVelocities(DemModel& model)
{
    SplitMix64 random(3);
    for (int c = 0; c < model.cells().size(); ++c)
        model.setCellVelocity(c, {random.uniform(-1e-3, 1e-3), random.uniform(-1e-3, 1e-3), 0}, {});
}

}  // namespace rockfrac
