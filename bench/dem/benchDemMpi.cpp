// benchDemMpi: the intact bonded block of benchDem decomposed over MPI ranks (docs/benchmarks.md).
//
//   mpirun -np N benchDemMpi -block <cells> [steps]
//
// Every rank builds the block (benchBlock.hpp), decomposes it as bondedDemFoam -parallel does
// (rcb, cost weights, parallel/mpi/demExchange.hpp) and steps it with OMP_NUM_THREADS threads;
// the wall time of `steps` steps is the best of 3, between barriers. Prints one line: cells,
// ranks, threads per rank, cell-steps/s of the whole model, ghost cells, bytes sent per cell-step (ghost
// states and item results), and the share of the wall time the slowest and the mean rank spent in the
// exchange's calls (messages, collectives and the waiting in them). Not a test.
#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

#include "benchBlock.hpp"
#include "parallel/decomposition.hpp"
#include "parallel/mpi/demExchange.hpp"
#include "parallel/mpi/haloExchange.hpp"

using namespace rockfrac;

int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    const int me = mpi::rank(MPI_COMM_WORLD), ranks = mpi::size(MPI_COMM_WORLD);
    if (argc < 3 || std::strcmp(argv[1], "-block") != 0) {
        if (me == 0) std::fprintf(stderr, "usage: mpirun -np N benchDemMpi -block <cells> [steps]\n");
        MPI_Finalize();
        return 1;
    }
    const int n_cells = std::stoi(argv[2]);
    const int steps = argc > 3 ? std::stoi(argv[3]) : 20;
    const VoronoiMesh mesh = benchBlockMesh(n_cells, CellOrder::morton);
    DemModel model(mesh, benchBlockParameters());
    setBenchBlockVelocities(model);
    const double dt = 0.5 * model.criticalTimeStep().value;
    DecomposeParameters decomposition;
    decomposition.n_subdomains = ranks;
    decomposition.method = decompositionMethods().make("rcb", Dictionary("rcb", "benchDemMpi"));
    const auto exchange = mpi::decomposeDemModel(model, decomposition, MPI_COMM_WORLD);
    for (int s = 0; s < 5; ++s) model.step(dt);  // lists, caches, threads
    double best = 1e300, exchange_best = 0.0;
    for (int r = 0; r < 3; ++r) {
        MPI_Barrier(MPI_COMM_WORLD);
        const double in_exchange = exchange->exchangeSeconds();
        const double start = MPI_Wtime();
        for (int s = 0; s < steps; ++s) model.step(dt);
        MPI_Barrier(MPI_COMM_WORLD);
        const double seconds = MPI_Wtime() - start;
        if (seconds < best) {
            best = seconds;
            exchange_best = exchange->exchangeSeconds() - in_exchange;
        }
    }
    double slowest = best, share_max = exchange_best / best, share_sum = share_max;
    MPI_Allreduce(MPI_IN_PLACE, &slowest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &share_max, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &share_sum, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    long ghosts = exchange->ghostCells(), bytes = static_cast<long>(exchange->bytesPerStep());
    MPI_Allreduce(MPI_IN_PLACE, &ghosts, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &bytes, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    if (me == 0) {
        std::printf("%-10s %8s %5s %7s %7s %10s %12s %8s %10s %9s %9s\n", "case", "cells", "ranks", "threads",
                    "steps", "wall [s]", "cell-steps/s", "ghosts", "B/cell-st", "exch.max", "exch.mean");
        std::printf("%-10s %8d %5d %7d %7d %10.3f %12.4g %8ld %10.3g %9.3f %9.3f\n", "mpi block",
                    mesh.nCells(), ranks, omp_get_max_threads(), steps, slowest,
                    static_cast<double>(mesh.nCells()) * steps / slowest, ghosts,
                    static_cast<double>(bytes) / mesh.nCells(), share_max, share_sum / ranks);
    }
    MPI_Finalize();
    return 0;
}
