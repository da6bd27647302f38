// The cells' PSD of a crusher run (libs/crusher/feedCells): each template cell measured as a
// one-cell fragment, and every rock fed its class's template cells scaled to its size. On box
// cells whose sieve size (the intermediate principal extent) and mass are known exactly.
#include <catch2/catch.hpp>
#include <stdexcept>

#include "crusher/feedCells.hpp"
#include "voronoi/tessellation.hpp"

using namespace rockfrac;
using Catch::Matchers::Contains;

namespace {

constexpr double density = 2650.0;

// A 30 x 20 x 12 mm block cut into two 15 x 20 x 12 mm boxes (seeds mirrored about x = 15 mm):
// the rock's sieve size 20 mm, each cell's 15 mm.
FeedRockTemplate twoBoxes()
{
    const VoronoiMesh mesh = tessellate(Domain::box({0.0, 0.0, 0.0}, {0.030, 0.020, 0.012}),
                                        {{0.0075, 0.01, 0.006}, {0.0225, 0.01, 0.006}});
    return makeFeedRockTemplate(mesh, density);
}

// The same block in 2 x 2 x 1 boxes of 15 x 10 x 12 mm: each cell's sieve size 12 mm.
FeedRockTemplate fourBoxes()
{
    std::vector<Vec3> seeds;
    for (double x : {0.0075, 0.0225})
        for (double y : {0.005, 0.015}) seeds.push_back({x, y, 0.006});
    return makeFeedRockTemplate(tessellate(Domain::box({0.0, 0.0, 0.0}, {0.030, 0.020, 0.012}), seeds),
                                density);
}

}  // namespace

TEST_CASE("a template's cells measured as one-cell fragments", "[crusher][feedCells]")
{
    const FeedRockTemplate two = twoBoxes(), four = fourBoxes();
    REQUIRE(two.sieve_size == Approx(0.020).epsilon(1e-9));
    const CellSizes a = templateCellSizes(two, density), b = templateCellSizes(four, density);
    REQUIRE(a.mass.size() == 2);
    REQUIRE(b.mass.size() == 4);
    for (std::size_t c = 0; c < 2; ++c) {
        CHECK(a.sieve_size[c] == Approx(0.015).epsilon(1e-9));
        CHECK(a.mass[c] == Approx(density * 0.015 * 0.020 * 0.012).epsilon(1e-9));
    }
    for (std::size_t c = 0; c < 4; ++c) {
        CHECK(b.sieve_size[c] == Approx(0.012).epsilon(1e-9));
        CHECK(b.mass[c] == Approx(density * 0.015 * 0.010 * 0.012).epsilon(1e-9));
    }
}

TEST_CASE("every rock fed contributes its class's template cells scaled to its size", "[crusher][feedCells]")
{
    const std::vector<FeedRockTemplate> templates = {twoBoxes(), fourBoxes()};
    const std::vector<CellSizes> perClass = {templateCellSizes(templates[0], density),
                                             templateCellSizes(templates[1], density)};
    // Rock 0: class 0 at 40 mm (s = 2); rock 1: class 1 at 30 mm (s = 1.5); rock 2: class 0 at
    // 20 mm (s = 1).
    std::vector<FedRock> rocks(3);
    rocks[0] = {0, 0, 2, 0.040, {}};
    rocks[1] = {1, 1, 4, 0.030, {}};
    rocks[2] = {2, 0, 2, 0.020, {}};
    const CellSizes all = fedCellSizes(rocks, templates, perClass);
    REQUIRE(all.mass.size() == 8);
    const double expectedSieve[8] = {0.030, 0.030, 0.018, 0.018, 0.018, 0.018, 0.015, 0.015};
    const double box2 = density * 0.015 * 0.020 * 0.012, box4 = density * 0.015 * 0.010 * 0.012;
    const double expectedMass[8] = {8 * box2,     8 * box2,     3.375 * box4, 3.375 * box4,
                                    3.375 * box4, 3.375 * box4, box2,         box2};
    double total = 0.0;
    for (int c = 0; c < 8; ++c) {
        INFO("cell " << c);
        CHECK(all.sieve_size[c] == Approx(expectedSieve[c]).epsilon(1e-9));
        CHECK(all.mass[c] == Approx(expectedMass[c]).epsilon(1e-9));
        total += all.mass[c];
    }
    // The cells hold the rocks' mass: each rock is its template scaled, s^3 its volume.
    CHECK(total == Approx(density * 0.030 * 0.020 * 0.012 * (8 + 3.375 + 1)).epsilon(1e-9));

    SECTION("a rock that does not fit its class is refused")
    {
        std::vector<FedRock> bad = rocks;
        bad[1].feed_class = 2;
        CHECK_THROWS_WITH(fedCellSizes(bad, templates, perClass),
                          Contains("rock 1") && Contains("no template"));
        bad = rocks;
        bad[2].n_cells = 4;
        CHECK_THROWS_WITH(fedCellSizes(bad, templates, perClass),
                          Contains("rock 2 has 4 cells, its template 2"));
    }
}
