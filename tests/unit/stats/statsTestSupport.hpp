#pragma once
// Reproducible synthetic samples for the statistics tests.
#include <cmath>
#include <cstdint>

#include "core/random.hpp"
#include "stats/descriptive.hpp"
#include "stats/weibull.hpp"

namespace rockfrac::stats::testing {

inline Sample weibullSample(std::size_t n, double modulus, double scale, std::uint64_t seed)
{
    SplitMix64 random(seed);
    Sample sample(n);
    for (double& x : sample) x = weibullQuantile(random.uniform(), modulus, scale);
    return sample;
}

// Box–Muller; u1 in (0, 1] so the logarithm is finite.
inline Sample normalSample(std::size_t n, double mean, double sd, std::uint64_t seed)
{
    SplitMix64 random(seed);
    Sample sample(n);
    const double twoPi = 2.0 * std::acos(-1.0);
    for (double& x : sample) {
        const double u1 = 1.0 - random.uniform(), u2 = random.uniform();
        x = mean + sd * std::sqrt(-2.0 * std::log(u1)) * std::cos(twoPi * u2);
    }
    return sample;
}

// Table 5 of the paper: granite Brazilian disc failure loads [N].
inline Sample graniteBdtLoads()
{
    return {10.9e3, 15.7e3, 12.3e3, 12.9e3, 13.6e3, 15.8e3, 13.0e3, 11.9e3, 12.0e3, 13.8e3};
}

}  // namespace rockfrac::stats::testing
