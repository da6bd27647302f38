#include "stats/design.hpp"

#include <algorithm>
#include <numeric>

#include "core/random.hpp"

namespace rockfrac::stats {

std::vector<std::vector<std::size_t>> fullFactorial(const std::vector<std::size_t>& levels)
{
    std::size_t runs = 1;
    for (std::size_t count : levels) runs *= count;
    std::vector<std::vector<std::size_t>> design(runs, std::vector<std::size_t>(levels.size()));
    for (std::size_t r = 0; r < runs; ++r) {
        std::size_t rest = r;
        for (std::size_t j = levels.size(); j-- > 0;) {
            design[r][j] = rest % levels[j];
            rest /= levels[j];
        }
    }
    return design;
}

namespace {

// Fisher–Yates shuffle of 0..n-1 with a portable random stream.
std::vector<std::size_t> randomPermutation(std::size_t n, SplitMix64& random)
{
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t(0));
    for (std::size_t i = n; i > 1; --i) {
        const auto j = std::min(static_cast<std::size_t>(random.uniform() * static_cast<double>(i)), i - 1);
        std::swap(order[i - 1], order[j]);
    }
    return order;
}

}  // namespace

std::vector<std::vector<double>> latinHypercube(std::size_t samples, std::size_t dimensions,
                                                std::uint64_t seed)
{
    SplitMix64 random(seed);
    std::vector<std::vector<double>> points(samples, std::vector<double>(dimensions));
    for (std::size_t j = 0; j < dimensions; ++j) {
        const std::vector<std::size_t> strata = randomPermutation(samples, random);
        for (std::size_t i = 0; i < samples; ++i)
            points[i][j] = (static_cast<double>(strata[i]) + random.uniform()) / static_cast<double>(samples);
    }
    return points;
}

}  // namespace rockfrac::stats
