// The features explainGap reads from a force–displacement curve (libs/explain/responseFeatures):
// the failure peak is the lab's "first notable drop", not a later maximum.
#include <catch2/catch.hpp>

#include "explain/responseFeatures.hpp"

using namespace rockfrac::explain;

namespace {

// A piecewise linear curve through (displacement, force) corners, sampled every 1 um.
void curve(const std::vector<std::pair<double, double>>& corners, std::vector<double>& d,
           std::vector<double>& f)
{
    d.clear();
    f.clear();
    for (std::size_t k = 1; k < corners.size(); ++k) {
        const auto [x0, y0] = corners[k - 1];
        const auto [x1, y1] = corners[k];
        const int n = static_cast<int>((x1 - x0) / 1e-6 + 0.5);
        for (int i = (k == 1 ? 0 : 1); i <= n; ++i) {
            d.push_back(x0 + (x1 - x0) * i / n);
            f.push_back(y0 + (y1 - y0) * i / n);
        }
    }
}

}  // namespace

TEST_CASE("a split disc: peak, stiffness, toe and softening of a straight rise and drop",
          "[explain][features]")
{
    std::vector<double> d, f;
    // Straight rise 0 -> 10 kN over 200 um, drop to 4 kN over 10 um.
    curve({{0.0, 0.0}, {200e-6, 10e3}, {210e-6, 4e3}}, d, f);
    std::string why;
    const auto c = curveFeatures(d, f, &why);
    INFO(why);
    REQUIRE(c);
    CHECK(c->peakForce == Approx(10e3));
    CHECK(c->peakDisplacement == Approx(200e-6 * (1 - onsetFraction)).epsilon(1e-6));
    CHECK(c->secantStiffness == Approx(10e3 / 200e-6).epsilon(1e-6));
    CHECK(c->toeIndex == Approx(1.0).epsilon(1e-6));
    // 20 % of the peak lost over 2 kN / (6 kN / 10 um) = 3.33 um.
    CHECK(c->softening == Approx(10e-6 / 3.0).epsilon(1e-6));
}

TEST_CASE("a split disc that jams and carries more later fails at its first notable drop",
          "[explain][features]")
{
    std::vector<double> d, f;
    // Peak 10 kN, a 45 % drop (not below half), then the jammed halves carry up to 14 kN.
    curve({{0.0, 0.0}, {200e-6, 10e3}, {210e-6, 5.5e3}, {500e-6, 14e3}, {510e-6, 2e3}}, d, f);
    const auto c = curveFeatures(d, f);
    REQUIRE(c);
    CHECK(c->peakForce == Approx(10e3));
    CHECK(c->peakDisplacement == Approx(200e-6 * (1 - onsetFraction)).epsilon(1e-6));
    CHECK(failurePeakIndex(f).has_value());
    CHECK(f[*failurePeakIndex(f)] == Approx(10e3));
    // A dip of less than 20 % is not the failure: the running maximum goes on.
    curve({{0.0, 0.0}, {100e-6, 5e3}, {105e-6, 4.2e3}, {250e-6, 12e3}, {260e-6, 3e3}}, d, f);
    const auto g = curveFeatures(d, f);
    REQUIRE(g);
    CHECK(g->peakForce == Approx(12e3));
}

TEST_CASE("a curve without a notable drop has no features, and says why", "[explain][features]")
{
    std::vector<double> d, f;
    curve({{0.0, 0.0}, {200e-6, 10e3}, {210e-6, 8.5e3}}, d, f);
    std::string why;
    CHECK_FALSE(curveFeatures(d, f, &why));
    CHECK(why.find("20 %") != std::string::npos);
    CHECK_FALSE(failurePeakIndex(f).has_value());
}

TEST_CASE("the median summary is not moved by one odd specimen", "[explain][features]")
{
    // Eleven specimens near 18 kN and one that chipped at 1.1 kN.
    std::vector<double> loads = {17.0e3, 17.5e3, 18.0e3, 18.5e3, 19.0e3, 17.2e3,
                                 18.2e3, 18.8e3, 17.8e3, 18.4e3, 17.6e3, 1.1e3};
    const FeatureSummary mean = summariseFailureLoads(loads);
    const FeatureSummary median = summariseFailureLoads(loads, Statistics::median);
    CHECK(mean.value[peakForce] < 16.7e3);
    CHECK(mean.value[peakForceSpread] > 4.5e3);
    CHECK(median.value[peakForce] == Approx(17.9e3));  // (17.8 + 18.0) / 2
    // Scaled MAD of the eleven: deviations from 17.9 kN, median 0.55 kN (x 1.4826).
    CHECK(median.value[peakForceSpread] == Approx(1.4826 * 0.55e3).epsilon(1e-9));
    CHECK(median.standardError[peakForce] == Approx(1.2533 * 1.4826 * 0.55e3 / std::sqrt(12.0)));
    // Without the odd one, mean and median agree to a fraction of the spread.
    loads.pop_back();
    const FeatureSummary clean = summariseFailureLoads(loads);
    CHECK(std::fabs(clean.value[peakForce] - median.value[peakForce]) < 0.2 * clean.value[peakForceSpread]);
}

TEST_CASE("the mean peak displacement of a set is measured from each curve's contact onset",
          "[explain][features]")
{
    // Two discs: a seated one (onset at 0) and one with a 50 um toe of zero force before
    // contact; peaks 200 and 300 um after their onsets (less the 2 % onset offset).
    std::vector<double> d1, f1, d2, f2;
    curve({{0.0, 0.0}, {200e-6, 10e3}, {210e-6, 4e3}}, d1, f1);
    curve({{0.0, 0.0}, {50e-6, 0.0}, {350e-6, 8e3}, {360e-6, 1e3}}, d2, f2);
    const double expected = 0.5 * (200e-6 + 300e-6) * (1 - onsetFraction);
    CHECK(meanPeakDisplacement({d1, d2}, {f1, f2}) == Approx(expected).epsilon(1e-6));
    CHECK(meanPeakDisplacement({}, {}) == 0.0);
    // A mean curve drawn that far from the onset reaches the peak.
    const auto mean = meanCurve({d1}, {f1}, 200e-6 * (1 - onsetFraction), 2);
    CHECK(mean.back() == Approx(10e3).epsilon(1e-6));
}
