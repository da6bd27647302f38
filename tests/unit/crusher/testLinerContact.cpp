// A cell against the crusher liners (triangulated walls with long thin triangles and
// a fan of slivers at the mantle top): the wall force is compared with a brute-force
// evaluation of the same contact model, independent of the kernel's geometry code
// (its own adjacency, ridge test, distances and box edges), one Hertz point per pair:
//  - each core vertex within r_d of the surface: overlap r_d - (brute-force
//    point-triangle distance to the nearest triangle), normal from that point to the vertex;
//  - each ridge of the surface (an edge where it bends away from the cell, or a rim) and
//    each of the box core's 12 edges more than 10 degrees from parallel to it and closer
//    than w r_d (w rising smoothly from 0 at 10 degrees to 1 at 20): overlap w r_d - segment
//    distance, normal from the ridge's point to the core edge's;
//  - each convex vertex of the surface (on a ridge) closer than r_d to the box core.
// The coarse triangulation (revolveProfile at 4 degrees: 0.45 m x 31 mm triangles and
// 90 slivers of 4 degrees at the top) is the one that stopped the CH660 tiny case with
// "DEM energy grew without input": a vertex beside a far candidate triangle but behind
// that triangle's infinite plane was given the overlap r_d + distance (up to centimetres).
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <utility>

#include "../dem/boxMeshes.hpp"
#include "dem/demModel.hpp"
#include "dem/gjk.hpp"
#include "dem/voronoiQnscBond.hpp"
#include "geometry/crusherGeometry.hpp"

using namespace rockfrac;

namespace {

constexpr double cell = 0.01;             // box cell edge [m]
constexpr double rd = 5e-4;               // dilation radius [m]
constexpr double half = 0.5 * cell - rd;  // core half edge

// Nearest point of segment [a, b] to p.
Vec3 segmentPoint(const Vec3& p, const Vec3& a, const Vec3& b)
{
    const Vec3 ab = b - a;
    const double t = std::clamp(dot(p - a, ab) / norm2(ab), 0.0, 1.0);
    return a + t * ab;
}

// Nearest point of triangle (a, b, c) to p: the projection when it falls inside
// (signs of the sub-triangle normals), else the nearest point of the three edges.
Vec3 trianglePoint(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 normal = normalised(cross(b - a, c - a));
    const Vec3 projected = p - dot(p - a, normal) * normal;
    const double s1 = dot(cross(b - a, projected - a), normal);
    const double s2 = dot(cross(c - b, projected - b), normal);
    const double s3 = dot(cross(a - c, projected - c), normal);
    if (s1 >= 0 && s2 >= 0 && s3 >= 0) return projected;
    Vec3 best = segmentPoint(p, a, b);
    for (const Vec3& q : {segmentPoint(p, b, c), segmentPoint(p, c, a)})
        if (norm2(q - p) < norm2(best - p)) best = q;
    return best;
}

// Closest points of segments [p1, q1] and [p2, q2] (Ericson 5.1.9, non-degenerate).
std::pair<Vec3, Vec3> segmentPoints(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2)
{
    const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = norm2(d1), e = norm2(d2), f = dot(d2, r), c = dot(d1, r), b = dot(d1, d2);
    const double denom = a * e - b * b;
    double s = denom > 1e-20 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
    double t = (b * s + f) / e;
    if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
    }
    return {p1 + s * d1, p2 + t * d2};
}

double segmentSegment(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2)
{
    const auto [a, b] = segmentPoints(p1, q1, p2, q2);
    return norm(a - b);
}

struct Surface {
    std::vector<Vec3> points;
    std::vector<std::array<int, 3>> triangles;
    Vec3 corner(int t, int k) const { return points[triangles[t][k]]; }
    Vec3 normal(int t) const
    {
        return normalised(cross(corner(t, 1) - corner(t, 0), corner(t, 2) - corner(t, 0)));
    }
    // Ridges seen from the winding side (vertex pairs) and the vertices on them.
    void ridges(std::vector<std::array<int, 2>>& edges, std::vector<int>& vertices) const
    {
        std::map<std::array<int, 2>, std::vector<int>> users;
        for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
            for (int k = 0; k < 3; ++k) {
                const int a = triangles[t][k], b = triangles[t][(k + 1) % 3];
                users[{std::min(a, b), std::max(a, b)}].push_back(t);
            }
        std::set<int> on_ridge;
        for (const auto& [edge, ts] : users) {
            bool ridge = ts.size() != 2;
            if (!ridge) {
                int far = 0;
                for (int k = 0; k < 3; ++k)
                    if (triangles[ts[1]][k] != edge[0] && triangles[ts[1]][k] != edge[1])
                        far = triangles[ts[1]][k];
                const Vec3 off = points[far] - points[edge[0]];
                ridge = dot(off, normal(ts[0])) < -1e-6 * norm(off);
            }
            if (!ridge) continue;
            edges.push_back(edge);
            on_ridge.insert(edge[0]);
            on_ridge.insert(edge[1]);
        }
        vertices.assign(on_ridge.begin(), on_ridge.end());
    }
};

Surface fromTriSurface(const TriSurface& s)
{
    Surface out;
    out.points = s.points;
    for (const auto& t : s.triangles) out.triangles.push_back({t[0], t[1], t[2]});
    return out;
}

// The CH660 tiny chamber (tutorials/CH660/tiny/system/meshCrusherDict) at 4 degrees.
const Profile mantle_profile{{0.0, 0.66}, {0.12, 0.64}, {0.22, 0.55}, {0.43, 0.10}, {0.50, 0.0}};
const Profile concave_profile{{0.3846, 0.5051}, {0.4276, 0.3181}, {0.4759, 0.1322}, {0.5605, 0.0001}};

struct Expected {
    Vec3 force;
    bool skip = false;  // a vertex behind the surface or the core cutting it: not a test of this model
    int touching = 0;   // core vertices within r_d
    int features = 0;   // ridge-edge and convex-vertex pairs within r_d
    double hull_distance = 1e300;
};

// Brute force: the contact model's force for the box core (vertices `core`, world)
// of a cell with centre `centre` and rotation R against every triangle of s.
Expected bruteForce(const Surface& s, const std::vector<Vec3>& core, const Vec3& centre, const Mat3& R,
                    double modulus)
{
    Expected e;
    for (const Vec3& x : core) {
        double best = 1e300;
        Vec3 nearest;
        int nearest_triangle = 0;
        for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t) {
            const Vec3 q = trianglePoint(x, s.corner(t, 0), s.corner(t, 1), s.corner(t, 2));
            if (norm(x - q) < best) {
                best = norm(x - q);
                nearest = q;
                nearest_triangle = t;
            }
        }
        if (dot(x - nearest, s.normal(nearest_triangle)) < 0.0) e.skip = true;
        e.hull_distance = std::min(e.hull_distance, best);
        if (best >= rd) continue;
        const double overlap = rd - best;
        ++e.touching;
        e.force += (4.0 / 3.0) * modulus * std::sqrt(rd * overlap) * overlap / best * (x - nearest);
    }
    // Hull distance: liner corners to the box, and box edges to liner edges (box
    // corners to triangles are above).
    std::vector<std::array<int, 2>> edges;  // the box's 12 edges: corners 2 half apart
    for (int i = 0; i < 8; ++i)
        for (int j = i + 1; j < 8; ++j)
            if (std::abs(norm(core[i] - core[j]) - 2.0 * half) < 1e-9) edges.push_back({i, j});
    for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t) {
        if (norm(trianglePoint(centre, s.corner(t, 0), s.corner(t, 1), s.corner(t, 2)) - centre) > 0.02)
            continue;
        for (int k = 0; k < 3; ++k) {
            const Vec3 local = transposeTimes(R, s.corner(t, k) - centre);
            const Vec3 clamped{std::clamp(local.x, -half, half), std::clamp(local.y, -half, half),
                               std::clamp(local.z, -half, half)};
            e.hull_distance = std::min(e.hull_distance, norm(local - clamped));
            for (const auto& edge : edges)
                e.hull_distance = std::min(
                    e.hull_distance,
                    segmentSegment(core[edge[0]], core[edge[1]], s.corner(t, k), s.corner(t, (k + 1) % 3)));
        }
    }
    // Ridges against the box's edges, convex vertices against the box.
    auto hertz = [&](double overlap) { return (4.0 / 3.0) * modulus * std::sqrt(rd * overlap) * overlap; };
    std::vector<std::array<int, 2>> ridges;
    std::vector<int> convex;
    s.ridges(ridges, convex);
    for (const auto& ridge : ridges)
        for (const auto& edge : edges) {
            // Within 10 degrees of parallel no pair; the reach grows smoothly to r_d at 20.
            const Vec3 a = normalised(core[edge[1]] - core[edge[0]]);
            const Vec3 b = normalised(s.points[ridge[1]] - s.points[ridge[0]]);
            const double angle = std::acos(std::min(1.0, std::fabs(dot(a, b)))) * 180.0 / 3.14159265358979;
            if (angle <= 10.0) continue;
            const double u = std::min(1.0, (angle - 10.0) / 10.0), weight = u * u * (3.0 - 2.0 * u);
            const auto [on_ridge, on_core] =
                segmentPoints(s.points[ridge[0]], s.points[ridge[1]], core[edge[0]], core[edge[1]]);
            const double distance = norm(on_core - on_ridge);
            if (distance >= weight * rd) continue;
            ++e.features;
            e.force += hertz(weight * rd - distance) / distance * (on_core - on_ridge);
        }
    for (int v : convex) {
        const Vec3 local = transposeTimes(R, s.points[v] - centre);
        const Vec3 clamped{std::clamp(local.x, -half, half), std::clamp(local.y, -half, half),
                           std::clamp(local.z, -half, half)};
        const double distance = norm(local - clamped);
        if (distance >= rd) continue;
        ++e.features;
        e.force += hertz(rd - distance) / distance * (R * (clamped - local));
    }
    if (e.hull_distance < 1e-9) e.skip = true;
    return e;
}

// Separating-axis test of a triangle against the box core (13 axes): true when they intersect.
bool triangleCutsBox(const std::array<Vec3, 3>& tri, const std::vector<Vec3>& core, const Mat3& R)
{
    const Vec3 axes_box[3] = {R * Vec3{1, 0, 0}, R * Vec3{0, 1, 0}, R * Vec3{0, 0, 1}};
    const Vec3 edges_tri[3] = {tri[1] - tri[0], tri[2] - tri[1], tri[0] - tri[2]};
    std::vector<Vec3> axes(axes_box, axes_box + 3);
    axes.push_back(cross(edges_tri[0], edges_tri[1]));
    for (const Vec3& a : axes_box)
        for (const Vec3& e : edges_tri) axes.push_back(cross(a, e));
    for (const Vec3& axis : axes) {
        if (!(norm2(axis) > 1e-30)) continue;
        double lo_a = 1e300, hi_a = -1e300, lo_b = 1e300, hi_b = -1e300;
        for (const Vec3& x : tri) lo_a = std::min(lo_a, dot(x, axis)), hi_a = std::max(hi_a, dot(x, axis));
        for (const Vec3& x : core) lo_b = std::min(lo_b, dot(x, axis)), hi_b = std::max(hi_b, dot(x, axis));
        if (hi_a < lo_b || hi_b < lo_a) return false;
    }
    return true;
}

// The core corners (body frame: the box axes, +-half) in the world.
std::vector<Vec3> worldCore(const Vec3& centre, const Mat3& R)
{
    std::vector<Vec3> core;
    for (int k = 0; k < 8; ++k)
        core.push_back(centre +
                       R * Vec3{(k & 1) ? half : -half, (k & 2) ? half : -half, (k & 4) ? half : -half});
    return core;
}

// The model's core of cell 0 is the same box in its body frame.
void requireAxisAlignedCore(const DemModel& model)
{
    const CellArrays& cells = model.cells();
    REQUIRE(cells.core_vertex_offset[1] == 8);
    for (int v = 0; v < 8; ++v)
        for (int d = 0; d < 3; ++d)
            REQUIRE(std::abs(cells.core_vertices[v][d]) == Approx(half).epsilon(1e-9));
}

}  // namespace

TEST_CASE("a cell near the coarse CH660 liners: wall force equals the brute-force contact model",
          "[crusher][contact]")
{
    DemParameters p;
    p.gravity = {0.0, 0.0, 0.0};
    const double modulus =
        1.0 / ((1.0 - p.rock_poisson_ratio * p.rock_poisson_ratio) / p.rock_youngs_modulus +
               (1.0 - p.steel_poisson_ratio * p.steel_poisson_ratio) / p.steel_youngs_modulus);
    const int n_segments = 90;
    const Surface mantle =
        fromTriSurface(revolveProfile(mantle_profile, n_segments, SurfaceFacing::awayFromAxis));
    const Surface concave =
        fromTriSurface(revolveProfile(concave_profile, n_segments, SurfaceFacing::towardsAxis));
    std::mt19937 random(2024);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    int touching = 0, edge_only = 0, with_features = 0, clear = 0, skipped = 0;
    for (const Surface* s : {&mantle, &concave}) {
        DemModel model(test::boxBlockMesh(1, 1, 1, {cell, cell, cell}, rd, false), p);
        model.addTriSurface(s->points, s->triangles);
        requireAxisAlignedCore(model);
        for (int sample = 0; sample < 300; ++sample) {
            // A point on the surface: one sample in three on the top fan of the mantle
            // (its first n_segments triangles), then a random orientation and a gap of
            // the lowest core corner from the triangle's plane: touching, grazing or
            // clear (up to 30 mm: "24 mm above the mantle top").
            const int nt = static_cast<int>(s->triangles.size());
            const int t = (s == &mantle && sample % 3 == 0) ? sample / 3 % n_segments
                                                            : std::min(nt - 1, int(uniform(random) * nt));
            double u = uniform(random), v = uniform(random);
            if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
            const Vec3 on = s->corner(t, 0) + u * (s->corner(t, 1) - s->corner(t, 0)) +
                            v * (s->corner(t, 2) - s->corner(t, 0));
            const Vec3 n = s->normal(t);
            const Quat q = quatFromRotationVector(
                {6 * uniform(random) - 3, 6 * uniform(random) - 3, 6 * uniform(random) - 3});
            const Mat3 R = rotationMatrix(q);
            double lowest = 1e300;
            for (const Vec3& x : worldCore({}, R)) lowest = std::min(lowest, dot(x, n));
            const double band = sample % 4 == 3 ? 0.03 * uniform(random) : rd * (0.2 + 1.6 * uniform(random));
            const Vec3 centre = on + (band - lowest) * n;
            const std::vector<Vec3> core = worldCore(centre, R);
            const Expected e = bruteForce(*s, core, centre, R, modulus);
            if (e.skip) {
                ++skipped;
                continue;
            }
            model.setCellPose(0, centre, q);
            model.setCellVelocity(0, {}, {});
            model.evaluateForces(1e-7);
            const Vec3 f = model.cells().force[0];
            INFO("surface " << (s == &mantle ? "mantle" : "concave") << " sample " << sample << " triangle "
                            << t << " gap " << band << " touching " << e.touching << " features "
                            << e.features << " hull distance " << e.hull_distance << " force " << f.x << " "
                            << f.y << " " << f.z << " expected " << e.force.x << " " << e.force.y << " "
                            << e.force.z);
            if (e.touching > 0 || e.features > 0) {
                ++(e.touching > 0 ? touching : edge_only);
                if (e.features > 0) ++with_features;
                for (int d = 0; d < 3; ++d) CHECK(f[d] == Approx(e.force[d]).margin(1e-6 * norm(e.force)));
            } else {
                CHECK(e.hull_distance >= rd);
                ++clear;
                CHECK(norm(f) == 0.0);
            }
        }
    }
    INFO("touching " << touching << " edge only " << edge_only << " with ridge or corner pairs "
                     << with_features << " clear " << clear << " skipped " << skipped);
    CHECK(touching > 150);
    CHECK(with_features > 20);
    CHECK(clear > 100);
    CHECK(skipped < 60);
}

TEST_CASE("GJK between a core and long thin triangles and slivers against brute force", "[crusher][gjk]")
{
    // A 0.45 m x 1 degree triangle (and a 4-degree fan sliver of 0.12 m) near the box core.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const std::array<std::array<Vec3, 3>, 2> triangles{
        std::array<Vec3, 3>{Vec3{0.45, 0.0, 0.0},
                            Vec3{0.45 * std::cos(0.01745), 0.45 * std::sin(0.01745), 0.0},
                            Vec3{0.0, 0.0, 0.002}},
        std::array<Vec3, 3>{Vec3{0.0, 0.0, 0.0}, Vec3{0.12, 0.0, -0.02},
                            Vec3{0.12 * std::cos(0.0698), 0.12 * std::sin(0.0698), -0.02}}};
    int separated = 0, intersecting = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const auto& tri = triangles[trial % 2];
        Surface s;
        s.points.assign(tri.begin(), tri.end());
        s.triangles = {{0, 1, 2}};
        const double along = 0.5 * (uniform(random) + 1.0);
        const Vec3 on = tri[0] + along * (tri[1] - tri[0]) + (1.0 - along) * 0.97 * (tri[2] - tri[0]) * 0.5;
        const Vec3 centre = on + Vec3{0.01 * uniform(random), 0.01 * uniform(random), 0.01 * uniform(random)};
        const Mat3 R = rotationMatrix(
            quatFromRotationVector({3 * uniform(random), 3 * uniform(random), 3 * uniform(random)}));
        const std::vector<Vec3> core = worldCore(centre, R);
        const Expected e = bruteForce(s, core, centre, R, 1.0);
        std::vector<Vec3> local;
        for (int k = 0; k < 8; ++k)
            local.push_back(Vec3{(k & 1) ? half : -half, (k & 2) ? half : -half, (k & 4) ? half : -half});
        ConvexVertexSet a, b;
        a.vertices = tri.data();
        a.n_vertices = 3;
        b.vertices = local.data();
        b.n_vertices = 8;
        b.position = centre;
        b.rotation = R;
        const GjkResult gjk = gjkDistance(a, b, tri[0] - centre);
        INFO("trial " << trial << " brute " << e.hull_distance << " gjk " << gjk.distance << " intersecting "
                      << gjk.intersecting);
        if (triangleCutsBox(tri, core, R)) {
            ++intersecting;
            CHECK(gjk.intersecting);
        } else {
            ++separated;
            CHECK_FALSE(gjk.intersecting);
            CHECK(gjk.distance == Approx(e.hull_distance).epsilon(1e-6).margin(1e-12));
        }
    }
    CHECK(separated > 100);
    CHECK(intersecting > 20);
}

TEST_CASE("experiment: a cell thrown at the CH660 liners with damping, energy balance", "[.linerbalance]")
{
    DemParameters p;
    p.gravity = {0.0, 0.0, 0.0};
    p.rock_steel_restitution = std::getenv("LB_E") ? std::atof(std::getenv("LB_E")) : 0.3;
    p.rock_steel_friction = 0.0;
    const bool concave = std::getenv("LB_CONCAVE") != nullptr;
    const int n_segments = std::getenv("LB_SEG") ? std::atoi(std::getenv("LB_SEG")) : 90;
    const TriSurface s = concave
                             ? revolveProfileShaped(concave_profile, n_segments, SurfaceFacing::towardsAxis)
                             : revolveProfileShaped(mantle_profile, n_segments, SurfaceFacing::awayFromAxis);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    double worst = 0.0;
    const int trials = std::getenv("LB_TRIALS") ? std::atoi(std::getenv("LB_TRIALS")) : 20;
    for (int trial = 0; trial < trials; ++trial) {
        const int nb = std::getenv("LB_BLOCK") ? std::atoi(std::getenv("LB_BLOCK")) : 1;
        if (nb > 1) {
            VoronoiQnscBondLaw::Parameters q;
            q.tensile_strength = q.cohesion = 1e12;
            p.bond_law = std::make_shared<VoronoiQnscBondLaw>(q);
        }
        DemModel model(test::boxBlockMesh(nb, nb, nb, {cell, cell, cell}, rd, nb > 1), p);
        model.addTriSurface(s.points, s.triangles);
        // A point on the surface at mid height, the cell 3 mm off it along the radial
        // direction, thrown at it with a spin.
        const double angle = 3.14159 * uniform(random), z = 0.3 + 0.05 * uniform(random);
        double r = 0.0;  // profile radius at z (linear between the points)
        const Profile& prof = concave ? concave_profile : mantle_profile;
        for (std::size_t k = 0; k + 1 < prof.size(); ++k) {
            const double z0 = prof[k].z, z1 = prof[k + 1].z;
            if ((z - z0) * (z - z1) <= 0.0)
                r = prof[k].r + (z - z0) / (z1 - z0) * (prof[k + 1].r - prof[k].r);
        }
        const Vec3 radial{std::cos(angle), std::sin(angle), 0.0};
        const double off = (concave ? -1.0 : 1.0) * (0.5 * nb * cell * std::sqrt(3.0) + 0.5e-3);
        const Vec3 x = Vec3{r * radial.x, r * radial.y, z} + off * radial;
        const Quat q =
            quatFromRotationVector({3 * uniform(random), 3 * uniform(random), 3 * uniform(random)});
        const Mat3 R = rotationMatrix(q);
        Vec3 mean{};
        for (int c = 0; c < model.cells().size(); ++c)
            mean += model.cells().position[c] / double(model.cells().size());
        const Vec3 v =
            (concave ? 2.0 : -2.0) * radial + Vec3{0.3 * uniform(random), 0.3 * uniform(random), 0.0};
        const Vec3 w{100 * uniform(random), 100 * uniform(random), 100 * uniform(random)};
        for (int c = 0; c < model.cells().size(); ++c) {
            const Vec3 arm = R * (model.cells().position[c] - mean);
            model.setCellPose(c, x + arm, q * model.cells().orientation[c]);
            model.setCellVelocity(
                c, v + cross(w / double(nb), arm),
                transposeTimes(rotationMatrix(q * model.cells().orientation[c]), w / double(nb)));
        }
        model.evaluateForces(0.0);
        const double frac = std::getenv("LB_FRAC") ? std::atof(std::getenv("LB_FRAC")) : 0.8;
        const double dt = std::min(1e-7, frac * model.criticalTimeStep().value);
        model.step(dt);
        const double initial = model.energies().balance();
        const double scale = model.energies().kinetic();
        double largest = 0.0;
        for (int i = 0; i < static_cast<int>(1.5e-3 / dt); ++i) {
            model.step(dt);
            largest = std::max(largest, std::fabs(model.energies().balance() - initial));
        }
        const DemEnergies& e = model.energies();
        WARN("dt " << dt << " trial " << trial << " KE0 " << scale << " KE " << e.kinetic() << " damping "
                   << e.contact_damping << " error " << (e.balance() - initial) / scale << " largest "
                   << largest / scale);
        worst = std::max(worst, largest / scale);
    }
    WARN("worst " << worst);
}
