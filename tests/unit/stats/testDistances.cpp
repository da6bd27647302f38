// Kolmogorov–Smirnov and Wasserstein-1 distances against hand-computed values.
#include <catch2/catch.hpp>

#include "stats/distances.hpp"
#include "statsTestSupport.hpp"

using namespace rockfrac::stats;
using Catch::Matchers::WithinAbs;

TEST_CASE("identical samples are at distance 0", "[stats]")
{
    const Sample a = testing::normalSample(50, 10.0, 2.0, 7);
    CHECK(kolmogorovSmirnov(a, a) == 0.0);
    CHECK(wasserstein1(a, a) == 0.0);
    Sample reordered(a.rbegin(), a.rend());
    CHECK(kolmogorovSmirnov(a, reordered) == 0.0);
    CHECK(wasserstein1(a, reordered) == 0.0);
}

TEST_CASE("KS and W1 of small samples by hand", "[stats]")
{
    // F_a steps 1/3 at 1, 2, 3; F_b at 2, 3, 4: the CDFs differ by 1/3 on [1, 4).
    CHECK_THAT(kolmogorovSmirnov({1, 2, 3}, {2, 3, 4}), WithinAbs(1.0 / 3.0, 1e-15));
    CHECK_THAT(wasserstein1({1, 2, 3}, {2, 3, 4}), WithinAbs(1.0, 1e-15));
    // A point mass at 0 against {1, 3}: KS 1 on [0, 1); W1 = 1·1 + 0.5·2 = 2.
    CHECK_THAT(kolmogorovSmirnov({0}, {1, 3}), WithinAbs(1.0, 1e-15));
    CHECK_THAT(wasserstein1({0}, {1, 3}), WithinAbs(2.0, 1e-15));
    // Ties: {1, 1, 2} against {1, 2, 2}: F differ by 1/3 on [1, 2).
    CHECK_THAT(kolmogorovSmirnov({1, 1, 2}, {1, 2, 2}), WithinAbs(1.0 / 3.0, 1e-15));
    CHECK_THAT(wasserstein1({1, 1, 2}, {1, 2, 2}), WithinAbs(1.0 / 3.0, 1e-15));
    // Samples of different sizes: {0, 1} against {0.5}: |F| diff 1/2 everywhere on [0, 1).
    CHECK_THAT(kolmogorovSmirnov({0, 1}, {0.5}), WithinAbs(0.5, 1e-15));
    CHECK_THAT(wasserstein1({0, 1}, {0.5}), WithinAbs(0.5, 1e-15));
}

TEST_CASE("W1 between a sample and its shifted copy is the shift", "[stats]")
{
    const Sample a = testing::weibullSample(200, 7.0, 13e3, 11);
    Sample shifted = a;
    for (double& x : shifted) x += 1234.5;
    CHECK_THAT(wasserstein1(a, shifted), WithinAbs(1234.5, 1e-6));
    CHECK_THAT(wasserstein1(shifted, a), WithinAbs(1234.5, 1e-6));
    CHECK(kolmogorovSmirnov(a, shifted) > 0.0);
}

TEST_CASE("one-sample KS against a continuous CDF", "[stats]")
{
    const CdfFunction uniform = [](double x) { return x < 0 ? 0.0 : (x > 1 ? 1.0 : x); };
    CHECK_THAT(kolmogorovSmirnov(Sample{0.5}, uniform), WithinAbs(0.5, 1e-15));
    CHECK_THAT(kolmogorovSmirnov(Sample{0.25, 0.75}, uniform), WithinAbs(0.25, 1e-15));
    CHECK_THAT(kolmogorovSmirnov(Sample{0.1, 0.2}, uniform), WithinAbs(0.8, 1e-15));
    // A large sample from the model is close to it (Dvoretzky–Kiefer–Wolfowitz: < 0.02 w.p. > 0.99).
    const Sample large = testing::weibullSample(20000, 7.0, 1.0, 5);
    CHECK(kolmogorovSmirnov(large, [](double x) { return weibullCdf(x, 7.0, 1.0); }) < 0.02);
}
