#include "stats/distances.hpp"

#include <algorithm>
#include <cmath>

namespace rockfrac::stats {

namespace {

// Every distinct value of both samples, sorted: between two consecutive ones
// both empirical CDFs are constant, so sup and integral need only these.
std::vector<double> pooledBreakpoints(const EmpiricalCdf& a, const EmpiricalCdf& b)
{
    std::vector<double> points(a.values());
    points.insert(points.end(), b.values().begin(), b.values().end());
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    return points;
}

}  // namespace

double kolmogorovSmirnov(const Sample& a, const Sample& b)
{
    const EmpiricalCdf cdfA(a), cdfB(b);
    double distance = 0.0;
    for (double x : pooledBreakpoints(cdfA, cdfB))
        distance = std::max(distance, std::fabs(cdfA(x) - cdfB(x)));
    return distance;
}

double kolmogorovSmirnov(const Sample& sample, const CdfFunction& cdf)
{
    const Sample values = sorted(sample);
    const double n = static_cast<double>(values.size());
    double distance = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double model = cdf(values[i]);
        const double below = static_cast<double>(i) / n;      // F_n just left of x_i
        const double above = static_cast<double>(i + 1) / n;  // F_n at x_i
        distance = std::max({distance, model - below, above - model});
    }
    return distance;
}

double wasserstein1(const Sample& a, const Sample& b)
{
    const EmpiricalCdf cdfA(a), cdfB(b);
    const std::vector<double> points = pooledBreakpoints(cdfA, cdfB);
    double area = 0.0;
    for (std::size_t k = 0; k + 1 < points.size(); ++k)
        area += std::fabs(cdfA(points[k]) - cdfB(points[k])) * (points[k + 1] - points[k]);
    return area;
}

}  // namespace rockfrac::stats
