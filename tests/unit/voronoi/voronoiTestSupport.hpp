#pragma once
// Shared fixtures of the voronoi tests: the paper's BDT disc, random convex
// rocks, and the geometric invariants every tessellation must satisfy.
#include <cstdint>
#include <string>
#include <vector>

#include "voronoi/domain.hpp"
#include "voronoi/voronoiMesh.hpp"

namespace rockfrac::test {

// The Brazilian disc of the paper: D = 44.8 mm, t = 13.8 mm.
Domain bdtDisc();

// A random convex polytope: `nPlanes` planes tangent to a sphere of radius
// about 1 (between 0.8 and 1.2) in random directions, plus the 8 octant planes
// that keep it bounded, all scaled by `scale` and moved to `centre`.
Domain randomConvexRock(int nPlanes, std::uint64_t seed, double scale = 1.0, const Vec3& centre = {});

// The same rock scaled to the given volume [m^3].
Domain rockOfVolume(double volume, std::uint64_t seed);

// Exactly equal, field by field and bit by bit.
bool identical(const VoronoiMesh& a, const VoronoiMesh& b);

// Each returns an empty string if the invariant holds, else what failed.
// `length` is the mean cell size, the scale of the tolerances.
std::string checkSharedFaces(const VoronoiMesh& mesh, double length);
std::string checkClosedConvexCells(const VoronoiMesh& mesh, double length);
std::string checkBonds(const VoronoiMesh& mesh);
std::string checkBoundaryFacesOnPlanes(const VoronoiMesh& mesh, const Domain& domain, double length);

double sumOfVolumes(const VoronoiMesh& mesh);
double minimumSeedDistance(const std::vector<Vec3>& seeds);

}  // namespace rockfrac::test
