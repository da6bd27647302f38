#include "stats/descriptive.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace rockfrac::stats {

namespace {

void requireNonEmpty(const Sample& sample, const char* what)
{
    if (sample.empty()) throw std::invalid_argument(std::string(what) + " of an empty sample");
}

}  // namespace

Sample sorted(Sample sample)
{
    std::sort(sample.begin(), sample.end());
    return sample;
}

double mean(const Sample& sample)
{
    requireNonEmpty(sample, "mean");
    return std::accumulate(sample.begin(), sample.end(), 0.0) / static_cast<double>(sample.size());
}

double standardDeviation(const Sample& sample)
{
    requireNonEmpty(sample, "standard deviation");
    if (sample.size() < 2) return 0.0;
    const double m = mean(sample);
    double sumOfSquares = 0.0;
    for (double x : sample) sumOfSquares += (x - m) * (x - m);
    return std::sqrt(sumOfSquares / static_cast<double>(sample.size() - 1));
}

double quantile(const Sample& sample, double p)
{
    requireNonEmpty(sample, "quantile");
    if (!(p >= 0.0 && p <= 1.0)) throw std::invalid_argument("quantile: p must be in [0, 1]");
    const Sample s = sorted(sample);
    const double position = p * static_cast<double>(s.size() - 1);
    const auto below = static_cast<std::size_t>(std::floor(position));
    const std::size_t above = std::min(below + 1, s.size() - 1);
    const double fraction = position - static_cast<double>(below);
    return s[below] + fraction * (s[above] - s[below]);
}

double median(const Sample& sample)
{
    return quantile(sample, 0.5);
}

double minimum(const Sample& sample)
{
    requireNonEmpty(sample, "minimum");
    return *std::min_element(sample.begin(), sample.end());
}

double maximum(const Sample& sample)
{
    requireNonEmpty(sample, "maximum");
    return *std::max_element(sample.begin(), sample.end());
}

}  // namespace rockfrac::stats

namespace rockfrac::stats {

double standardNormalQuantile(double p)
{
    if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("standardNormalQuantile: p must be in (0, 1)");
    // Bisection on Φ(z) = erfc(−z/√2)/2: monotone, exact to double precision
    // after 200 halvings of [−40, 40]; speed does not matter here.
    double lo = -40.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace rockfrac::stats
