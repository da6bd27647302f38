#pragma once
// The core of a dilated cell: the convex cell eroded by the dilation radius, so
// that core (+) sphere(r_d) has the cell's shape with rounded edges and two face
// neighbours touch at zero overlap (docs/theory-dem.md §Cores).
#include <array>
#include <vector>

#include "core/vec3.hpp"

namespace rockfrac {

// A face plane of a convex cell: points x inside satisfy dot(normal, x) <= offset.
struct CellPlane {
    Vec3 normal;  // outward unit normal
    double offset = 0.0;
};

struct ErodedCore {
    std::vector<Vec3> vertices;             // same frame as the input
    std::vector<std::array<int, 2>> edges;  // vertex index pairs, each edge once (i < j)
    bool shrunk = false;                    // erosion emptied the cell: shrink fallback used
};

// Every face plane moved inward by dilation_radius, cut exactly (Voro++ plane
// clipping). Coordinates are relative to a point inside the cell (its centroid).
// If the eroded cell is empty or degenerate, the core is the cell shrunk toward
// the centroid by max(1 - r_d / h_min, 0.1), h_min the smallest centroid–face distance,
// and keeps the cell's edges (cell_edges). The edges serve the wall contact of a core
// edge with a ridge of a triangulated surface (docs/theory-dem.md §7).
ErodedCore erodeConvexCell(const std::vector<Vec3>& cell_vertices, const std::vector<CellPlane>& faces,
                           const std::vector<std::array<int, 2>>& cell_edges, double dilation_radius);

}  // namespace rockfrac
