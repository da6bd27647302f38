// Tessellation invariants: volumes add up to the domain, cells are closed
// convex polyhedra sharing faces pairwise, bonds are one per face vertex, and
// the mesh depends on nothing but its inputs (seed, thread count).
#include <omp.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <tuple>

#include "core/error.hpp"
#include "voronoi/polyhedron.hpp"
#include "voronoi/seeding.hpp"
#include "voronoi/tessellation.hpp"
#include "voronoiTestSupport.hpp"

using namespace rockfrac;

namespace {

constexpr double tessellationPi = 3.14159265358979323846;

void checkInvariants(const VoronoiMesh& mesh)
{
    const double length = meanCellSize(mesh);
    CHECK(test::checkSharedFaces(mesh, length) == "");
    CHECK(test::checkClosedConvexCells(mesh, length) == "");
    CHECK(test::checkBonds(mesh) == "");
}

// Restores the OpenMP thread count when a test ends.
struct ThreadCount {
    explicit ThreadCount(int n) : saved(omp_get_max_threads()) { omp_set_num_threads(n); }
    ~ThreadCount() { omp_set_num_threads(saved); }
    int saved;
};

}  // namespace

TEST_CASE("cell volumes of a box and of rock hulls add up to the domain volume", "[voronoi][tessellation]")
{
    const Domain box = Domain::box({0.01, -0.02, 0.0}, {0.05, 0.03, 0.02});
    const Domain rock = test::randomConvexRock(20, 7, 0.03, {0.1, 0.2, -0.05});
    const Domain smallRock = test::rockOfVolume(82.7e-6, 101);
    for (const Domain* domain : {&box, &rock, &smallRock}) {
        const VoronoiMesh mesh = generateVoronoiMesh(*domain, 400, 0.0, 5);
        CHECK(std::fabs(test::sumOfVolumes(mesh) / domain->volume() - 1.0) < 1e-9);
        CHECK(mesh.domainVolume == domain->volume());
        checkInvariants(mesh);
        CHECK(test::checkBoundaryFacesOnPlanes(mesh, *domain, meanCellSize(mesh)) == "");
    }
}

TEST_CASE("the 300-cell BDT disc keeps pi r^2 t within 0.5 %", "[voronoi][tessellation]")
{
    const Domain disc = test::bdtDisc();
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const VoronoiMesh mesh = generateVoronoiMesh(disc, 300, 2.5e-3, seed);
        const double exact = tessellationPi * 22.4e-3 * 22.4e-3 * 13.8e-3;
        CHECK(std::fabs(test::sumOfVolumes(mesh) / exact - 1.0) < 0.005);
        checkInvariants(mesh);
        // Mean volume-equivalent diameter: the paper quotes 5.5 mm.
        CHECK(meanCellSize(mesh) == Approx(5.1e-3).epsilon(0.03));
        CHECK(mesh.dilationRadius == Approx(0.1 * meanCellSize(mesh)));
        CHECK(mesh.seed == seed);
        CHECK(mesh.pruningDistance == 2.5e-3);
    }
}

TEST_CASE("cells carry correct volume, centroid and inertia", "[voronoi][tessellation]")
{
    // Two seeds in a 2 x 1 x 1 box split it into two unit cubes.
    const Domain box = Domain::box({0, 0, 0}, {2, 1, 1});
    const VoronoiMesh mesh = tessellate(box, {{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}});
    REQUIRE(mesh.nCells() == 2);
    CHECK(mesh.volumes[0] == Approx(1.0).epsilon(1e-14));
    CHECK(mesh.centroids[1].x == Approx(1.5).epsilon(1e-14));
    // Unit cube: J = (1/6) I about its centre, no products of inertia.
    CHECK(mesh.inertia[0].m[0][0] == Approx(1.0 / 6.0).epsilon(1e-13));
    CHECK(mesh.inertia[1].m[2][2] == Approx(1.0 / 6.0).epsilon(1e-13));
    CHECK(std::fabs(mesh.inertia[0].m[0][1]) < 1e-14);
    // One shared square face: four bonds of area 1/4, l = 1/2 on each side.
    REQUIRE(mesh.nBonds() == 4);
    CHECK(mesh.bonds[0].area == Approx(0.25).epsilon(1e-14));
    CHECK(mesh.bonds[0].normalI.x == Approx(1.0).epsilon(1e-14));
    CHECK(mesh.bonds[0].lI == Approx(0.5).epsilon(1e-14));
    CHECK(mesh.bonds[0].lJ == Approx(0.5).epsilon(1e-14));
    CHECK(mesh.bonds[0].point.x == Approx(1.0).epsilon(1e-14));
}

TEST_CASE("inertia tensors of irregular cells are physical", "[voronoi][tessellation]")
{
    // Symmetric, positive diagonal, and J_xx + J_yy >= J_zz (true of any body).
    const Domain rock = test::randomConvexRock(20, 3);
    const VoronoiMesh mesh = generateVoronoiMesh(rock, 30, 0.0, 9);
    const double total = test::sumOfVolumes(mesh);
    for (int c = 0; c < mesh.nCells(); ++c) {
        const Mat3& J = mesh.inertia[c];
        CHECK(J.m[0][1] == Approx(J.m[1][0]).margin(1e-15));      // symmetric
        CHECK(J.m[0][0] + J.m[1][1] >= J.m[2][2] * (1 - 1e-12));  // triangle inequality of principal moments
        CHECK(J.m[0][0] > 0);
    }
    CHECK(total == Approx(rock.volume()).epsilon(1e-9));
}

TEST_CASE("the mesh is reproducible from its seed and independent of threads", "[voronoi][tessellation]")
{
    const Domain disc = test::bdtDisc();
    const VoronoiMesh first = generateVoronoiMesh(disc, 300, 2.5e-3, 11);
    CHECK(test::identical(first, generateVoronoiMesh(disc, 300, 2.5e-3, 11)));
    CHECK_FALSE(test::identical(first, generateVoronoiMesh(disc, 300, 2.5e-3, 12)));

    const Domain block = Domain::box({0, 0, 0}, {1, 1, 1});
    VoronoiMesh oneThread, twoThreads;
    {
        ThreadCount threads(1);
        oneThread = generateVoronoiMesh(block, 3000, 0.02, 3);
    }
    {
        ThreadCount threads(2);
        twoThreads = generateVoronoiMesh(block, 3000, 0.02, 3);
    }
    CHECK(test::identical(oneThread, twoThreads));
    checkInvariants(twoThreads);
    CHECK(test::checkBoundaryFacesOnPlanes(twoThreads, block, meanCellSize(twoThreads)) == "");
}

TEST_CASE("seeds outside the domain are refused", "[voronoi][tessellation]")
{
    const Domain box = Domain::box({0, 0, 0}, {1, 1, 1});
    CHECK_THROWS_AS(tessellate(box, {{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}}), UserError);
    CHECK_THROWS_AS(tessellate(box, {}), UserError);
}

TEST_CASE("cellOrder morton: the same cells renumbered, neighbours close in index", "[voronoi][order]")
{
    const Domain box = Domain::box({0, 0, 0}, {0.04, 0.02, 0.02});
    const VoronoiMesh seeding = generateVoronoiMesh(box, 2000, 5e-4, 11);
    const VoronoiMesh morton = generateVoronoiMesh(box, 2000, 5e-4, 11, 0.1, CellOrder::morton);
    REQUIRE(morton.nCells() == seeding.nCells());
    REQUIRE(morton.nBonds() == seeding.nBonds());
    checkInvariants(morton);
    // A permutation of the same seeds (hence the same cells).
    auto sorted = [](std::vector<Vec3> v) {
        std::sort(v.begin(), v.end(), [](const Vec3& a, const Vec3& b) {
            return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
        });
        return v;
    };
    const std::vector<Vec3> a = sorted(seeding.seeds), b = sorted(morton.seeds);
    for (std::size_t i = 0; i < a.size(); ++i) REQUIRE(a[i] == b[i]);
    // What the ordering is for: bonded neighbours close in memory.
    auto meanIndexGap = [](const VoronoiMesh& m) {
        double sum = 0.0;
        for (const VoronoiBond& bond : m.bonds) sum += std::abs(bond.cellJ - bond.cellI);
        return sum / m.nBonds();
    };
    INFO("mean |i - j| over bonds: seeding " << meanIndexGap(seeding) << ", morton " << meanIndexGap(morton));
    CHECK(meanIndexGap(morton) < 0.25 * meanIndexGap(seeding));
}

namespace {

// A convex polytope close to a sphere of radius r: the tangent planes at n points spread
// evenly over it (a Fibonacci sphere), the hull of a dense scan in kind.
Domain tangentSphere(int n, double r)
{
    std::vector<HalfSpace> planes;
    const double golden = tessellationPi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / n, rho = std::sqrt(1.0 - z * z);
        planes.push_back({{rho * std::cos(golden * i), rho * std::sin(golden * i), z}, r});
    }
    return Domain::fromPlanes(planes);
}

}  // namespace

TEST_CASE("a domain of more planes than Voro++ takes as walls: each cell clipped by them",
          "[voronoi][tessellation]")
{
    // 3 000 planes (Voro++'s limit is 2 048 walls): the cells fill the polytope and keep every
    // invariant; their boundary faces lie on its planes.
    const Domain many = tangentSphere(3000, 0.02);
    const VoronoiMesh mesh = generateVoronoiMesh(many, 300, 0.0, 11);
    CHECK(std::fabs(test::sumOfVolumes(mesh) / many.volume() - 1.0) < 1e-9);
    checkInvariants(mesh);
    CHECK(test::checkBoundaryFacesOnPlanes(mesh, many, meanCellSize(mesh)) == "");

    // The clipped cells are the walled cells: 400 planes both ways, cell by cell.
    const Domain some = tangentSphere(400, 0.02);
    const std::vector<Vec3> seeds = placeSeeds(some, 200, 0.0, 3);
    const VoronoiMesh walled = tessellate(some, seeds, 0.1, 1000);
    const VoronoiMesh clipped = tessellate(some, seeds, 0.1, 100);
    REQUIRE(walled.nCells() == clipped.nCells());
    double worst = 0.0;
    for (int c = 0; c < walled.nCells(); ++c) {
        worst = std::max(worst, std::fabs(clipped.volumes[c] / walled.volumes[c] - 1.0));
        CHECK(clipped.cellFaceOffset[c + 1] - clipped.cellFaceOffset[c] ==
              walled.cellFaceOffset[c + 1] - walled.cellFaceOffset[c]);
    }
    CHECK(worst < 1e-10);
    CHECK(clipped.nBonds() == walled.nBonds());
}
