#include "dem/neighbourSearch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rockfrac {

namespace {

// A uniform grid over a box: bin coordinates of points, clamped to the box.
struct UniformGrid {
    Vec3 low;
    double spacing = 1.0;
    int dims[3] = {1, 1, 1};

    UniformGrid(const Vec3& lo, const Vec3& hi, double cell_size, std::size_t max_bins)
        : low(lo), spacing(cell_size)
    {
        for (;;) {
            std::size_t total = 1;
            for (int d = 0; d < 3; ++d) {
                dims[d] = std::max(1, static_cast<int>(std::floor((hi[d] - lo[d]) / spacing)) + 1);
                total *= static_cast<std::size_t>(dims[d]);
            }
            if (total <= max_bins) break;
            spacing *= 1.5;  // a sparse cloud: coarser bins keep the grid small
        }
    }
    int coordinate(double x, int d) const
    {
        return std::min(dims[d] - 1, std::max(0, static_cast<int>(std::floor((x - low[d]) / spacing))));
    }
    int bin(int ix, int iy, int iz) const { return (ix * dims[1] + iy) * dims[2] + iz; }
    int nBins() const { return dims[0] * dims[1] * dims[2]; }
};

}  // namespace

std::vector<std::pair<int, int>> findNearPairs(const std::vector<Vec3>& centres,
                                               const std::vector<double>& radii, double skin)
{
    const int n = static_cast<int>(centres.size());
    std::vector<std::pair<int, int>> pairs;
    if (n < 2) return pairs;
    Vec3 lo = centres[0], hi = centres[0];
    double largest = 0.0;
    for (int i = 0; i < n; ++i) {
        for (int d = 0; d < 3; ++d) {
            lo[d] = std::min(lo[d], centres[i][d]);
            hi[d] = std::max(hi[d], centres[i][d]);
        }
        largest = std::max(largest, radii[i]);
    }
    const UniformGrid grid(lo, hi, 2.0 * largest + skin, 4 * static_cast<std::size_t>(n) + 64);
    // Counting sort of the cells by bin.
    std::vector<int> cell_bin(n), bin_offset(grid.nBins() + 1, 0), binned(n);
    for (int i = 0; i < n; ++i) {
        cell_bin[i] = grid.bin(grid.coordinate(centres[i].x, 0), grid.coordinate(centres[i].y, 1),
                               grid.coordinate(centres[i].z, 2));
        ++bin_offset[cell_bin[i] + 1];
    }
    for (int b = 0; b < grid.nBins(); ++b) bin_offset[b + 1] += bin_offset[b];
    std::vector<int> fill(bin_offset.begin(), bin_offset.end() - 1);
    for (int i = 0; i < n; ++i) binned[fill[cell_bin[i]]++] = i;

    std::vector<int> partners;
    for (int i = 0; i < n; ++i) {
        partners.clear();
        const int c[3] = {grid.coordinate(centres[i].x, 0), grid.coordinate(centres[i].y, 1),
                          grid.coordinate(centres[i].z, 2)};
        for (int ix = std::max(0, c[0] - 1); ix <= std::min(grid.dims[0] - 1, c[0] + 1); ++ix)
            for (int iy = std::max(0, c[1] - 1); iy <= std::min(grid.dims[1] - 1, c[1] + 1); ++iy)
                for (int iz = std::max(0, c[2] - 1); iz <= std::min(grid.dims[2] - 1, c[2] + 1); ++iz) {
                    const int b = grid.bin(ix, iy, iz);
                    for (int e = bin_offset[b]; e < bin_offset[b + 1]; ++e) {
                        const int j = binned[e];
                        const double reach = radii[i] + radii[j] + skin;
                        if (j > i && norm2(centres[j] - centres[i]) < reach * reach) partners.push_back(j);
                    }
                }
        std::sort(partners.begin(), partners.end());
        for (int j : partners) pairs.emplace_back(i, j);
    }
    return pairs;
}

TriangleGrid::TriangleGrid(const std::vector<Vec3>& triangle_vertices)
{
    const int n_triangles = static_cast<int>(triangle_vertices.size() / 3);
    if (n_triangles == 0) return;
    Vec3 lo = triangle_vertices[0], hi = triangle_vertices[0];
    double mean_size = 0.0;
    for (int t = 0; t < n_triangles; ++t) {
        for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d) {
                lo[d] = std::min(lo[d], triangle_vertices[3 * t + k][d]);
                hi[d] = std::max(hi[d], triangle_vertices[3 * t + k][d]);
            }
        mean_size += norm(triangle_vertices[3 * t + 1] - triangle_vertices[3 * t]) +
                     norm(triangle_vertices[3 * t + 2] - triangle_vertices[3 * t]);
    }
    mean_size /= 2.0 * n_triangles;
    const UniformGrid grid(lo, hi, std::max(mean_size, 1e-12 * norm(hi - lo) + 1e-300),
                           8 * static_cast<std::size_t>(n_triangles) + 64);
    origin_ = grid.low;
    spacing_ = grid.spacing;
    for (int d = 0; d < 3; ++d) dims_[d] = grid.dims[d];
    // Two passes over the triangles' bin ranges: count, then fill (CSR).
    std::vector<std::vector<int>> per_bin(grid.nBins());
    for (int t = 0; t < n_triangles; ++t) {
        Vec3 tlo = triangle_vertices[3 * t], thi = tlo;
        for (int k = 1; k < 3; ++k)
            for (int d = 0; d < 3; ++d) {
                tlo[d] = std::min(tlo[d], triangle_vertices[3 * t + k][d]);
                thi[d] = std::max(thi[d], triangle_vertices[3 * t + k][d]);
            }
        int a[3], b[3];
        binRange(tlo, thi, a, b);
        for (int ix = a[0]; ix <= b[0]; ++ix)
            for (int iy = a[1]; iy <= b[1]; ++iy)
                for (int iz = a[2]; iz <= b[2]; ++iz)
                    per_bin[(ix * dims_[1] + iy) * dims_[2] + iz].push_back(t);
    }
    bin_offset_.assign(per_bin.size() + 1, 0);
    for (std::size_t b = 0; b < per_bin.size(); ++b) {
        bin_offset_[b + 1] = bin_offset_[b] + static_cast<int>(per_bin[b].size());
        bin_triangles_.insert(bin_triangles_.end(), per_bin[b].begin(), per_bin[b].end());
    }
}

void TriangleGrid::binRange(const Vec3& low, const Vec3& high, int lo[3], int hi[3]) const
{
    for (int d = 0; d < 3; ++d) {
        lo[d] = std::min(dims_[d] - 1,
                         std::max(0, static_cast<int>(std::floor((low[d] - origin_[d]) / spacing_))));
        hi[d] = std::min(dims_[d] - 1,
                         std::max(0, static_cast<int>(std::floor((high[d] - origin_[d]) / spacing_))));
    }
}

void TriangleGrid::query(const Vec3& centre, double radius, std::vector<int>& found) const
{
    found.clear();
    if (bin_offset_.empty()) return;
    for (int d = 0; d < 3; ++d)  // the query box misses the grid's box: nothing near
        if (centre[d] + radius < origin_[d] || centre[d] - radius > origin_[d] + dims_[d] * spacing_) return;
    int a[3], b[3];
    binRange(centre - Vec3{radius, radius, radius}, centre + Vec3{radius, radius, radius}, a, b);
    for (int ix = a[0]; ix <= b[0]; ++ix)
        for (int iy = a[1]; iy <= b[1]; ++iy)
            for (int iz = a[2]; iz <= b[2]; ++iz) {
                const int bin = (ix * dims_[1] + iy) * dims_[2] + iz;
                found.insert(found.end(), bin_triangles_.begin() + bin_offset_[bin],
                             bin_triangles_.begin() + bin_offset_[bin + 1]);
            }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
}

}  // namespace rockfrac
