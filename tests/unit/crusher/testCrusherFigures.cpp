// The figures per tonne (libs/crusher/crusherFigures): specific energy with its propagated
// spread, the F80 of a uniform feed against a PSD of drawn rocks, and the not-available cases.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "crusher/crusherFigures.hpp"
#include "fragments/psd.hpp"

using namespace rockfrac;

TEST_CASE("specific energy: the paper's CH660 and the propagated spread", "[crusher][perTonne]")
{
    // 146 kW at 199 t/h (the reference paper's CH660): 146 / 199 kWh/t.
    const CrusherFigure e = specificEnergy(146e3, 0.0, 199.0 / 3.6, 0.0);
    REQUIRE(e.available);
    CHECK(e.value == Approx(146.0 / 199.0).epsilon(1e-12));
    CHECK(e.spread == 0.0);
    // 10 % on the power and 20 % on the throughput: sqrt(0.01 + 0.04) of the value.
    const CrusherFigure s = specificEnergy(100.0, 10.0, 2.0, 0.4);
    CHECK(s.value == Approx(100.0 / 2.0 / 3600.0).epsilon(1e-12));
    CHECK(s.spread == Approx(s.value * std::sqrt(0.05)).epsilon(1e-12));
    // Zero power: the spread comes from the throughput alone (no division by zero).
    const CrusherFigure z = specificEnergy(0.0, 1.0, 2.0, 0.4);
    CHECK(z.available);
    CHECK(z.value == 0.0);
    CHECK(std::isfinite(z.spread));
}

TEST_CASE("specific energy: not available without throughput, never inf or nan", "[crusher][perTonne]")
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (double q : {0.0, -1.0, nan}) {
        const CrusherFigure e = specificEnergy(5.0, 1.0, q, 0.0);
        CHECK_FALSE(e.available);
        CHECK_FALSE(e.why.empty());
    }
    CHECK_FALSE(specificEnergy(nan, 0.0, 1.0, 0.0).available);
}

TEST_CASE("uniform feed F80 equals the PSD of many rocks drawn from it", "[crusher][perTonne]")
{
    // Sizes evenly spaced in number over [lo, hi] (the factory draws them uniformly), masses as
    // size^3 (scaled copies of one template): the PSD's P80 tends to the closed form.
    for (auto [lo, hi] : {std::pair{0.060, 0.090}, std::pair{0.014, 0.018}, std::pair{0.060, 0.075}}) {
        const int n = 20000;
        std::vector<double> sizes, masses;
        for (int i = 0; i < n; ++i) {
            const double s = lo + (hi - lo) * (i + 0.5) / n;
            sizes.push_back(s);
            masses.push_back(s * s * s);
        }
        const double p80 = sizeAtPassing(cumulativePassing(sizes, masses), 0.8);
        CHECK(uniformFeedPassingSize(lo, hi, 0.8) == Approx(p80).epsilon(1e-4));
    }
    // The paper's feed, +60/-90 mm: F80 = (60^4 + 0.8 (90^4 - 60^4))^(1/4) = 86.15 mm.
    CHECK(uniformFeedPassingSize(0.060, 0.090, 0.8) == Approx(0.086149).epsilon(1e-4));
    CHECK(uniformFeedPassingSize(0.05, 0.05, 0.8) == Approx(0.05));
    CHECK(uniformFeedPassingSize(0.06, 0.09, 1.0) == Approx(0.09).epsilon(1e-12));
    CHECK_THROWS_AS(uniformFeedPassingSize(0.0, 0.09, 0.8), std::invalid_argument);
    CHECK_THROWS_AS(uniformFeedPassingSize(0.09, 0.06, 0.8), std::invalid_argument);
    CHECK_THROWS_AS(uniformFeedPassingSize(0.06, 0.09, 0.0), std::invalid_argument);
}

TEST_CASE("size ratios: P80/CSS and F80/P80, not available without a P80", "[crusher][perTonne]")
{
    const CrusherFigure r = sizeRatio(0.0412, 0.038, "no P80");
    REQUIRE(r.available);
    CHECK(r.value == Approx(41.2 / 38.0).epsilon(1e-12));
    const CrusherFigure none = sizeRatio(0.0, 0.038, "nothing discharged yet");
    CHECK_FALSE(none.available);
    CHECK(none.why == "nothing discharged yet");
    CHECK_FALSE(sizeRatio(0.08, 0.0, "no P80").available);
}
