#include "fragments/psd.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace rockfrac {

PsdCurve cumulativePassing(const std::vector<double>& sizes, const std::vector<double>& masses)
{
    if (sizes.size() != masses.size())
        throw std::invalid_argument("cumulativePassing: sizes and masses differ in count");
    double total = 0.0;
    for (std::size_t k = 0; k < sizes.size(); ++k) {
        if (!(sizes[k] > 0.0))
            throw std::invalid_argument("cumulativePassing: a fragment size is not positive");
        if (!(masses[k] >= 0.0))
            throw std::invalid_argument("cumulativePassing: a fragment mass is negative");
        total += masses[k];
    }
    if (!(total > 0.0)) throw std::invalid_argument("cumulativePassing: the total mass is zero");

    std::vector<std::size_t> order(sizes.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return sizes[a] < sizes[b]; });
    PsdCurve curve;
    double sum = 0.0;
    for (std::size_t k : order) {
        sum += masses[k];
        if (!curve.size.empty() && curve.size.back() == sizes[k]) {
            curve.passing.back() = sum / total;
        } else {
            curve.size.push_back(sizes[k]);
            curve.passing.push_back(sum / total);
        }
    }
    curve.passing.back() = 1.0;  // exactly, whatever the rounding of the sum
    return curve;
}

double passingAt(const PsdCurve& curve, double size)
{
    if (curve.empty() || size < curve.size.front()) return 0.0;
    if (size >= curve.size.back()) return 1.0;
    // First point above `size`; its predecessor is at or below it.
    const auto above = std::upper_bound(curve.size.begin(), curve.size.end(), size);
    const std::size_t k = static_cast<std::size_t>(above - curve.size.begin());
    const double s = std::log(size / curve.size[k - 1]) / std::log(curve.size[k] / curve.size[k - 1]);
    return curve.passing[k - 1] + s * (curve.passing[k] - curve.passing[k - 1]);
}

double sizeAtPassing(const PsdCurve& curve, double fraction)
{
    if (curve.empty()) throw std::invalid_argument("sizeAtPassing: empty curve");
    if (!(fraction > 0.0 && fraction <= 1.0))
        throw std::invalid_argument("sizeAtPassing: fraction not in (0, 1]");
    if (fraction <= curve.passing.front()) return curve.size.front();
    // First point whose passing reaches the fraction; the previous one is below it.
    const auto reach = std::lower_bound(curve.passing.begin(), curve.passing.end(), fraction);
    const std::size_t k =
        std::min<std::size_t>(static_cast<std::size_t>(reach - curve.passing.begin()), curve.size.size() - 1);
    const double s = (fraction - curve.passing[k - 1]) / (curve.passing[k] - curve.passing[k - 1]);
    return curve.size[k - 1] * std::pow(curve.size[k] / curve.size[k - 1], s);
}

PsdSummary summarisePsd(const PsdCurve& curve, double original_size)
{
    PsdSummary s;
    s.p50 = sizeAtPassing(curve, 0.5);
    s.p80 = sizeAtPassing(curve, 0.8);
    s.t10 = passingAt(curve, original_size / 10.0);
    return s;
}

}  // namespace rockfrac
