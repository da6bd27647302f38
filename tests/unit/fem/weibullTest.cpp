// DFH Weibull thresholds: mean, scatter, size effect, reproducibility.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/counterRandom.hpp"
#include "fem/weibullStrength.hpp"

using namespace rockfrac;
using namespace rockfrac::fem;

namespace {

struct Moments {
    double mean, squaredCoefficientOfVariation;
};

Moments sampleMoments(const WeibullStrength& w, double volume, int n)
{
    double sum = 0.0, sumSquares = 0.0;
    for (int i = 0; i < n; ++i) {
        const double s = w.quantile(uniform01(2024, i, 0), volume);
        sum += s, sumSquares += s * s;
    }
    const double mean = sum / n, variance = sumSquares / n - mean * mean;
    return {mean, variance / (mean * mean)};
}

}  // namespace

TEST_CASE("Weibull strength: mean sigma_w at V_ref, Weibull scatter, size effect", "[fem][dfh]")
{
    const double m = 7.0, sigmaW = 21e6, vRef = 1e-9;
    const WeibullStrength weibull(m, sigmaW, vRef);
    const int n = 100000;
    const Moments atReference = sampleMoments(weibull, vRef, n);
    CHECK(atReference.mean == Approx(sigmaW).epsilon(0.01));
    const double expectedCv2 = std::tgamma(1 + 2 / m) / std::pow(std::tgamma(1 + 1 / m), 2) - 1.0;
    CHECK(atReference.squaredCoefficientOfVariation == Approx(expectedCv2).epsilon(0.03));
    // An element 1000 times smaller is stronger by 1000^(1/m).
    const Moments small = sampleMoments(weibull, vRef / 1000.0, n);
    CHECK(small.mean / atReference.mean == Approx(std::pow(1000.0, 1.0 / m)).epsilon(0.01));
}

TEST_CASE("element thresholds are sorted, reproducible and differ between elements", "[fem][dfh]")
{
    const WeibullStrength weibull(7.0, 21e6, 1e-9);
    const auto a = weibull.elementThresholds(11, 1234, 2e-9);
    CHECK(a[0] <= a[1]);
    CHECK(a[1] <= a[2]);
    CHECK(weibull.elementThresholds(11, 1234, 2e-9) == a);
    CHECK(weibull.elementThresholds(11, 1235, 2e-9) != a);
    CHECK(weibull.elementThresholds(12, 1234, 2e-9) != a);
}
