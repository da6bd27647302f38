#include "calibration/boxMinimiser.hpp"

#include <cmath>
#include <exception>
#include <limits>
#include <nlopt.hpp>

#include "stats/design.hpp"

namespace rockfrac::calibration {

namespace {

struct Context {
    const Objective* objective = nullptr;
    int evaluations = 0;
    std::exception_ptr error;
    std::vector<double> bestX;
    double bestValue = std::numeric_limits<double>::infinity();
};

double callObjective(unsigned n, const double* x, double* /*gradient*/, void* data)
{
    auto& context = *static_cast<Context*>(data);
    std::vector<double> point(x, x + n);
    try {
        const double value = (*context.objective)(point);
        ++context.evaluations;
        if (value < context.bestValue) {
            context.bestValue = value;
            context.bestX = point;
        }
        return value;
    } catch (...) {
        context.error = std::current_exception();
        throw nlopt::forced_stop();
    }
}

std::string describe(nlopt::result result)
{
    switch (result) {
        case nlopt::SUCCESS:
            return "success";
        case nlopt::STOPVAL_REACHED:
            return "objective tolerance reached";
        case nlopt::FTOL_REACHED:
            return "objective converged";
        case nlopt::XTOL_REACHED:
            return "parameters converged";
        case nlopt::MAXEVAL_REACHED:
            return "evaluation budget used";
        case nlopt::MAXTIME_REACHED:
            return "time limit";
        case nlopt::ROUNDOFF_LIMITED:
            return "round-off limited";
        default:
            return "stopped (" + std::to_string(static_cast<int>(result)) + ")";
    }
}

}  // namespace

Minimum minimiseBobyqa(const Objective& objective, const std::vector<double>& start,
                       const MinimiserSettings& settings)
{
    const std::size_t k = start.size();
    Context context;
    context.objective = &objective;
    Minimum best;
    if (k == 0) {
        best.value = objective({});
        best.evaluations = 1;
        best.status = "nothing to vary";
        return best;
    }
    nlopt::opt opt(k == 1 ? nlopt::LN_COBYLA : nlopt::LN_BOBYQA,
                   static_cast<unsigned>(k));  // BOBYQA needs k >= 2
    opt.set_lower_bounds(std::vector<double>(k, -1.0));
    opt.set_upper_bounds(std::vector<double>(k, 1.0));
    opt.set_min_objective(callObjective, &context);
    opt.set_maxeval(settings.maxEvaluations);
    opt.set_xtol_rel(settings.relativeTolerance);
    opt.set_xtol_abs(settings.relativeTolerance);
    if (settings.objectiveTolerance > 0) opt.set_stopval(settings.objectiveTolerance);
    opt.set_initial_step(std::vector<double>(k, settings.initialStep));
    std::vector<double> x = start;
    double value = 0.0;
    nlopt::result result = nlopt::FAILURE;
    try {
        result = opt.optimize(x, value);
        best.status = describe(result);
    } catch (const nlopt::forced_stop&) {
        if (context.error) std::rethrow_exception(context.error);
        best.status = "forced stop";
    } catch (const nlopt::roundoff_limited&) {
        best.status = "round-off limited";
    }
    if (context.error) std::rethrow_exception(context.error);
    best.x = context.bestX.empty() ? x : context.bestX;
    best.value = context.bestX.empty() ? value : context.bestValue;
    best.evaluations = context.evaluations;
    return best;
}

Minimum minimiseMultiStart(const Objective& objective, std::size_t dimensions, int levels,
                           const MinimiserSettings& settings)
{
    const auto grid =
        stats::fullFactorial(std::vector<std::size_t>(dimensions, static_cast<std::size_t>(levels)));
    Minimum best;
    best.value = std::numeric_limits<double>::infinity();
    int evaluations = 0;
    for (const auto& indices : grid) {
        std::vector<double> start;
        for (std::size_t i : indices)
            start.push_back(levels > 1 ? -0.9 + 1.8 * double(i) / (levels - 1) : 0.0);
        Minimum m = minimiseBobyqa(objective, start, settings);
        evaluations += m.evaluations;
        if (m.value < best.value) best = m;
    }
    best.evaluations = evaluations;
    return best;
}

}  // namespace rockfrac::calibration
