// Rocks put straight into the crusher chamber: the liners read back as profiles of
// revolution (linerClearance), their clearance in a gyrated pose, and the feed factory
// placing rocks between them without touching either (checked by the contact model).
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "crusher/feedRock.hpp"
#include "crusher/linerClearance.hpp"
#include "dem/contactKernels.hpp"
#include "dem/demModel.hpp"
#include "dem/quat.hpp"
#include "voronoi/tessellation.hpp"

using namespace rockfrac;

namespace {

// The approximate CH660 coarse chamber (tutorials/CH660/geometry), concave as placed.
const Profile ch660_mantle{{0.0, 0.66}, {0.12, 0.64}, {0.22, 0.55}, {0.43, 0.10}, {0.50, 0.0}};
const Profile ch660_concave{{0.3846, 0.5051}, {0.4276, 0.3181}, {0.4759, 0.1322}, {0.5605, 0.0001}};

// A point at signed normal distance d from the middle of profile segment k, at azimuth
// phi; d > 0 towards increasing r (away from the axis).
Vec3 offLinerProfile(const Profile& p, int k, double d, double phi)
{
    const ProfilePoint a = p[k], b = p[k + 1];
    const double len = std::hypot(b.r - a.r, b.z - a.z);
    // Unit normal in (r, z) with a positive r part.
    double nr = (b.z - a.z) / len, nz = -(b.r - a.r) / len;
    if (nr < 0) nr = -nr, nz = -nz;
    const double r = 0.5 * (a.r + b.r) + d * nr, z = 0.5 * (a.z + b.z) + d * nz;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

CrusherKinematics ch660Gyration()
{
    CrusherKinematics k;
    k.pivot = {0.0, 0.0, 1.5};
    k.eccentric_angle = 0.012;  // ~26 mm of throw at the discharge, as the CH660
    k.eccentric_speed = 30.4;   // 290 rpm
    return k;
}

WallMotion mantleMotionOf(const MantlePose& p)
{
    return {p.translation, quatFromRotationVector(p.rotation_vector), p.velocity, p.angular_velocity};
}

}  // namespace

TEST_CASE("a liner read back from meshCrusher's triangles gives its profile and signed clearances",
          "[crusher][feed]")
{
    const TriSurface mantle = revolveProfileShaped(ch660_mantle, 180, SurfaceFacing::awayFromAxis);
    const TriSurface concave = revolveProfileShaped(ch660_concave, 180, SurfaceFacing::towardsAxis);
    const RevolvedLiner m = revolvedLiner(mantle, 0, SurfaceFacing::awayFromAxis, "mantle.stl");
    const RevolvedLiner c = revolvedLiner(concave, 1, SurfaceFacing::towardsAxis, "concave.stl");
    // Every point of the given profile is a ring of the surface.
    for (const auto& [liner, given] : {std::pair{&m, &ch660_mantle}, std::pair{&c, &ch660_concave}})
        for (const ProfilePoint& q : *given) {
            bool found = false;
            for (const ProfilePoint& p : liner->profile)
                if (std::abs(p.z - q.z) < 1e-12) {
                    CHECK(p.r == Approx(q.r).margin(1e-12));
                    found = true;
                }
            CHECK(found);
        }
    // Clearances at known normal offsets (the chamber side positive), in the mean pose
    // and in a gyrated one (the point carried along with the mantle).
    const WallState at_rest{};
    WallState gyrated;
    const MantlePose pose = mantlePose(ch660Gyration(), 0.037);
    gyrated.origin = pose.translation;
    gyrated.orientation = quatFromRotationVector(pose.rotation_vector);
    const Mat3 R = rotationMatrix(gyrated.orientation);
    for (double d : {-0.02, -0.003, 0.004, 0.03})
        for (double phi : {0.1, 2.0, 4.5}) {
            for (int k : {2, 3}) {  // the mantle's chamber segments
                const Vec3 x = offLinerProfile(ch660_mantle, k, d, phi);
                CHECK(linerClearance(m, at_rest, x) == Approx(d).margin(1e-12));
                CHECK(linerClearance(m, gyrated, gyrated.origin + R * x) == Approx(d).margin(1e-12));
            }
            for (int k : {0, 1, 2}) {
                const Vec3 x = offLinerProfile(ch660_concave, k, d, phi);
                CHECK(linerClearance(c, at_rest, x) == Approx(-d).margin(1e-12));
            }
        }
    // Above and below the steel: no constraint.
    CHECK(std::isinf(linerClearance(c, at_rest, {0.45, 0.0, 0.6})));
    CHECK(std::isinf(linerClearance(m, at_rest, {0.1, 0.0, -0.1})));
}

TEST_CASE("a liner that is not a surface of revolution about z is refused by name", "[crusher][feed]")
{
    const TriSurface disc = discSurface(0.2, 0.05, {0.3, 0.0, 0.2}, 24);  // axis along y, off the z axis
    try {
        revolvedLiner(disc, 0, SurfaceFacing::towardsAxis, "scan.stl");
        FAIL("no error");
    } catch (const UserError& e) {
        CHECK(std::string(e.what()).find("scan.stl") != std::string::npos);
        CHECK(std::string(e.what()).find("not a surface of revolution") != std::string::npos);
    }
}

TEST_CASE("rocks put into the gyrating chamber clear both liners' triangles; without the check some do not",
          "[crusher][feed]")
{
    DemParameters p;
    p.gravity = {0.0, 0.0, 0.0};
    const VoronoiMesh rock =
        generateVoronoiMesh(Domain::box({0.0, 0.0, 0.0}, {0.03, 0.02, 0.012}), 20, 2.5e-3, 5);
    FeedSpec spec;
    spec.size_min = 0.02;
    spec.size_max = 0.035;
    spec.mass_rate = 1e6;
    spec.total_mass = 0.8;  // ~ 14 rocks
    spec.z_min = 0.05;      // the lower chamber, where the gap is a few rock sizes
    spec.z_max = 0.30;
    spec.r_min = 0.30;  // across both liners: many draws fall inside the steel
    spec.r_max = 0.55;
    spec.attempts = 200;
    spec.interval = 1e-3;
    spec.liner_clearance = 1e-3;
    const TriSurface mantle = revolveProfileShaped(ch660_mantle, 90, SurfaceFacing::awayFromAxis);
    const TriSurface concave = revolveProfileShaped(ch660_concave, 90, SurfaceFacing::towardsAxis);
    // Brute force over the triangles: the least distance of the rocks' vertices from the
    // steel, negative for a vertex behind a liner's nearest triangle (normals face the chamber).
    auto leastDistance = [](const TriSurface& s, const WallState& w, const std::vector<Vec3>& world) {
        const Mat3 R = rotationMatrix(w.orientation);
        double least = 1e300;
        for (const Vec3& xw : world) {
            const Vec3 x = transposeTimes(R, xw - w.origin);
            double best = 1e300, sign = 1.0;
            for (const auto& t : s.triangles) {
                const Vec3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
                const Vec3 q = closestPointOnTriangle(x, a, b, c);
                const double d = norm(x - q);
                if (d < best) best = d, sign = dot(x - q, cross(b - a, c - a)) >= 0.0 ? 1.0 : -1.0;
            }
            least = std::min(least, sign * best);
        }
        return least;
    };
    auto run = [&](bool check, double& least, int& rocks) {
        DemModel model(p);
        const int mw = model.addTriSurface(mantle.points, mantle.triangles,
                                           mantleMotionOf(mantlePose(ch660Gyration(), 0.05)));
        const int cw = model.addTriSurface(concave.points, concave.triangles);
        FeedFactory factory(spec, makeFeedRockTemplate(rock, p.rock_density));
        if (check)
            factory.setLiners({revolvedLiner(mantle, mw, SurfaceFacing::awayFromAxis, "mantle"),
                               revolvedLiner(concave, cw, SurfaceFacing::towardsAxis, "concave")});
        std::vector<Vec3> vertices;
        for (const InsertedRock& r : factory.feed(model, 1.0))
            for (const Vec3& v : r.mesh.vertices)
                vertices.push_back(r.pose.translation + rotationMatrix(r.pose.orientation) * v);
        rocks = factory.rocksFed();
        least = std::min(leastDistance(mantle, model.wall(mw), vertices),
                         leastDistance(concave, model.wall(cw), vertices));
    };
    double least = 0.0;
    int rocks = 0;
    run(true, least, rocks);
    CHECK(rocks >= 10);
    CHECK(least > 0.9e-3);  // the 1 mm asked for, less the chords of the triangulation
    run(false, least, rocks);
    CHECK(rocks >= 10);
    CHECK(least < -0.01);  // the test can fail: unchecked, rocks land in the steel
}
