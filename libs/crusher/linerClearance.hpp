#pragma once
// Where the feed may put a rock: the free chamber between the liners.
//
// meshCrusher's mantle and concave are surfaces of revolution about the z axis of their
// own frame. Read back from the STL, each is a profile r(z); a point of the world is
// taken into the liner's frame (its current pose: the mantle gyrates) and compared with
// r at its height. The feed factory (feedRock.hpp) uses this so that a rock can be put
// straight into the chamber, e.g. at the height where it will be nipped, without any of
// its vertices inside a liner (docs/theory-crusher.md, "Feed").
#include <limits>
#include <string>
#include <vector>

#include "dem/demState.hpp"
#include "geometry/crusherGeometry.hpp"
#include "geometry/triSurface.hpp"

namespace rockfrac {

struct RevolvedLiner {
    int wall = -1;          // the DEM wall that carries the liner (its pose moves the profile)
    Profile profile;        // (r, z) in the liner's frame, z strictly increasing
    bool free_outside = 1;  // mantle: the chamber is at r > r(z); concave: at r < r(z)
};

// The profile of `surface` (points in the liner's own frame). At a height with several
// rings (a horizontal profile segment) the one nearest the chamber counts: the largest r
// of a mantle, the smallest of a concave. UserError naming `name` when the surface is not
// one of revolution about z (a ring off the axis with fewer than three points at equal r),
// e.g. a scanned liner.
RevolvedLiner revolvedLiner(const TriSurface& surface, int wall, SurfaceFacing facing,
                            const std::string& name);

// Distance of the world point x from the liner in the pose `wall`, measured normal to the
// profile's local segment: positive in the chamber, negative inside the steel. +infinity
// above or below the liner's profile (no steel at that height).
double linerClearance(const RevolvedLiner& liner, const WallState& wall, const Vec3& x);

}  // namespace rockfrac
