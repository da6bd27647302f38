#pragma once
// Internal to libs/explain: the analysis behind explainGap(), one class whose phases
// live in their own files:
//   explainGap.cpp        the measurements split into halves, the baseline's values, the driver
//   explainScreening.cpp  1-4: baseline scatter, sensitivities, baseline refit, score tests
//   explainRefit.cpp      the Gauss-Newton refit, and 5: the candidates' joint refits
//   explainVerdict.cpp    the verdict and its sentence
//   explainChecks.cpp     the checks before any fit: odd specimens and members, geometry
//   explainReport.cpp     the tables, the result and report files, the augmented case, the plots
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "calibration/calibrationStudy.hpp"
#include "explain/chiSquare.hpp"
#include "explain/explainGap.hpp"
#include "explain/pointRuns.hpp"

namespace rockfrac::explain::detail {

// " Pa" after a value; nothing for a dimensionless one (unit "-" or none).
std::string unitSuffix(const std::string& unit);
// What each feature needs to be measured, for "the measurement that would separate them".
const char* measurementFor(int feature);
std::string format(double v, int digits = 4);

// One half of the measured specimens (calibration or held out).
struct Half {
    std::vector<std::string> ids;
    FeatureSummary features;
    std::vector<CurveFeatures> curves;  // per specimen, with curves
    std::vector<double> loads;
    std::vector<std::vector<double>> displacement, force;  // empty without curves
};

// The measured specimens of one test condition, split into the two halves.
struct ConditionData {
    Half cal, held;
    bool curves = false;
};

// One compared number: a feature of one condition. The model's features of all
// conditions are stacked in one vector (condition-major) of nConditions x nFeatures rows.
struct Observed {
    int condition = 0, feature = 0;
};

// The model's features at one point of parameter space, one summary per condition.
using Summaries = std::vector<FeatureSummary>;
using RunsPerCondition = std::vector<PointRuns>;

// When a Gauss-Newton refit stops: converged when the next step moves every parameter by
// less than stepTolerance of its probe, or when an accepted step lowers chi-square by less
// than chiTolerance; after two steps in a row that did not lower chi-square, converged when
// the linearised fit expects another to gain less than expectedGainTolerance; not converged
// after maxSteps simulated steps. The default is the baseline refit's (three steps).
struct RefitControl {
    int maxSteps = 3;
    double stepTolerance = 1e-3;
    double chiTolerance = 0.0;
    double expectedGainTolerance = 0.0;
};

class Analysis {
public:
    Analysis(ExplainStudy study, int jobs) : s_(std::move(study))
    {
        s_.jobs = jobs;
        for (std::size_t c = 0; c < s_.conditions.size(); ++c) runs_.push_back(s_.runStudy(c));
        nb_ = static_cast<int>(s_.baseline.size());
        ne_ = static_cast<int>(s_.effects.size());
        splitMeasurements();
    }

    ExplainOutcome execute();

private:
    ExplainStudy s_;
    std::vector<calibration::CalibrationStudy> runs_;  // one per condition, same parameters
    int nb_ = 0, ne_ = 0;
    std::vector<ConditionData> cond_;
    std::vector<Observed> obs_;  // observed features
    std::vector<double> theta0_;
    RunsPerCondition base0_;
    Summaries model0_;
    std::vector<double> sigmaCal_, sigmaHeld_;  // per observed feature
    Eigen::MatrixXd jacobian_;  // (nConditions x nFeatures) x (nb + ne), physical units per parameter unit
    std::vector<double> probeSize_;  // the step of each parameter's probe
    std::vector<char> probeFailed_;  // its probe's runs failed: not screened
    int simulations_ = 0;
    std::vector<std::string> log_;

    // A point with its runs: the baseline, a probe, a refit.
    struct Fit {
        std::vector<double> values;
        RunsPerCondition runs;
        Summaries model;
        double chi = 0.0;
        Eigen::MatrixXd covariance;  // of the free parameters (linearised)
        // The sensitivities the refit ended with: observed features (whitened by sigmaCal_) per
        // free parameter, in physical units
        Eigen::MatrixXd sensitivities;
        bool converged = false;  // the refit met its criterion (refit())
        int steps = 0;           // simulated Gauss-Newton steps
        std::string stopped;     // why the refit stopped
    };

    // explainGap.cpp: the data and the study.
    void splitMeasurements();
    void readBaselineValues();
    void describeStudy();
    void writeEffectTemplates();
    void summariseMeasured();

    // explainChecks.cpp: before any fit.
    void checkGeometry(ExplainOutcome& out);
    bool checkOddMembers(ExplainOutcome& out);
    void noteOddMembers(const std::string& label, const RunsPerCondition& runs);
    void writeOddMembers(const ExplainOutcome& out) const;

    // explainScreening.cpp: steps 1 to 4.
    void evaluateBaseline();
    double probeStep(int j) const;
    void probeSensitivities();
    void saySignatures();
    Fit refitBaseline(ExplainOutcome& out, std::string& fitted);
    std::vector<int> screenEffects(const Fit& baseline, ExplainOutcome& out,
                                   std::vector<Eigen::VectorXd>& projected);
    bool gapExceedsScatter(const ExplainOutcome& out, const std::vector<int>& order,
                           const std::vector<Eigen::VectorXd>& projected);

    // explainRefit.cpp: Gauss–Newton refit of `free` parameters from `start` (checked by
    // simulation), and step 5.
    Fit refit(const std::vector<int>& free, const Fit& start, const std::string& label,
              const Fit* previous = nullptr, RefitControl control = {});
    std::vector<int> confirmCandidates(const std::vector<int>& order, const Fit& baseline,
                                       ExplainOutcome& out, std::vector<Fit>& fits);
    bool refitWithEffect(int e, const Fit& baseline, const ScreenedEffect& se, Fit& fit);
    const Fit* scanRange(int e, const Fit& baseline, const std::string& name, Fit& from,
                         std::vector<Fit>& tried);
    void judgeRefit(int e, const Fit& fit, double aicBaseline, const ExplainOutcome& out, ScreenedEffect& se);

    // explainVerdict.cpp: the verdict; returns the effect that explains the gap, or -1.
    int decideVerdict(const std::vector<int>& candidates, const std::vector<Fit>& fits, ExplainOutcome& out);
    void testAbsolutely(int top, const Fit& fit, ExplainOutcome& out);
    // The absolute test of a fit on the held-out half; r gets each feature's error in its own
    // standard errors.
    HeldOutTest absoluteTest(const Fit& fit, Eigen::VectorXd& r);
    bool halvesDisagreementSaid_ = false;  // the halves' disagreement is said once
    void describeIndistinguishable(int top, const std::vector<int>& twins, const std::vector<int>& rivals,
                                   ExplainOutcome& out);
    Eigen::VectorXd fullDirection(int e) const;
    int separatingRow(int top, int twin) const;

    // explainPairs.cpp: when no single effect passes the absolute test, pairs of the
    // top-ranked effects; true (with `pairFit` and out.pair) when one passes both tests.
    bool screenPairs(const std::vector<int>& order, const Fit& baseline, const std::vector<Fit>& fits,
                     ExplainOutcome& out, Fit& pairFit);
    Fit refitPair(int a, int b, const Fit& baseline, const std::vector<Fit>& fits, const ExplainOutcome& out);

    // explainReport.cpp: every output file; `effectIndices` the effects switched on in the
    // augmented case (one, or a pair).
    void writeOutputs(const ExplainOutcome& outcome, const Fit& baseline, const Fit* effect,
                      const std::vector<int>& effectIndices);
    void writeGapTable(const Fit& baseline, const Summaries& after) const;
    void writeGapMetrics(const Fit& baseline, const Summaries& after,
                         const RunsPerCondition& afterRuns) const;
    void writeScreeningTable(const ExplainOutcome& out) const;
    void writeResult(const ExplainOutcome& out, int effectIndex) const;
    void writeAugmentedCases(const ExplainOutcome& out, const Fit& effect,
                             const std::vector<int>& effectIndices);
    void drawResidualPlot(const Fit& baseline, const Summaries& after, const ExplainOutcome& out,
                          bool effectKept) const;
    void drawCurvePlot(std::size_t k, const Fit& baseline, const RunsPerCondition& afterRuns,
                       const ExplainOutcome& out, bool effectKept) const;

    void say(const std::string& line)
    {
        std::cout << "explainGap: " << line << std::endl;
        log_.push_back(line);
    }

    const calibration::CalibratedParameter& parameter(int j) const
    {
        return runs_.front().parameters[static_cast<std::size_t>(j)];
    }
    bool several() const { return cond_.size() > 1; }
    const std::string& conditionName(std::size_t c) const { return s_.conditions[c].name; }
    // Rows of the Jacobian: every feature of every condition.
    int featureRows() const { return static_cast<int>(cond_.size()) * nFeatures; }
    static int row(const Observed& o) { return o.condition * nFeatures + o.feature; }
    // The indices of the baseline parameters (the first nb_).
    std::vector<int> baselineFree() const
    {
        std::vector<int> free;
        for (int j = 0; j < nb_; ++j) free.push_back(j);
        return free;
    }
    // "peakForce", or "fast:peakForce" in a study of several conditions.
    std::string label(const Observed& o) const
    {
        return (several() ? conditionName(static_cast<std::size_t>(o.condition)) + ":" : std::string()) +
               featureName(o.feature);
    }
    // One point run in every condition.
    RunsPerCondition evaluate(const std::vector<double>& values, const std::string& label)
    {
        RunsPerCondition all;
        for (const auto& run : runs_) {
            PointRuns r = runPoint(run, values, label, s_.displacementColumn, s_.forceColumn);
            simulations_ += static_cast<int>(r.features.size()) + r.failed;
            all.push_back(std::move(r));
        }
        if (!base0_.empty()) noteOddMembers(label, all);
        return all;
    }
    Summaries summary(const RunsPerCondition& runs) const
    {
        Summaries m;
        for (const auto& r : runs) m.push_back(r.summary(s_.statistics));
        return m;
    }
    const Half& half(const Observed& o, bool held) const
    {
        const ConditionData& c = cond_[static_cast<std::size_t>(o.condition)];
        return held ? c.held : c.cal;
    }
    Eigen::VectorXd residual(const Summaries& model, bool held, const std::vector<double>& sigma) const
    {
        Eigen::VectorXd r(static_cast<int>(obs_.size()));
        for (std::size_t i = 0; i < obs_.size(); ++i) {
            const Observed& o = obs_[i];
            r[static_cast<int>(i)] = (half(o, held).features.value[o.feature] -
                                      model[static_cast<std::size_t>(o.condition)].value[o.feature]) /
                                     sigma[i];
        }
        return r;
    }
    double chiCal(const Summaries& m) const { return residual(m, false, sigmaCal_).squaredNorm(); }
    double heldGap(const Summaries& m) const
    {
        return std::sqrt(residual(m, true, sigmaHeld_).squaredNorm() / static_cast<double>(obs_.size()));
    }
    // Whitened sensitivity columns (observed features) of the given parameters.
    Eigen::MatrixXd whitened(const std::vector<int>& parameters) const
    {
        Eigen::MatrixXd m(static_cast<int>(obs_.size()), static_cast<int>(parameters.size()));
        for (std::size_t i = 0; i < obs_.size(); ++i)
            for (std::size_t j = 0; j < parameters.size(); ++j)
                m(static_cast<int>(i), static_cast<int>(j)) =
                    jacobian_(row(obs_[i]), parameters[j]) / sigmaCal_[i];
        return m;
    }
    std::vector<double> clip(std::vector<double> v) const
    {
        // The parameters are the baseline's first, then one per effect.
        for (std::size_t j = 0; j < v.size(); ++j) {
            const auto& p = parameter(static_cast<int>(j));
            v[j] = std::clamp(v[j], p.low, p.high);
        }
        return v;
    }
    std::string describeParameter(int j, double v) const
    {
        return parameter(j).name + " = " + format(v) + unitSuffix(parameter(j).unit);
    }
};

}  // namespace rockfrac::explain::detail
