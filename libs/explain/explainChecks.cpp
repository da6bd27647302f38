// explainGap's checks before any fit: the specimens' dimensions against the model case's,
// and specimens or model members that fail differently from the rest of their set
// (docs/explainGap.md, "Odd specimens" and "Geometry check").
#include <algorithm>

#include "explain/explainAnalysis.hpp"
#include "explain/geometryCheck.hpp"
#include "explain/outliers.hpp"
#include "io/textTable.hpp"

namespace rockfrac::explain::detail {

namespace fs = std::filesystem;

// The specimens' dimensions, where the measurements give them, against the model case's
// (its prepared template's constant/geometryProperties); a mismatch is its own finding.
void Analysis::checkGeometry(ExplainOutcome& out)
{
    std::string mismatches;
    for (std::size_t c = 0; c < cond_.size(); ++c) {
        const std::string where = several() ? "condition " + conditionName(c) + ": " : std::string();
        const fs::path properties = runs_[c].templateDirectory() / "constant/geometryProperties";
        const auto comparisons = compareGeometry(s_.conditions[c].measurements, properties);
        if (comparisons.empty()) {
            say(where + "geometry not compared: " +
                (fs::exists(properties) ? std::string("the measurements give no specimen dimensions")
                                        : "the prepared model case has no constant/geometryProperties"));
            continue;
        }
        for (const GeometryComparison& g : comparisons) {
            say(where + "geometry: " + describeComparison(g) +
                (g.mismatch ? " (beyond the tolerance of " + format(100 * geometryTolerance, 2) + " %)"
                            : " (within " + format(100 * geometryTolerance, 2) + " %)"));
            if (!g.mismatch) continue;
            if (std::find(out.geometryMismatch.begin(), out.geometryMismatch.end(), g.quantity) ==
                out.geometryMismatch.end())
                out.geometryMismatch.push_back(g.quantity);
            mismatches += (mismatches.empty() ? "" : "; ") + where + describeComparison(g);
        }
    }
    if (mismatches.empty()) return;
    out.geometryFinding = "Set-up finding: the specimens do not have the model case's geometry (" +
                          mismatches + "; tolerance " + format(100 * geometryTolerance, 2) +
                          " %): this is an error of the set-up, not a physical effect, and an effect or "
                          "strength named above may stand in for it; give the case the specimens' "
                          "dimensions and run explainGap again.";
    say(out.geometryFinding);
}

// Specimens and baseline members whose failure peak is far from their set's median
// (outliers.hpp). With some: robust statistics (medians, scaled MAD) from here on; with too
// many in a set: no conclusion (false, out's verdict and sentence set).
bool Analysis::checkOddMembers(ExplainOutcome& out)
{
    std::string tooMany;
    auto check = [&](std::size_t c, bool measured, const std::vector<std::string>& ids,
                     const std::vector<double>& peaks) {
        const std::string name = several() ? conditionName(c) : std::string();
        const std::string set =
            std::string(measured ? "measured specimens" : "model members (baseline seeds)") +
            (name.empty() ? "" : " of condition " + name);
        if (peaks.size() < 3) {
            say("odd specimens: the " + std::to_string(peaks.size()) + " " + set +
                " are not judged (fewer than 3: no median to judge by)");
            return;
        }
        const auto odd = oddFailures(peaks);
        const double median = medianOf(peaks);
        for (const OddSpecimen& o : odd) {
            out.oddMembers.push_back({name, measured, ids[o.index], o.peak, o.ratio});
            say("odd " + std::string(measured ? "specimen " : "model member, seed ") + ids[o.index] +
                (name.empty() ? "" : " (" + name + ")") + ": failure peak " + format(o.peak, 4) + " N, " +
                format(o.ratio, 2) + " times the median " + format(median, 4) + " N of the " + set +
                ": it fails differently from the rest (rule: a peak below " + format(oddLowRatio, 2) +
                " or above " + format(oddHighRatio, 2) + " times the median)");
        }
        if (tooManyOdd(odd.size(), peaks.size()))
            tooMany += (tooMany.empty() ? "" : "; ") + std::to_string(odd.size()) + " of " +
                       std::to_string(peaks.size()) + " " + set;
    };
    for (std::size_t c = 0; c < cond_.size(); ++c) {
        std::vector<std::string> ids;
        std::vector<double> peaks;
        for (const Half* h : {&cond_[c].cal, &cond_[c].held}) {
            ids.insert(ids.end(), h->ids.begin(), h->ids.end());
            peaks.insert(peaks.end(), h->loads.begin(), h->loads.end());
        }
        check(c, true, ids, peaks);
        std::vector<double> memberPeaks;
        for (const CurveFeatures& f : base0_[c].features) memberPeaks.push_back(f.peakForce);
        check(c, false, base0_[c].seeds, memberPeaks);
    }
    writeOddMembers(out);
    if (!tooMany.empty()) {
        out.verdict = Verdict::inconclusive;
        out.sentence =
            "explainGap: no conclusion: too many fail differently from the rest (" + tooMany +
            "; more than " + format(100 * tooManyOddFraction, 2) +
            " % of a set): neither a mean nor a median describes one failure mode there. Check "
            "those specimens (a contact cell lost under a plate, a disc crushed without a split) "
            "or the model case (its resolution near the plates, its stop criterion), leave the odd "
            "ones out, and run explainGap again; outliers.dat lists them.";
        return false;
    }
    if (out.oddMembers.empty()) {
        say("odd specimens: none (every failure peak within " + format(oddLowRatio, 2) + " to " +
            format(oddHighRatio, 2) + " times its set's median)");
        return true;
    }
    if (s_.statistics == Statistics::mean) {
        s_.statistics = Statistics::median;
        out.robustStatistics = true;
        summariseMeasured();
        say("odd specimens present: every set is summarised by medians and the scaled median absolute "
            "deviation (statistics median) instead of means and standard deviations, so that they do not "
            "move it (outliers.dat lists them)");
    } else {
        say("odd specimens present: the sets are already summarised by medians (statistics median)");
    }
    return true;
}

// A later evaluation's members that fail differently from the rest: said, so that a jump in
// a probe or a refit can be traced (with statistics mean they move that point's features).
void Analysis::noteOddMembers(const std::string& pointLabel, const RunsPerCondition& runs)
{
    for (std::size_t c = 0; c < runs.size(); ++c) {
        std::vector<double> peaks;
        for (const CurveFeatures& f : runs[c].features) peaks.push_back(f.peakForce);
        for (const OddSpecimen& o : oddFailures(peaks))
            say("  note: " + pointLabel + (several() ? " (" + conditionName(c) + ")" : std::string()) +
                ": seed " + runs[c].seeds[o.index] + " fails at " + format(o.ratio, 2) +
                " times the members' median peak (an odd member" +
                (s_.statistics == Statistics::mean ? "; statistics mean lets it move this point)" : ")"));
    }
}

// outliers.dat: every odd specimen and baseline member.
void Analysis::writeOddMembers(const ExplainOutcome& out) const
{
    TextTable table;
    table.names = {"condition", "set", "id", "failurePeak", "ratioToMedian"};
    table.units = {"-", "-", "-", "N", "-"};
    for (const OddMember& m : out.oddMembers)
        table.rows.push_back({m.condition.empty() ? "-" : m.condition, m.measured ? "measured" : "model",
                              m.id, format(m.peak, 6), format(m.ratio, 4)});
    writeTextTable(s_.directory / "outliers.dat", table);
}

}  // namespace rockfrac::explain::detail
