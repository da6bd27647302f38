#pragma once
// What the contact tests share: the box cell's size and radius, quiet and elastic-wall
// parameters, the Hertz modulus and the lowest core point of a posed cell.
#include <algorithm>

#include "dem/demModel.hpp"

namespace rockfrac::test {

inline constexpr double contact_cell_size = 5e-3;
inline constexpr double contact_dilation = 5e-4;

inline DemParameters quietContactParameters()
{
    DemParameters p;
    p.gravity = {0.0, 0.0, 0.0};
    p.bond_damping = 0.0;
    return p;
}

// Cells on walls with elastic (e = 1), frictionless contacts: their energy is conserved.
inline DemParameters elasticWallParameters()
{
    DemParameters p = quietContactParameters();
    p.rock_steel_restitution = 1.0;
    p.rock_steel_friction = 0.0;
    return p;
}

inline double effectiveModulus(double E1, double nu1, double E2, double nu2)
{
    return 1.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2);
}

// Lowest z of the core of cell c at orientation q.
inline double lowestCoreZ(const DemModel& model, int c, const Vec3& position, const Quat& q)
{
    const CellArrays& cells = model.cells();
    const Mat3 R = rotationMatrix(q);
    double lowest = 1e300;
    for (int v = cells.core_vertex_offset[c]; v < cells.core_vertex_offset[c + 1]; ++v)
        lowest = std::min(lowest, (position + R * cells.core_vertices[v]).z);
    return lowest;
}

}  // namespace rockfrac::test

using rockfrac::test::contact_cell_size;
using rockfrac::test::contact_dilation;
using rockfrac::test::effectiveModulus;
using rockfrac::test::elasticWallParameters;
using rockfrac::test::lowestCoreZ;
using rockfrac::test::quietContactParameters;
