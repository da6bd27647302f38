// explainGap's outputs: the gap, metrics and screening tables, the result and report
// files, the augmented case and the plots (docs/explainGap.md "Outputs").
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/atomicFile.hpp"
#include "core/dictionary.hpp"
#include "core/dictionaryEditor.hpp"
#include "core/error.hpp"
#include "effects/modelEffect.hpp"
#include "explain/explainAnalysis.hpp"
#include "io/textTable.hpp"
#include "plot/gnuplot.hpp"
#include "stats/distances.hpp"

namespace rockfrac::explain::detail {

namespace fs = std::filesystem;

void Analysis::writeOutputs(const ExplainOutcome& out, const Fit& baseline, const Fit* effect,
                            const std::vector<int>& effectIndices)
{
    const Summaries& after = effect ? effect->model : baseline.model;
    const RunsPerCondition& afterRuns = effect ? effect->runs : baseline.runs;
    writeGapTable(baseline, after);
    writeGapMetrics(baseline, after, afterRuns);
    writeScreeningTable(out);
    // A single effect's value and interval go to the result; a pair's are in out.pairs.
    writeResult(out, out.namedPair < 0 && !effectIndices.empty() ? effectIndices.front() : -1);
    if (effect) writeAugmentedCases(out, *effect, effectIndices);
    // Plots: normalised residuals before/after, and the mean curves.
    try {
        drawResidualPlot(baseline, after, out, effect != nullptr);
        for (std::size_t k = 0; k < cond_.size(); ++k) {
            if (!cond_[k].curves) continue;
            drawCurvePlot(k, baseline, afterRuns, out, effect != nullptr);
        }
    } catch (const UserError& e) {
        say(std::string("plots not drawn: ") + e.what());
    }
}

// Gap table: every observed feature, measured and simulated, before and after.
void Analysis::writeGapTable(const Fit& baseline, const Summaries& after) const
{
    const fs::path dir = s_.directory;
    TextTable table;
    table.names = {"feature",   "measuredFit",     "baseline",       "withEffect",   "zFitBefore",
                   "zFitAfter", "measuredHeldOut", "zHeldOutBefore", "zHeldOutAfter"};
    table.units = {"-", "SI", "SI", "SI", "-", "-", "SI", "-", "-"};
    const Eigen::VectorXd zb = residual(baseline.model, false, sigmaCal_),
                          za = residual(after, false, sigmaCal_);
    const Eigen::VectorXd hb = residual(baseline.model, true, sigmaHeld_),
                          ha = residual(after, true, sigmaHeld_);
    for (std::size_t i = 0; i < obs_.size(); ++i) {
        const Observed& o = obs_[i];
        const int f = o.feature;
        const std::size_t c = static_cast<std::size_t>(o.condition);
        const int k = static_cast<int>(i);
        table.rows.push_back({label(o) + "[" + featureUnit(f) + "]",
                              format(cond_[c].cal.features.value[f], 6),
                              format(baseline.model[c].value[f], 6), format(after[c].value[f], 6),
                              format(zb[k], 3), format(za[k], 3), format(cond_[c].held.features.value[f], 6),
                              format(hb[k], 3), format(ha[k], 3)});
    }
    writeTextTable(dir / "gapTable.dat", table);
}

// The calibration issue's metrics on the held-out half, before and after (per condition).
void Analysis::writeGapMetrics(const Fit& baseline, const Summaries& after,
                               const RunsPerCondition& afterRuns) const
{
    const fs::path dir = s_.directory;
    auto peaks = [](const PointRuns& runs) {
        std::vector<double> p;
        for (const auto& c : runs.features) p.push_back(c.peakForce);
        return p;
    };
    TextTable metrics;
    metrics.names = {"metric", "baseline", "withEffect"};
    metrics.units = {"-", "-", "-"};
    for (std::size_t c = 0; c < cond_.size(); ++c) {
        const Half& held = cond_[c].held;
        const PointRuns &before = baseline.runs[c], &withEffect = afterRuns[c];
        const std::string prefix = several() ? conditionName(c) + ":" : "";
        metrics.rows.push_back({prefix + "KS_failureLoads",
                                format(stats::kolmogorovSmirnov(held.loads, peaks(before)), 3),
                                format(stats::kolmogorovSmirnov(held.loads, peaks(withEffect)), 3)});
        metrics.rows.push_back({prefix + "W1_failureLoads[N]",
                                format(stats::wasserstein1(held.loads, peaks(before)), 4),
                                format(stats::wasserstein1(held.loads, peaks(withEffect)), 4)});
        auto relative = [&](const Summaries& m, int f) {
            return format(100 * (m[c].value[f] - held.features.value[f]) / held.features.value[f], 3);
        };
        metrics.rows.push_back(
            {prefix + "peakForceError[%]", relative(baseline.model, peakForce), relative(after, peakForce)});
        if (!cond_[c].curves) continue;
        metrics.rows.push_back({prefix + "peakDisplacementError[%]",
                                relative(baseline.model, peakDisplacement),
                                relative(after, peakDisplacement)});
        metrics.rows.push_back({prefix + "secantStiffnessError[%]", relative(baseline.model, secantStiffness),
                                relative(after, secantStiffness)});
        metrics.rows.push_back({prefix + "toeIndexDifference",
                                format(baseline.model[c].value[toeIndex] - held.features.value[toeIndex], 3),
                                format(after[c].value[toeIndex] - held.features.value[toeIndex], 3)});
        const double upTo = held.features.value[peakDisplacement];
        const auto measured = meanCurve(held.displacement, held.force, upTo, 50);
        auto nrms = [&](const PointRuns& runs) {
            const auto sim = meanCurve(runs.displacement, runs.force, upTo, 50);
            double sum = 0;
            for (std::size_t i = 0; i < sim.size(); ++i)
                sum += (sim[i] - measured[i]) * (sim[i] - measured[i]);
            return std::sqrt(sum / static_cast<double>(sim.size())) / held.features.value[peakForce];
        };
        metrics.rows.push_back({prefix + "curveNRMS", format(nrms(before), 3), format(nrms(withEffect), 3)});
    }
    writeTextTable(dir / "gapMetrics.dat", metrics);
}

void Analysis::writeScreeningTable(const ExplainOutcome& out) const
{
    const fs::path dir = s_.directory;
    TextTable screen;
    screen.names = {"effect",    "status", "score", "p",      "linearisedChange",
                    "refitted",  "value",  "low90", "high90", "heldOutGap",
                    "reduction", "AIC",    "kept"};
    screen.units = {"-", "-", "-", "-", "-", "-", "-", "-", "-", "-", "-", "-", "-"};
    for (const auto& se : out.screened) {
        const bool tested = se.screened && se.testable;
        screen.rows.push_back(
            {se.name, !se.screened ? "probeFailed" : (se.testable ? "screened" : "notTestable"),
             tested ? format(se.score, 4) : "-", tested ? format(se.pValue, 3) : "-",
             tested ? format(se.amplitude, 4) : "-", se.confirmed ? "yes" : "no",
             se.confirmed ? format(se.value, 4) : "-", se.confirmed ? format(se.intervalLow, 4) : "-",
             se.confirmed ? format(se.intervalHigh, 4) : "-", se.confirmed ? format(se.heldOutGap, 3) : "-",
             se.confirmed ? format(se.reduction, 3) : "-", se.confirmed ? format(se.aic, 4) : "-",
             se.kept ? "yes" : "no"});
    }
    writeTextTable(dir / "screening.dat", screen);
}

// Machine-readable result (tests and scripts read it), and the report: every line said.
void Analysis::writeResult(const ExplainOutcome& out, int effectIndex) const
{
    const fs::path dir = s_.directory;
    writeFileAtomically(dir / "explainGap.result", [&](std::ostream& o) {
        o << "FoamFile { format ascii; class dictionary; object explainGapResult; }\n\n"
          << "verdict            " << verdictName(out.verdict) << ";\n"
          << "effect             \"" << out.effect << "\";\n"
          << "alternatives       (";
        for (std::size_t i = 0; i < out.alternatives.size(); ++i) o << (i ? " " : "") << out.alternatives[i];
        o << ");\nseparatingMeasurement \"" << out.separatingMeasurement << "\";\n"
          << "baselineChiSquare  " << format(out.baselineChiSquare, 6) << ";\n"
          << "baselinePValue     " << format(out.baselinePValue, 6) << ";\n"
          << "baselineHeldOutGap " << format(out.baselineHeldOutGap, 6) << ";\n";
        if (effectIndex >= 0) {
            const auto& se = out.screened[static_cast<std::size_t>(effectIndex)];
            o << "value              " << format(se.value, 6) << ";\ninterval           ("
              << format(se.intervalLow, 6) << " " << format(se.intervalHigh, 6) << ");\nheldOutGap         "
              << format(se.heldOutGap, 6) << ";\nreduction          " << format(se.reduction, 6) << ";\n"
              << "heldOutChiSquare   " << format(se.heldOutChiSquare, 6) << ";\nheldOutPValue      "
              << format(se.heldOutPValue, 6) << ";\nrefitConverged     " << (se.converged ? "yes" : "no")
              << ";\n";
        }
        auto list = [&](const char* key, const std::vector<std::string>& words) {
            o << key << " (";
            for (std::size_t i = 0; i < words.size(); ++i) o << (i ? " " : "") << "\"" << words[i] << "\"";
            o << ");\n";
        };
        list("remaining         ", out.remaining);
        if (out.namedPair >= 0) {
            const PairFit& p = out.pairs[static_cast<std::size_t>(out.namedPair)];
            o << "pair               (" << p.first << " " << p.second << ");\npairValues         ("
              << format(p.firstValue, 6) << " " << format(p.secondValue, 6) << ");\nreduction          "
              << format(p.reduction, 6) << ";\nheldOutChiSquare   " << format(p.heldOutChiSquare, 6)
              << ";\nheldOutPValue      " << format(p.heldOutPValue, 6) << ";\nrefitConverged     "
              << (p.converged ? "yes" : "no") << ";\n";
        }
        o << "pairsRefitted      " << out.pairs.size() << ";\npairSimulations    " << out.pairSimulations
          << ";\n";
        std::vector<std::string> oddSpecimens, oddMembers;
        for (const OddMember& m : out.oddMembers)
            (m.measured ? oddSpecimens : oddMembers)
                .push_back((m.condition.empty() ? "" : m.condition + ":") + m.id);
        list("oddSpecimens      ", oddSpecimens);
        list("oddModelMembers   ", oddMembers);
        o << "robustStatistics   " << (out.robustStatistics ? "yes" : "no") << ";\n";
        list("geometryMismatch  ", out.geometryMismatch);
        o << "simulations        " << out.simulations << ";\n";
    });
    writeFileAtomically(dir / "explainGap.report", [&](std::ostream& o) {
        for (const auto& line : log_) o << line << "\n";
    });
}

// The augmented case: the effect switched on with its fitted size, the baseline re-fitted;
// with several conditions one per condition (augmentedCase/<condition>).
void Analysis::writeAugmentedCases(const ExplainOutcome& out, const Fit& effect,
                                   const std::vector<int>& effectIndices)
{
    const fs::path dir = s_.directory;
    fs::remove_all(dir / "augmentedCase");
    for (std::size_t c = 0; c < cond_.size(); ++c) {
        const fs::path augmented =
            several() ? dir / "augmentedCase" / conditionName(c) : dir / "augmentedCase";
        fs::create_directories(augmented);
        for (const char* sub : {"system", "constant"})
            fs::copy(s_.conditions[c].targetCase / sub, augmented / sub, fs::copy_options::recursive);
        for (int j = 0; j < nb_; ++j) {
            const auto& b = s_.baseline[static_cast<std::size_t>(j)];
            setEntryInFile(augmented / b.where.file, b.where.entry,
                           formatNumber(effect.values[static_cast<std::size_t>(j)]));
        }
        for (const auto& t : s_.tied)
            setEntryInFile(augmented / t.file, t.entry, formatNumber(t.factor * effect.values[t.parameter]));
        writeFileAtomically(augmented / "constant/modelEffects", [&](std::ostream& o) {
            o << "FoamFile { format ascii; class dictionary; object modelEffects; }\n\n"
              << "// Written by explainGap (" << s_.directory.filename().string() << ").\n"
              << "// " << out.sentence << "\n";
            for (int e : effectIndices) {
                const std::string& name = s_.effects[static_cast<std::size_t>(e)];
                const EffectDescriptor& d = findEffect(name, "");
                o << "// " << d.physics << ".\n"
                  << name << "\n{\n    " << d.parameter << " "
                  << formatNumber(effect.values[static_cast<std::size_t>(nb_ + e)]) << ";\n";
                for (const auto& [entry, value] : s_.effectFixed[name])
                    o << "    " << entry << " " << value << ";\n";
                o << "}\n";
            }
        });
    }
}

namespace {

// A case judged as calibrated (no baseline parameter free) is not re-fitted.
std::string plotBaselineTitle(int nb)
{
    return nb > 0 ? "baseline re-fitted" : "baseline (as calibrated)";
}

}  // namespace

// The held-out features' errors in standard errors, before and after, as bars.
void Analysis::drawResidualPlot(const Fit& baseline, const Summaries& after, const ExplainOutcome& out,
                                bool effectKept) const
{
    const fs::path dir = s_.directory;
    const Eigen::VectorXd hb = residual(baseline.model, true, sigmaHeld_),
                          ha = residual(after, true, sigmaHeld_);
    std::vector<std::vector<double>> rows;
    std::string labels;
    // The bars start at zero: the range must hold it (gnuplot's autoscale fits the bar
    // ends only, which cut every bar of a one-signed set at its shortest end).
    double zLow = 0.0, zHigh = 0.0;
    for (std::size_t i = 0; i < obs_.size(); ++i) {
        rows.push_back({static_cast<double>(i), hb[static_cast<int>(i)], ha[static_cast<int>(i)]});
        for (double z : {hb[static_cast<int>(i)], ha[static_cast<int>(i)]}) {
            if (std::isfinite(z)) {
                zLow = std::min(zLow, z);
                zHigh = std::max(zHigh, z);
            }
        }
        labels += std::string(i ? ", " : "") + "\"" + label(obs_[i]) + "\" " + std::to_string(i);
    }
    const std::string baselineTitle = plotBaselineTitle(nb_);
    std::ostringstream g;
    g << plot::gnuplotDataBlock("z", rows) << "set title "
      << plot::gnuplotString("Held-out specimens: feature error in standard errors (measured - simulated)")
      << "\nset style data histogram\nset style histogram clustered gap 1\nset style fill solid 0.8 "
         "border -1\n"
      << "set xtics (" << labels << ") rotate by -20\nset ylabel \"z\"\nset grid ytics\nset xzeroaxis lt -1\n"
      << "set yrange [" << format(zLow - 0.1 * (zHigh - zLow + 1.0), 4) << ":"
      << format(zHigh + 0.1 * (zHigh - zLow + 1.0), 4) << "]\n"
      << plot::legendBelowPlot(2) << "plot $z using 2 title " << plot::gnuplotString(baselineTitle) << " "
      << plot::seriesColour(0) << ", $z using 3 title "
      << plot::gnuplotString(effectKept ? "with " + out.effect : "(no effect kept)") << " "
      << plot::seriesColour(1) << "\n";
    // Wider for the stacked features of several conditions.
    plot::renderPng(g.str(), dir / "residuals.png", 900 + 60 * std::max(0, static_cast<int>(obs_.size()) - 6),
                    600);
}

// The mean curves of condition k, measured and simulated, before and after.
void Analysis::drawCurvePlot(std::size_t k, const Fit& baseline, const RunsPerCondition& afterRuns,
                             const ExplainOutcome& out, bool effectKept) const
{
    const fs::path dir = s_.directory;
    const std::string baselineTitle = plotBaselineTitle(nb_);
    const Half& held = cond_[k].held;
    // Far enough for every mean curve to show its peak: a model that fails at three
    // times the measured displacement (the DEM against the FEM on an SPB rock) would
    // otherwise be cut on its rising branch.
    const double upTo =
        1.3 * std::max({held.features.value[peakDisplacement],
                        meanPeakDisplacement(baseline.runs[k].displacement, baseline.runs[k].force),
                        meanPeakDisplacement(afterRuns[k].displacement, afterRuns[k].force)});
    const int n = 120;
    const auto measured = meanCurve(held.displacement, held.force, upTo, n);
    const auto before = meanCurve(baseline.runs[k].displacement, baseline.runs[k].force, upTo, n);
    const auto withEffect = meanCurve(afterRuns[k].displacement, afterRuns[k].force, upTo, n);
    std::vector<std::vector<double>> c;
    for (int i = 0; i < n; ++i)
        c.push_back({1e3 * upTo * i / (n - 1), 1e-3 * measured[static_cast<std::size_t>(i)],
                     1e-3 * before[static_cast<std::size_t>(i)],
                     1e-3 * withEffect[static_cast<std::size_t>(i)]});
    std::ostringstream p;
    p << plot::gnuplotDataBlock("c", c) << "set title "
      << plot::gnuplotString("Mean force-displacement curves, held-out specimens (aligned at contact onset)" +
                             (several() ? ", condition " + conditionName(k) : std::string()))
      << "\nset xlabel \"displacement from contact onset [mm]\"\nset ylabel \"force [kN]\"\nset "
         "grid\n"
      << plot::legendBelowPlot(3) << "plot $c using 1:2 with lines lw 3 lc rgb \"black\" title \"measured\", "
      << "$c using 1:3 with lines lw 2 " << plot::seriesColour(0) << " title "
      << plot::gnuplotString(effectKept ? baselineTitle : baselineTitle + "; no effect kept");
    // Without a kept effect the third curve would be the baseline's again, drawn over it.
    if (effectKept)
        p << ", $c using 1:4 with lines lw 2 " << plot::seriesColour(1) << " title "
          << plot::gnuplotString("with " + out.effect);
    p << "\n";
    plot::renderPng(p.str(), dir / (several() ? "curves-" + conditionName(k) + ".png" : "curves.png"), 900,
                    650);
}

}  // namespace rockfrac::explain::detail
