#include "dem/cellCore.hpp"

#include <algorithm>
#include <cmath>
#include <voro++.hh>

namespace rockfrac {

namespace {

ErodedCore shrinkTowardCentroid(const std::vector<Vec3>& cell_vertices, const std::vector<CellPlane>& faces,
                                const std::vector<std::array<int, 2>>& cell_edges, double dilation_radius)
{
    double smallest_offset = 1e300;
    for (const CellPlane& face : faces) smallest_offset = std::min(smallest_offset, face.offset);
    const double factor = std::max(1.0 - dilation_radius / smallest_offset, 0.1);
    ErodedCore core;
    core.shrunk = true;
    core.radius = dilation_radius;
    for (const Vec3& v : cell_vertices) core.vertices.push_back(factor * v);
    core.edges = cell_edges;
    return core;
}

}  // namespace

ErodedCore erodeConvexCell(const std::vector<Vec3>& cell_vertices, const std::vector<CellPlane>& faces,
                           const std::vector<std::array<int, 2>>& cell_edges, double dilation_radius)
{
    // Voro++ works to an absolute tolerance (~1e-11): cut in units of the cell size.
    double size = 0.0;
    for (const Vec3& v : cell_vertices) size = std::max(size, norm(v));
    if (!(size > 0.0)) return shrinkTowardCentroid(cell_vertices, faces, cell_edges, dilation_radius);
    const double scale = 1.0 / size;
    const double box = 1.5;
    voro::voronoicell cell;
    cell.init(-box, box, -box, box, -box, box);
    for (const CellPlane& face : faces) {
        const double eroded_offset = (face.offset - dilation_radius) * scale;
        // voro++ keeps the points with x . (a, b, c) < rsq / 2.
        if (!cell.plane(face.normal.x, face.normal.y, face.normal.z, 2.0 * eroded_offset))
            return shrinkTowardCentroid(cell_vertices, faces, cell_edges, dilation_radius);
    }
    // A core thinner than 1e-6 of the cell is degenerate for GJK and inertia alike.
    if (cell.volume() < 1e-18 || cell.p < 4)
        return shrinkTowardCentroid(cell_vertices, faces, cell_edges, dilation_radius);
    std::vector<double> coordinates;
    cell.vertices(coordinates);
    ErodedCore core;
    core.radius = dilation_radius;
    std::vector<int> kept(cell.p);  // Voro++ vertex -> core vertex
    for (int i = 0; i < cell.p; ++i) {
        const Vec3 v{coordinates[3 * i] * size, coordinates[3 * i + 1] * size, coordinates[3 * i + 2] * size};
        // Voro++ can return coincident vertices at degenerate corners; keep one.
        const auto same = std::find_if(core.vertices.begin(), core.vertices.end(),
                                       [&](const Vec3& u) { return norm2(u - v) <= 1e-24 * size * size; });
        kept[i] = static_cast<int>(same - core.vertices.begin());
        if (same == core.vertices.end()) core.vertices.push_back(v);
    }
    // Edges from Voro++'s vertex graph (ed[i][j], j < nu[i]); an edge between two merged
    // vertices vanishes, and one seen twice is kept once.
    for (int i = 0; i < cell.p; ++i)
        for (int j = 0; j < cell.nu[i]; ++j) {
            int a = kept[i], b = kept[cell.ed[i][j]];
            if (a == b) continue;
            if (a > b) std::swap(a, b);
            const std::array<int, 2> edge{a, b};
            if (std::find(core.edges.begin(), core.edges.end(), edge) == core.edges.end())
                core.edges.push_back(edge);
        }
    return core;
}

ErodedCore dilatedCellCore(const std::vector<Vec3>& cell_vertices, const std::vector<CellPlane>& faces,
                           const std::vector<std::array<int, 2>>& cell_edges, double dilation_radius)
{
    ErodedCore core = erodeConvexCell(cell_vertices, faces, cell_edges, dilation_radius);
    if (!core.shrunk) return core;
    double smallest_offset = 1e300;
    for (const CellPlane& face : faces) smallest_offset = std::min(smallest_offset, face.offset);
    if (!(dilation_radius > 0.9 * smallest_offset) || !(smallest_offset > 0.0)) return core;
    return erodeConvexCell(cell_vertices, faces, cell_edges, 0.5 * smallest_offset);
}

}  // namespace rockfrac
