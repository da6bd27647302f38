#include "explain/explainGap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "calibration/studyRunner.hpp"
#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "effects/modelEffect.hpp"
#include "explain/explainAnalysis.hpp"

namespace rockfrac::explain {

namespace fs = std::filesystem;

const char* verdictName(Verdict v)
{
    switch (v) {
        case Verdict::noGapBeyondScatter:
            return "noGapBeyondScatter";
        case Verdict::explained:
            return "explained";
        case Verdict::indistinguishable:
            return "indistinguishable";
        case Verdict::partlyExplained:
            return "partlyExplained";
        case Verdict::unexplained:
            return "unexplained";
        case Verdict::inconclusive:
            return "inconclusive";
    }
    return "?";
}

namespace detail {

// " Pa" after a value; nothing for a dimensionless one (unit "-" or none).
std::string unitSuffix(const std::string& unit)
{
    return unit.empty() || unit == "-" ? std::string() : " " + unit;
}

// What each feature needs to be measured, for "the measurement that would separate them".
const char* measurementFor(int feature)
{
    switch (feature) {
        case peakForce:
            return "the failure loads";
        case peakForceSpread:
            return "more specimens (the spread of the failure loads)";
        case peakDisplacement:
            return "the displacement at failure";
        case secantStiffness:
            return "full force-displacement curves (the stiffness between 30 and 70 % of the peak)";
        case toeIndex:
            return "full force-displacement curves from the first contact (the toe)";
        case softening:
            return "force-displacement curves past the peak (the softening)";
    }
    return "?";
}

std::string format(double v, int digits)
{
    char b[64];
    std::snprintf(b, sizeof(b), "%.*g", digits, v);
    return b;
}

void Analysis::splitMeasurements()
{
    for (const TestCondition& condition : s_.conditions) {
        ConditionData data;
        const auto& specimens = condition.measurements.specimens;
        const std::size_t n = specimens.size();
        const std::size_t nHeld =
            static_cast<std::size_t>(std::lround(s_.heldOutFraction * static_cast<double>(n)));
        if (n < 6 || nHeld < 3 || n - nHeld < 3)
            throw UserError(
                condition.measurementsFile.string() + ": " + std::to_string(n) +
                " specimens; explainGap fits on some and checks on the others held out (heldOut " +
                format(s_.heldOutFraction) +
                "), and each part needs at least 3: give at least 6 specimens, or change heldOut in " +
                s_.dictionary.string());
        data.curves = std::all_of(specimens.begin(), specimens.end(),
                                  [](const auto& sp) { return sp.curve.has_value(); });
        // Every k-th specimen is held out, spread over the file order (no cherry-picking).
        for (std::size_t i = 0; i < n; ++i) {
            const bool isHeld =
                static_cast<std::size_t>(
                    std::floor((static_cast<double>(i) + 1) * nHeld / static_cast<double>(n))) >
                static_cast<std::size_t>(std::floor(static_cast<double>(i) * nHeld / static_cast<double>(n)));
            Half& h = isHeld ? data.held : data.cal;
            const auto& sp = specimens[i];
            h.ids.push_back(sp.id);
            if (data.curves) {
                std::string why;
                const auto c = curveFeatures(sp.curve->displacement, sp.curve->force, &why);
                if (!c)
                    throw UserError(
                        sp.curve->file.string() + " (specimen " + sp.id + "): " + why +
                        "; explainGap compares curves up to and past the failure: give the whole curve "
                        "to the load drop, or leave out every curve to compare failure loads only");
                h.curves.push_back(*c);
                h.loads.push_back(c->peakForce);
                h.displacement.push_back(sp.curve->displacement);
                h.force.push_back(sp.curve->force);
            } else {
                h.loads.push_back(sp.failureLoad);
            }
        }
        for (Half* h : {&data.cal, &data.held})
            h->features = data.curves ? summarise(h->curves, s_.statistics)
                                      : summariseFailureLoads(h->loads, s_.statistics);
        std::vector<int> wanted = s_.requestedFeatures;
        if (wanted.empty())
            for (int f = 0; f < nFeatures; ++f) wanted.push_back(f);
        for (int f : wanted) {
            if (data.cal.features.available[f])
                obs_.push_back({static_cast<int>(cond_.size()), f});
            else if (!s_.requestedFeatures.empty())
                throw UserError(s_.dictionary.string() + ": feature '" + featureName(f) +
                                "' needs curves, and " + condition.measurementsFile.string() +
                                " has failure loads only");
        }
        cond_.push_back(std::move(data));
    }
}

// The measured halves summarised again (after a switch to robust statistics).
void Analysis::summariseMeasured()
{
    for (ConditionData& data : cond_)
        for (Half* h : {&data.cal, &data.held})
            h->features = data.curves ? summarise(h->curves, s_.statistics)
                                      : summariseFailureLoads(h->loads, s_.statistics);
}

void Analysis::readBaselineValues()
{
    theta0_.clear();
    for (const auto& b : s_.baseline) {
        double first = 0.0;
        for (std::size_t c = 0; c < s_.conditions.size(); ++c) {
            const fs::path file = s_.conditions[c].targetCase / b.where.file;
            const Dictionary d = Dictionary::readFile(file);
            const double v = d.getScalar(b.where.entry, Bounds::any());
            if (v < b.where.low || v > b.where.high)
                throw UserError(s_.dictionary.string() + ": baseline parameter '" + b.where.name + "' is " +
                                format(v) + " in the case, outside its range (" + format(b.where.low) + " " +
                                format(b.where.high) + "); widen the range");
            if (c == 0) first = v;
            if (v != first)
                throw UserError(file.string() + ": " + b.where.entry + " is " + format(v, 8) + ", and " +
                                format(first, 8) + " in " + s_.conditions.front().targetCase.string() +
                                ": the conditions model the same rock, so their cases must start from the "
                                "same calibrated values; set them equal");
        }
        theta0_.push_back(first);
    }
    for (const std::string& name : s_.effects) theta0_.push_back(findEffect(name, "").neutral);
}

// The study as read: conditions, specimens, halves, seeds and the features compared.
void Analysis::describeStudy()
{
    for (std::size_t c = 0; c < cond_.size(); ++c) {
        const TestCondition& condition = s_.conditions[c];
        say((several() ? "condition " + condition.name + ": " : std::string()) +
            std::to_string(condition.measurements.specimens.size()) + " specimens in " +
            condition.measurementsFile.string() + " (" + std::to_string(cond_[c].cal.ids.size()) +
            " to fit, " + std::to_string(cond_[c].held.ids.size()) + " held out), " +
            (cond_[c].curves ? "with curves" : "failure loads only") + "; model case " +
            condition.targetCase.string() + ", " + std::to_string(s_.seeds.values.size()) +
            " Voronoi seeds per evaluation");
    }
    std::string features;
    for (const Observed& o : obs_) features += std::string(features.empty() ? "" : ", ") + label(o);
    say("features compared: " + features);
}

// Every effect at its neutral value (and its fixed entries) in the templates' modelEffects.
void Analysis::writeEffectTemplates()
{
    for (const auto& run : runs_) calibration::prepareTemplate(run);
    std::ostringstream body;
    for (const std::string& name : s_.effects) {
        const EffectDescriptor& d = findEffect(name, "");
        body << name << "\n{\n    " << d.parameter << " " << formatNumber(d.neutral)
             << ";   // neutral: off\n";
        for (const auto& [entry, value] : s_.effectFixed[name])
            body << "    " << entry << " " << value << ";\n";
        body << "}\n";
    }
    for (const auto& run : runs_) writeTemplateEffects(run, body.str());
}

ExplainOutcome Analysis::execute()
{
    ExplainOutcome out;
    readBaselineValues();
    describeStudy();
    writeEffectTemplates();
    // The set-up before any fit: the specimens' dimensions against the model case's.
    checkGeometry(out);
    // 1. The baseline as the case has it, and its scatter over the seeds; odd specimens
    // and members first (robust statistics, or no conclusion).
    base0_ = evaluate(theta0_, "baseline");
    if (!checkOddMembers(out)) {
        out.simulations = simulations_;
        say(out.sentence.substr(std::string("explainGap: ").size()));
        writeResult(out, -1);
        return out;
    }
    evaluateBaseline();
    // 2. Sensitivities: baseline parameters by a relative step, effects by their probe.
    probeSensitivities();
    saySignatures();
    // 3. The baseline re-fitted on the calibration half: is what is left beyond the scatter?
    std::string fitted;
    const Fit baseline = refitBaseline(out, fitted);
    // 4. Score test of every effect at the re-fitted baseline.
    std::vector<Eigen::VectorXd> projected;
    const std::vector<int> order = screenEffects(baseline, out, projected);
    std::vector<Fit> fits;
    int bestEffect = -1;
    if (!gapExceedsScatter(out, order, projected)) {
        out.verdict = Verdict::noGapBeyondScatter;
        out.sentence =
            "explainGap: no missing effect is needed: the baseline, re-fitted (" + fitted +
            "), is within the model's own scatter (chi-square p = " + format(out.baselinePValue, 3) + ").";
    } else {
        // 5. Confirm the significant candidates by a joint refit, judged on the held-out half.
        const std::vector<int> candidates = confirmCandidates(order, baseline, out, fits);
        bestEffect = decideVerdict(candidates, fits, out);
    }
    // Pairs of the top-ranked effects when no single one passes the absolute test.
    Fit pairFit;
    std::vector<int> augmented;
    if (bestEffect >= 0) augmented.push_back(bestEffect);
    const Fit* effectFit = bestEffect >= 0 ? &fits[static_cast<std::size_t>(bestEffect)] : nullptr;
    if (screenPairs(order, baseline, fits, out, pairFit)) {
        const PairFit& p = out.pairs[static_cast<std::size_t>(out.namedPair)];
        const auto index = [&](const std::string& name) {
            return static_cast<int>(std::find(s_.effects.begin(), s_.effects.end(), name) -
                                    s_.effects.begin());
        };
        augmented = {index(p.first), index(p.second)};
        effectFit = &pairFit;
        bestEffect = -1;
    }
    if (!out.geometryFinding.empty()) out.sentence += " " + out.geometryFinding;
    out.simulations = simulations_;
    say(out.sentence.substr(std::string("explainGap: ").size()));
    writeOutputs(out, baseline, effectFit, augmented);
    return out;
}

}  // namespace detail

ExplainOutcome explainGap(ExplainStudy study, int jobs)
{
    detail::Analysis analysis(std::move(study), jobs);
    return analysis.execute();
}

}  // namespace rockfrac::explain
