#pragma once
// Broad phase: uniform grids for cell–cell pairs and for the triangles of a
// rigid surface. Built on the host at neighbour-list rebuilds only.
#include <cstddef>
#include <utility>
#include <vector>

#include "core/vec3.hpp"

namespace rockfrac {

// Pairs (i < j) whose spheres (centre, radius) come closer than skin, sorted by (i, j).
std::vector<std::pair<int, int>> findNearPairs(const std::vector<Vec3>& centres,
                                               const std::vector<double>& radii, double skin);

// Triangles (3 vertices each, in the surface's own frame) binned by their bounding boxes.
class TriangleGrid {
public:
    TriangleGrid() = default;
    explicit TriangleGrid(const std::vector<Vec3>& triangle_vertices);

    // Triangles whose bounding box comes within radius of centre (sorted, unique).
    void query(const Vec3& centre, double radius, std::vector<int>& found) const;
    // What its bins hold [bytes] (capacities).
    std::size_t memoryBytes() const
    {
        return bin_offset_.capacity() * sizeof(int) + bin_triangles_.capacity() * sizeof(int);
    }

private:
    void binRange(const Vec3& low, const Vec3& high, int lo[3], int hi[3]) const;

    Vec3 origin_;
    double spacing_ = 1.0;
    int dims_[3] = {1, 1, 1};
    std::vector<int> bin_offset_;
    std::vector<int> bin_triangles_;
};

}  // namespace rockfrac
