// Full factorial and Latin hypercube designs.
#include <catch2/catch.hpp>
#include <set>

#include "stats/design.hpp"

using namespace rockfrac::stats;

TEST_CASE("full factorial: every combination once, last factor fastest", "[stats]")
{
    const auto design = fullFactorial({2, 3});
    REQUIRE(design.size() == 6);
    CHECK(design[0] == std::vector<std::size_t>{0, 0});
    CHECK(design[1] == std::vector<std::size_t>{0, 1});
    CHECK(design[3] == std::vector<std::size_t>{1, 0});
    CHECK(design[5] == std::vector<std::size_t>{1, 2});
    CHECK(fullFactorial({}).size() == 1);  // no factors: one run
    CHECK(fullFactorial({3, 0}).empty());
}

TEST_CASE("Latin hypercube: one point per stratum in each dimension, reproducible", "[stats]")
{
    const std::size_t n = 20;
    const auto points = latinHypercube(n, 3, 3);
    REQUIRE(points.size() == n);
    for (std::size_t j = 0; j < 3; ++j) {
        std::set<std::size_t> strata;
        for (const auto& p : points) {
            REQUIRE(p[j] >= 0.0);
            REQUIRE(p[j] < 1.0);
            strata.insert(static_cast<std::size_t>(p[j] * n));
        }
        CHECK(strata.size() == n);
    }
    CHECK(latinHypercube(n, 3, 3) == points);
    CHECK(latinHypercube(n, 3, 4) != points);
}
