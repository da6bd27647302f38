// Quadratic response surfaces: exact on a quadratic, honest R² on noise.
#include <catch2/catch.hpp>
#include <cmath>

#include "calibration/responseSurface.hpp"
#include "core/error.hpp"
#include "stats/design.hpp"

using namespace rockfrac::calibration;

namespace {

double knownQuadratic(const Point& x)
{
    return 3.0 + 2.0 * x[0] - x[1] + 0.5 * x[2] + 1.5 * x[0] * x[0] - 0.7 * x[0] * x[1] + 0.2 * x[1] * x[2] +
           0.9 * x[2] * x[2];
}

std::vector<Point> threeLevelDesign()
{
    std::vector<Point> points;
    for (const auto& levels : rockfrac::stats::fullFactorial({3, 3, 3})) {
        Point x;
        for (auto l : levels) x.push_back(-1.0 + double(l));
        points.push_back(x);
    }
    return points;
}

}  // namespace

TEST_CASE("a full quadratic in 3 inputs has 10 terms", "[calibration]")
{
    CHECK(quadraticTermCount(3) == 10);
    CHECK(quadraticTermCount(2) == 6);
    CHECK(quadraticTerms({2.0, 3.0}) == std::vector<double>{1, 2, 3, 4, 6, 9});
}

TEST_CASE("the fit of a quadratic reproduces it exactly", "[calibration]")
{
    const auto points = threeLevelDesign();
    std::vector<double> values;
    for (const auto& x : points) values.push_back(knownQuadratic(x));
    const auto s = QuadraticSurface::fit(points, values);
    CHECK(s.rSquared() == Approx(1.0).margin(1e-12));
    CHECK(s.leaveOneOutRSquared() == Approx(1.0).margin(1e-10));
    for (const Point& x : {Point{0.3, -0.2, 0.7}, Point{-0.9, 0.5, 0.1}})
        CHECK(s(x) == Approx(knownQuadratic(x)).epsilon(1e-12));
}

TEST_CASE("leave-one-out R2 is below R2 when the data are noisy", "[calibration]")
{
    const auto points = threeLevelDesign();
    std::vector<double> values;
    double sign = 1.0;
    for (const auto& x : points)
        values.push_back(knownQuadratic(x) + 0.3 * (sign = -sign) * std::cos(7 * x[0]));
    const auto s = QuadraticSurface::fit(points, values);
    CHECK(s.rSquared() < 1.0);
    CHECK(s.leaveOneOutRSquared() < s.rSquared());
    CHECK(s.rSquared() > 0.9);
}

TEST_CASE("too few points or too few levels are refused", "[calibration]")
{
    const std::vector<Point> few{{0, 0, 0}, {1, 1, 1}, {-1, 0, 1}};
    CHECK_THROWS_AS(QuadraticSurface::fit(few, {1, 2, 3}), rockfrac::UserError);
    std::vector<Point> twoLevels;
    std::vector<double> values;
    for (const auto& levels :
         rockfrac::stats::fullFactorial({2, 2, 2, 2})) {  // 16 points, 2 levels: rank deficient
        twoLevels.push_back(
            {-1.0 + 2.0 * double(levels[0]), -1.0 + 2.0 * double(levels[1]), -1.0 + 2.0 * double(levels[2])});
        values.push_back(double(levels[3]));
    }
    CHECK_THROWS_AS(QuadraticSurface::fit(twoLevels, values), rockfrac::UserError);
}

TEST_CASE("normalisation maps the bounds onto [-1, 1]", "[calibration]")
{
    CHECK(toUnit(20e9, 20e9, 80e9) == Approx(-1.0));
    CHECK(toUnit(80e9, 20e9, 80e9) == Approx(1.0));
    CHECK(fromUnit(0.0, 20e9, 80e9) == Approx(50e9));
    CHECK(fromUnit(toUnit(37e9, 20e9, 80e9), 20e9, 80e9) == Approx(37e9));
}
