#pragma once
// What a closed triangulated surface must also be to bound one rock: a single shell (one
// connected closed surface) that does not cross itself. checkSurface (triSurface.hpp) finds
// holes, non-manifold and misoriented edges; these two need the surface closed first.
#include <array>
#include <vector>

#include "geometry/triSurface.hpp"

namespace rockfrac {

// The connected pieces of the surface (triangles joined through shared vertices), each as the
// indices of its triangles, largest first.
std::vector<std::vector<int>> surfaceShells(const TriSurface& surface);

// Pairs of triangles that intersect other than along a shared edge or vertex (CGAL's
// Polygon_mesh_processing::self_intersections), at most `limit` of them. The surface must be
// closed and manifold (checkSurface(...).watertight()).
std::vector<std::array<int, 2>> selfIntersections(const TriSurface& surface, std::size_t limit = 10);

// Removes the triangles that name one vertex twice (collapsed to an edge or a point by the
// vertex welding: zero area, no edge of their own); returns how many.
int dropCollapsedTriangles(TriSurface& surface);

// Triangles of three distinct vertices on one line (area at most 1e-12 of their longest
// edge squared): zero-area needles that cannot be dropped without opening the surface.
std::vector<int> needleTriangles(const TriSurface& surface);

// How many vertices lie within `distance` of another vertex (exported duplicates that the
// exact welding of readStl did not merge).
int nearDuplicateVertices(const TriSurface& surface, double distance);

}  // namespace rockfrac
