#pragma once
// Descriptive statistics of a sample: mean, standard deviation, quantiles.
//
// A sample is a plain std::vector<double>; functions that need it sorted sort
// a copy. Empty samples are a programming error (std::invalid_argument): the
// readers of measured and simulated data refuse empty input with a UserError
// before a statistic is ever computed.
#include <vector>

namespace rockfrac::stats {

using Sample = std::vector<double>;

Sample sorted(Sample sample);

double mean(const Sample& sample);
// Sample standard deviation (divisor n − 1, as the paper's Table 5 means); 0 for n = 1.
double standardDeviation(const Sample& sample);
double median(const Sample& sample);
// Quantile by linear interpolation between order statistics (Hyndman & Fan type 7,
// the default of R and NumPy): p in [0, 1].
double quantile(const Sample& sample, double p);
double minimum(const Sample& sample);
double maximum(const Sample& sample);

}  // namespace rockfrac::stats

namespace rockfrac::stats {

// Φ⁻¹(p), the standard normal quantile, p in (0, 1): for confidence levels.
double standardNormalQuantile(double p);

}  // namespace rockfrac::stats
