// Cells entering and leaving a DEM model: every array and index stays consistent
// after insert/remove cycles, the remaining clusters give bitwise the forces of a
// model built fresh from the same cells, and a fed run is reproducible (same seed,
// same result; 1 and 2 threads bitwise equal) with the mass balance closed.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cstring>

#include "crusher/destructor.hpp"
#include "crusher/feedRock.hpp"
#include "dem/demModel.hpp"
#include "dem/voronoiQnscBond.hpp"
#include "funnelFeed.hpp"
#include "voronoi/tessellation.hpp"

using namespace rockfrac;

namespace {

DemParameters testParameters()
{
    DemParameters p;
    p.damping_reading = DampingReading::criticalFraction;
    p.bond_damping = 0.05;
    return p;
}

const VoronoiMesh& rockMesh()
{
    static const VoronoiMesh mesh =
        generateVoronoiMesh(Domain::box({0.0, 0.0, 0.0}, {0.03, 0.02, 0.012}), 20, 2.5e-3, 5);
    return mesh;
}

WallMotion pose(const Vec3& at, const Vec3& axis_angle, const Vec3& velocity)
{
    return {at, quatFromRotationVector(axis_angle), velocity, {0.0, 0.0, 30.0}};
}

// Every index names something that exists, every offset array is monotone and
// closes on its data, and every per-item array has its item count.
void checkConsistent(const DemModel& model)
{
    const CellArrays& c = model.cells();
    const int n = c.size();
    for (auto size : {c.position.size(), c.velocity.size(), c.orientation.size(), c.angular_velocity.size(),
                      c.force.size(), c.torque.size(), c.principal_inertia.size(), c.dilation_radius.size(),
                      c.bounding_radius.size(), c.initial_bond_count.size()})
        REQUIRE(static_cast<int>(size) == n);
    REQUIRE(static_cast<int>(c.core_vertex_offset.size()) == n + 1);
    REQUIRE(c.core_vertex_offset.back() == static_cast<int>(c.core_vertices.size()));
    for (int k = 0; k < n; ++k) REQUIRE(c.core_vertex_offset[k] < c.core_vertex_offset[k + 1]);

    const InterfaceArrays& f = model.interfaces();
    const BondArrays& b = model.bonds();
    REQUIRE(static_cast<int>(f.bond_offset.size()) == f.size() + 1);
    REQUIRE(f.bond_offset.front() == 0);
    REQUIRE(f.bond_offset.back() == b.size());
    for (int k = 0; k < f.size(); ++k) {
        REQUIRE(f.bond_offset[k] < f.bond_offset[k + 1]);
        REQUIRE(0 <= f.cell_i[k]);
        REQUIRE(f.cell_i[k] < f.cell_j[k]);
        REQUIRE(f.cell_j[k] < n);
        if (k > 0)
            REQUIRE(std::make_pair(f.cell_i[k - 1], f.cell_j[k - 1]) <
                    std::make_pair(f.cell_i[k], f.cell_j[k]));
        int intact = 0;
        for (int e = f.bond_offset[k]; e < f.bond_offset[k + 1]; ++e) intact += b.stage[e] != bondBroken;
        REQUIRE(intact == f.intact_bonds[k]);
    }
    for (auto size :
         {f.cell_j.size(), f.intact_bonds.size(), f.normal_i.size(), f.normal_j.size(), f.length_i.size(),
          f.length_j.size(), f.bond_area.size(), f.damping_beta.size(), f.force_on_i.size()})
        REQUIRE(static_cast<int>(size) == f.size());
    for (auto size : {b.anchor_i.size(), b.anchor_j.size(), b.onset_displacement.size(), b.damage.size(),
                      b.max_displacement.size(), b.rupture_displacement.size(), b.onset_stress.size()})
        REQUIRE(static_cast<int>(size) == b.size());
    REQUIRE(model.counters().bonds == b.size());

    // The compact storage behind bonds(): anchor nodes per cell, node indices within
    // their cell's list, and softening slots exactly for interfaces past an onset,
    // each inside the pool and none overlapping another.
    const BondStorage& storage = model.bondStorage();
    REQUIRE(static_cast<int>(c.anchor_node_offset.size()) == n + 1);
    REQUIRE(c.anchor_node_offset.back() == static_cast<int>(c.anchor_nodes.size()));
    REQUIRE(static_cast<int>(f.softening_slot.size()) == f.size());
    for (auto size : {storage.node_i.size(), storage.node_j.size(), storage.stage.size()})
        REQUIRE(static_cast<int>(size) == b.size());
    std::vector<char> pool_used(storage.softening.size(), 0);
    for (int k = 0; k < f.size(); ++k) {
        bool softened = false;
        for (int e = f.bond_offset[k]; e < f.bond_offset[k + 1]; ++e) {
            REQUIRE(storage.node_i[e] <
                    c.anchor_node_offset[f.cell_i[k] + 1] - c.anchor_node_offset[f.cell_i[k]]);
            REQUIRE(storage.node_j[e] <
                    c.anchor_node_offset[f.cell_j[k] + 1] - c.anchor_node_offset[f.cell_j[k]]);
            softened = softened || storage.stage[e] != bondElastic;
        }
        if (softened) REQUIRE(f.softening_slot[k] >= 0);
        if (f.softening_slot[k] < 0) continue;
        for (int e = 0; e < f.bond_offset[k + 1] - f.bond_offset[k]; ++e) {
            REQUIRE(f.softening_slot[k] + e < static_cast<int>(pool_used.size()));
            REQUIRE(!pool_used[f.softening_slot[k] + e]);
            pool_used[f.softening_slot[k] + e] = 1;
        }
    }

    const ContactPairArrays& p = model.contactPairs();
    for (int k = 0; k < p.size(); ++k) {
        REQUIRE(0 <= p.cell_a[k]);
        REQUIRE(p.cell_a[k] < p.cell_b[k]);
        REQUIRE(p.cell_b[k] < n);
        if (p.interface[k] >= 0) {
            REQUIRE(p.interface[k] < f.size());
            REQUIRE(f.cell_i[p.interface[k]] == p.cell_a[k]);
            REQUIRE(f.cell_j[p.interface[k]] == p.cell_b[k]);
        }
    }
    const WallContactArrays& w = model.wallContacts();
    for (int k = 0; k < w.size(); ++k) {
        REQUIRE(0 <= w.cell[k]);
        REQUIRE(w.cell[k] < n);
        REQUIRE(w.wall[k] < model.nWalls());
    }
}

double totalMass(const DemModel& model)
{
    double m = 0.0;
    for (double c : model.cells().mass) m += c;
    return m;
}

}  // namespace

TEST_CASE("inserted cells: the body frames, masses and bonds of the mesh, placed by the pose",
          "[crusher][insert]")
{
    const VoronoiMesh& mesh = rockMesh();
    DemModel reference(mesh, testParameters());
    DemModel model(testParameters());
    CHECK(model.cells().size() == 0);
    const Vec3 shift{0.3, -0.1, 0.2};
    const Quat q = quatFromRotationVector({0.3, -1.1, 0.7});
    const int first = model.insertCells(mesh, {shift, q, {}, {}});
    CHECK(first == 0);
    REQUIRE(model.cells().size() == mesh.nCells());
    CHECK(model.nBonds() == reference.nBonds());
    CHECK(model.interfaces().size() == reference.interfaces().size());
    const Mat3 R = rotationMatrix(q);
    for (int c = 0; c < mesh.nCells(); ++c) {
        CHECK(norm(model.cells().position[c] - (shift + R * mesh.centroids[c])) < 1e-15);
        CHECK(model.cells().mass[c] == reference.cells().mass[c]);
    }
    // A rigidly moved rock at rest is unstrained: no bond force anywhere.
    model.evaluateForces(0.0);
    CHECK(model.energies().bond_strain < 1e-20);
    for (int c = 0; c < model.cells().size(); ++c)
        CHECK(norm(model.cells().force[c] - model.cells().mass[c] * model.parameters().gravity) <
              1e-6);  // [N] round-off of bonds with stiffness ~1e8 N/m
    checkConsistent(model);
}

TEST_CASE("a scaled rock: volumes s^3, inertia s^5, areas s^2, lengths s", "[crusher][feed]")
{
    const VoronoiMesh& mesh = rockMesh();
    const double s = 2.5;
    const VoronoiMesh big = scaleVoronoiMesh(mesh, s, {0.01, 0.01, 0.01});
    CHECK(big.volumes[3] == Approx(s * s * s * mesh.volumes[3]).epsilon(1e-14));
    CHECK(big.inertia[3](0, 1) == Approx(std::pow(s, 5) * mesh.inertia[3](0, 1)).epsilon(1e-14));
    CHECK(big.bonds[7].area == Approx(s * s * mesh.bonds[7].area).epsilon(1e-14));
    CHECK(big.bonds[7].lI == Approx(s * mesh.bonds[7].lI).epsilon(1e-14));
    CHECK(big.dilationRadius == Approx(s * mesh.dilationRadius).epsilon(1e-14));
    const FeedRockTemplate small = makeFeedRockTemplate(mesh, 2540.0);
    const FeedRockTemplate large = makeFeedRockTemplate(big, 2540.0);
    CHECK(large.sieve_size == Approx(s * small.sieve_size).epsilon(1e-9));
    CHECK(large.volume == Approx(s * s * s * small.volume).epsilon(1e-12));
    // The scaled rock is a valid model: its stable step scales with s (same wave speed).
    DemModel a(mesh, testParameters()), b(big, testParameters());
    CHECK(b.criticalTimeStep().bond == Approx(s * a.criticalTimeStep().bond).epsilon(1e-3));
}

TEST_CASE("insert/remove cycles keep every index consistent; remaining clusters give fresh-model forces",
          "[crusher][insert][remove]")
{
    const VoronoiMesh& mesh = rockMesh();
    const DemParameters p = testParameters();
    const std::vector<WallMotion> poses = {pose({0.0, 0.0, 0.012}, {0.1, 0.2, 0.3}, {0, 0, -20}),
                                           pose({0.01, 0.0, 0.04}, {-0.4, 0.2, 0.1}, {0, 0, -20}),
                                           pose({0.1, 0.0, 0.015}, {0.5, -0.2, 0.9}, {0, 0, -20})};
    DemModel model(p);
    const int plate = model.addPlate({0, 0, 0}, {0, 0, 1});
    for (const WallMotion& w : poses) model.insertCells(mesh, w);
    checkConsistent(model);
    const double dt = 0.5 * model.criticalTimeStep().value;
    for (int i = 0; i < 6000; ++i) {
        model.step(dt);
        REQUIRE(model.status().ok());
    }
    INFO("broken " << model.counters().bonds_broken << ", wall contacts "
                   << model.counters().wall_contacts_active << ", contacts "
                   << model.counters().contacts_active);
    CHECK(model.counters().bonds_broken > 0);
    CHECK(model.counters().wall_contacts_active > 0);

    // Remove the middle rock (cells [20, 40)) and every third cell of the first rock.
    const int n = model.cells().size();
    const double before = totalMass(model);
    std::vector<char> remove(n, 0);
    double removed_mass = 0.0;
    for (int c = 0; c < n; ++c) {
        remove[c] = (c >= 20 && c < 40) || (c < 20 && c % 3 == 0);
        if (remove[c]) removed_mass += model.cells().mass[c];
    }
    const std::vector<int> new_index = model.removeCells(remove);
    checkConsistent(model);
    CHECK(model.cells().size() == n - static_cast<int>(std::count(remove.begin(), remove.end(), 1)));
    CHECK(totalMass(model) == Approx(before - removed_mass).epsilon(1e-14));
    CHECK(new_index[2] == 1);
    CHECK(new_index[40] == 20 - 7);

    // A fresh model of the same cells (the kept cells of rock 1, rock 3) put in the same
    // state gives bitwise the same forces.
    DemModel fresh(p);
    fresh.addPlate({0, 0, 0}, {0, 0, 1});
    fresh.insertCells(mesh, poses[0]);
    fresh.insertCells(mesh, poses[2]);
    std::vector<char> remove_fresh(fresh.cells().size(), 0);
    for (int c = 0; c < 20; ++c) remove_fresh[c] = c % 3 == 0;
    fresh.removeCells(remove_fresh);
    REQUIRE(fresh.cells().size() == model.cells().size());
    REQUIRE(fresh.nBonds() == model.nBonds());
    fresh.setCellState(model.cells().position, model.cells().velocity, model.cells().orientation,
                       model.cells().angular_velocity);
    fresh.setBondHistory(model.bonds());
    fresh.setContactHistory(model.contactPairs(), model.wallContacts());
    fresh.setWallState(plate, model.wall(plate));
    fresh.evaluateForces(0.0);
    const auto& a = model.cells().force;
    const auto& b = fresh.cells().force;
    CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0);
    CHECK(std::memcmp(model.cells().torque.data(), fresh.cells().torque.data(), a.size() * sizeof(Vec3)) ==
          0);
    CHECK(fresh.contactPairs().size() == model.contactPairs().size());

    // Cycles: insert again, step, remove again; still consistent and stable.
    for (int cycle = 0; cycle < 3; ++cycle) {
        model.insertCells(mesh, pose({0.05 * cycle - 0.05, 0.06, 0.05}, {0.3 * cycle, 0.1, 0.0}, {0, 0, -5}));
        for (int i = 0; i < 500; ++i) {
            model.step(dt);
            REQUIRE(model.status().ok());
        }
        std::vector<char> drop(model.cells().size(), 0);
        for (int c = 0; c < model.cells().size(); c += 4) drop[c] = 1;
        model.removeCells(drop);
        checkConsistent(model);
        model.step(dt);
        REQUIRE(model.status().ok());
    }
}

namespace {

struct FedRun {
    std::vector<Vec3> position;
    double fed = 0.0, inside = 0.0, discharged = 0.0, balance_error = 0.0, scale = 0.0;
    int fragments = 0, rocks = 0;
};

FedRun runFed(int threads, std::uint64_t seed)
{
    omp_set_num_threads(threads);
    DemParameters p = testParameters();
    p.gravity = {0.0, 0.0, -200.0};  // faster falling: a short test
    VoronoiQnscBondLaw::Parameters q;
    q.youngs_modulus = 4.6e9;  // 10 x softer than granite: a 3 x larger step
    p.bond_law = std::make_shared<VoronoiQnscBondLaw>(q);
    p.rock_youngs_modulus = 7.7e9;
    const FeedSpec spec = funnelFeedSpec(seed);
    FeedFactory factory(spec, makeFeedRockTemplate(rockMesh(), p.rock_density));
    DemModel model(p);
    // A funnel of two inclined plates makes the rocks meet before they leave.
    model.addPlate({-0.05, 0, 0}, {1, 0, 0.5});
    model.addPlate({0.05, 0, 0}, {-1, 0, 0.5});
    const double dt = 0.5 * DemModel(factory.smallestRock(), p).criticalTimeStep().value;
    FedRun run;
    const long feed_every = std::lround(spec.interval / dt);
    for (long step = 0; step < 15000; ++step) {
        if (step % feed_every == 0) factory.feed(model, model.time());
        model.step(dt);
        REQUIRE(model.status().ok());
        if (step % 50 == 0) {
            const DestructorResult r = destroyBelow(model, -0.03);
            run.discharged += r.mass;
            run.fragments += static_cast<int>(r.fragments.size());
        }
    }
    run.position = model.cells().position;
    run.fed = factory.massFed();
    run.rocks = factory.rocksFed();
    run.inside = totalMass(model);
    run.balance_error = model.energies().balance() - model.initialBalance();
    run.scale = model.energies().externalWork();
    return run;
}

}  // namespace

TEST_CASE("a fed run: same seed same result, 1 and 2 threads bitwise equal, mass balance closed",
          "[crusher][feed][determinism]")
{
    const FedRun one = runFed(1, 7);
    const FedRun two = runFed(2, 7);
    omp_set_num_threads(2);
    INFO("rocks " << one.rocks << " fed " << one.fed << " kg, inside " << one.inside << " kg, out "
                  << one.discharged << " kg in " << one.fragments << " fragments; balance error "
                  << one.balance_error << " J of " << one.scale << " J");
    CHECK(one.rocks >= 3);
    CHECK(one.fragments > 0);
    CHECK(one.discharged > 0.0);
    CHECK(one.fed == Approx(one.inside + one.discharged).epsilon(1e-13));
    CHECK(std::fabs(one.balance_error) < 0.05 * one.scale);
    REQUIRE(one.position.size() == two.position.size());
    CHECK(std::memcmp(one.position.data(), two.position.data(), one.position.size() * sizeof(Vec3)) == 0);
    CHECK(one.discharged == two.discharged);
    const FedRun other = runFed(1, 8);
    CHECK(
        !(other.position.size() == one.position.size() &&
          std::memcmp(one.position.data(), other.position.data(), one.position.size() * sizeof(Vec3)) == 0));
}
