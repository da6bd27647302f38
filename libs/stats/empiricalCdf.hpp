#pragma once
// Cumulative distributions of a sample: the median-rank plotting positions the
// paper uses for failure-load CDFs (Figs. 6, 10, 14) and the empirical CDF
// that the distances between distributions are defined on.
#include <cstddef>
#include <functional>
#include <vector>

#include "stats/descriptive.hpp"

namespace rockfrac::stats {

// Benard's approximation of the median rank of the i-th smallest of n values:
// F_i = (i − 0.3) / (n + 0.4), i = 1..n. Returned for i = 1..n in order.
std::vector<double> medianRanks(std::size_t n);

// One plotted point of a failure-load CDF: the i-th smallest value and its median rank.
struct CdfPoint {
    double value;
    double probability;
};
// The sample sorted, each value with its median rank.
std::vector<CdfPoint> medianRankCdf(const Sample& sample);

// The empirical CDF F_n(x) = #{x_i <= x} / n, a right-continuous step function.
class EmpiricalCdf {
public:
    explicit EmpiricalCdf(const Sample& sample);  // std::invalid_argument when empty
    double operator()(double x) const;
    const Sample& values() const { return sorted_; }  // sorted
    std::size_t size() const { return sorted_.size(); }

private:
    Sample sorted_;
};

// A continuous model CDF, e.g. a fitted Weibull distribution.
using CdfFunction = std::function<double(double)>;

}  // namespace rockfrac::stats
