// Median ranks, empirical CDF and descriptive statistics against hand values.
#include <catch2/catch.hpp>

#include "stats/descriptive.hpp"
#include "stats/empiricalCdf.hpp"
#include "statsTestSupport.hpp"

using namespace rockfrac::stats;
using Catch::Matchers::WithinAbs;

TEST_CASE("Benard median ranks for n = 10 match hand values", "[stats]")
{
    // F_i = (i − 0.3) / 10.4
    const std::vector<double> expected = {0.7 / 10.4, 1.7 / 10.4, 2.7 / 10.4, 3.7 / 10.4, 4.7 / 10.4,
                                          5.7 / 10.4, 6.7 / 10.4, 7.7 / 10.4, 8.7 / 10.4, 9.7 / 10.4};
    const std::vector<double> ranks = medianRanks(10);
    REQUIRE(ranks.size() == 10);
    for (std::size_t i = 0; i < 10; ++i) CHECK_THAT(ranks[i], WithinAbs(expected[i], 1e-15));
    CHECK_THAT(ranks[0], WithinAbs(0.0673077, 1e-7));
    CHECK_THAT(ranks[9], WithinAbs(0.9326923, 1e-7));
}

TEST_CASE("median-rank CDF sorts the sample and pairs each value with its rank", "[stats]")
{
    const auto points = medianRankCdf({3.0, 1.0, 2.0});
    REQUIRE(points.size() == 3);
    CHECK(points[0].value == 1.0);
    CHECK(points[2].value == 3.0);
    CHECK_THAT(points[1].probability, WithinAbs(1.7 / 3.4, 1e-15));
}

TEST_CASE("empirical CDF is a right-continuous step function", "[stats]")
{
    const EmpiricalCdf cdf({2.0, 1.0, 2.0, 4.0});
    CHECK(cdf(0.5) == 0.0);
    CHECK(cdf(1.0) == 0.25);
    CHECK(cdf(1.999) == 0.25);
    CHECK(cdf(2.0) == 0.75);
    CHECK(cdf(4.0) == 1.0);
    CHECK(cdf(9.0) == 1.0);
}

TEST_CASE("mean, standard deviation and median of the granite BDT loads (Table 5)", "[stats]")
{
    const Sample loads = testing::graniteBdtLoads();
    CHECK_THAT(mean(loads), WithinAbs(13.19e3, 0.5));
    CHECK_THAT(standardDeviation(loads), WithinAbs(1.59e3, 5.0));  // the paper's 1.59 kN
    CHECK_THAT(median(loads), WithinAbs(12.95e3, 1e-9));           // (12.9 + 13.0) / 2
    CHECK(minimum(loads) == 10.9e3);
    CHECK(maximum(loads) == 15.8e3);
    CHECK_THAT(quantile({1.0, 2.0, 3.0, 4.0}, 0.25), WithinAbs(1.75, 1e-15));  // type 7
    CHECK(standardDeviation({5.0}) == 0.0);
}

TEST_CASE("standard normal quantile", "[stats]")
{
    CHECK_THAT(standardNormalQuantile(0.975), WithinAbs(1.959963985, 1e-8));
    CHECK_THAT(standardNormalQuantile(0.95), WithinAbs(1.644853627, 1e-8));
    CHECK_THAT(standardNormalQuantile(0.5), WithinAbs(0.0, 1e-12));
}
