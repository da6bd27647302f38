// The chi-square survival function against closed forms (k = 2: e^(-x/2); k = 4:
// e^(-x/2) (1 + x/2); k = 1: erfc(sqrt(x/2))) and the tables' 5 % points, on both sides of
// the switch from the series to the continued fraction (x/2 = k/2 + 1).
#include <catch2/catch.hpp>
#include <cmath>

#include "explain/chiSquare.hpp"

using rockfrac::explain::chiSquareSurvival;

TEST_CASE("chi-square survival: closed forms for 1, 2 and 4 degrees of freedom", "[explain][chiSquare]")
{
    for (double x : {0.01, 0.5, 1.0, 2.9, 3.0, 3.1, 5.999, 6.0, 6.001, 10.0, 40.0, 200.0}) {
        INFO("x = " << x);
        CHECK(chiSquareSurvival(x, 2.0) == Approx(std::exp(-0.5 * x)).epsilon(1e-12));
        CHECK(chiSquareSurvival(x, 4.0) == Approx(std::exp(-0.5 * x) * (1.0 + 0.5 * x)).epsilon(1e-12));
        CHECK(chiSquareSurvival(x, 1.0) == Approx(std::erfc(std::sqrt(0.5 * x))).epsilon(1e-10));
    }
}

TEST_CASE("chi-square survival: the tables' 5 % and 1 % points", "[explain][chiSquare]")
{
    CHECK(chiSquareSurvival(3.841458820694124, 1.0) == Approx(0.05).epsilon(1e-10));
    CHECK(chiSquareSurvival(5.991464547107979, 2.0) == Approx(0.05).epsilon(1e-10));
    CHECK(chiSquareSurvival(18.307038053275146, 10.0) == Approx(0.05).epsilon(1e-9));
    CHECK(chiSquareSurvival(6.634896601021214, 1.0) == Approx(0.01).epsilon(1e-9));
    CHECK(chiSquareSurvival(23.209251158954356, 10.0) == Approx(0.01).epsilon(1e-9));
}

TEST_CASE("chi-square survival: limits", "[explain][chiSquare]")
{
    CHECK(chiSquareSurvival(0.0, 3.0) == 1.0);
    CHECK(chiSquareSurvival(-1.0, 3.0) == 1.0);
    CHECK(chiSquareSurvival(1e-12, 3.0) == Approx(1.0).epsilon(1e-12));
    const double tail = chiSquareSurvival(1000.0, 3.0);
    CHECK(tail > 0.0);
    CHECK(tail < 1e-200);
    // Decreasing in x, increasing in k.
    CHECK(chiSquareSurvival(5.0, 3.0) < chiSquareSurvival(4.0, 3.0));
    CHECK(chiSquareSurvival(5.0, 4.0) > chiSquareSurvival(5.0, 3.0));
}
