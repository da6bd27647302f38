#include "stats/empiricalCdf.hpp"

#include <algorithm>
#include <stdexcept>

namespace rockfrac::stats {

std::vector<double> medianRanks(std::size_t n)
{
    std::vector<double> ranks(n);
    for (std::size_t i = 1; i <= n; ++i)
        ranks[i - 1] = (static_cast<double>(i) - 0.3) / (static_cast<double>(n) + 0.4);
    return ranks;
}

std::vector<CdfPoint> medianRankCdf(const Sample& sample)
{
    const Sample values = sorted(sample);
    const std::vector<double> ranks = medianRanks(values.size());
    std::vector<CdfPoint> points(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) points[i] = {values[i], ranks[i]};
    return points;
}

EmpiricalCdf::EmpiricalCdf(const Sample& sample) : sorted_(sorted(sample))
{
    if (sorted_.empty()) throw std::invalid_argument("empirical CDF of an empty sample");
}

double EmpiricalCdf::operator()(double x) const
{
    const auto atOrBelow = std::upper_bound(sorted_.begin(), sorted_.end(), x) - sorted_.begin();
    return static_cast<double>(atOrBelow) / static_cast<double>(sorted_.size());
}

}  // namespace rockfrac::stats
