#pragma once
// What a set of force–displacement curves (or only failure loads) says, as a few
// numbers that the model effects move in recognisably different ways
// (docs/explainGap.md, "Features"):
//
//   peakForce          mean failure force [N]: the running maximum at the first drop of more
//                      than 20 % below it (the lab's "first notable drop", as the solvers'
//                      failureLoad), not a later maximum of a split specimen jammed between the plates
//   peakForceSpread    standard deviation of the peak forces [N]
//   peakDisplacement   mean displacement at the peak [m]
//   secantStiffness    mean secant stiffness between 30 % and 70 % of the peak [N/m]
//   toeIndex           mean ratio of the initial compliance (onset to 30 %) to the secant one:
//                      1 for a straight rise, > 1 for a soft start (toe) [-]
//   softening          mean displacement from the failure peak to that 20 % drop [m]
//
// Displacements are measured from the contact onset: the first point where the force
// reaches onsetFraction (2 %) of the curve's peak, interpolated. Curves are aligned there
// and never shifted to fit.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace rockfrac::explain {

enum Feature { peakForce, peakForceSpread, peakDisplacement, secantStiffness, toeIndex, softening };
constexpr int nFeatures = 6;
const char* featureName(int feature);
const char* featureUnit(int feature);
// The feature called name; -1 when there is none.
int featureIndex(const std::string& name);

constexpr double onsetFraction = 0.02;
constexpr double failureDropFraction = 0.2;

// Index of the failure peak of a force series: the running maximum at the first point
// more than failureDropFraction below it; std::nullopt when the force never drops so far.
std::optional<std::size_t> failurePeakIndex(const std::vector<double>& force);

struct CurveFeatures {
    double peakForce = 0.0, peakDisplacement = 0.0, secantStiffness = 0.0, toeIndex = 0.0, softening = 0.0;
};

// The features of one curve (displacement ascending in time, force compression
// positive). std::nullopt with the reason when the curve has no rise to a peak or
// no notable drop after it.
std::optional<CurveFeatures> curveFeatures(const std::vector<double>& displacement,
                                           const std::vector<double>& force, std::string* whyNot = nullptr);

// Summary features of a set of specimens: value and standard error of each; a
// feature without data (failure loads only) is marked unavailable.
struct FeatureSummary {
    std::array<double, nFeatures> value{};
    std::array<double, nFeatures> standardError{};
    std::array<bool, nFeatures> available{};
    int specimens = 0;
};
//
// Statistics::mean: means and the standard deviation (the default). Statistics::median:
// medians and the scaled median absolute deviation 1.4826 MAD for the spread, with their
// large-sample standard errors (1.2533 s/sqrt(n) for a median, 1.1664 s/sqrt(n) for the
// MAD, s the scaled MAD), so that one odd specimen (a crushed contact cell taken as the
// failure, a disc crushed flat without a split) does not move a whole set.
enum class Statistics { mean, median };
FeatureSummary summarise(const std::vector<CurveFeatures>& curves, Statistics statistics = Statistics::mean);
FeatureSummary summariseFailureLoads(const std::vector<double>& failureLoads,
                                     Statistics statistics = Statistics::mean);

// The mean curve of a set, force on a common grid of onset-aligned displacement
// [0, upTo] (n points), for the normalised RMS gap between two sets.
std::vector<double> meanCurve(const std::vector<std::vector<double>>& displacements,
                              const std::vector<std::vector<double>>& forces, double upTo, int n);

// The mean displacement from contact onset to the failure peak over a set's curves (0 when
// none has an onset): how far a plot of the set's mean curve has to reach.
double meanPeakDisplacement(const std::vector<std::vector<double>>& displacements,
                            const std::vector<std::vector<double>>& forces);

}  // namespace rockfrac::explain
