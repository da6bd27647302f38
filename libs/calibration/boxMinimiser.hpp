#pragma once
// Bound-constrained minimisation without derivatives: NLopt's BOBYQA (Powell),
// which builds a quadratic model of the objective from its own evaluations
// and so suits both a response surface (cheap) and a simulation (each
// evaluation one or more runs, a budget of a few dozen).
#include <functional>
#include <string>
#include <vector>

namespace rockfrac::calibration {

using Objective = std::function<double(const std::vector<double>&)>;

struct MinimiserSettings {
    int maxEvaluations = 200;
    double initialStep = 0.5;         // in the unit of x (x ∈ [−1, 1]: a quarter of the range)
    double relativeTolerance = 1e-6;  // on x
    double objectiveTolerance = 0.0;  // stop when f <= this (0: off)
};

struct Minimum {
    std::vector<double> x;
    double value = 0.0;
    int evaluations = 0;
    std::string status;  // NLopt's reason for stopping
};

// x in [−1, 1]^k. An exception thrown by the objective stops the search and is rethrown.
Minimum minimiseBobyqa(const Objective& objective, const std::vector<double>& start,
                       const MinimiserSettings& settings);

// BOBYQA from every point of a `levels`^k grid over [−1, 1]^k; the best minimum.
// For cheap objectives with several local minima (a response surface).
Minimum minimiseMultiStart(const Objective& objective, std::size_t dimensions, int levels,
                           const MinimiserSettings& settings);

}  // namespace rockfrac::calibration
