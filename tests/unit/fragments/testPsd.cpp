// The cumulative mass-passing curve, P50/P80 by log-linear interpolation and
// t10, against hand computations.
#include <catch2/catch.hpp>
#include <cmath>

#include "fragments/psd.hpp"

using namespace rockfrac;

namespace {
// Four fragments of 10, 20, 40, 80 mm holding 1, 2, 3, 4 parts of the mass:
// P = 0.1, 0.3, 0.6, 1.0 at those sizes.
PsdCurve fourFragments()
{
    return cumulativePassing({0.080, 0.010, 0.040, 0.020}, {4, 1, 3, 2});
}
}  // namespace

TEST_CASE("the cumulative curve merges equal sizes and ends at 1", "[fragments][psd]")
{
    const PsdCurve c = fourFragments();
    REQUIRE(c.size == std::vector<double>{0.010, 0.020, 0.040, 0.080});
    CHECK(c.passing[0] == Approx(0.1));
    CHECK(c.passing[1] == Approx(0.3));
    CHECK(c.passing[2] == Approx(0.6));
    CHECK(c.passing[3] == 1.0);

    const PsdCurve tied = cumulativePassing({0.01, 0.02, 0.01}, {1, 2, 1});
    REQUIRE(tied.size.size() == 2);
    CHECK(tied.passing[0] == Approx(0.5));
}

TEST_CASE("P80 and P50 by log-linear interpolation", "[fragments][psd]")
{
    const PsdCurve c = fourFragments();
    // P80 between 40 mm (0.6) and 80 mm (1.0): halfway in ln x: 40 * 2^0.5 mm.
    CHECK(sizeAtPassing(c, 0.8) == Approx(0.040 * std::sqrt(2.0)).epsilon(1e-14));
    // P50 between 20 mm (0.3) and 40 mm (0.6): two thirds: 20 * 2^(2/3) mm.
    CHECK(sizeAtPassing(c, 0.5) == Approx(0.020 * std::pow(2.0, 2.0 / 3.0)).epsilon(1e-14));
    // At a point, the point; below the first point, the smallest size.
    CHECK(sizeAtPassing(c, 0.6) == Approx(0.040));
    CHECK(sizeAtPassing(c, 0.05) == Approx(0.010));
    CHECK(sizeAtPassing(c, 1.0) == Approx(0.080));
    // The inverse of passingAt.
    for (double p : {0.15, 0.35, 0.8, 0.99})
        CHECK(passingAt(c, sizeAtPassing(c, p)) == Approx(p).epsilon(1e-12));
}

TEST_CASE("t10 against a hand computation", "[fragments][psd]")
{
    const PsdCurve c = fourFragments();
    // Original particle 250 mm: x0/10 = 25 mm lies between 20 (0.3) and 40 mm (0.6),
    // at ln(1.25)/ln(2) of the way: t10 = 0.3 + 0.3 ln(1.25)/ln(2) = 0.396578...
    const PsdSummary s = summarisePsd(c, 0.250);
    CHECK(s.t10 == Approx(0.3 + 0.3 * std::log(1.25) / std::log(2.0)).epsilon(1e-14));
    CHECK(s.t10 == Approx(0.396578428));
    CHECK(s.p80 == Approx(0.0565685425));
    // Nothing below the smallest fragment, everything from the largest on.
    CHECK(passingAt(c, 0.009) == 0.0);
    CHECK(passingAt(c, 0.080) == 1.0);
    CHECK(passingAt(c, 1.0) == 1.0);
    // An unbroken specimen: t10 = 0, P80 = its own size.
    const PsdSummary whole = summarisePsd(cumulativePassing({0.05}, {1.0}), 0.05);
    CHECK(whole.t10 == 0.0);
    CHECK(whole.p80 == 0.05);
}

TEST_CASE("bad PSD input is refused", "[fragments][psd]")
{
    CHECK_THROWS_AS(cumulativePassing({0.01}, {}), std::invalid_argument);
    CHECK_THROWS_AS(cumulativePassing({0.0}, {1.0}), std::invalid_argument);
    CHECK_THROWS_AS(cumulativePassing({0.01}, {0.0}), std::invalid_argument);
    CHECK_THROWS_AS(sizeAtPassing(fourFragments(), 0.0), std::invalid_argument);
}
