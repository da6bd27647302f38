// The DEM step on the CUDA backend (libs/demCuda) against the same model stepped
// on the CPU: the same RF_HD kernels, so the two agree to round-off (the GPU sums
// in a different order, contracts FMAs and has its own sin/cos: docs/benchmarks.md
// gives the tolerance). Needs a GPU: without one the run is skipped (exit 77).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

#include "boxMeshes.hpp"
#include "dem/demModel.hpp"
#include "dem/voronoiQnscBond.hpp"
#include "demCuda/cudaDemModel.hpp"

using namespace rockfrac;

namespace {

constexpr double cell_size = 5e-3;
constexpr double dilation = 5e-4;

void shake(DemModel& model, double speed, double spin, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (int c = 0; c < model.cells().size(); ++c)
        model.setCellVelocity(c, speed * Vec3{uniform(random), uniform(random), uniform(random)},
                              spin * Vec3{uniform(random), uniform(random), uniform(random)});
}

// A weakly bonded block thrown under gravity on a plate, or on a floor of two triangles
// (the triangulated-surface path of the wall kernel): breakage, contacts, a wall.
DemModel eventfulCluster(bool triangulated_floor = false)
{
    DemParameters p;
    VoronoiQnscBondLaw::Parameters q;
    q.tensile_strength = 2e5;
    q.cohesion = 3e5;
    q.fracture_energy_I = q.fracture_energy_II = 0.5;
    p.bond_law = std::make_shared<VoronoiQnscBondLaw>(q);
    p.bond_damping = 0.05;
    p.damping_reading = DampingReading::criticalFraction;
    DemModel model(test::boxBlockMesh(5, 5, 4, {cell_size, cell_size, cell_size}, dilation, true,
                                      {0.0, 0.0, 0.2 * dilation}),
                   p);
    if (triangulated_floor) {
        const double half = 0.05;
        model.addTriSurface({{-half, -half, 0.0}, {half, -half, 0.0}, {half, half, 0.0}, {-half, half, 0.0}},
                            {{{0, 1, 2}}, {{0, 2, 3}}});
    } else {
        model.addPlate({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0});
    }
    shake(model, 0.5, 50.0, 11);
    for (int c = 0; c < model.cells().size(); ++c)
        model.setCellVelocity(c, model.cells().velocity[c] + Vec3{0.0, 0.0, -2.0},
                              model.cells().angular_velocity[c]);
    return model;
}

double largestDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
    double largest = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, norm(a[i] - b[i]));
    return largest;
}

}  // namespace

TEST_CASE("an intact bonded block steps on the device as on the CPU, to round-off", "[gpu][dem]")
{
    DemParameters p;
    p.gravity = {0.0, 0.0, 0.0};
    VoronoiQnscBondLaw::Parameters q;
    q.tensile_strength = q.cohesion = 1e12;
    p.bond_law = std::make_shared<VoronoiQnscBondLaw>(q);
    DemModel cpu(test::boxBlockMesh(6, 5, 4, {cell_size, cell_size, cell_size}, dilation), p);
    shake(cpu, 0.05, 20.0, 7);
    DemModel gpu_host(test::boxBlockMesh(6, 5, 4, {cell_size, cell_size, cell_size}, dilation), p);
    shake(gpu_host, 0.05, 20.0, 7);
    CudaDemModel gpu(gpu_host);
    const double dt = 0.02 * cpu.rayleighTimeStep();
    for (int i = 0; i < 500; ++i) {
        cpu.step(dt);
        gpu.step(dt);
        REQUIRE(gpu_host.status().ok());
    }
    gpu.downloadState();
    const double distance = largestDistance(cpu.cells().position, gpu_host.cells().position);
    INFO("largest CPU-GPU position difference " << distance << " m");
    CHECK(distance < 1e-9 * cell_size);
    CHECK(gpu_host.energies().bond_strain == Approx(cpu.energies().bond_strain).epsilon(1e-9));
    CHECK(gpu_host.energies().kinetic() == Approx(cpu.energies().kinetic()).epsilon(1e-9));
    CHECK(gpu_host.time() == cpu.time());
    CHECK(gpu_host.counters().steps == cpu.counters().steps);
}

TEST_CASE("breakage, contacts and a wall on the device: close to the CPU early, same physics later",
          "[gpu][dem]")
{
    const bool triangulated = GENERATE(false, true);
    INFO((triangulated ? "triangulated floor" : "plate"));
    DemModel cpu = eventfulCluster(triangulated);
    DemModel gpu_host = eventfulCluster(triangulated);
    CudaDemModel gpu(gpu_host);
    const double dt = 0.02 * cpu.rayleighTimeStep();
    int gpu_wall_contacts = 0;
    double largest_floor_push = 0.0;
    for (int i = 0; i < 1500; ++i) {
        cpu.step(dt);
        gpu.step(dt);
        REQUIRE(gpu_host.status().ok());
        gpu_wall_contacts = std::max(gpu_wall_contacts, gpu_host.counters().wall_contacts_active);
        largest_floor_push = std::max(largest_floor_push, -gpu_host.wallReaction(0).z);
        if (i == 100) {
            gpu.downloadState();
            const double distance = largestDistance(cpu.cells().position, gpu_host.cells().position);
            INFO("step 100: largest CPU-GPU position difference " << distance << " m");
            CHECK(distance < 1e-8 * cell_size);
        }
    }
    // Fracture amplifies round-off: compare what the run did, not where each cell is.
    CHECK(gpu_host.counters().bonds_broken > 0);
    CHECK(gpu_wall_contacts > 0);
    CHECK(gpu_host.counters().bonds_broken == Approx(cpu.counters().bonds_broken).epsilon(0.1));
    const double scale = std::max(cpu.energies().externalWork(), cpu.energies().kinetic());
    CHECK(std::fabs(gpu_host.energies().balance() - gpu_host.initialBalance()) < 0.01 * scale);
    // The floor's reaction, summed on the device per wall, carried the block's impact.
    CHECK(largest_floor_push > 0.0);
}

TEST_CASE("the device run is reproducible, and download + upload continue it unchanged", "[gpu][dem]")
{
    auto run = [](bool round_trip) {
        DemModel host = eventfulCluster();
        CudaDemModel gpu(host);
        const double dt = 0.02 * host.rayleighTimeStep();
        for (int i = 0; i < 600; ++i) {
            gpu.step(dt);
            if (round_trip && i == 300) {
                gpu.downloadState();
                gpu.upload();
            }
        }
        gpu.downloadState();
        return host.cells().position;
    };
    const std::vector<Vec3> plain = run(false), again = run(false), round_trip = run(true);
    REQUIRE(plain.size() == again.size());
    CHECK(std::memcmp(plain.data(), again.data(), plain.size() * sizeof(Vec3)) == 0);
    CHECK(std::memcmp(plain.data(), round_trip.data(), plain.size() * sizeof(Vec3)) == 0);
}

// The device versions of two CPU tests of testDynamics.cpp: the energy bookkeeping
// (block sums downloaded each step) and the finiteness check (the status the run loop reads).
TEST_CASE("on the device, a bonded cluster without damping or breakage conserves energy", "[gpu][dem]")
{
    DemParameters p;
    p.gravity = {0.0, 0.0, 0.0};
    p.bond_damping = 0.0;
    VoronoiQnscBondLaw::Parameters q;
    q.tensile_strength = q.cohesion = 1e12;
    p.bond_law = std::make_shared<VoronoiQnscBondLaw>(q);
    DemModel host(test::boxBlockMesh(5, 5, 4, {cell_size, cell_size, cell_size}, dilation), p);
    shake(host, 0.05, 20.0, 7);
    host.evaluateForces(0.0);
    CudaDemModel gpu(host);
    const double dt = 0.02 * host.rayleighTimeStep();
    const double initial = host.energies().balance();
    double largest_deviation = 0.0;
    for (int i = 0; i < 10000; ++i) {
        gpu.step(dt);
        REQUIRE(host.status().ok());
        largest_deviation = std::max(largest_deviation, std::fabs(host.energies().balance() - initial));
    }
    INFO("strain " << host.energies().bond_strain << " initial " << initial << " largest deviation "
                   << largest_deviation);
    CHECK(host.energies().bond_strain > 0.1 * initial);
    CHECK(largest_deviation < 0.005 * initial);
    CHECK(host.counters().bonds_broken == 0);
}

TEST_CASE("on the device, a time step far too large is reported, naming the step", "[gpu][dem]")
{
    DemParameters p;
    p.gravity = {0.0, 0.0, 0.0};
    p.bond_damping = 0.0;
    VoronoiQnscBondLaw::Parameters q;
    q.tensile_strength = q.cohesion = 1e12;
    p.bond_law = std::make_shared<VoronoiQnscBondLaw>(q);
    DemModel host(test::boxBlockMesh(3, 3, 3, {cell_size, cell_size, cell_size}, dilation), p);
    shake(host, 0.05, 0.0, 3);
    CudaDemModel gpu(host);
    const double dt = 2.0 * host.rayleighTimeStep();
    long failed_at = -1;
    for (int i = 0; i < 2000 && failed_at < 0; ++i) {
        gpu.step(dt);
        if (!host.status().ok()) failed_at = host.status().step;
    }
    REQUIRE(failed_at > 0);
    CHECK_THAT(host.status().message(), Catch::Contains("step " + std::to_string(failed_at)));
}

int main(int argc, char** argv)
{
    const CudaBackendInfo info = cudaBackendInfo();
    if (info.devices == 0) {
        std::printf("SKIP: the CUDA backend tests need a GPU: %s\n", info.status.c_str());
        return 77;
    }
    return Catch::Session().run(argc, argv);
}
