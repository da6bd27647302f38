// Domains (volume, bounds, containment) and seeding (exact counts, pruning
// distance, reproducibility, Table 7 of the paper, impossible requests).
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "voronoi/domain.hpp"
#include "voronoi/seeding.hpp"
#include "voronoiTestSupport.hpp"

using namespace rockfrac;
using rockfrac::test::bdtDisc;

namespace {
constexpr double pi = 3.14159265358979323846;
}

TEST_CASE("a box domain has its exact volume and bounds", "[voronoi][domain]")
{
    const Domain box = Domain::box({-1, 2, 3}, {1, 2.5, 7});
    CHECK(box.volume() == Approx(2.0 * 0.5 * 4.0).epsilon(1e-14));
    CHECK(box.boundingBox().lower.x == Approx(-1));
    CHECK(box.boundingBox().upper.z == Approx(7));
    CHECK(box.contains({0, 2.2, 5}));
    CHECK_FALSE(box.contains({0, 2.6, 5}));
}

TEST_CASE("a plane domain's volume matches a known polytope", "[voronoi][domain]")
{
    // The octahedron |x| + |y| + |z| <= 1 has volume 4/3; move it away from the origin.
    const Vec3 centre{10, -3, 2};
    std::vector<HalfSpace> planes;
    for (int octant = 0; octant < 8; ++octant) {
        const Vec3 n{octant & 1 ? 1.0 : -1.0, octant & 2 ? 1.0 : -1.0, octant & 4 ? 1.0 : -1.0};
        planes.push_back({n, 1.0 + dot(n, centre)});  // normal not unit: normalised by fromPlanes
    }
    const Domain octahedron = Domain::fromPlanes(planes);
    CHECK(octahedron.volume() == Approx(4.0 / 3.0).epsilon(1e-12));
    CHECK(octahedron.boundingBox().lower.x == Approx(9.0).epsilon(1e-12));
    CHECK(octahedron.boundingBox().upper.y == Approx(-2.0).epsilon(1e-12));
}

TEST_CASE("plane domains that enclose nothing or are unbounded are refused", "[voronoi][domain]")
{
    // Half of a box: unbounded.
    CHECK_THROWS_AS(Domain::fromPlanes({{{1, 0, 0}, 1}, {{0, 1, 0}, 1}, {{0, 0, 1}, 1}, {{-1, 0, 0}, 1}}),
                    UserError);
    // Contradictory planes: empty.
    CHECK_THROWS_AS(Domain::fromPlanes({{{1, 0, 0}, -1},
                                        {{-1, 0, 0}, -1},
                                        {{0, 1, 0}, 1},
                                        {{0, -1, 0}, 1},
                                        {{0, 0, 1}, 1},
                                        {{0, 0, -1}, 1}}),
                    UserError);
    CHECK_THROWS_AS(Domain::fromPlanes({{{0, 0, 0}, 1}, {{1, 0, 0}, 1}, {{0, 1, 0}, 1}, {{0, 0, 1}, 1}}),
                    UserError);
}

TEST_CASE("a disc domain is pi r^2 t with the right bounds", "[voronoi][domain]")
{
    const Domain disc = bdtDisc();
    CHECK(disc.volume() == Approx(pi * 22.4e-3 * 22.4e-3 * 13.8e-3).epsilon(1e-14));
    CHECK(disc.boundingBox().upper.x == Approx(22.4e-3));
    CHECK(disc.boundingBox().upper.z == Approx(6.9e-3));
    CHECK(disc.contains({22.0e-3, 0, 6.8e-3}));
    CHECK_FALSE(disc.contains({16.0e-3, 16.0e-3, 0}));  // outside the circle, inside the box
    CHECK_FALSE(disc.contains({0, 0, 7.0e-3}));

    const Domain tilted = Domain::disc({1, 1, 1}, {1, 1, 0}, 2.0, 0.5);
    CHECK(tilted.contains({1, 1, 1.99}));
    CHECK(tilted.contains(Vec3{1, 1, 1} + 0.24 * normalised(Vec3{1, 1, 0})));
    CHECK_FALSE(tilted.contains(Vec3{1, 1, 1} + 0.26 * normalised(Vec3{1, 1, 0})));
    CHECK_THROWS_AS(Domain::disc({0, 0, 0}, {0, 0, 1}, -1.0, 1.0), UserError);
}

TEST_CASE("seeding gives exactly the count, pd apart, inside, reproducibly", "[voronoi][seeding]")
{
    const Domain disc = bdtDisc();
    const std::vector<Vec3> seeds = placeSeeds(disc, 300, 2.5e-3, 42);
    REQUIRE(seeds.size() == 300);
    CHECK(test::minimumSeedDistance(seeds) >= 2.5e-3);
    for (const Vec3& p : seeds) CHECK(disc.contains(p));

    const std::vector<Vec3> again = placeSeeds(disc, 300, 2.5e-3, 42);
    CHECK(again == seeds);
    CHECK(placeSeeds(disc, 300, 2.5e-3, 43) != seeds);
}

TEST_CASE("seeding is pinned to the generator, not the standard library", "[voronoi][seeding]")
{
    // Values of the reference C code of xoshiro256** seeded by SplitMix64(1),
    // top 53 bits / 2^53: a change here changes every mesh made from a seed.
    const std::vector<Vec3> seeds = placeSeeds(Domain::box({0, 0, 0}, {1, 1, 1}), 2, 0.0, 1);
    CHECK(seeds[0].x == 0.70292183315885048);
    CHECK(seeds[1].z == 0.14357203674443619);
}

TEST_CASE("every BDT row of Table 7 is seeded with exactly the requested count", "[voronoi][seeding]")
{
    struct Row {
        int nCells;
        double pruningDistance;
    };
    const Row rows[] = {{50, 3.5e-3},  {100, 3.0e-3}, {150, 3.0e-3}, {200, 2.5e-3}, {250, 2.5e-3},
                        {300, 2.5e-3}, {350, 2.5e-3}, {400, 2.0e-3}, {450, 2.0e-3}, {500, 2.0e-3}};
    const Domain disc = bdtDisc();
    for (const Row& row : rows)
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            INFO("nCells " << row.nCells << " pd " << row.pruningDistance << " seed " << seed);
            const std::vector<Vec3> seeds = placeSeeds(disc, row.nCells, row.pruningDistance, seed);
            CHECK(static_cast<int>(seeds.size()) == row.nCells);
            CHECK(test::minimumSeedDistance(seeds) >= row.pruningDistance);
        }
}

TEST_CASE("a rock keeps the meso constant at pd 3.5 mm", "[voronoi][seeding]")
{
    const double rockVolume = 82.7e-6;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const Domain rock = test::rockOfVolume(rockVolume, 100 + seed);
        REQUIRE(rock.volume() == Approx(rockVolume).epsilon(1e-12));
        const int nCells = cellCountFromMesoConstant(rock.volume(), 2.2e-7);
        CHECK(nCells == 376);
        const std::vector<Vec3> seeds = placeSeeds(rock, nCells, 3.5e-3, seed);
        CHECK(static_cast<int>(seeds.size()) == nCells);
        CHECK(test::minimumSeedDistance(seeds) >= 3.5e-3);
    }
    CHECK_THROWS_AS(cellCountFromMesoConstant(1e-4, 0.0), UserError);
}

TEST_CASE("impossible seeding requests are refused quickly with advice", "[voronoi][seeding]")
{
    const Domain disc = bdtDisc();
    CHECK_THROWS_AS(placeSeeds(disc, 1, 2.5e-3, 1), UserError);
    CHECK_THROWS_AS(placeSeeds(disc, 0, 2.5e-3, 1), UserError);
    CHECK_THROWS_AS(placeSeeds(disc, 100, -1.0, 1), UserError);

    const auto start = std::chrono::steady_clock::now();
    std::string message;
    try {
        placeSeeds(disc, 5000, 3.5e-3, 1);
    } catch (const UserError& e) {
        message = e.what();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO(message);
    CHECK(seconds < 3.0);
    // The estimate of what fits: random packing of 3.5 mm spheres in 21.8 cm^3
    // saturates at a few hundred seeds.
    REQUIRE(message.find("at most about ") != std::string::npos);
    const int largest = std::stoi(message.substr(message.find("at most about ") + 14));
    CHECK(largest > 300);
    CHECK(largest < 1000);
    CHECK(message.find("pruning distance") != std::string::npos);
}
