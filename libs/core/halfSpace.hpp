#pragma once
// A closed half-space normal·x <= offset with a unit outward normal: the
// facets of a convex hull, the walls of a Voronoi domain.
#include "core/vec3.hpp"

namespace rockfrac {

struct HalfSpace {
    Vec3 normal;
    double offset = 0.0;
    // Signed distance of p from the plane, positive outside.
    double signedDistance(const Vec3& p) const { return dot(normal, p) - offset; }
};

}  // namespace rockfrac
