// The MPI halo exchange (parallel/mpi/haloExchange.hpp), run under mpirun with 1, 2 and 4
// ranks (ctest parallel.mpi.np1/np2/np4): every rank receives exactly its own cells and
// exactly the ghosts the serial rule gives (haloReport, parallel/decomposition.hpp), each
// byte for byte the cell it stands for, in global id order.
#define CATCH_CONFIG_RUNNER
#include <mpi.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <cstring>
#include <vector>

#include "boxMeshes.hpp"
#include "dem/demModel.hpp"
#include "parallel/decomposition.hpp"
#include "parallel/mpi/haloExchange.hpp"
#include "parallel/rcb.hpp"

using namespace rockfrac;

namespace {

// Cell i of `from` equals cell j of `to` in every migrated array (CSR children included).
bool sameCell(const CellArrays& from, int i, const CellArrays& to, int j)
{
    std::vector<unsigned char> a, b;
    packEntity(from, i, a);
    packEntity(to, j, b);
    return a == b;
}

DemModel block()
{
    DemParameters p;
    p.gravity = {0.0, 0.0, 0.0};
    return DemModel(test::boxBlockMesh(8, 6, 5, {1e-3, 1.2e-3, 0.9e-3}, 1e-4), p);
}

}  // namespace

TEST_CASE("cells and their ghosts reach the ranks that need them, byte for byte", "[mpi]")
{
    const MPI_Comm comm = MPI_COMM_WORLD;
    const int me = mpi::rank(comm), n_ranks = mpi::size(comm);
    const DemModel model = block();
    const CellArrays& cells = model.cells();
    const int n = cells.size();
    std::vector<Vec3> centroids(n);
    std::vector<double> reach(n), weights(n, 1.0);
    for (int i = 0; i < n; ++i) {
        centroids[i] = cells.position[i];
        reach[i] = cells.bounding_radius[i];
    }
    const std::vector<int> part_of = rcbDecompose(centroids, weights, n_ranks).part_of;
    const double margin = 0.2e-3;

    CellArrays mine;
    std::vector<std::int64_t> ids;
    mpi::scatterEntities(cells, part_of, mine, ids, comm);
    std::vector<std::int64_t> expected_own;
    for (int i = 0; i < n; ++i)
        if (part_of[i] == me) expected_own.push_back(i);
    REQUIRE(ids == expected_own);
    REQUIRE(mine.size() == static_cast<int>(ids.size()));
    for (int k = 0; k < mine.size(); ++k) CHECK(sameCell(cells, static_cast<int>(ids[k]), mine, k));

    std::vector<Vec3> my_centroids(mine.size());
    std::vector<double> my_reach(mine.size());
    for (int k = 0; k < mine.size(); ++k) {
        my_centroids[k] = mine.position[k];
        my_reach[k] = mine.bounding_radius[k];
    }
    CellArrays ghosts;
    const mpi::GhostLayer layer =
        mpi::exchangeGhosts(mine, ids, my_centroids, my_reach, margin, ghosts, comm);

    // The serial rule, by brute force over all pairs.
    std::vector<std::int64_t> expected_ghosts;
    for (int j = 0; j < n; ++j) {
        if (part_of[j] == me) continue;
        for (int i = 0; i < n; ++i) {
            if (part_of[i] != me) continue;
            const Vec3 d = centroids[j] - centroids[i];
            const double range = reach[i] + reach[j] + margin;
            if (dot(d, d) <= range * range) {
                expected_ghosts.push_back(j);
                break;
            }
        }
    }
    CHECK(layer.ids == expected_ghosts);
    REQUIRE(ghosts.size() == static_cast<int>(layer.ids.size()));
    for (std::size_t k = 0; k < layer.ids.size(); ++k) {
        CHECK(layer.owner[k] == part_of[layer.ids[k]]);
        CHECK(sameCell(cells, static_cast<int>(layer.ids[k]), ghosts, static_cast<int>(k)));
    }
    std::printf("rank %d of %d: %d cells, %zu ghosts, %llu bytes received\n", me, n_ranks, mine.size(),
                layer.ids.size(), static_cast<unsigned long long>(layer.bytes_received));
    if (n_ranks == 1) CHECK(layer.ids.empty());
    if (n_ranks > 1) CHECK(!layer.ids.empty());  // the block is cut: every part has neighbours

    // Summed over the ranks: haloReport's count (what decomposeCells reports).
    long local = static_cast<long>(layer.ids.size()), total = 0;
    MPI_Allreduce(&local, &total, 1, MPI_LONG, MPI_SUM, comm);
    const HaloReport report = haloReport(centroids, reach, weights, {}, part_of, n_ranks, margin);
    CHECK(total == report.ghost_cells);
}

TEST_CASE("exchangeBytes delivers each rank's buffer to its addressee", "[mpi]")
{
    const MPI_Comm comm = MPI_COMM_WORLD;
    const int me = mpi::rank(comm), n_ranks = mpi::size(comm);
    std::vector<std::vector<unsigned char>> to(n_ranks);
    for (int q = 0; q < n_ranks; ++q)  // rank me sends q a buffer of me + 2q bytes, each me * 7 + q
        to[q].assign(static_cast<std::size_t>(me + 2 * q), static_cast<unsigned char>(me * 7 + q));
    const auto from = mpi::exchangeBytes(to, comm);
    REQUIRE(static_cast<int>(from.size()) == n_ranks);
    for (int q = 0; q < n_ranks; ++q)
        CHECK(from[q] == std::vector<unsigned char>(static_cast<std::size_t>(q + 2 * me),
                                                    static_cast<unsigned char>(q * 7 + me)));
}

int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    const int result = Catch::Session().run(argc, argv);
    int worst = 0;
    MPI_Allreduce(&result, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    MPI_Finalize();
    return worst;
}
