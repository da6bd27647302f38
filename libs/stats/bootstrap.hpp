#pragma once
// Bootstrap percentile intervals (Efron): resample the sample with replacement,
// recompute the statistic, and take the (1 ± confidence)/2 quantiles of the
// recomputed values. Works for any statistic (mean, median, Weibull modulus, a
// distance to another sample) and is reproducible: resampling draws from the
// portable SplitMix64 stream of the given seed.
#include <cstddef>
#include <cstdint>
#include <functional>

#include "stats/descriptive.hpp"
#include "stats/weibull.hpp"

namespace rockfrac::stats {

using Statistic = std::function<double(const Sample&)>;

struct BootstrapInterval {
    double estimate = 0.0;  // the statistic of the sample itself
    Interval bounds;
    double confidence = 0.0;
    std::size_t resamples = 0;
};

BootstrapInterval bootstrapPercentile(const Sample& sample, const Statistic& statistic,
                                      double confidence = 0.95, std::size_t resamples = 2000,
                                      std::uint64_t seed = 1);

}  // namespace rockfrac::stats
