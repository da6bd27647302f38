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
    double radius = 0.0;                    // the dilation radius the core was made for [m]
};

// Every face plane moved inward by dilation_radius, cut exactly (Voro++ plane
// clipping). Coordinates are relative to a point inside the cell (its centroid).
// If the eroded cell is empty or degenerate, the core is the cell shrunk toward
// the centroid by max(1 - r_d / h_min, 0.1), h_min the smallest centroid–face distance,
// and keeps the cell's edges (cell_edges). The edges serve the wall contact of a core
// edge with a ridge of a triangulated surface (docs/theory-dem.md §7).
ErodedCore erodeConvexCell(const std::vector<Vec3>& cell_vertices, const std::vector<CellPlane>& faces,
                           const std::vector<std::array<int, 2>>& cell_edges, double dilation_radius);

// The core for the model's dilation radius r_d: erodeConvexCell, unless erosion fails and its
// shrink factor 1 - r_d / h_min falls below the 0.1 floor (r_d > 0.9 h_min): that clamped core
// dilated by r_d would stick out of its cell by up to r_d - 0.9 h_min, into its neighbours and
// through a plate set at the mesh, an overlap at rest that the first step turns into contact
// energy with no input. Such a cell (a cell far finer than the mesh's mean, e.g. at the fine end
// of a size field) gets its own radius 0.5 h_min instead, eroded or shrunk by 0.5, so its
// dilated core stays inside the cell. core.radius is the radius used.
ErodedCore dilatedCellCore(const std::vector<Vec3>& cell_vertices, const std::vector<CellPlane>& faces,
                           const std::vector<std::array<int, 2>>& cell_edges, double dilation_radius);

}  // namespace rockfrac
