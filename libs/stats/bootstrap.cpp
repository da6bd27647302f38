#include "stats/bootstrap.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/random.hpp"

namespace rockfrac::stats {

BootstrapInterval bootstrapPercentile(const Sample& sample, const Statistic& statistic, double confidence,
                                      std::size_t resamples, std::uint64_t seed)
{
    if (sample.empty()) throw std::invalid_argument("bootstrap of an empty sample");
    if (!(confidence > 0.0 && confidence < 1.0))
        throw std::invalid_argument("bootstrap: confidence in (0, 1)");
    if (resamples < 2) throw std::invalid_argument("bootstrap: at least 2 resamples");
    SplitMix64 random(seed);
    const std::size_t n = sample.size();
    Sample resample(n), replicates(resamples);
    for (double& replicate : replicates) {
        for (double& x : resample) {
            // uniform() < 1, so the index is < n; the min guards the rounding edge.
            const auto index = static_cast<std::size_t>(random.uniform() * static_cast<double>(n));
            x = sample[std::min(index, n - 1)];
        }
        replicate = statistic(resample);
    }
    BootstrapInterval result;
    result.estimate = statistic(sample);
    result.bounds = {quantile(replicates, 0.5 * (1.0 - confidence)),
                     quantile(replicates, 0.5 * (1.0 + confidence))};
    result.confidence = confidence;
    result.resamples = resamples;
    return result;
}

}  // namespace rockfrac::stats
