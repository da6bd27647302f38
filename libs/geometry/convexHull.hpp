#pragma once
// Convex hulls (CGAL) and the half-space description the Voronoi mesher fills.
#include <cstdint>
#include <vector>

#include "core/halfSpace.hpp"
#include "geometry/triSurface.hpp"

namespace rockfrac {

struct ConvexHull {
    TriSurface surface;             // triangulated hull, outward oriented
    std::vector<HalfSpace> planes;  // one per distinct facet plane (coplanar triangles merged)
};

// UserError when the points are fewer than 4 or (nearly) coplanar.
ConvexHull convexHull(const std::vector<Vec3>& points);

// A random irregular convex rock, reproducible from `seed`: points on an
// ellipsoid with axes a >= b >= c, where elongation = b/a and flatness = c/b
// (Zingg's shape ratios, both in (0, 1]), each pushed in or out by up to
// `roughness` of its radius; with roundness ρ > 0 its corners and edges are then
// rounded to radius ρ R_in (R_in the inscribed radius about the centroid); the
// result is scaled to exactly `volume`.
struct RockShape {
    double volume = 0.0;      // [m^3]
    double elongation = 0.8;  // b/a
    double flatness = 0.7;    // c/b
    double roughness = 0.25;  // relative radial scatter of the hull points
    int nPoints = 40;         // points the hull is built from (more: rounder)
    double roundness = 0.0;   // Wadell's corner radius / inscribed radius; 0 = sharp hull
    std::uint64_t seed = 1;
};
ConvexHull generateRock(const RockShape& shape);

}  // namespace rockfrac
