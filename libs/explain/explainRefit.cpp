// explainGap's refits: the Gauss–Newton refit of some parameters, and step 5, the joint
// refit of each significant effect with the baseline, judged on the held-out half.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "explain/explainAnalysis.hpp"

namespace rockfrac::explain::detail {

// The joint refit of an effect with the baseline runs to convergence: a step below 5 % of
// every parameter's probe, or a chi-square gain below 0.1 (a tenth of one degree of freedom's
// expectation), within 8 simulated steps; after two failed steps, when another is expected to
// gain less than 0.5.
constexpr RefitControl jointRefit{8, 0.05, 0.1, 0.5};

Analysis::Fit Analysis::refit(const std::vector<int>& free, const Fit& start, const std::string& label,
                              const Fit* previous, RefitControl control)
{
    // Gauss–Newton in coordinates scaled by each parameter's probe, with Broyden's rank-one
    // update of the sensitivities after every simulated point: the probes give secants at the
    // case's values, and an effect can be strongly nonlinear (a strength loss of 0.8 does far
    // more than 4/3 of 0.6), so the sensitivities learn from every point on the way.
    const int n = static_cast<int>(free.size());
    Eigen::VectorXd scale(n);
    for (int k = 0; k < n; ++k)
        scale[k] = std::max(
            std::fabs(probeSize_[static_cast<std::size_t>(free[static_cast<std::size_t>(k)])]), 1e-300);
    Eigen::MatrixXd A = whitened(free) * scale.asDiagonal();
    auto coordinates = [&](const Fit& f) {
        Eigen::VectorXd x(n);
        for (int k = 0; k < n; ++k)
            x[k] = f.values[static_cast<std::size_t>(free[static_cast<std::size_t>(k)])] / scale[k];
        return x;
    };
    auto broyden = [&](const Fit& from, const Fit& to) {
        const Eigen::VectorXd dx = coordinates(to) - coordinates(from);
        const double dxdx = dx.squaredNorm();
        if (dxdx <= 0) return;
        const Eigen::VectorXd dm =
            residual(from.model, false, sigmaCal_) - residual(to.model, false, sigmaCal_);
        A += (dm - A * dx) * dx.transpose() / dxdx;
    };
    if (previous) broyden(*previous, start);
    Fit best = start;
    best.converged = false;
    best.steps = 0;
    int worse = 0, steps = 0;
    std::string stopped = "the cap of " + std::to_string(control.maxSteps) + " steps";
    bool converged = false;
    while (steps < control.maxSteps) {
        const Eigen::VectorXd r = residual(best.model, false, sigmaCal_);
        const Eigen::VectorXd step = A.colPivHouseholderQr().solve(r);
        if (worse >= 2) {
            // At the seeds' noise floor when the sensitivities, updated by the failed steps,
            // expect next to nothing from another step.
            const double expected = r.squaredNorm() - (r - A * step).squaredNorm();
            converged = expected < control.expectedGainTolerance;
            stopped = "two steps in a row did not lower chi-square; another would gain " +
                      format(expected, 2) + " by the linearised fit";
            break;
        }
        std::vector<double> next = best.values;
        for (int k = 0; k < n; ++k)
            next[static_cast<std::size_t>(free[static_cast<std::size_t>(k)])] += step[k] * scale[k];
        next = clip(next);
        bool moves = false;
        for (int k = 0; k < n; ++k) {
            const std::size_t j = static_cast<std::size_t>(free[static_cast<std::size_t>(k)]);
            moves = moves || std::fabs(next[j] - best.values[j]) > control.stepTolerance * scale[k];
        }
        if (!moves) {
            converged = true;
            stopped = "the next step is below " + format(control.stepTolerance, 2) + " of every probe";
            break;
        }
        ++steps;
        Fit trial;
        trial.values = next;
        try {
            trial.runs = evaluate(next, label + "-" + std::to_string(steps));
        } catch (const UserError& error) {
            say("  " + label + ": step " + std::to_string(steps) +
                " not taken, its runs failed: " + error.what());
            stopped = "the runs of step " + std::to_string(steps) + " failed";
            break;
        }
        trial.model = summary(trial.runs);
        trial.chi = chiCal(trial.model);
        broyden(best, trial);
        if (trial.chi < best.chi) {
            const double gain = best.chi - trial.chi;
            best = std::move(trial);
            worse = 0;
            if (gain < control.chiTolerance) {
                converged = true;
                stopped = "chi-square fell by less than " + format(control.chiTolerance, 2);
                break;
            }
        } else {
            ++worse;
        }
    }
    best.converged = converged;
    best.steps = steps;
    best.stopped = stopped;
    const Eigen::MatrixXd unscaled = A * scale.cwiseInverse().asDiagonal();
    best.sensitivities = unscaled;
    best.covariance = (unscaled.transpose() * unscaled).completeOrthogonalDecomposition().pseudoInverse();
    return best;
}

// 5. Confirm the significant candidates by a joint refit, judged on the held-out half;
// `fits` gets each confirmed effect's fit. Returns the candidates.
std::vector<int> Analysis::confirmCandidates(const std::vector<int>& order, const Fit& baseline,
                                             ExplainOutcome& out, std::vector<Fit>& fits)
{
    // (An effect whose probe failed has a zero column and score: never a candidate.)
    std::vector<int> candidates;
    for (int e : order)
        if (out.screened[static_cast<std::size_t>(e)].pValue < s_.significance &&
            !out.screened[static_cast<std::size_t>(e)].wrongSign)
            candidates.push_back(e);
    if (candidates.size() > 3) candidates.resize(3);
    const double aicBaseline = baseline.chi + 2.0 * nb_;
    fits.resize(static_cast<std::size_t>(ne_));
    for (int e : candidates) {
        ScreenedEffect& se = out.screened[static_cast<std::size_t>(e)];
        Fit fit;
        if (!refitWithEffect(e, baseline, se, fit)) continue;
        judgeRefit(e, fit, aicBaseline, out, se);
        fits[static_cast<std::size_t>(e)] = std::move(fit);
    }
    return candidates;
}

// The baseline and effect e refitted together into `fit`; false (and said) when its runs failed.
bool Analysis::refitWithEffect(int e, const Fit& baseline, const ScreenedEffect& se, Fit& fit)
{
    std::vector<int> free = baselineFree();
    free.push_back(nb_ + e);
    // The linearised size, within a trust region of three probes (the sensitivity
    // is a secant over one probe; far beyond it the model may not even run).
    const double probe = std::fabs(probeSize_[static_cast<std::size_t>(nb_ + e)]);
    Fit from = baseline;
    from.values[static_cast<std::size_t>(nb_ + e)] += std::clamp(se.amplitude, -3 * probe, 3 * probe);
    from.values = clip(from.values);
    try {
        from.runs = evaluate(from.values, "fit-" + se.name + "-0");
        from.model = summary(from.runs);
        from.chi = chiCal(from.model);
        const Fit* previous = &baseline;
        std::vector<Fit> tried;  // the scan's points, when there is a scan
        if (from.chi >= baseline.chi) previous = scanRange(e, baseline, se.name, from, tried);
        fit = refit(free, from, "fit-" + se.name, previous, jointRefit);
        say("  refit " + se.name + ": " + (fit.converged ? "converged" : "did not converge") + " after " +
            std::to_string(fit.steps) + " Gauss-Newton steps (" + fit.stopped + ")");
    } catch (const UserError& error) {
        say("  refit " + se.name + ": not confirmed, its runs failed: " + error.what());
        return false;
    }
    return true;
}

// The linearised size did not lower chi-square: the effect acts past a
// threshold (plates that let the rock slide only below some friction) or
// bends strongly, where the secant at the case's value sees nothing useful.
// Scan its range (fractions 0.05, 0.3, 0.55, 0.8), then halve the distance
// from the best point to each neighbour once, and start the refit there (`from`),
// with the nearest scanned point as the secant partner of its sensitivities (returned;
// the baseline when there is none). `tried` keeps the scan's points.
const Analysis::Fit* Analysis::scanRange(int e, const Fit& baseline, const std::string& effectName, Fit& from,
                                         std::vector<Fit>& tried)
{
    const std::size_t j = static_cast<std::size_t>(nb_ + e);
    const double low = parameter(static_cast<int>(j)).low, high = parameter(static_cast<int>(j)).high;
    int k = 0;
    auto tryValue = [&](double value) {
        Fit trial = baseline;
        trial.values[j] = value;
        trial.values = clip(trial.values);
        const std::string pointName = "fit-" + effectName + "-scan" + std::to_string(++k);
        try {
            trial.runs = evaluate(trial.values, pointName);
        } catch (const UserError& error) {
            say("  refit " + effectName + ": scan point " + describeParameter(nb_ + e, value) +
                " left out, its runs failed: " + error.what());
            return;
        }
        trial.model = summary(trial.runs);
        trial.chi = chiCal(trial.model);
        tried.push_back(std::move(trial));
    };
    for (double fraction : {0.05, 0.3, 0.55, 0.8}) tryValue(low + fraction * (high - low));
    tried.push_back(from);
    tried.push_back(baseline);
    auto byValue = [j](const Fit& a, const Fit& b) { return a.values[j] < b.values[j]; };
    auto bestOf = [&]() {
        std::sort(tried.begin(), tried.end(), byValue);
        std::size_t b = 0;
        for (std::size_t i = 1; i < tried.size(); ++i)
            if (tried[i].chi < tried[b].chi) b = i;
        return b;
    };
    std::size_t best = bestOf();
    const double bestValue = tried[best].values[j];
    const double left = best > 0 ? tried[best - 1].values[j] : low;
    const double right = best + 1 < tried.size() ? tried[best + 1].values[j] : high;
    if (left < bestValue) tryValue(0.5 * (left + bestValue));
    if (right > bestValue) tryValue(0.5 * (bestValue + right));
    best = bestOf();
    from = tried[best];
    // The nearest other point: a local secant, not one across the threshold.
    std::size_t partner = best > 0 ? best - 1 : best + 1;
    if (best > 0 && best + 1 < tried.size() &&
        tried[best + 1].values[j] - tried[best].values[j] < tried[best].values[j] - tried[best - 1].values[j])
        partner = best + 1;
    const Fit* previous = &baseline;
    if (partner < tried.size() && partner != best) previous = &tried[partner];
    say("  refit " + effectName + ": the linearised start did not lower chi-square; starting from " +
        describeParameter(nb_ + e, from.values[j]) + " (best of a " + std::to_string(k) +
        "-point scan of its range, chi-square " + format(from.chi, 4) + ")");
    return previous;
}

// A confirmed refit of effect e: its value, interval, held-out gap and AIC, and whether it is kept.
void Analysis::judgeRefit(int e, const Fit& fit, double aicBaseline, const ExplainOutcome& out,
                          ScreenedEffect& se)
{
    se.confirmed = true;
    se.converged = fit.converged;
    se.refitSteps = fit.steps;
    se.value = fit.values[static_cast<std::size_t>(nb_ + e)];
    const double sd = std::sqrt(std::max(0.0, fit.covariance(nb_, nb_)));
    se.intervalLow = std::max(parameter(nb_ + e).low, se.value - 1.645 * sd);
    se.intervalHigh = std::min(parameter(nb_ + e).high, se.value + 1.645 * sd);
    se.heldOutGap = heldGap(fit.model);
    se.reduction = out.baselineHeldOutGap > 0 ? 1.0 - se.heldOutGap / out.baselineHeldOutGap : 0.0;
    se.aic = fit.chi + 2.0 * (nb_ + 1);
    se.kept = se.reduction >= s_.minimumGapReduction && se.aic < aicBaseline;
    say("  refit " + se.name + ": " + describeParameter(nb_ + e, se.value) + " (90 % " +
        format(se.intervalLow, 3) + " to " + format(se.intervalHigh, 3) + "), chi-square " +
        format(fit.chi, 3) + ", held-out gap " + format(se.heldOutGap, 3) + " (" +
        format(100 * se.reduction, 3) + " %), AIC " + format(se.aic, 4) + " vs " + format(aicBaseline, 4) +
        (se.kept ? ": kept" : ": not kept"));
}

}  // namespace rockfrac::explain::detail
