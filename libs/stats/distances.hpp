#pragma once
// Distances between a simulated and a measured distribution of failure loads
// (physics.md §5). Both are defined on the empirical CDFs F_n, so they use
// every value of both samples and need no binning or fitted model.
#include "stats/empiricalCdf.hpp"

namespace rockfrac::stats {

// Two-sample Kolmogorov–Smirnov distance sup_x |F_a(x) − F_b(x)|, in [0, 1].
double kolmogorovSmirnov(const Sample& a, const Sample& b);

// One-sample Kolmogorov–Smirnov distance sup_x |F_n(x) − F(x)| to a continuous
// CDF: checked on both sides of every step of F_n.
double kolmogorovSmirnov(const Sample& sample, const CdfFunction& cdf);

// Wasserstein-1 (earth mover's) distance ∫ |F_a(x) − F_b(x)| dx, the area
// between the two empirical CDFs, in the unit of the values (e.g. N).
double wasserstein1(const Sample& a, const Sample& b);

}  // namespace rockfrac::stats
