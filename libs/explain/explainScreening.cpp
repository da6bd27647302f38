// explainGap's steps 1 to 4: the baseline's scatter, the sensitivities, the baseline
// re-fitted on the calibration half, and the score test of every effect.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "effects/modelEffect.hpp"
#include "explain/chiSquare.hpp"
#include "explain/explainAnalysis.hpp"

namespace rockfrac::explain::detail {

// 1. The baseline as the case has it, and its scatter over the seeds.
void Analysis::evaluateBaseline()
{
    model0_ = summary(base0_);  // base0_: run by execute() before the check of odd members
    for (const Observed& o : obs_) {
        const double model = model0_[static_cast<std::size_t>(o.condition)].standardError[o.feature];
        sigmaCal_.push_back(std::hypot(model, half(o, false).features.standardError[o.feature]));
        sigmaHeld_.push_back(std::hypot(model, half(o, true).features.standardError[o.feature]));
    }
    for (double& v : sigmaCal_) v = std::max(v, 1e-300);
    for (double& v : sigmaHeld_) v = std::max(v, 1e-300);
}

// The step of parameter j's probe before clipping: baseline parameters by a relative
// step, effects by their probe.
double Analysis::probeStep(int j) const
{
    double step = 0.0;
    if (j < nb_) {
        const auto& b = s_.baseline[static_cast<std::size_t>(j)];
        step = b.relativeStep * theta0_[static_cast<std::size_t>(j)];
        if (theta0_[static_cast<std::size_t>(j)] + step > b.where.high) step = -step;
    } else {
        const EffectDescriptor& d = findEffect(s_.effects[static_cast<std::size_t>(j - nb_)], "");
        // Scaled by the first condition's response (a probe is one size for all).
        double scale = 1.0;
        const FeatureSummary& m0 = model0_.front();
        if (d.probeScale == ProbeScale::peakDisplacement) scale = m0.value[peakDisplacement];
        if (d.probeScale == ProbeScale::peakCompliance)
            scale = m0.value[peakDisplacement] / m0.value[peakForce];
        step = d.probe * scale;
    }
    return step;
}

// 2. Sensitivities: one probe per parameter, the Jacobian by forward differences.
void Analysis::probeSensitivities()
{
    jacobian_ = Eigen::MatrixXd::Zero(featureRows(), nb_ + ne_);
    for (int j = 0; j < nb_ + ne_; ++j) {
        std::vector<double> probe = theta0_;
        double step = probeStep(j);
        probe[static_cast<std::size_t>(j)] += step;
        probe = clip(probe);
        step = probe[static_cast<std::size_t>(j)] - theta0_[static_cast<std::size_t>(j)];
        probeSize_.push_back(step);
        probeFailed_.push_back(0);
        RunsPerCondition runs;
        try {
            runs = evaluate(probe, "probe-" + parameter(j).name);
        } catch (const UserError& error) {
            // A baseline parameter is needed; an effect whose probe does not run is left out
            // of the screening (its column stays zero, so its score is zero) and said so.
            if (j < nb_) throw;
            say("  " + parameter(j).name + ": not screened, the runs of its probe failed: " + error.what());
            probeFailed_.back() = 1;
            continue;
        }
        const Summaries m = summary(runs);
        for (std::size_t c = 0; c < m.size(); ++c)
            for (int f = 0; f < nFeatures; ++f)
                jacobian_(static_cast<int>(c) * nFeatures + f, j) =
                    (m[c].value[f] - model0_[c].value[f]) / step;
    }
}

// What each parameter's probe does to every feature, in standard errors of the
// calibration half (the signatures the screening tells the effects apart by).
void Analysis::saySignatures()
{
    for (int j = 0; j < nb_ + ne_; ++j) {
        if (probeFailed_[static_cast<std::size_t>(j)]) {
            say("  signature of " + parameter(j).name + ": not measured, its probe failed");
            continue;
        }
        std::string changes;
        for (std::size_t i = 0; i < obs_.size(); ++i)
            changes +=
                std::string(i ? ", " : "") + label(obs_[i]) + " " +
                format(jacobian_(row(obs_[i]), j) * probeSize_[static_cast<std::size_t>(j)] / sigmaCal_[i],
                       2);
        say("  signature of " + parameter(j).name + " (probe " +
            format(probeSize_[static_cast<std::size_t>(j)], 3) + "): " + changes);
    }
}

// 3. The baseline re-fitted on the calibration half: is what is left beyond the scatter?
// `fitted` gets the fitted values as the report names them.
Analysis::Fit Analysis::refitBaseline(ExplainOutcome& out, std::string& fitted)
{
    Fit start;
    start.values = theta0_;
    start.runs = base0_;
    start.model = model0_;
    start.chi = chiCal(model0_);
    // No free baseline parameter: the case is tested as calibrated elsewhere (e.g. bonds
    // from Brazilian discs judged on single particle breakage, the paper's question).
    Fit baseline = nb_ > 0 ? refit(baselineFree(), start, "fit-baseline") : start;
    const int dof = std::max(1, static_cast<int>(obs_.size()) - nb_);
    out.baselineChiSquare = baseline.chi;
    out.baselinePValue = chiSquareSurvival(baseline.chi, dof);
    out.baselineHeldOutGap = heldGap(baseline.model);
    for (int j = 0; j < nb_; ++j)
        fitted += (j ? ", " : "") + describeParameter(j, baseline.values[static_cast<std::size_t>(j)]);
    if (nb_ == 0) fitted = "no baseline parameter free: the case as calibrated";
    say(std::string(nb_ > 0 ? "baseline re-fitted (" : "baseline (") + fitted + "): chi-square " +
        format(baseline.chi) + " on " + std::to_string(dof) +
        " degrees of freedom, p = " + format(out.baselinePValue, 3) + "; held-out gap " +
        format(out.baselineHeldOutGap, 3) + " (RMS of the feature errors in standard errors)" +
        (nb_ > 0 ? std::string(baseline.converged ? "; converged" : "; not converged") + " after " +
                       std::to_string(baseline.steps) + " steps (" + baseline.stopped + ")"
                 : std::string()));
    return baseline;
}

// An effect whose probe moves no feature by this many standard errors has no signature on
// the data (plate friction on discs: exactly zero) and cannot be tested.
constexpr double untestableChange = 0.01;

// 4. Score test of every effect at the re-fitted baseline: fills out.screened, and
// `projected` with each effect's whitened signature, the baseline projected out.
// Returns the effects by decreasing score.
std::vector<int> Analysis::screenEffects(const Fit& baseline, ExplainOutcome& out,
                                         std::vector<Eigen::VectorXd>& projected)
{
    const Eigen::MatrixXd A = whitened(baselineFree());
    Eigen::MatrixXd projector = Eigen::MatrixXd::Identity(A.rows(), A.rows());
    if (nb_ > 0)
        projector -=
            A * (A.transpose() * A).completeOrthogonalDecomposition().pseudoInverse() * A.transpose();
    const Eigen::VectorXd r = residual(baseline.model, false, sigmaCal_);
    for (int e = 0; e < ne_; ++e) {
        const EffectDescriptor& d = findEffect(s_.effects[static_cast<std::size_t>(e)], "");
        ScreenedEffect se;
        se.name = d.name;
        se.screened = !probeFailed_[static_cast<std::size_t>(nb_ + e)];
        const Eigen::VectorXd b = projector * whitened({nb_ + e}).col(0);
        projected.push_back(b);
        const double bb = b.squaredNorm();
        const int j = nb_ + e;
        for (std::size_t i = 0; i < obs_.size(); ++i)
            se.largestChange =
                std::max(se.largestChange, std::abs(jacobian_(row(obs_[i]), j) *
                                                    probeSize_[static_cast<std::size_t>(j)] / sigmaCal_[i]));
        se.testable = !se.screened || se.largestChange >= untestableChange;
        if (se.screened && se.testable && bb > 1e-12) {
            se.amplitude = b.dot(r) / bb;
            se.score = b.dot(r) * b.dot(r) / bb;
            const double target = d.neutral + se.amplitude;
            se.wrongSign = (d.neutral <= d.low && target < d.low) || (d.neutral >= d.high && target > d.high);
            if (se.wrongSign) se.score = 0.0;
        }
        se.pValue = chiSquareSurvival(se.score, 1);
        out.screened.push_back(se);
    }
    std::vector<int> order(static_cast<std::size_t>(ne_));
    for (int e = 0; e < ne_; ++e) order[static_cast<std::size_t>(e)] = e;
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return out.screened[static_cast<std::size_t>(a)].score >
               out.screened[static_cast<std::size_t>(b)].score;
    });
    for (int e : order) {
        const auto& se = out.screened[static_cast<std::size_t>(e)];
        if (!se.screened) {
            say("  screen " + se.name + ": not screened, its probe failed");
            continue;
        }
        if (!se.testable) {
            say("  screen " + se.name +
                ": not testable on these data, its probe moved no feature (largest change " +
                format(se.largestChange, 2) + " standard errors)");
            continue;
        }
        say("  screen " + se.name + ": score " + format(se.score, 3) + ", p = " + format(se.pValue, 3) +
            (se.wrongSign ? " (the data want it outside its physical range)" : "") + ", linearised " +
            findEffect(se.name, "").parameter + " change " + format(se.amplitude, 3));
    }
    return order;
}

// The gap exceeds the scatter when the omnibus test rejects, or when one effect's
// targeted score test rejects after a Bonferroni correction for the number screened
// (an effect concentrates its signature in one direction, which the omnibus test
// dilutes over every degree of freedom). Says how alike the significant effects' signatures are.
bool Analysis::gapExceedsScatter(const ExplainOutcome& out, const std::vector<int>& order,
                                 const std::vector<Eigen::VectorXd>& projected)
{
    auto cosine = [&](int a, int b) {
        const double na = projected[static_cast<std::size_t>(a)].norm(),
                     nb = projected[static_cast<std::size_t>(b)].norm();
        return na > 0 && nb > 0
                   ? projected[static_cast<std::size_t>(a)].dot(projected[static_cast<std::size_t>(b)]) /
                         (na * nb)
                   : 0.0;
    };
    double smallestScoreP = 1.0;
    for (const auto& se : out.screened) smallestScoreP = std::min(smallestScoreP, se.pValue);
    const bool gapBeyondScatter =
        out.baselinePValue < s_.significance || smallestScoreP < s_.significance / std::max(1, ne_);
    for (std::size_t a = 0; a < order.size(); ++a)
        for (std::size_t b = a + 1; b < order.size(); ++b) {
            const auto& ea = out.screened[static_cast<std::size_t>(order[a])];
            const auto& eb = out.screened[static_cast<std::size_t>(order[b])];
            if (ea.pValue < s_.significance && eb.pValue < s_.significance && !ea.wrongSign && !eb.wrongSign)
                say("  " + ea.name + " and " + eb.name + ": cosine of their projected signatures " +
                    format(cosine(order[a], order[b]), 3));
        }
    return gapBeyondScatter;
}

}  // namespace rockfrac::explain::detail
