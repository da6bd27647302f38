#pragma once
// Two-parameter Weibull distribution of strengths (or failure loads), the
// model behind the DFH failure stresses (physics.md §2, Eq. 3):
//
//     P_F(x) = 1 − exp(−(x/σ_0)^m),    σ_w = σ_0 Γ(1 + 1/m) (the mean),
//
// fitted by maximum likelihood, with likelihood-ratio confidence bounds on m,
// σ_0 and σ_w (docs/statistics.md). Likelihood-ratio bounds, unlike Fisher
// (Wald) bounds, stay asymmetric and positive for the 6 to 10 specimens of a
// laboratory series.
#include <cstddef>

#include "stats/descriptive.hpp"

namespace rockfrac::stats {

struct Interval {
    double lower = 0.0;
    double upper = 0.0;
    bool contains(double x) const { return lower <= x && x <= upper; }
};

double weibullCdf(double x, double modulus, double scale);
double weibullQuantile(double p, double modulus, double scale);  // inverse CDF, p in [0, 1)
double weibullMean(double modulus, double scale);                // σ_0 Γ(1 + 1/m)

struct WeibullFit {
    std::size_t n = 0;
    double modulus = 0.0;        // m, the Weibull modulus
    double scale = 0.0;          // σ_0, the 63.2 % value
    double mean = 0.0;           // σ_w = σ_0 Γ(1 + 1/m)
    double logLikelihood = 0.0;  // at the maximum
    double confidence = 0.0;     // of the bounds, e.g. 0.90
    Interval modulusBounds, scaleBounds, meanBounds;

    double cdf(double x) const { return weibullCdf(x, modulus, scale); }
};

// Maximum-likelihood fit with bounds at `confidence` (in (0, 1)). UserError when
// the sample has fewer than 2 distinct values or a value that is not positive.
WeibullFit fitWeibull(const Sample& sample, double confidence = 0.90);

}  // namespace rockfrac::stats
