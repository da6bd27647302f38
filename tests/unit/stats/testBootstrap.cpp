// Bootstrap percentile intervals: coverage and reproducibility.
#include <catch2/catch.hpp>

#include "stats/bootstrap.hpp"
#include "statsTestSupport.hpp"

using namespace rockfrac::stats;

TEST_CASE("bootstrap interval of the mean covers the true mean of a normal sample", "[stats]")
{
    // One fixed sample (its mean is 10.16, 0.6 standard errors from the truth) ...
    const Sample sample = testing::normalSample(60, 10.0, 2.0, 1);
    const BootstrapInterval interval = bootstrapPercentile(sample, mean, 0.95, 4000, 17);
    CHECK(interval.bounds.contains(10.0));
    CHECK(interval.bounds.contains(interval.estimate));
    // Width close to the normal theory 2·1.96·σ/√n ≈ 1.01.
    const double width = interval.bounds.upper - interval.bounds.lower;
    CHECK(width > 0.7);
    CHECK(width < 1.3);
}

TEST_CASE("bootstrap 95 % intervals of the mean cover the true mean about 95 % of the time", "[stats]")
{
    // ... and the coverage over 200 samples of 40: the percentile interval is
    // a little short for small n, so expect 0.88 to 0.99.
    int covered = 0;
    for (std::uint64_t s = 1; s <= 200; ++s) {
        const Sample sample = testing::normalSample(40, 10.0, 2.0, 1000 + s);
        covered += bootstrapPercentile(sample, mean, 0.95, 1000, s).bounds.contains(10.0);
    }
    CHECK(covered >= 176);
    CHECK(covered <= 198);
}

TEST_CASE("bootstrap is reproducible from its seed and works for any statistic", "[stats]")
{
    const Sample sample = testing::graniteBdtLoads();
    const auto a = bootstrapPercentile(sample, median, 0.90, 1000, 3);
    const auto b = bootstrapPercentile(sample, median, 0.90, 1000, 3);
    const auto c = bootstrapPercentile(sample, median, 0.90, 1000, 4);
    CHECK(a.bounds.lower == b.bounds.lower);
    CHECK(a.bounds.upper == b.bounds.upper);
    CHECK((a.bounds.lower != c.bounds.lower || a.bounds.upper != c.bounds.upper));
    const auto modulus = bootstrapPercentile(
        sample, [](const Sample& s) { return minimum(s) < maximum(s) ? fitWeibull(s).modulus : 1e3; }, 0.90,
        200, 5);
    CHECK(modulus.bounds.contains(modulus.estimate));
}
