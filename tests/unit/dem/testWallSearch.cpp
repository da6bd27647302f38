// The liner search's shortcuts against the search in full (docs/theory-dem.md §7, "Cost"):
// the triangles' prism bound, the clearance kept from the list build, the pruned ridge–edge
// pairs and the candidates trimmed to the reach of the list's skin must each leave every
// wall item's force, torque, power, energies and status as they were, bit for bit.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "dem/demModel.hpp"
#include "dem/hertzMindlinContact.hpp"
#include "dem/kernelViews.hpp"
#include "dem/voronoiQnscBond.hpp"
#include "demBackend.hpp"
#include "geometry/crusherGeometry.hpp"
#include "voronoi/domain.hpp"
#include "voronoi/tessellation.hpp"

using namespace rockfrac;

namespace {

// Everything one wall item's evaluation wrote.
struct ItemResult {
    Vec3 force, torque, spring;
    double power = 0.0, elastic = 0.0, damping = 0.0, friction = 0.0;
    int status = 0;
};

bool sameBits(const ItemResult& a, const ItemResult& b)
{
    auto same = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof(x)) == 0; };
    return same(a.force, b.force) && same(a.torque, b.torque) && same(a.spring, b.spring) &&
           same(a.power, b.power) && same(a.elastic, b.elastic) && same(a.damping, b.damping) &&
           same(a.friction, b.friction) && a.status == b.status;
}

// Evaluates every wall item of the model's current lists with the model's cells as they are
// now, with the shortcuts (fast) or without them (exhaustive), optionally on candidate lists
// that hold every triangle of the wall (in index order, as the grid gives its triangles).
std::vector<ItemResult> evaluateItems(const DemModel& model, const std::vector<TrianglePrism>& prisms,
                                      bool exhaustive, bool every_triangle)
{
    const CellArrays& cells = model.cells();
    std::vector<Mat3> rotation;
    std::vector<Vec3> spin;
    for (int c = 0; c < cells.size(); ++c) {
        rotation.push_back(rotationMatrix(cells.orientation[c]));
        spin.push_back(rotation.back() * cells.angular_velocity[c]);
    }
    WallContactArrays items = model.wallContacts();
    if (every_triangle) {
        items.triangle_offset.assign(1, 0);
        items.triangles.clear();
        for (int i = 0; i < items.size(); ++i) {
            const WallState& w = model.wall(items.wall[i]);
            for (int t = 0; t < w.n_triangles; ++t) items.triangles.push_back(w.first_triangle + t);
            items.triangle_offset.push_back(static_cast<int>(items.triangles.size()));
        }
    }
    std::vector<WallPose> poses;
    for (int k = 0; k < model.nWalls(); ++k) poses.push_back(model.wallPose(model.wall(k)));
    WallKernelArgs a;
    a.constants.effective_modulus = 5e9;
    a.constants.effective_shear_modulus = 2e9;
    a.constants.friction = 0.5;
    a.constants.restitution_beta = -0.3;
    a.dt = 1e-6;
    a.cells = cellContactView(cells, rotation, spin);
    a.walls = poses.data();
    a.triangle_vertices = model.triangleVertices().data();
    a.triangle_features = model.triangleFeatures().data();
    a.triangle_prisms = prisms.data();
    a.exhaustive = exhaustive;
    viewWallItemArrays(a, items);
    std::vector<ItemResult> results(items.size());
    for (int i = 0; i < items.size(); ++i) {
        wallKernel<HertzMindlinLaw>(a, i);
        ItemResult& r = results[i];
        r.force = items.force_on_cell[i];
        r.torque = items.torque_on_cell[i];
        r.spring = items.tangential_spring[i];
        r.power = items.wall_power[i];
        r.elastic = items.elastic_energy[i];
        r.damping = items.damping_power[i];
        r.friction = items.friction_dissipation[i];
        r.status = items.status[i];
    }
    return results;
}

}  // namespace

TEST_CASE("a triangle's prism bounds a point's distance from below, tightly over its face", "[dem][wall]")
{
    std::mt19937 random(5);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    int tight = 0;
    for (int sample = 0; sample < 20000; ++sample) {
        // Triangles of every shape: slivers 100 times longer than wide among them.
        const double stretch = sample % 3 == 0 ? 100.0 : 1.0;
        const Vec3 p[3] = {{uniform(random), uniform(random), uniform(random)},
                           {stretch * uniform(random), uniform(random), uniform(random)},
                           {uniform(random), 0.01 * uniform(random), uniform(random)}};
        const TrianglePrism prism = trianglePrism(p);
        const Vec3 x =
            (sample % 2 == 0 ? 0.1 : 3.0) * Vec3{uniform(random), uniform(random), uniform(random)};
        const double exact = norm(x - closestPointOnTriangle(x, p[0], p[1], p[2]));
        const double bound = std::sqrt(prism.boundSquared(x));
        INFO("sample " << sample << ": bound " << bound << ", exact " << exact);
        REQUIRE(bound <= exact * (1.0 + 1e-12) + 1e-13);
        int feature = 0, vertex = 0;
        closestPointOnTriangle(x, p[0], p[1], p[2], feature, vertex);
        if (feature == featureFace) {  // over the face the bound is the distance itself
            CHECK(bound == Approx(exact).epsilon(1e-9).margin(1e-12));
            ++tight;
        }
    }
    CHECK(tight > 1000);
    const Vec3 flat[3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};  // zero area: no bound, always searched
    CHECK(trianglePrism(flat).boundSquared({5, 5, 5}) == 0.0);
}

TEST_CASE("the liner search's shortcuts leave every wall item as the search in full gives it, bitwise",
          "[dem][wall]")
{
    // A 30-cell rock thrown at the CH660 mantle's slope (benchDem -liners' surface, 90 segments
    // around) and tumbling on it; at every 100th step every item is evaluated three ways.
    const Profile mantle_profile{{0.0, 0.66}, {0.12, 0.64}, {0.22, 0.55}, {0.43, 0.10}, {0.50, 0.0}};
    const TriSurface mantle = revolveProfileShaped(mantle_profile, 90, SurfaceFacing::awayFromAxis);
    DemParameters p;
    p.rock_youngs_modulus = 7.7e9;
    VoronoiQnscBondLaw::Parameters q;
    q.youngs_modulus = 4.6e9;
    p.bond_law = std::make_shared<VoronoiQnscBondLaw>(q);
    p.damping_reading = DampingReading::criticalFraction;
    p.bond_damping = 0.05;
    const VoronoiMesh rock =
        generateVoronoiMesh(Domain::box({0.0, 0.0, 0.0}, {0.03, 0.02, 0.012}), 30, 2.5e-3, 7);
    p.gravity = -3000.0 * normalised(Vec3{0.45, 0.0, 0.21});
    DemModel model(rock, p);
    model.addTriSurface(mantle.points, mantle.triangles);
    std::vector<TrianglePrism> prisms;
    for (std::size_t t = 0; t < model.triangleVertices().size() / 3; ++t)
        prisms.push_back(trianglePrism(&model.triangleVertices()[3 * t]));
    // The slope at r = 0.32 m (z = 0.336 m), its outward normal, the rock 14 mm off it, thrown at
    // it and held on it by a strong
    // gravity along the normal (p.gravity).
    const Vec3 normal = normalised(Vec3{0.45, 0.0, 0.21});
    const Vec3 target = Vec3{0.32, 0.0, 0.55 - 0.45 * (0.32 - 0.22) / 0.21} + 0.014 * normal;
    Vec3 centre;
    for (int c = 0; c < model.cells().size(); ++c) centre += model.cells().position[c];
    centre = (1.0 / model.cells().size()) * centre;
    const Quat tilt = quatFromRotationVector({0.3, 0.5, 0.2});
    for (int c = 0; c < model.cells().size(); ++c) {
        const Vec3 at = target + rotationMatrix(tilt) * (model.cells().position[c] - centre);
        model.setCellPose(c, at, tilt * model.cells().orientation[c]);
        model.setCellVelocity(c, -2.0 * normal + Vec3{0.0, 0.3, 0.0}, {40.0, -20.0, 10.0});
    }
    const double dt = 0.8 * model.criticalTimeStep().value;
    int checks = 0, items_seen = 0, in_contact = 0, cleared_from_build = 0;
    for (int block = 0; block < 150; ++block) {
        test::steps(model, dt, 100);
        REQUIRE(model.status().ok());
        const std::vector<ItemResult> fast = evaluateItems(model, prisms, false, false);
        const std::vector<ItemResult> full = evaluateItems(model, prisms, true, false);
        const std::vector<ItemResult> whole = evaluateItems(model, prisms, true, true);
        for (std::size_t i = 0; i < fast.size(); ++i) {
            INFO("block " << block << ", item " << i);
            CHECK(sameBits(fast[i], full[i]));
            CHECK(sameBits(fast[i], whole[i]));
            in_contact += fast[i].status != contactNone;
            // Cleared by the clearance from the build, without a search.
            const WallContactArrays& w = model.wallContacts();
            const int c = w.cell[i];
            const Vec3 local = transposeTimes(rotationMatrix(model.wall(w.wall[i]).orientation),
                                              model.cells().position[c] - model.wall(w.wall[i]).origin);
            cleared_from_build += w.clearance_at_build[i] - norm(local - w.centre_at_build[i]) >
                                  1.001 * model.cells().bounding_radius[c];
        }
        items_seen += static_cast<int>(fast.size());
        ++checks;
    }
    // The rock reached the slope, and items were cleared from their build's clearance.
    CHECK(checks == 150);
    CHECK(in_contact > 100);           // 194 of 4 500 evaluations
    CHECK(cleared_from_build > 1500);  // 2 977
    CHECK(items_seen > in_contact);
}
