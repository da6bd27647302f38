// BOBYQA in the box [-1, 1]^k: interior and boundary minima, budget, errors.
#include <catch2/catch.hpp>
#include <stdexcept>

#include "calibration/boxMinimiser.hpp"

using namespace rockfrac::calibration;

TEST_CASE("BOBYQA finds an interior minimum", "[calibration]")
{
    const Objective bowl = [](const std::vector<double>& x) {
        return (x[0] - 0.3) * (x[0] - 0.3) + 2 * (x[1] + 0.4) * (x[1] + 0.4) + (x[2] - 0.1) * (x[2] - 0.1);
    };
    MinimiserSettings settings;
    settings.relativeTolerance = 1e-10;
    const Minimum m = minimiseBobyqa(bowl, {0, 0, 0}, settings);
    CHECK(m.x[0] == Approx(0.3).margin(1e-6));
    CHECK(m.x[1] == Approx(-0.4).margin(1e-6));
    CHECK(m.x[2] == Approx(0.1).margin(1e-6));
    CHECK(m.evaluations <= settings.maxEvaluations);
}

TEST_CASE("BOBYQA stays inside the bounds", "[calibration]")
{
    const Objective slope = [](const std::vector<double>& x) {
        return (x[0] - 3) * (x[0] - 3) + x[1] * x[1];
    };
    const Minimum m = minimiseBobyqa(slope, {0, 0.5}, {});
    CHECK(m.x[0] == Approx(1.0).margin(1e-6));
    CHECK(m.x[1] == Approx(0.0).margin(1e-4));
}

TEST_CASE("the evaluation budget is kept and the best point returned", "[calibration]")
{
    int calls = 0;
    const Objective f = [&](const std::vector<double>& x) {
        ++calls;
        return x[0] * x[0] + x[1] * x[1];
    };
    MinimiserSettings settings;
    settings.maxEvaluations = 7;
    const Minimum m = minimiseBobyqa(f, {0.8, 0.8}, settings);
    CHECK(calls <= 7);
    CHECK(m.value <= 0.8 * 0.8 * 2);
}

TEST_CASE("multi-start finds the better of two minima", "[calibration]")
{
    const Objective twoWells = [](const std::vector<double>& x) {
        const double a = (x[0] + 0.7) * (x[0] + 0.7) + x[1] * x[1] + 0.1;
        const double b = (x[0] - 0.7) * (x[0] - 0.7) + x[1] * x[1];
        return std::min(a, b);
    };
    const Minimum m = minimiseMultiStart(twoWells, 2, 3, {});
    CHECK(m.x[0] == Approx(0.7).margin(1e-4));
}

TEST_CASE("an error in the objective stops the search and reaches the caller", "[calibration]")
{
    const Objective failing = [](const std::vector<double>&) -> double {
        throw std::runtime_error("run failed");
    };
    CHECK_THROWS_WITH(minimiseBobyqa(failing, {0, 0}, {}), "run failed");
}

#include "calibration/calibrationDetail.hpp"

TEST_CASE("a parameter set asked for again reuses its objective", "[calibration]")
{
    CalibrationStudy study;
    study.parameters.push_back(
        {"weibullStress", "constant/rockProperties", "kstDfh/dfh/weibullStress", "Pa", 8e6, 12e6});
    int simulations = 0;
    const Objective simulated = [&](const std::vector<double>& x) {
        ++simulations;
        return x[0] * x[0] + 0.5;
    };
    const Objective objective = detail::reusingRepeatedSets(study, simulated);
    const double first = objective({0.25});
    CHECK(objective({0.25}) == first);          // the same point
    CHECK(objective({0.25 + 1e-12}) == first);  // the same rounded values: the same runs
    CHECK(simulations == 1);
    CHECK(objective({-0.5}) == Approx(0.75));  // another set runs
    CHECK(simulations == 2);
}
