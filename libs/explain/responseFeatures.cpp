#include "explain/responseFeatures.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "stats/descriptive.hpp"

namespace rockfrac::explain {

namespace {

const char* const names[nFeatures] = {"peakForce",       "peakForceSpread", "peakDisplacement",
                                      "secantStiffness", "toeIndex",        "softening"};
const char* const units[nFeatures] = {"N", "N", "m", "N/m", "-", "m"};

// Displacement where the force first reaches `level` on the way up to index `last`.
std::optional<double> firstCrossing(const std::vector<double>& d, const std::vector<double>& f, double level,
                                    std::size_t last)
{
    for (std::size_t i = 0; i <= last && i < f.size(); ++i)
        if (f[i] >= level) {
            if (i == 0) return d[0];
            const double t = (level - f[i - 1]) / (f[i] - f[i - 1]);
            return d[i - 1] + t * (d[i] - d[i - 1]);
        }
    return std::nullopt;
}

// Force of a curve at onset-aligned displacement x (0 before the onset, last value after the end).
double forceAt(const std::vector<double>& d, const std::vector<double>& f, double x)
{
    if (d.empty() || x <= d.front()) return f.empty() ? 0.0 : f.front();
    for (std::size_t i = 1; i < d.size(); ++i)
        if (d[i] >= x) {
            const double span = d[i] - d[i - 1];
            const double t = span > 0 ? (x - d[i - 1]) / span : 1.0;
            return f[i - 1] + t * (f[i] - f[i - 1]);
        }
    return f.back();
}

}  // namespace

std::optional<std::size_t> failurePeakIndex(const std::vector<double>& f)
{
    std::size_t peak = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        if (f[i] > f[peak]) peak = i;
        if (f[peak] > 0.0 && f[i] < (1.0 - failureDropFraction) * f[peak]) return peak;
    }
    return std::nullopt;
}

const char* featureName(int feature)
{
    return names[feature];
}
const char* featureUnit(int feature)
{
    return units[feature];
}
int featureIndex(const std::string& name)
{
    for (int f = 0; f < nFeatures; ++f)
        if (name == names[f]) return f;
    return -1;
}

std::optional<CurveFeatures> curveFeatures(const std::vector<double>& d, const std::vector<double>& f,
                                           std::string* whyNot)
{
    auto fail = [&](const std::string& why) -> std::optional<CurveFeatures> {
        if (whyNot) *whyNot = why;
        return std::nullopt;
    };
    if (d.size() != f.size() || f.size() < 4) return fail("fewer than 4 points");
    if (!(*std::max_element(f.begin(), f.end()) > 0)) return fail("no positive force");
    // The failure peak: the running maximum at the first notable drop, as a lab reads it
    // (a split specimen that jams between the plates may carry more later: not the failure).
    const auto failure = failurePeakIndex(f);
    if (!failure)
        return fail("no load drop: the force never falls " + std::to_string(int(100 * failureDropFraction)) +
                    " % below its running maximum");
    const std::size_t ip = *failure;
    const double fp = f[ip];
    const auto d0 = firstCrossing(d, f, onsetFraction * fp, ip);
    const auto d30 = firstCrossing(d, f, 0.3 * fp, ip);
    const auto d70 = firstCrossing(d, f, 0.7 * fp, ip);
    if (!d0 || !d30 || !d70 || !(*d70 > *d30) || !(*d30 >= *d0))
        return fail("no rise from contact to the peak");
    // Softening: the plate travel from the failure peak to the notable drop (which exists).
    std::optional<double> dDrop;
    const double dropLevel = (1.0 - failureDropFraction) * fp;
    for (std::size_t i = ip + 1; i < f.size(); ++i)
        if (f[i] < dropLevel) {
            const double t = (f[i - 1] - dropLevel) / (f[i - 1] - f[i]);
            dDrop = d[i - 1] + t * (d[i] - d[i - 1]);
            break;
        }
    CurveFeatures c;
    c.peakForce = fp;
    c.peakDisplacement = d[ip] - *d0;
    c.secantStiffness = 0.4 * fp / (*d70 - *d30);
    const double initialCompliance = (*d30 - *d0) / ((0.3 - onsetFraction) * fp);
    c.toeIndex = initialCompliance * c.secantStiffness;
    c.softening = *dDrop - d[ip];
    return c;
}

namespace {

// Location, its standard error, spread and its standard error of one sample.
struct Moments {
    double location, locationError, spread, spreadError;
};

Moments moments(const stats::Sample& v, Statistics statistics)
{
    const double n = static_cast<double>(v.size());
    if (statistics == Statistics::median) {
        const double m = stats::median(v);
        stats::Sample deviation;
        for (double x : v) deviation.push_back(std::fabs(x - m));
        const double s = 1.4826 * stats::median(deviation);
        return {m, 1.2533 * s / std::sqrt(n), s, 1.1664 * s / std::sqrt(n)};
    }
    const double sd = stats::standardDeviation(v);
    return {stats::mean(v), sd / std::sqrt(n), sd, n > 1 ? sd / std::sqrt(2.0 * (n - 1)) : sd};
}

}  // namespace

FeatureSummary summarise(const std::vector<CurveFeatures>& curves, Statistics statistics)
{
    if (curves.empty()) throw std::invalid_argument("summarise: no curves");
    FeatureSummary s;
    s.specimens = static_cast<int>(curves.size());
    auto column = [&](double CurveFeatures::*member) {
        stats::Sample v;
        for (const auto& c : curves) v.push_back(c.*member);
        return v;
    };
    const Moments peaks = moments(column(&CurveFeatures::peakForce), statistics);
    s.value[peakForce] = peaks.location;
    s.standardError[peakForce] = peaks.locationError;
    s.value[peakForceSpread] = peaks.spread;
    s.standardError[peakForceSpread] = peaks.spreadError;
    const std::pair<Feature, double CurveFeatures::*> locations[] = {
        {peakDisplacement, &CurveFeatures::peakDisplacement},
        {secantStiffness, &CurveFeatures::secantStiffness},
        {toeIndex, &CurveFeatures::toeIndex},
        {softening, &CurveFeatures::softening}};
    for (const auto& [feature, member] : locations) {
        const Moments m = moments(column(member), statistics);
        s.value[feature] = m.location;
        s.standardError[feature] = m.locationError;
    }
    s.available.fill(true);
    return s;
}

FeatureSummary summariseFailureLoads(const std::vector<double>& loads, Statistics statistics)
{
    if (loads.empty()) throw std::invalid_argument("summariseFailureLoads: no loads");
    FeatureSummary s;
    s.specimens = static_cast<int>(loads.size());
    const Moments m = moments(loads, statistics);
    s.value[peakForce] = m.location;
    s.standardError[peakForce] = m.locationError;
    s.value[peakForceSpread] = m.spread;
    s.standardError[peakForceSpread] = m.spreadError;
    s.available[peakForce] = s.available[peakForceSpread] = true;
    return s;
}

std::vector<double> meanCurve(const std::vector<std::vector<double>>& displacements,
                              const std::vector<std::vector<double>>& forces, double upTo, int n)
{
    std::vector<double> mean(static_cast<std::size_t>(n), 0.0);
    std::size_t used = 0;
    for (std::size_t s = 0; s < displacements.size(); ++s) {
        const auto& d = displacements[s];
        const auto& f = forces[s];
        if (f.empty()) continue;
        const std::size_t ip = failurePeakIndex(f).value_or(
            static_cast<std::size_t>(std::max_element(f.begin(), f.end()) - f.begin()));
        const auto d0 = firstCrossing(d, f, onsetFraction * f[ip], ip);
        if (!d0) continue;
        for (int i = 0; i < n; ++i) {
            const double x = *d0 + upTo * i / std::max(1, n - 1);
            mean[static_cast<std::size_t>(i)] += forceAt(d, f, x);
        }
        ++used;
    }
    if (used > 0)
        for (double& v : mean) v /= static_cast<double>(used);
    return mean;
}

double meanPeakDisplacement(const std::vector<std::vector<double>>& displacements,
                            const std::vector<std::vector<double>>& forces)
{
    double sum = 0.0;
    std::size_t used = 0;
    for (std::size_t s = 0; s < displacements.size(); ++s) {
        const auto& d = displacements[s];
        const auto& f = forces[s];
        if (f.empty()) continue;
        const std::size_t ip = failurePeakIndex(f).value_or(
            static_cast<std::size_t>(std::max_element(f.begin(), f.end()) - f.begin()));
        const auto d0 = firstCrossing(d, f, onsetFraction * f[ip], ip);
        if (!d0) continue;
        sum += d[ip] - *d0;
        ++used;
    }
    return used > 0 ? sum / static_cast<double>(used) : 0.0;
}

}  // namespace rockfrac::explain
