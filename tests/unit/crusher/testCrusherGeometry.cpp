// Crusher geometry: triangle counts and closedness of the surfaces, the period of
// the gyration, the pose as a rigid motion, and the closed and open side settings
// of the CH660 tutorial chamber, in the meridian plane and on the moved 3D surface.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "core/dictionary.hpp"
#include "geometry/crusherGeometry.hpp"

using namespace rockfrac;

namespace {

constexpr double pi = 3.14159265358979323846;

Profile readProfile(const Dictionary& d, const std::string& key)
{
    Profile p;
    for (const auto& v : d.get<std::vector<std::vector<double>>>(key)) p.push_back({v[0], v[1]});
    return p;
}

// The tutorial's chamber, as meshCrusher reads it.
ChamberSpec ch660(ThrowDefinition definition = ThrowDefinition::settingDifference)
{
    const Dictionary d = Dictionary::readFile(std::string(ROCKFRAC_SOURCE_DIR) +
                                              "/tutorials/CH660/geometry/system/meshCrusherDict");
    ChamberSpec s;
    s.mantle = readProfile(d, "mantle/profile");
    s.concave = readProfile(d, "concave/profile");
    s.closed_side_setting = d.get<double>("closedSideSetting");
    s.eccentric_throw = d.get<double>("throw");
    s.pivot_height = d.get<double>("pivotHeight");
    s.eccentric_speed_rpm = d.get<double>("eccentricSpeed");
    s.throw_definition = definition;
    return s;
}

// Profile with every segment cut into pieces no longer than `step`.
Profile refined(const Profile& p, double step)
{
    Profile out{p.front()};
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
        const double len = std::hypot(p[i + 1].r - p[i].r, p[i + 1].z - p[i].z);
        const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
        for (int k = 1; k <= n; ++k)
            out.push_back({p[i].r + (p[i + 1].r - p[i].r) * k / n, p[i].z + (p[i + 1].z - p[i].z) * k / n});
    }
    return out;
}

double distanceToProfile(double r, double z, const Profile& profile)
{
    return profileDistance({{r, z}, {r, z}}, profile);
}

}  // namespace

TEST_CASE("surfaces of revolution: counts, closed apex, open rims, facing", "[crusher]")
{
    const int n = 36;
    SECTION("mantle: apex on the axis, open lower rim, normals away from the axis")
    {
        const Profile mantle{{0.0, 0.66}, {0.12, 0.64}, {0.22, 0.55}, {0.43, 0.10}, {0.50, 0.0}};
        const TriSurface s = revolveProfile(mantle, n, SurfaceFacing::awayFromAxis);
        CHECK(s.points.size() == 1u + 4u * n);
        CHECK(s.triangles.size() == std::size_t(n + 2 * n * 3));
        const SurfaceCheck c = checkSurface(s);
        CHECK(c.boundaryEdges == n);  // the lower rim only
        CHECK(c.nonManifoldEdges == 0);
        CHECK(c.misorientedEdges == 0);
        CHECK(c.degenerateTriangles == 0);
        for (const auto& t : s.triangles) {
            const Vec3 normal = cross(s.points[t[1]] - s.points[t[0]], s.points[t[2]] - s.points[t[0]]);
            const Vec3 centre = (s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.0;
            CHECK(normal.x * centre.x + normal.y * centre.y > 0);  // outward
        }
    }
    SECTION("concave: a band open at both rims, normals towards the axis")
    {
        const Profile concave{{0.38, 0.5}, {0.47, 0.13}, {0.56, 0.0}};
        const TriSurface s = revolveProfile(concave, n, SurfaceFacing::towardsAxis);
        CHECK(s.points.size() == 3u * n);
        CHECK(s.triangles.size() == 4u * n);
        const SurfaceCheck c = checkSurface(s);
        CHECK(c.boundaryEdges == 2 * n);
        CHECK(c.nonManifoldEdges == 0);
        CHECK(c.misorientedEdges == 0);
        for (const auto& t : s.triangles) {
            const Vec3 normal = cross(s.points[t[1]] - s.points[t[0]], s.points[t[2]] - s.points[t[0]]);
            const Vec3 centre = (s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.0;
            CHECK(normal.x * centre.x + normal.y * centre.y < 0);  // inward
        }
    }
    SECTION("a profile closed at both ends is a closed solid")
    {
        const Profile spindle{{0.0, 1.0}, {0.3, 0.5}, {0.0, 0.0}};
        const TriSurface s = revolveProfile(spindle, n, SurfaceFacing::awayFromAxis);
        CHECK(checkSurface(s).watertight());
        CHECK(massProperties(s).volume == Approx(2 * pi * 0.09 * 0.5 / 3).epsilon(0.01));
    }
    CHECK_THROWS_AS(revolveProfile({{0.1, 0.0}}, n, SurfaceFacing::awayFromAxis), UserError);
    CHECK_THROWS_AS(revolveProfile({{0.0, 0.0}, {0.0, 1.0}}, n, SurfaceFacing::awayFromAxis), UserError);
}

TEST_CASE("well-shaped surfaces of revolution: no slivers, no strips, same topology", "[crusher]")
{
    const Profile mantle{{0.0, 0.66}, {0.12, 0.64}, {0.22, 0.55}, {0.43, 0.10}, {0.50, 0.0}};
    const Profile concave{{0.3846, 0.505}, {0.4276, 0.318}, {0.4759, 0.1321}, {0.5605, 0.0}};
    for (int n : {90, 360}) {
        for (const bool is_mantle : {true, false}) {
            const TriSurface s =
                revolveProfileShaped(is_mantle ? mantle : concave, n,
                                     is_mantle ? SurfaceFacing::awayFromAxis : SurfaceFacing::towardsAxis);
            const SurfaceCheck c = checkSurface(s);
            INFO("n " << n << (is_mantle ? " mantle" : " concave"));
            CHECK(c.nonManifoldEdges == 0);
            CHECK(c.misorientedEdges == 0);
            CHECK(c.degenerateTriangles == 0);
            CHECK(c.boundaryEdges == (is_mantle ? n : 2 * n));  // open rims only
            const double spacing = 2 * pi * (is_mantle ? 0.5 : 0.5605) / n;
            double smallest_angle = 180.0, longest = 0.0;
            for (const auto& t : s.triangles) {
                const Vec3 p[3] = {s.points[t[0]], s.points[t[1]], s.points[t[2]]};
                for (int k = 0; k < 3; ++k) {
                    const Vec3 u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
                    smallest_angle =
                        std::min(smallest_angle, 180 / pi * std::acos(dot(u, v) / (norm(u) * norm(v))));
                    longest = std::max(longest, norm(u));
                }
                const Vec3 normal = cross(p[1] - p[0], p[2] - p[0]);
                const Vec3 centre = (p[0] + p[1] + p[2]) / 3.0;
                CHECK((normal.x * centre.x + normal.y * centre.y > 0) == is_mantle);
            }
            CHECK(smallest_angle > 30.0);  // revolveProfile: 1 degree
            CHECK(longest < 1.5 * spacing);
        }
    }
    // Every point lies on the profile's surface of revolution.
    const TriSurface s = revolveProfileShaped(mantle, 90, SurfaceFacing::awayFromAxis);
    for (const Vec3& p : s.points)
        CHECK(profileDistance({{std::hypot(p.x, p.y), p.z}, {std::hypot(p.x, p.y), p.z}}, mantle) < 1e-12);
}

TEST_CASE("gyration: period of 290 rpm, rigid pose about the pivot", "[crusher]")
{
    CrusherKinematics k;
    k.pivot = {0, 0, 1.5};
    k.eccentric_angle = 0.01;
    k.eccentric_speed = 2 * pi * 290 / 60;
    k.phase = 0.3;
    CHECK(k.period() == Approx(60.0 / 290.0).epsilon(1e-14));
    const Vec3 x{0.4, -0.2, 0.1};
    for (double t : {0.0, 0.013, 0.05}) {
        const MantlePose a = mantlePose(k, t), b = mantlePose(k, t + k.period());
        CHECK(norm(a.translation + a.rotation * x - (b.translation + b.rotation * x)) < 1e-12);
        // The pivot does not move; the axis is tilted by alpha.
        CHECK(norm(a.translation + a.rotation * k.pivot - k.pivot) < 1e-14);
        CHECK(std::acos((a.rotation * Vec3{0, 0, 1}).z) == Approx(k.eccentric_angle).epsilon(1e-9));
        // A point below the pivot on the axis moves towards the closed side.
        const Vec3 low = a.translation + a.rotation * Vec3{0, 0, 0};
        const double phi = k.closedSideAzimuth(t);
        CHECK(low.x * std::cos(phi) + low.y * std::sin(phi) == Approx(1.5 * std::sin(0.01)).epsilon(1e-12));
        // Velocities agree with a finite difference of the positions.
        const double h = 1e-7;
        const MantlePose p = mantlePose(k, t + h), m = mantlePose(k, t - h);
        const Vec3 world = a.translation + a.rotation * x;
        const Vec3 fd = (p.translation + p.rotation * x - (m.translation + m.rotation * x)) / (2 * h);
        const Vec3 v = a.velocity + cross(a.angular_velocity, world - a.translation);
        CHECK(norm(fd - v) < 1e-7 * norm(v) + 1e-12);
    }
    // Half a period later the closed side is opposite.
    CHECK(k.closedSideAzimuth(0.5 * k.period()) - k.phase == Approx(pi));
}

TEST_CASE("CH660 chamber: CSS and OSS = CSS + throw in the meridian plane", "[crusher]")
{
    const ChamberSpec spec = ch660();
    const ChamberDesign d = designChamber(spec);
    CHECK(std::abs(d.gaps.closed - 0.038) < 1e-4);
    CHECK(std::abs(d.gaps.open - (0.038 + 0.026)) < 1e-4);
    CHECK(d.gaps.closed == Approx(0.038).epsilon(1e-9));
    // Measured at the chamber exit: within the lowest 100 mm (the parallel zone).
    CHECK(d.gaps.closed_z < d.discharge_level + 0.1);
    CHECK(d.gaps.open_z < d.discharge_level + 0.1);
    // The feed opening takes the +60/-90 mm feed.
    CHECK(d.gaps.feed_closed > 0.090);
    CHECK(d.kinematics.period() == Approx(60.0 / 290.0));
    // The angle lies near the axis-offset approximation (same order, within 20 %).
    CHECK(d.kinematics.eccentric_angle == Approx(d.axis_offset_angle).epsilon(0.2));

    SECTION("the axisOffset definition: the axis moves throw/2 at the discharge level")
    {
        const ChamberDesign a = designChamber(ch660(ThrowDefinition::axisOffset));
        CHECK((spec.pivot_height - a.discharge_level) * std::sin(a.kinematics.eccentric_angle) ==
              Approx(0.013).epsilon(1e-12));
        CHECK(a.gaps.closed == Approx(0.038).epsilon(1e-9));
    }
}

TEST_CASE("CH660 chamber: the gaps on the moving 3D surfaces", "[crusher]")
{
    // Move a finely revolved mantle with the pose at several times and measure its
    // distance to the (axisymmetric) concave in every meridian: the smallest is the
    // CSS, at the closed-side azimuth; the one opposite is the OSS.
    const ChamberDesign d = designChamber(ch660());
    const int n = 720;
    const Profile mantle = refined(d.chamber.mantle, 0.002);
    const TriSurface s = revolveProfile(mantle, n, SurfaceFacing::awayFromAxis);
    for (double t : {0.0, 0.031, 0.1}) {
        const MantlePose pose = mantlePose(d.kinematics, t);
        const double phi = d.kinematics.closedSideAzimuth(t);
        double closed = 1e300, open = 1e300, overall = 1e300;
        for (const Vec3& p : s.points) {
            if (std::hypot(p.x, p.y) == 0.0) continue;
            const Vec3 x = pose.translation + pose.rotation * p;
            const double gap = distanceToProfile(std::hypot(x.x, x.y), x.z, d.chamber.concave);
            const double azimuth = std::atan2(x.y, x.x);
            const double from_closed = std::abs(std::remainder(azimuth - phi, 2 * pi));
            overall = std::min(overall, gap);
            if (from_closed < 0.5 * pi / 180) closed = std::min(closed, gap);
            if (from_closed > pi - 0.5 * pi / 180) open = std::min(open, gap);
        }
        CHECK(std::abs(overall - 0.038) < 1e-4);
        CHECK(std::abs(closed - 0.038) < 1e-4);
        CHECK(std::abs(open - 0.064) < 1e-4);
    }
}
