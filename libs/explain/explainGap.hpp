#pragma once
// explainGap: from a case and measured data, (1) measure the gap, (2) decide
// whether it exceeds the model's own scatter, (3) screen every candidate effect
// by a score test (its sensitivity projected out of the baseline parameters'),
// (4) confirm the best by a joint refit judged on held-out specimens and an
// information criterion, and (5) write the augmented case, the gap tables, the
// plots and one sentence. A study of several test conditions (two loading rates, say)
// stacks their features into one vector and fits them together. docs/explainGap.md gives
// the method in full.
#include <string>
#include <vector>

#include "explain/explainStudy.hpp"

namespace rockfrac::explain {

enum class Verdict {
    noGapBeyondScatter,  // the baseline, re-fitted, is within the model's own scatter
    explained,           // one effect explains the gap: its held-out errors are within the scatter
    partlyExplained,     // one effect closes part of the gap; the held-out errors still exceed the scatter
    indistinguishable,   // two or more effects explain it equally and the data cannot tell them apart
    unexplained,         // the gap is real and no effect of the library closes it
    inconclusive         // too many specimens (or model members) fail differently from the rest
};
const char* verdictName(Verdict v);

struct ScreenedEffect {
    std::string name;
    bool screened = true;  // false: its probe's runs failed, so it was not tested
    // false: its probe moved no feature by 0.01 standard errors (a zero signature on these
    // data: plate friction on discs), so the data cannot test it; listed, never screened
    bool testable = true;
    double largestChange = 0.0;  // its probe's largest feature change [standard errors]
    double score = 0.0;          // chi-square reduction of the linearised fit
    double pValue = 1.0;
    double amplitude = 0.0;                        // linearised estimate of the parameter change
    bool wrongSign = false;                        // the data want it outside its physical bounds
    bool confirmed = false;                        // refit ran
    double value = 0.0;                            // refitted parameter
    double intervalLow = 0.0, intervalHigh = 0.0;  // 90 % (linearised)
    double heldOutGap = 0.0;  // RMS of the normalised held-out feature errors after the refit
    double reduction = 0.0;   // 1 - heldOutGap / baseline's
    double aic = 0.0;         // calibration half
    bool kept = false;
    bool converged = false;                              // the joint refit met its convergence criterion
    int refitSteps = 0;                                  // simulated Gauss-Newton steps of the joint refit
    double heldOutChiSquare = 0.0, heldOutPValue = 1.0;  // the absolute test on the held-out half
};

// A pair of effects refitted together with the baseline (docs/explainGap.md, "Pairs").
struct PairFit {
    std::string first, second;
    double firstValue = 0.0, secondValue = 0.0;
    double firstLow = 0.0, firstHigh = 0.0, secondLow = 0.0, secondHigh = 0.0;  // 90 % (linearised)
    double chiSquare = 0.0, aic = 0.0;                                          // calibration half
    double heldOutGap = 0.0, reduction = 0.0;
    bool relative =
        false;  // passes the relative test (held-out reduction, AIC below the baseline's and its members')
    double heldOutChiSquare = 0.0, heldOutPValue = 1.0;  // the absolute test
    bool converged = false;
};

// A specimen or model member whose failure peak is far from its set's median (outliers.hpp).
struct OddMember {
    std::string condition;  // "" for a study of one condition
    bool measured = true;   // false: a model member (Voronoi seed) of the baseline
    std::string id;         // specimen id or seed
    double peak = 0.0, ratio = 0.0;
};

struct ExplainOutcome {
    Verdict verdict = Verdict::noGapBeyondScatter;
    std::string sentence;
    std::string effect;                     // explained: the effect
    std::vector<std::string> alternatives;  // indistinguishable: the effects
    std::string separatingMeasurement;      // indistinguishable: what would separate them
    double baselineChiSquare = 0.0, baselinePValue = 1.0;
    double baselineHeldOutGap = 0.0;
    std::vector<ScreenedEffect> screened;
    std::vector<OddMember> oddMembers;
    bool robustStatistics = false;              // switched to medians because of odd members
    std::vector<std::string> geometryMismatch;  // "diameter", ...: beyond geometryTolerance
    std::string geometryFinding;                // the sentence on it ("" without a mismatch)
    std::vector<std::string> remaining;         // partlyExplained: "peakForce 3.6", ...
    std::vector<PairFit> pairs;                 // the pairs refitted (none unless no single effect passed)
    int namedPair = -1;                         // the pair that explains the gap (index into pairs), or -1
    int pairSimulations = 0;                    // the simulations the pairs took
    int simulations = 0;
};

// Run the analysis (simulations through runCases, resumable) and write its outputs
// into the study directory; `jobs` overrides the study's.
ExplainOutcome explainGap(ExplainStudy study, int jobs);

}  // namespace rockfrac::explain
