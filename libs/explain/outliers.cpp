#include "explain/outliers.hpp"

#include <algorithm>

namespace rockfrac::explain {

double medianOf(std::vector<double> values)
{
    if (values.empty()) return 0.0;
    const std::size_t n = values.size(), mid = n / 2;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
    const double upper = values[mid];
    if (n % 2 == 1) return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
    return 0.5 * (lower + upper);
}

std::vector<OddSpecimen> oddFailures(const std::vector<double>& peaks)
{
    std::vector<OddSpecimen> odd;
    if (peaks.size() < 3) return odd;
    const double median = medianOf(peaks);
    if (!(median > 0.0)) return odd;
    for (std::size_t i = 0; i < peaks.size(); ++i) {
        const double ratio = peaks[i] / median;
        if (ratio < oddLowRatio || ratio > oddHighRatio) odd.push_back({i, peaks[i], ratio});
    }
    return odd;
}

bool tooManyOdd(std::size_t odd, std::size_t n)
{
    return odd > 0 && static_cast<double>(odd) > tooManyOddFraction * static_cast<double>(n);
}

}  // namespace rockfrac::explain
