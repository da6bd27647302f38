// explainGap's pairs: when no single effect passes the absolute test, the top-ranked effects of
// the screening are refitted two at a time with the baseline, and a pair is named only when it
// passes the relative test (with Akaike's penalty for its extra parameter) and the absolute one.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "effects/modelEffect.hpp"
#include "explain/effectPairs.hpp"
#include "explain/explainAnalysis.hpp"

namespace rockfrac::explain::detail {

namespace {

// The joint refit's criteria (explainRefit.cpp): at most this many simulated evaluations per
// pair, its start and eight Gauss-Newton steps.
constexpr int evaluationsPerPair = 9;

}  // namespace

// Effects a and b with the baseline: from the better-ranked effect's single refit (or the
// baseline) with the other at its single refit's value (or its linearised size within three
// probes), then the joint refit to convergence.
Analysis::Fit Analysis::refitPair(int a, int b, const Fit& baseline, const std::vector<Fit>& fits,
                                  const ExplainOutcome& out)
{
    const std::size_t ia = static_cast<std::size_t>(a), ib = static_cast<std::size_t>(b);
    const auto confirmed = [&](std::size_t e) {
        return out.screened[e].confirmed && !fits[e].values.empty();
    };
    Fit from = baseline;
    if (confirmed(ia)) from.values = fits[ia].values;
    const std::size_t jb = static_cast<std::size_t>(nb_) + ib;
    if (confirmed(ib)) {
        from.values[jb] = fits[ib].values[jb];
    } else {
        const double probe = std::fabs(probeSize_[jb]);
        from.values[jb] += std::clamp(out.screened[ib].amplitude, -3 * probe, 3 * probe);
    }
    from.values = clip(from.values);
    const std::string name = "fit-" + out.screened[ia].name + "+" + out.screened[ib].name;
    from.runs = evaluate(from.values, name + "-0");
    from.model = summary(from.runs);
    from.chi = chiCal(from.model);
    std::vector<int> free = baselineFree();
    free.push_back(nb_ + a);
    free.push_back(nb_ + b);
    constexpr RefitControl jointRefit{evaluationsPerPair - 1, 0.05, 0.1, 0.5};
    return refit(free, from, name, &baseline, jointRefit);
}

bool Analysis::screenPairs(const std::vector<int>& order, const Fit& baseline, const std::vector<Fit>& fits,
                           ExplainOutcome& out, Fit& pairFit)
{
    if (out.verdict != Verdict::partlyExplained && out.verdict != Verdict::unexplained) return false;
    if (s_.maxPairs == 0) {
        say("pairs: off (explainGapDict pairs), no pair of effects refitted");
        return false;
    }
    // The ranking of the screening: effects it could test, with a score, best first.
    std::vector<int> ranked;
    for (int e : order) {
        const ScreenedEffect& se = out.screened[static_cast<std::size_t>(e)];
        if (se.screened && se.testable && !se.wrongSign && se.score > 0) ranked.push_back(e);
    }
    const std::vector<std::pair<int, int>> pairs = pairsToScreen(ranked, s_.maxPairs);
    if (pairs.empty()) {
        say("pairs: fewer than two effects with a score, no pair to refit");
        return false;
    }
    const int perEvaluation = static_cast<int>(s_.seeds.values.size() * cond_.size());
    std::string names;
    for (const auto& [a, b] : pairs)
        names += (names.empty() ? "" : ", ") + out.screened[static_cast<std::size_t>(a)].name + "+" +
                 out.screened[static_cast<std::size_t>(b)].name;
    say("pairs: no single effect passes the absolute test; refitting " + std::to_string(pairs.size()) +
        " pair(s) of the top-ranked effects (" + names + "; explainGapDict pairs " +
        std::to_string(s_.maxPairs) + "): up to " + std::to_string(evaluationsPerPair) + " evaluations of " +
        std::to_string(perEvaluation) + " simulations each, at most " +
        std::to_string(static_cast<int>(pairs.size()) * evaluationsPerPair * perEvaluation) +
        " more simulations");
    const int before = simulations_;
    const double aicBaseline = akaike(baseline.chi, nb_);
    int best = -1;
    std::vector<Fit> pairFits;
    for (const auto& [a, b] : pairs) {
        const ScreenedEffect &sa = out.screened[static_cast<std::size_t>(a)],
                             &sb = out.screened[static_cast<std::size_t>(b)];
        PairFit p;
        p.first = sa.name;
        p.second = sb.name;
        Fit fit;
        try {
            fit = refitPair(a, b, baseline, fits, out);
        } catch (const UserError& error) {
            say("  pair " + p.first + "+" + p.second + ": not refitted, its runs failed: " + error.what());
            continue;
        }
        const std::size_t ja = static_cast<std::size_t>(nb_ + a), jb = static_cast<std::size_t>(nb_ + b);
        p.firstValue = fit.values[ja];
        p.secondValue = fit.values[jb];
        const double sdA = std::sqrt(std::max(0.0, fit.covariance(nb_, nb_))),
                     sdB = std::sqrt(std::max(0.0, fit.covariance(nb_ + 1, nb_ + 1)));
        p.firstLow = std::max(parameter(nb_ + a).low, p.firstValue - 1.645 * sdA);
        p.firstHigh = std::min(parameter(nb_ + a).high, p.firstValue + 1.645 * sdA);
        p.secondLow = std::max(parameter(nb_ + b).low, p.secondValue - 1.645 * sdB);
        p.secondHigh = std::min(parameter(nb_ + b).high, p.secondValue + 1.645 * sdB);
        p.chiSquare = fit.chi;
        p.aic = akaike(fit.chi, nb_ + 2);
        p.heldOutGap = heldGap(fit.model);
        p.reduction = out.baselineHeldOutGap > 0 ? 1.0 - p.heldOutGap / out.baselineHeldOutGap : 0.0;
        p.converged = fit.converged;
        // The extra parameter must pay for itself: the pair's AIC below the baseline's and below
        // each of its members' own (when refitted alone).
        double members = aicBaseline;
        for (const ScreenedEffect* se : {&sa, &sb})
            if (se->confirmed) members = std::min(members, se->aic);
        p.relative = p.reduction >= s_.minimumGapReduction && p.aic < members;
        Eigen::VectorXd r;
        const HeldOutTest test = absoluteTest(fit, r);
        p.heldOutChiSquare = test.chiSquare;
        p.heldOutPValue = test.pValue;
        say("  pair " + p.first + "+" + p.second + ": " + describeParameter(nb_ + a, p.firstValue) + ", " +
            describeParameter(nb_ + b, p.secondValue) + ", chi-square " + format(fit.chi, 3) + ", AIC " +
            format(p.aic, 4) + " vs " + format(members, 4) + " (baseline or a member alone), held-out gap " +
            format(p.heldOutGap, 3) + " (" + format(100 * p.reduction, 3) + " %)" +
            (p.relative ? "" : ": fails the relative test") + "; held-out chi-square " +
            format(test.chiSquare, 3) + ", p = " + format(test.pValue, 3) +
            (test.consistent ? ": consistent with the scatter" : ": beyond the scatter") +
            (fit.converged ? "" : "; the refit did not converge (" + fit.stopped + ")"));
        const bool passes = p.relative && test.consistent;
        out.pairs.push_back(p);
        pairFits.push_back(std::move(fit));
        if (passes && (best < 0 || p.aic < out.pairs[static_cast<std::size_t>(best)].aic))
            best = static_cast<int>(out.pairs.size()) - 1;
    }
    out.pairSimulations = simulations_ - before;
    say("pairs: " + std::to_string(out.pairSimulations) + " more simulations");
    if (best < 0) {
        out.sentence +=
            " No pair of the top-ranked effects passes both the relative and the absolute test (" +
            std::to_string(out.pairs.size()) + " refitted, " + std::to_string(out.pairSimulations) +
            " more simulations).";
        return false;
    }
    const PairFit& p = out.pairs[static_cast<std::size_t>(best)];
    out.namedPair = best;
    out.verdict = Verdict::explained;
    out.effect = p.first + "+" + p.second;
    out.remaining.clear();
    const EffectDescriptor &da = findEffect(p.first, ""), &db = findEffect(p.second, "");
    out.sentence = "explainGap: the gap is explained by the pair " + p.first + " (" + da.physics + ") and " +
                   p.second + " (" + db.physics + "), no single effect of the library: " + da.parameter +
                   " = " + format(p.firstValue, 3) + unitSuffix(da.unit) + " (90 % interval " +
                   format(p.firstLow, 3) + " to " + format(p.firstHigh, 3) + "), " + db.parameter + " = " +
                   format(p.secondValue, 3) + unitSuffix(db.unit) + " (90 % interval " +
                   format(p.secondLow, 3) + " to " + format(p.secondHigh, 3) +
                   "); the held-out gap falls by " + format(100 * p.reduction, 3) +
                   " % and what is left is within the scatter (held-out chi-square " +
                   format(p.heldOutChiSquare, 3) + ", p = " + format(p.heldOutPValue, 3) + ")." +
                   (p.converged ? "" : " The joint refit did not converge.");
    pairFit = std::move(pairFits[static_cast<std::size_t>(best)]);
    return true;
}

}  // namespace rockfrac::explain::detail
