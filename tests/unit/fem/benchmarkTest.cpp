// Throughput of the KST-DFH explicit step (hidden: run with `test_fem "[.bench]"`).
//
// A gmsh box of about ROCKFRAC_BENCH_TETS tetrahedra (a comma list, default "1e4,1e5";
// docs/benchmarks.md also runs 1e6) compressed between two plates, weak enough that
// elements crack during the run, so the DFH branch is exercised. The same model steps
// on 1 and then 2 threads; element-steps/s counts whole explicit steps (element loop,
// force gather, contact, update, energy sums). Memory: the resident-set growth from
// before the model is built to after its first step, per element (the mesh itself,
// 52 bytes per tet and 24 per node, is held by the test and not counted).
#include <omp.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fem/femModel.hpp"
#include "femTestSupport.hpp"

using namespace rockfrac;
using namespace rockfrac::fem;

namespace {

// Resident set size of this process [bytes] (Linux /proc; 0 elsewhere).
double residentBytes()
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmRSS:", 0) == 0) return 1024.0 * std::atof(line.c_str() + 6);
    return 0.0;
}

std::vector<double> benchmarkSizes()
{
    const char* env = std::getenv("ROCKFRAC_BENCH_TETS");
    std::stringstream list(env ? env : "1e4,1e5");
    std::vector<double> sizes;
    for (std::string item; std::getline(list, item, ',');) sizes.push_back(std::atof(item.c_str()));
    return sizes;
}

}  // namespace

TEST_CASE("KST-DFH element-steps per second under plate compression", "[.bench]")
{
    for (const double targetTets : benchmarkSizes()) {
        const double size = 0.02;
        // gmsh's Delaunay tets at CharacteristicLengthMax h fill the box with about
        // 9.5 (size / h)^3 tets (measured); the count printed is the real one.
        const double h = size * std::cbrt(9.5 / targetTets);
        TetMesh mesh;
        {
            test::GmshSession gmshSession;
            mesh = test::boxMesh(gmshSession, size, size, size, h);
        }
        const double before = residentBytes();
        FemParameters parameters;
        parameters.material.referenceVolume = 1e-9;
        parameters.material.weibullStress = 1e6;  // weak, so that elements crack during the run
        parameters.massDamping = 1e4;
        FemModel model(mesh, parameters);
        RigidPlate bottom, top;
        top.point = {0, 0, size};
        top.normal = {0, 0, -1};
        top.velocity = {0, 0, -1.0};
        model.addPlate(bottom);
        model.addPlate(top);
        const double dt = model.stableTimeStep();
        REQUIRE(model.step(dt).ok);
        const double bytesPerElement = (residentBytes() - before) / double(mesh.numTets());
        // About 3e7 element-steps per measurement (a few seconds each).
        const int steps = std::max(10, int(3e7 / double(mesh.numTets())));
        for (int threads : {1, 2}) {
            omp_set_num_threads(threads);
            const auto start = std::chrono::steady_clock::now();
            for (int i = 0; i < steps; ++i) REQUIRE(model.step(dt).ok);
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            int cracked = 0;
            for (double d : model.elementOutput().damage[0]) cracked += d > 0.5;
            std::printf(
                "bench: %zu tets, %zu nodes, %d threads, %d steps in %.2f s: %.3g element-steps/s "
                "(%d cracked), %.0f bytes/element\n",
                mesh.numTets(), mesh.numNodes(), threads, steps, seconds,
                double(mesh.numTets()) * steps / seconds, cracked, bytesPerElement);
            std::fflush(stdout);
        }
    }
}
