// Throughput of the Voronoi mesher: seeding + tessellation (with bonds) of a
// block of 1e4 and 1e5 cells, with 1 and 2 OpenMP threads, best of a few
// runs. The pruning distance is 0.6 of the mean seed spacing, the ratio of the
// paper's 300-cell BDT disc (2.5 mm against a spacing of 4.2 mm).
//
// Usage: benchVoronoi [repeats]   (default 3)
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "voronoi/seeding.hpp"
#include "voronoi/tessellation.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Timing {
    double seeding = 1e300, tessellation = 1e300;
};

Timing timeBlock(int nCells, int repeats)
{
    // A 10 cm x 10 cm x 5 cm block.
    const rockfrac::Domain block = rockfrac::Domain::box({0, 0, 0}, {0.1, 0.1, 0.05});
    const double pruningDistance = 0.6 * std::cbrt(block.volume() / nCells);
    Timing best;
    for (int r = 0; r < repeats; ++r) {
        const auto start = Clock::now();
        const std::vector<rockfrac::Vec3> seeds = rockfrac::placeSeeds(block, nCells, pruningDistance, 1 + r);
        best.seeding = std::min(best.seeding, secondsSince(start));
        const auto middle = Clock::now();
        const rockfrac::VoronoiMesh mesh = rockfrac::tessellate(block, seeds);
        best.tessellation = std::min(best.tessellation, secondsSince(middle));
        if (mesh.nCells() != nCells) std::abort();
    }
    return best;
}

}  // namespace

int main(int argc, char** argv)
{
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    std::printf("%8s %8s %12s %14s %14s\n", "cells", "threads", "seeding[s]", "tessellate[s]", "cells/s");
    for (int nCells : {10000, 100000})
        for (int threads : {1, 2}) {
            omp_set_num_threads(threads);
            const Timing t = timeBlock(nCells, repeats);
            std::printf("%8d %8d %12.3f %14.3f %14.0f\n", nCells, threads, t.seeding, t.tessellation,
                        nCells / (t.seeding + t.tessellation));
        }
    return 0;
}
