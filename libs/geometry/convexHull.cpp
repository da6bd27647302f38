#include "geometry/convexHull.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "core/random.hpp"

namespace rockfrac {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point3>;

// Merge the planes of coplanar triangles: two triangles belong to the same
// facet plane when their normals and offsets agree to a relative tolerance.
std::vector<HalfSpace> distinctPlanes(const TriSurface& surface, double lengthScale)
{
    std::vector<HalfSpace> planes;
    for (const auto& t : surface.triangles) {
        const Vec3& a = surface.points[t[0]];
        const Vec3 n = normalised(cross(surface.points[t[1]] - a, surface.points[t[2]] - a));
        const HalfSpace h{n, dot(n, a)};
        bool known = false;
        for (const auto& p : planes)
            if (norm(p.normal - h.normal) < 1e-9 && std::abs(p.offset - h.offset) < 1e-9 * lengthScale) {
                known = true;
                break;
            }
        if (!known) planes.push_back(h);
    }
    return planes;
}

// Directions on the unit sphere: the vertices of an icosahedron whose triangles
// are split in four `level` times and pushed out to the sphere (12, 42, 162, ...
// points; at level 2 neighbouring directions are 15.9–18.7° apart).
std::vector<Vec3> icosphereDirections(int level)
{
    const double t = 0.5 * (1 + std::sqrt(5.0));
    std::vector<Vec3> v{{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                        {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (auto& p : v) p = normalised(p);
    std::vector<std::array<int, 3>> faces{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                          {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                          {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                          {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int l = 0; l < level; ++l) {
        std::map<std::pair<int, int>, int> middle;
        auto mid = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            const auto found = middle.find(key);
            if (found != middle.end()) return found->second;
            v.push_back(normalised(v[static_cast<std::size_t>(a)] + v[static_cast<std::size_t>(b)]));
            return middle[key] = static_cast<int>(v.size()) - 1;
        };
        std::vector<std::array<int, 3>> split;
        for (const auto& f : faces) {
            const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
            split.insert(split.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
        }
        faces = std::move(split);
    }
    return v;
}

}  // namespace

ConvexHull convexHull(const std::vector<Vec3>& points)
{
    if (points.size() < 4)
        throw UserError("a convex hull needs at least 4 points, got " + std::to_string(points.size()));
    std::vector<Point3> cgalPoints;
    cgalPoints.reserve(points.size());
    for (const auto& p : points) cgalPoints.emplace_back(p.x, p.y, p.z);

    Mesh mesh;
    CGAL::convex_hull_3(cgalPoints.begin(), cgalPoints.end(), mesh);
    if (mesh.number_of_faces() < 4)
        throw UserError("the points are (nearly) coplanar: their convex hull has no volume");

    // Canonical output, independent of CGAL's internal order: points sorted
    // lexicographically, each triangle starting at its smallest index, the
    // triangles sorted. The same points then give the same hull, bit for bit.
    std::vector<Vec3> hullPoints;
    std::map<Mesh::Vertex_index, int> ids;
    for (auto v : mesh.vertices()) {
        const auto& p = mesh.point(v);
        ids[v] = static_cast<int>(hullPoints.size());
        hullPoints.push_back({p.x(), p.y(), p.z()});
    }
    std::vector<int> order(hullPoints.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    auto less = [](const Vec3& a, const Vec3& b) {
        return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
    };
    std::sort(order.begin(), order.end(), [&](int a, int b) { return less(hullPoints[a], hullPoints[b]); });
    std::vector<int> rank(order.size());
    ConvexHull hull;
    for (std::size_t r = 0; r < order.size(); ++r) {
        rank[order[r]] = static_cast<int>(r);
        hull.surface.points.push_back(hullPoints[order[r]]);
    }
    for (auto f : mesh.faces()) {
        std::vector<int> loop;
        for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) loop.push_back(rank[ids[v]]);
        // convex_hull_3 yields triangles; fan-triangulate defensively otherwise.
        for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
            std::array<int, 3> t{loop[0], loop[k], loop[k + 1]};
            std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
            hull.surface.triangles.push_back(t);
        }
    }
    std::sort(hull.surface.triangles.begin(), hull.surface.triangles.end());
    const MassProperties props = massProperties(hull.surface);
    if (!(props.volume > 0)) throw UserError("the convex hull of the points has no volume (coplanar points)");
    const double lengthScale = std::cbrt(props.volume);
    hull.planes = distinctPlanes(hull.surface, lengthScale);
    return hull;
}

ConvexHull generateRock(const RockShape& shape)
{
    if (!(shape.volume > 0)) throw UserError("rock volume must be positive");
    if (!(shape.elongation > 0 && shape.elongation <= 1) || !(shape.flatness > 0 && shape.flatness <= 1))
        throw UserError("elongation (b/a) and flatness (c/b) must be in (0, 1]");
    if (shape.nPoints < 8) throw UserError("a generated rock needs at least 8 hull points");
    if (!(shape.roundness >= 0 && shape.roundness < 1)) throw UserError("roundness must be in [0, 1)");
    if (shape.roundness > 0 && shape.roundness < 0.01)
        throw UserError("roundness " + std::to_string(shape.roundness) +
                        " is below 0.01: use 0 for a sharp hull (a tiny radius only multiplies the facets)");

    SplitMix64 random(shape.seed);
    const double a = 1.0, b = shape.elongation, c = shape.elongation * shape.flatness;
    std::vector<Vec3> points;
    points.reserve(static_cast<std::size_t>(shape.nPoints));
    for (int i = 0; i < shape.nPoints; ++i) {
        // Uniform direction on the sphere (Archimedes: z uniform, azimuth uniform).
        const double z = random.uniform(-1.0, 1.0);
        const double phi = random.uniform(0.0, 2 * M_PI);
        const double rxy = std::sqrt(std::max(0.0, 1 - z * z));
        const double radius = 1.0 + shape.roughness * random.uniform(-1.0, 1.0);
        points.push_back(
            {a * radius * rxy * std::cos(phi), b * radius * rxy * std::sin(phi), c * radius * z});
    }
    ConvexHull hull = convexHull(points);
    if (shape.roundness > 0) {
        // Rounded corners: the hull shrunk about its centroid by (1 - ρ), dilated by a
        // ball of radius r = ρ R_in (a sphero-polyhedron, like the DEM's cells). Its
        // inscribed radius about the centroid stays R_in (to 1.8 % of r: the ball is the
        // hull of 162 icosphere directions) and every corner and edge has radius r, so ρ
        // approximates Wadell's roundness (corner radius over inscribed radius).
        const MassProperties core = massProperties(hull.surface);
        double inradius = 1e300;
        for (const auto& p : hull.planes)
            inradius = std::min(inradius, p.offset - dot(p.normal, core.centroid));
        const double r = shape.roundness * inradius;
        const std::vector<Vec3> ball = icosphereDirections(2);
        std::vector<Vec3> rounded;
        rounded.reserve(hull.surface.points.size() * ball.size());
        for (const auto& v : hull.surface.points)
            for (const auto& u : ball)
                rounded.push_back(core.centroid + (1 - shape.roundness) * (v - core.centroid) + r * u);
        hull = convexHull(rounded);
    }
    const MassProperties props = massProperties(hull.surface);
    const double scale = std::cbrt(shape.volume / props.volume);
    // Scale about the centroid and place the centroid at the origin.
    transformSurface(hull.surface, scale, Mat3::identity(), -scale * props.centroid);
    for (auto& p : hull.planes) p.offset = scale * (p.offset - dot(p.normal, props.centroid));
    return hull;
}

}  // namespace rockfrac
