#pragma once
// The convex features of a triangulated wall: its ridges (edges where the surface bends
// away from the side a cell is on) and its convex vertices. A convex core can only first
// touch a surface at a core vertex (on a face, edge or vertex of the surface), or with
// a core edge or face on a ridge or a convex vertex; flat and concave edges never hold
// the nearest point. The wall contact pairs core edges with ridges and the core with
// convex vertices (wallContact.hpp, wallPatch; docs/theory-dem.md §7).
#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"

namespace rockfrac {

// One 16-bit word per triangle, bits as read by ridgeBit/convexCornerBit (wallContact.hpp):
// bit k (k = 0, 1, 2): edge k (corner k to corner k+1) is a ridge seen from the winding
// side; bit 3 + k: seen from the other side; bit 6 + k / 9 + k: corner k is a convex vertex
// seen from the winding / other side. Each edge and vertex is flagged on its lowest-numbered
// triangle only. An edge of one triangle (an open rim) or of more than two is a ridge from
// both sides; an edge between two triangles is a ridge from the side its dihedral angle
// opens away from, when the second triangle's far corner lies off the first's plane by more
// than flat_tolerance times its distance from the edge (a flat pair, such as a square split
// in two, is no ridge). A vertex is convex from a side when one of its edges is a ridge
// from that side.
std::vector<std::uint16_t> surfaceFeatureFlags(const std::vector<Vec3>& vertices,
                                               const std::vector<std::array<int, 3>>& triangles,
                                               double flat_tolerance = 1e-6);

}  // namespace rockfrac
