#include "geometry/surfaceTopology.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <iterator>
#include <numeric>

#include "core/error.hpp"

namespace rockfrac {

namespace {

int findRoot(std::vector<int>& parent, int i)
{
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// Stops CGAL's search once enough pairs are found.
struct EnoughPairs {};

}  // namespace

std::vector<std::vector<int>> surfaceShells(const TriSurface& surface)
{
    std::vector<int> parent(surface.points.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (const auto& t : surface.triangles)
        for (int k = 1; k < 3; ++k) {
            const int a = findRoot(parent, t[0]), b = findRoot(parent, t[k]);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
    std::vector<int> shellOfRoot(surface.points.size(), -1);
    std::vector<std::vector<int>> shells;
    for (std::size_t i = 0; i < surface.triangles.size(); ++i) {
        const int root = findRoot(parent, surface.triangles[i][0]);
        if (shellOfRoot[root] < 0) {
            shellOfRoot[root] = static_cast<int>(shells.size());
            shells.emplace_back();
        }
        shells[shellOfRoot[root]].push_back(static_cast<int>(i));
    }
    std::stable_sort(shells.begin(), shells.end(),
                     [](const auto& a, const auto& b) { return a.size() > b.size(); });
    return shells;
}

std::vector<std::array<int, 2>> selfIntersections(const TriSurface& surface, std::size_t limit)
{
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
    Mesh mesh;
    std::vector<Mesh::Vertex_index> vertex;
    vertex.reserve(surface.points.size());
    for (const Vec3& p : surface.points) vertex.push_back(mesh.add_vertex({p.x, p.y, p.z}));
    std::vector<int> triangleOfFace;
    for (std::size_t i = 0; i < surface.triangles.size(); ++i) {
        const auto& t = surface.triangles[i];
        const Mesh::Face_index f = mesh.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]);
        if (f == Mesh::null_face())
            throw UserError("selfIntersections: triangle " + std::to_string(i) +
                            " does not fit a manifold surface (check the surface first)");
        triangleOfFace.push_back(static_cast<int>(i));
    }
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
    // An output iterator that throws once `limit` pairs are in: the search stops there.
    struct Collect {
        std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>>* out;
        std::size_t limit;
        Collect& operator*() { return *this; }
        Collect& operator++() { return *this; }
        Collect operator++(int) { return *this; }
        Collect& operator=(const std::pair<Mesh::Face_index, Mesh::Face_index>& p)
        {
            out->push_back(p);
            if (out->size() >= limit) throw EnoughPairs{};
            return *this;
        }
    };
    try {
        CGAL::Polygon_mesh_processing::self_intersections(mesh,
                                                          Collect{&pairs, std::max<std::size_t>(limit, 1)});
    } catch (const EnoughPairs&) {
    }
    std::vector<std::array<int, 2>> out;
    for (const auto& [a, b] : pairs)
        out.push_back(
            {triangleOfFace[static_cast<std::size_t>(a)], triangleOfFace[static_cast<std::size_t>(b)]});
    return out;
}

int dropCollapsedTriangles(TriSurface& surface)
{
    const std::size_t before = surface.triangles.size();
    surface.triangles.erase(
        std::remove_if(surface.triangles.begin(), surface.triangles.end(),
                       [](const auto& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }),
        surface.triangles.end());
    return static_cast<int>(before - surface.triangles.size());
}

std::vector<int> needleTriangles(const TriSurface& surface)
{
    std::vector<int> needles;
    for (std::size_t i = 0; i < surface.triangles.size(); ++i) {
        const auto& t = surface.triangles[i];
        const Vec3 &a = surface.points[t[0]], &b = surface.points[t[1]], &c = surface.points[t[2]];
        const double longest = std::max({norm2(b - a), norm2(c - b), norm2(a - c)});
        if (norm(cross(b - a, c - a)) <= 2e-12 * longest) needles.push_back(static_cast<int>(i));
    }
    return needles;
}

int nearDuplicateVertices(const TriSurface& surface, double distance)
{
    std::vector<int> order(surface.points.size());
    std::iota(order.begin(), order.end(), 0);
    const auto& p = surface.points;
    std::sort(order.begin(), order.end(), [&p](int a, int b) { return p[a].x < p[b].x; });
    std::vector<char> close(p.size(), 0);
    for (std::size_t i = 0; i < order.size(); ++i)
        for (std::size_t j = i + 1; j < order.size() && p[order[j]].x - p[order[i]].x <= distance; ++j)
            if (norm(p[order[j]] - p[order[i]]) <= distance) close[order[i]] = close[order[j]] = 1;
    return static_cast<int>(std::count(close.begin(), close.end(), 1));
}

}  // namespace rockfrac
