// benchDem: speed and memory of the bonded Voronoi DEM (docs/benchmarks.md).
//
//   benchDem                        intact bonded blocks of 1e4 and 1e5 cells, 1 and 2 threads
//   benchDem -block <cells> [N]     one intact block, N steps, 1 and 2 threads
//   benchDem -block <cells> [N] -cuda   the same block on the CUDA backend (needs a GPU)
//   benchDem -block <cells> [N] -dt <s> with the given step instead of 0.5 x the critical step
//                                   (whose serial power iteration takes many minutes at 1e6 cells)
//   benchDem -block <cells> [N] -order seeding   cells in the random order of the seeds instead
//                                   of along a Morton curve (the default, cellOrder morton)
//   benchDem -case <dir> [N]        a bondedDemFoam case from its latest time directory (e.g. an
//                                   SPB rock after fracture), N steps
//   benchDem -liners [rocks] [N]    rocks of 30 cells (40-55 mm) resting in the lower chamber of the
//                                   CH660 (meshCrusher's liners at 360 segments, mantle gyrating at
//                                   290 rpm): the liner contacts of a choked crusher, N steps after
//                                   settling 2000
//
// Prints cell-steps per second (wall clock, best of 3 repetitions), bonds per cell, the
// model's memory per cell (device memory with -cuda) and the time step (bench/run gives the
// same step to the Yade peer). Not a test: speed is measured here, never asserted.
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "benchBlock.hpp"
#include "core/dictionary.hpp"
#include "core/random.hpp"
#include "core/timeControl.hpp"
#include "crusher/feedRock.hpp"
#include "crusher/linerClearance.hpp"
#include "dem/demModel.hpp"
#include "dem/voronoiQnscBond.hpp"
#include "demCase/demCase.hpp"
#include "demCuda/cudaDemModel.hpp"
#include "voronoi/domain.hpp"
#include "voronoi/tessellation.hpp"
#include "voronoi/voronoiMeshIO.hpp"

using namespace rockfrac;

namespace {

double secondsFor(DemModel& model, int steps, double dt)
{
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) model.step(dt);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double secondsFor(CudaDemModel& device, int steps, double dt)
{
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) device.step(dt);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// threads < 0: the CUDA backend. b/cell: bond ends per cell (2 x bonds / cells).
void report(const char* what, int nCells, int nBonds, std::size_t bytes, int threads, int steps,
            double seconds, double dt)
{
    char thr[8];
    std::snprintf(thr, sizeof(thr), "%s", threads < 0 ? "gpu" : std::to_string(threads).c_str());
    std::printf("%-28s %8d %6.1f %3s %7d %10.3f %12.4g %8.0f %10.4g\n", what, nCells, 2.0 * nBonds / nCells,
                thr, steps, seconds, static_cast<double>(nCells) * steps / seconds,
                static_cast<double>(bytes) / nCells, dt);
    std::fflush(stdout);
}

void header()
{
    std::printf("%-28s %8s %6s %3s %7s %10s %12s %8s %10s\n", "case", "cells", "b/cell", "thr", "steps",
                "wall [s]", "cell-steps/s", "B/cell", "dt [s]");
}

void intactBlock(int nCells, int steps, bool cuda, double given_dt, CellOrder order)
{
    const VoronoiMesh mesh = benchBlockMesh(nCells, order);
    const DemParameters p = benchBlockParameters();
    const std::string name = "intact block " + std::to_string(nCells);
    // One model for every thread count (set-up, the critical step's power iteration and the
    // first neighbour lists cost more than the timed steps at 1e5 cells and beyond).
    DemModel model(mesh, p);
    setBenchBlockVelocities(model);
    const double dt = given_dt > 0.0 ? given_dt : 0.5 * model.criticalTimeStep().value;
    if (cuda) {
        CudaDemModel device(model);
        secondsFor(device, 5, dt);  // warm up: lists, caches
        double best = 1e300;
        for (int r = 0; r < 3; ++r) best = std::min(best, secondsFor(device, steps, dt));
        report(name.c_str(), model.cells().size(), model.nBonds(), device.deviceBytes(), -1, steps, best, dt);
        return;
    }
    for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        secondsFor(model, 5, dt);  // warm up: lists, caches, threads
        double best = 1e300;
        for (int r = 0; r < 3; ++r) best = std::min(best, secondsFor(model, steps, dt));
        report(name.c_str(), model.cells().size(), model.nBonds(), model.memoryBytes(), threads, steps, best,
               dt);
    }
    // Where the bytes per cell go (DemModel::memoryUse, capacities of the state arrays).
    const DemMemoryBytes m = model.memoryUse();
    const double n = model.cells().size();
    std::printf(
        "# memory per cell [B]: cells %.0f, cores %.0f, anchor nodes %.0f (%.1f per cell), interfaces %.0f, "
        "bonds %.0f, softening pool %.0f, contact pairs %.0f (%.1f per cell), wall items %.0f, lists %.0f\n",
        m.cells / n, m.cores / n, m.anchor_nodes / n, model.cells().anchor_nodes.size() / n, m.interfaces / n,
        m.bonds / n, m.softening / n, m.pairs / n, model.contactPairs().size() / n, m.wall_items / n,
        m.lists / n);
    // What the CUDA backend would hold on the device for this model (from the array sizes).
    const std::size_t device_bytes = CudaDemModel::estimateDeviceBytes(model);
    if (device_bytes > 0)
        std::printf("# estimated CUDA device memory: %.0f bytes/cell\n",
                    static_cast<double>(device_bytes) / model.cells().size());
}

void fromCase(const std::string& caseDir, int steps)
{
    const VoronoiMesh mesh = readVoronoiMesh(caseDir);
    const Dictionary props = Dictionary::readFile(caseDir + "/constant/rockProperties");
    DemParameters p = readDemParameters(props);
    const auto times = TimeControl::timeDirectories(caseDir);
    for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        DemModel model(mesh, p);
        // Plates as bondedDemFoam places them (then restored from the state).
        double zMin = 1e300, zMax = -1e300;
        for (const auto& v : mesh.vertices) {
            zMin = std::min(zMin, v.z);
            zMax = std::max(zMax, v.z);
        }
        model.addPlate({0, 0, zMin}, {0, 0, 1});
        model.addPlate({0, 0, zMax}, {0, 0, -1});
        char name[64];
        std::snprintf(name, sizeof(name), "%.12g", times.empty() ? 0.0 : times.back());
        if (!times.empty()) readDemState(caseDir + "/" + name + "/demState", model);
        const double dt = 0.5 * model.criticalTimeStep().value;
        double best = 1e300;
        for (int r = 0; r < 3; ++r) best = std::min(best, secondsFor(model, steps, dt));
        std::string label =
            "case t=" + std::string(name) + " (" + std::to_string(model.counters().bonds_broken) + " broken)";
        report(label.c_str(), model.cells().size(), model.nBonds(), model.memoryBytes(), threads, steps, best,
               dt);
    }
}

// Rocks in the lower chamber of the CH660 (the profiles of tutorials/CH660/geometry, the
// kinematics meshCrusher computes for them), settled under gravity onto the liners.
void linerContacts(int rocks, int steps)
{
    const Profile mantle_profile{{0.0, 0.66}, {0.12, 0.64}, {0.22, 0.55}, {0.43, 0.10}, {0.50, 0.0}};
    const Profile concave_profile{{0.3846, 0.5051}, {0.4276, 0.3181}, {0.4759, 0.1322}, {0.5605, 0.0001}};
    CrusherKinematics k;
    k.pivot = {0.0, 0.0, 1.5};
    k.eccentric_angle = 0.008481216352835365;
    k.eccentric_speed = 30.36872898470133;
    const TriSurface mantle = revolveProfileShaped(mantle_profile, 360, SurfaceFacing::awayFromAxis);
    const TriSurface concave = revolveProfileShaped(concave_profile, 360, SurfaceFacing::towardsAxis);
    DemParameters p;
    p.rock_youngs_modulus = 7.7e9;  // the reduced crusher's 10 x softer rock
    VoronoiQnscBondLaw::Parameters q;
    q.youngs_modulus = 4.6e9;
    p.bond_law = std::make_shared<VoronoiQnscBondLaw>(q);
    p.damping_reading = DampingReading::criticalFraction;
    p.bond_damping = 0.05;
    const VoronoiMesh rock =
        generateVoronoiMesh(Domain::box({0.0, 0.0, 0.0}, {0.03, 0.02, 0.012}), 30, 2.5e-3, 7);
    FeedSpec spec;
    spec.size_min = 0.040;
    spec.size_max = 0.055;
    spec.mass_rate = 1.0;  // [kg/s] fed one rock per call below (each ~0.1 kg)
    spec.z_min = 0.03;
    spec.z_max = 0.30;
    spec.r_min = 0.33;
    spec.r_max = 0.55;
    spec.attempts = 2000;
    spec.interval = 1.0;
    spec.liner_clearance = 1e-3;
    auto motion = [&](double t) {
        const MantlePose m = mantlePose(k, t);
        return WallMotion{m.translation, quatFromRotationVector(m.rotation_vector), m.velocity,
                          m.angular_velocity};
    };
    for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        DemModel model(p);
        const int mw = model.addTriSurface(mantle.points, mantle.triangles, motion(0.0));
        const int cw = model.addTriSurface(concave.points, concave.triangles);
        FeedFactory factory(spec, makeFeedRockTemplate(rock, p.rock_density));
        factory.setLiners({revolvedLiner(mantle, mw, SurfaceFacing::awayFromAxis, "mantle"),
                           revolvedLiner(concave, cw, SurfaceFacing::towardsAxis, "concave")});
        // One rock at a time up to `rocks` (or as many as find room in 400 calls).
        for (int call = 1; call <= 400 && factory.rocksFed() < rocks; ++call)
            factory.feed(model, 0.01 * call);
        const double dt = 0.8 * DemModel(factory.smallestRock(), p).criticalTimeStep().value;
        auto run = [&](int n) {
            const auto start = std::chrono::steady_clock::now();
            for (int s = 0; s < n; ++s) {
                model.setWallMotion(mw, motion(model.time()));
                model.step(dt);
            }
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        };
        run(2000);
        const double seconds = run(steps);
        const std::string label = "CH660 liners, " + std::to_string(factory.rocksFed()) + " rocks";
        report(label.c_str(), model.cells().size(), model.nBonds(), model.memoryBytes(), threads, steps,
               seconds, dt);
    }
}

}  // namespace

int main(int argc, char** argv)
{
    header();
    if (argc >= 3 && std::strcmp(argv[1], "-case") == 0) {
        fromCase(argv[2], argc >= 4 ? std::atoi(argv[3]) : 2000);
        return 0;
    }
    if (argc >= 2 && std::strcmp(argv[1], "-liners") == 0) {
        linerContacts(argc >= 3 ? std::atoi(argv[2]) : 30, argc >= 4 ? std::atoi(argv[3]) : 2000);
        return 0;
    }
    if (argc >= 3 && std::strcmp(argv[1], "-block") == 0) {
        bool cuda = false;
        int steps = 10;
        CellOrder order = CellOrder::morton;
        double dt = 0.0;
        for (int a = 3; a < argc; ++a) {
            if (std::strcmp(argv[a], "-cuda") == 0)
                cuda = true;
            else if (std::strcmp(argv[a], "-dt") == 0 && a + 1 < argc)
                dt = std::atof(argv[++a]);
            else if (std::strcmp(argv[a], "-order") == 0 && a + 1 < argc)
                order = std::strcmp(argv[++a], "seeding") == 0 ? CellOrder::seeding : CellOrder::morton;
            else
                steps = std::atoi(argv[a]);
        }
        try {
            intactBlock(std::atoi(argv[2]), steps, cuda, dt, order);
        } catch (const std::exception& error) {
            std::fprintf(stderr, "benchDem: %s\n", error.what());
            return 1;
        }
        return 0;
    }
    intactBlock(10000, 100, false, 0.0, CellOrder::morton);
    intactBlock(100000, 10, false, 0.0, CellOrder::morton);
    return 0;
}
