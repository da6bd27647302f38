// Throughput of the KST-DFH explicit step (hidden: run with `test_fem "[.bench]"`).
//
// A gmsh box of about ROCKFRAC_BENCH_TETS tetrahedra (a comma list, default "1e4,1e5";
// docs/benchmarks.md also runs 1e6) compressed between two plates, weak enough that
// elements crack during the run, so the DFH branch is exercised. The same model steps
// on 1 and then 2 threads; element-steps/s counts whole explicit steps (element loop,
// force gather, contact, update, energy sums). Memory: the heap growth from before
// the model is built to after its first step, per element, node arrays included (the
// mesh itself, 20 bytes per tet and 24 per node, is held by the test and not counted).
#include <malloc.h>
#include <omp.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "fem/femModel.hpp"
#include "fem/kstDfhMaterial.hpp"
#include "femTestSupport.hpp"

using namespace rockfrac;
using namespace rockfrac::fem;

namespace {

// Heap bytes in use (glibc): small blocks plus mmap'd ones. Unlike the resident set
// it does not hide allocations that reuse memory gmsh freed.
double heapBytesInUse()
{
    const struct mallinfo2 info = mallinfo2();
    return double(info.uordblks) + double(info.hblkhd);
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
    for (const double targetTets : benchmarkSizes())
        for (const bool weak : {false, true}) {
            const double size = 0.02;
            // gmsh's Delaunay tets at CharacteristicLengthMax h fill the box with about
            // 5.9 (size / h)^3 tets (measured); the count printed is the real one.
            const double h = size * std::cbrt(5.9 / targetTets);
            TetMesh mesh;
            {
                test::GmshSession gmshSession;
                mesh = test::boxMesh(gmshSession, size, size, size, h);
            }
            const double before = heapBytesInUse();
            FemParameters parameters;
            // The BDT granite tutorial's rock (m = 7, sigma_w = 21 MPa, V_ref = 2e-8 m^3), or
            // a weak one (sigma_w = 1 MPa, V_ref = 1e-9 m^3) whose elements crack in the
            // compression wave.
            KstDfhParameters k;
            k.referenceVolume = weak ? 1e-9 : 2e-8;
            if (weak) k.weibullStress = 1e6;
            parameters.material = std::make_shared<FemMaterialModelOf<KstDfhMaterial>>(k);
            parameters.massDamping = 2e4;
            FemModel model(mesh, parameters);
            RigidPlate bottom, top;
            top.point = {0, 0, size};
            top.normal = {0, 0, -1};
            model.addPlate(bottom);
            const double dtEstimate = model.stableTimeStep();
            // About 3e7 element-steps per measurement (a few seconds each).
            const int steps = std::max(10, int(3e7 / double(mesh.numTets())));
            // The plate compresses the box by 0.1 % over the whole benchmark, whatever the
            // mesh: too little to invert any element. The granite rock stays intact (every
            // element still runs the whole KST-DFH update: crack check, KST return); the weak
            // rock cracks most elements, the costly branch (stress in the crack frame).
            top.velocity = {0, 0, -0.001 * size / ((2 * steps + 1) * dtEstimate)};
            model.addPlate(top);
            const double dt = model.stableTimeStep();
            REQUIRE(model.step(dt).ok);
            const double bytesPerElement = (heapBytesInUse() - before) / double(mesh.numTets());
            for (int threads : {1, 2}) {
                omp_set_num_threads(threads);
                const auto start = std::chrono::steady_clock::now();
                for (int i = 0; i < steps; ++i) REQUIRE(model.step(dt).ok);
                const double seconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                int cracked = 0;
                for (double d : model.elementOutput().damage[0]) cracked += d > 0.5;
                std::printf(
                    "bench: %s rock, %zu tets, %zu nodes, %d threads, %d steps in %.2f s: %.3g "
                    "element-steps/s "
                    "(%.1f %% cracked), %.0f bytes/element\n",
                    weak ? "weak" : "granite", mesh.numTets(), mesh.numNodes(), threads, steps, seconds,
                    double(mesh.numTets()) * steps / seconds, 100.0 * cracked / double(mesh.numTets()),
                    bytesPerElement);
                std::fflush(stdout);
            }
        }
}
