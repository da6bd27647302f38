#include "stats/weibull.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/error.hpp"

namespace rockfrac::stats {

double weibullCdf(double x, double modulus, double scale)
{
    return x <= 0.0 ? 0.0 : 1.0 - std::exp(-std::pow(x / scale, modulus));
}

double weibullQuantile(double p, double modulus, double scale)
{
    if (!(p >= 0.0 && p < 1.0)) throw std::invalid_argument("weibullQuantile: p must be in [0, 1)");
    return scale * std::pow(-std::log1p(-p), 1.0 / modulus);
}

double weibullMean(double modulus, double scale)
{
    return scale * std::tgamma(1.0 + 1.0 / modulus);
}

namespace {

// The sample in units of its geometric mean, y = x / unit: y^m then stays
// finite for every modulus the searches below try, and the log-likelihood
// differences that set the bounds do not depend on the unit.
struct ScaledSample {
    std::vector<double> logY;
    double unit = 1.0;
    double sumLogY = 0.0;
    double n = 0.0;
};

ScaledSample scaleSample(const Sample& sample)
{
    ScaledSample s;
    s.n = static_cast<double>(sample.size());
    double sumLogX = 0.0;
    for (double x : sample) sumLogX += std::log(x);
    s.unit = std::exp(sumLogX / s.n);
    for (double x : sample) s.logY.push_back(std::log(x / s.unit));
    for (double l : s.logY) s.sumLogY += l;
    return s;
}

// log Σ exp(m ln y_i), without overflow.
double logSumPower(const ScaledSample& s, double m)
{
    double largest = -std::numeric_limits<double>::infinity();
    for (double l : s.logY) largest = std::max(largest, m * l);
    double sum = 0.0;
    for (double l : s.logY) sum += std::exp(m * l - largest);
    return largest + std::log(sum);
}

// ln L(m, σ_0) = n ln m − n m ln σ_0 + (m − 1) Σ ln y − Σ (y/σ_0)^m   (σ_0 in scaled units)
double logLikelihood(const ScaledSample& s, double m, double scale)
{
    const double logScale = std::log(scale);
    double sumPower = 0.0;
    for (double l : s.logY) sumPower += std::exp(m * (l - logScale));
    return s.n * std::log(m) - s.n * m * logScale + (m - 1.0) * s.sumLogY - sumPower;
}

// For a given m the likelihood is largest at σ_0 = (Σ y^m / n)^(1/m).
double scaleGivenModulus(const ScaledSample& s, double m)
{
    return std::exp((logSumPower(s, m) - std::log(s.n)) / m);
}

// Root of an increasing function f on (0, ∞), searched in log space from `guess`.
double positiveRoot(const std::function<double(double)>& f, double guess)
{
    double lo = guess, hi = guess;
    for (int i = 0; i < 200 && f(lo) > 0.0; ++i) lo *= 0.5;
    for (int i = 0; i < 200 && f(hi) < 0.0; ++i) hi *= 2.0;
    for (int i = 0; i < 200 && hi / lo > 1.0 + 1e-14; ++i) {
        const double mid = std::sqrt(lo * hi);
        (f(mid) < 0.0 ? lo : hi) = mid;
    }
    return std::sqrt(lo * hi);
}

// The likelihood equation for m after eliminating σ_0 (increasing in m):
// Σ y^m ln y / Σ y^m − 1/m − mean(ln y) = 0.
double maximumLikelihoodModulus(const ScaledSample& s)
{
    return positiveRoot(
        [&](double m) {
            const double logSum = logSumPower(s, m);
            double weighted = 0.0;
            for (double l : s.logY) weighted += std::exp(m * l - logSum) * l;
            return weighted - 1.0 / m - s.sumLogY / s.n;
        },
        1.0);
}

// For a given σ_0, ∂lnL/∂m = n/m − n ln σ_0 + Σ ln y − Σ (y/σ_0)^m ln(y/σ_0) is decreasing in m.
double modulusGivenScale(const ScaledSample& s, double scale)
{
    const double logScale = std::log(scale);
    return positiveRoot(
        [&](double m) {
            double sum = 0.0;
            for (double l : s.logY) sum += std::exp(m * (l - logScale)) * (l - logScale);
            return -(s.n / m - s.n * logScale + s.sumLogY - sum);
        },
        1.0);
}

// For a given mean σ_w, the best m: a log-spaced scan around the estimate
// (the profile is unimodal but not concave), refined by golden sections.
double modulusGivenMean(const ScaledSample& s, double mean, double modulusEstimate)
{
    auto logL = [&](double logM) {
        const double m = std::exp(logM);
        return logLikelihood(s, m, mean / std::tgamma(1.0 + 1.0 / m));
    };
    const double first = std::log(modulusEstimate) - std::log(100.0), step = 2.0 * std::log(100.0) / 80;
    int best = 0;
    for (int k = 1; k <= 80; ++k)
        if (logL(first + k * step) > logL(first + best * step)) best = k;
    double a = first + (best - 1) * step, b = first + (best + 1) * step;
    const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
    for (int i = 0; i < 100; ++i) {
        const double c = b - ratio * (b - a), d = a + ratio * (b - a);
        if (logL(c) > logL(d))
            b = d;
        else
            a = c;
    }
    return std::exp(0.5 * (a + b));
}

// Likelihood-ratio interval of a positive parameter: where the profile
// log-likelihood is within drop = χ²_1(confidence)/2 of its maximum.
Interval likelihoodRatioInterval(const std::function<double(double)>& profile, double estimate, double drop)
{
    const double threshold = profile(estimate) - drop;
    auto inside = [&](double theta) { return profile(theta) >= threshold; };
    auto boundary = [&](double factor) {
        double near = estimate, far = estimate * factor;
        for (int i = 0; i < 60 && inside(far); ++i) near = far, far *= factor;
        for (int i = 0; i < 100 && std::fabs(std::log(far / near)) > 1e-12; ++i) {
            const double mid = std::sqrt(near * far);
            (inside(mid) ? near : far) = mid;
        }
        return std::sqrt(near * far);
    };
    return {boundary(0.5), boundary(2.0)};
}

void checkFittable(const Sample& sample)
{
    for (double x : sample)
        if (!(x > 0.0) || !std::isfinite(x))
            throw UserError("a Weibull fit needs positive values; the sample holds " + std::to_string(x));
    if (sample.size() < 2 || minimum(sample) == maximum(sample))
        throw UserError("a Weibull fit needs at least 2 distinct values; the sample has " +
                        std::to_string(sample.size()) + " value(s), all equal");
}

}  // namespace

WeibullFit fitWeibull(const Sample& sample, double confidence)
{
    if (!(confidence > 0.0 && confidence < 1.0))
        throw std::invalid_argument("fitWeibull: confidence in (0, 1)");
    checkFittable(sample);
    const ScaledSample s = scaleSample(sample);
    WeibullFit fit;
    fit.n = sample.size();
    fit.confidence = confidence;
    const double m = maximumLikelihoodModulus(s);
    const double scale = scaleGivenModulus(s, m);
    fit.modulus = m;
    fit.scale = scale * s.unit;
    fit.mean = weibullMean(m, fit.scale);
    fit.logLikelihood = logLikelihood(s, m, scale) - s.n * std::log(s.unit);  // back to the data's unit

    const double z = standardNormalQuantile(0.5 * (1.0 + confidence));
    const double drop = 0.5 * z * z;  // χ²_1 quantile = z², halved
    fit.modulusBounds = likelihoodRatioInterval(
        [&](double mm) { return logLikelihood(s, mm, scaleGivenModulus(s, mm)); }, m, drop);
    const Interval scaleBounds = likelihoodRatioInterval(
        [&](double ss) { return logLikelihood(s, modulusGivenScale(s, ss), ss); }, scale, drop);
    const double meanScaled = weibullMean(m, scale);
    const Interval meanBounds = likelihoodRatioInterval(
        [&](double w) {
            const double mw = modulusGivenMean(s, w, m);
            return logLikelihood(s, mw, w / std::tgamma(1.0 + 1.0 / mw));
        },
        meanScaled, drop);
    fit.scaleBounds = {scaleBounds.lower * s.unit, scaleBounds.upper * s.unit};
    fit.meanBounds = {meanBounds.lower * s.unit, meanBounds.upper * s.unit};
    return fit;
}

}  // namespace rockfrac::stats
