// Throughput of the KST-DFH element loop (hidden: run with `test_fem "[.bench]"`).
#include <omp.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>

#include "fem/femModel.hpp"
#include "femTestSupport.hpp"

using namespace rockfrac;
using namespace rockfrac::fem;

TEST_CASE("KST-DFH element-steps per second under plate compression", "[.bench]")
{
    test::GmshSession gmshSession;
    const double size = 0.02;
    const TetMesh mesh = test::boxMesh(gmshSession, size, size, size, 0.04 * size);
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
    const int steps = 200;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) REQUIRE(model.step(dt).ok);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int cracked = 0;
    for (double d : model.elementOutput().damage[0]) cracked += d > 0.5;
    std::printf("bench: %zu tets, %d threads, %d steps in %.2f s: %.3g element-steps/s (%d cracked)\n",
                mesh.numTets(), omp_get_max_threads(), steps, seconds,
                mesh.numTets() * double(steps) / seconds, cracked);
}
