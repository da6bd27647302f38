#pragma once
// Particle size distributions of fragments (docs/theory-fragments.md).
//
// The cumulative mass passing P(x) is the mass fraction of the fragments whose
// size is at most x. From the fragments it is known exactly at their sizes
// x_1 < x_2 < ... (equal sizes merged): P_k = sum of the masses up to x_k / total.
// Between two of these points P is interpolated linearly in ln x (the sieve
// analyst's log-linear interpolation); below x_1 nothing passes (P = 0), at and
// above the largest size everything does (P = 1). The size at a passing fraction
// (P50, P80) is the inverse of that same curve, and t10 = P(x0 / 10) with x0 the
// size of the original particle.
#include <vector>

namespace rockfrac {

struct PsdCurve {
    std::vector<double> size;     // distinct sizes, ascending [m]
    std::vector<double> passing;  // cumulative mass fraction at each size, ascending, last = 1
    bool empty() const { return size.empty(); }
};

// std::invalid_argument when the sizes and masses differ in count, a size is not
// positive, a mass is negative, or the total mass is zero.
PsdCurve cumulativePassing(const std::vector<double>& sizes, const std::vector<double>& masses);

// P(x): 0 below the smallest size, log-linear between the points, 1 from the largest on.
double passingAt(const PsdCurve& curve, double size);

// The size at which P reaches `fraction` (0 < fraction <= 1): the smallest size when
// the smallest fragment alone already holds that fraction, else log-linear between the
// two points that bracket it.
double sizeAtPassing(const PsdCurve& curve, double fraction);

struct PsdSummary {
    double p50 = 0.0;  // [m]
    double p80 = 0.0;  // [m]
    double t10 = 0.0;  // mass fraction passing original_size / 10 [-]
};
PsdSummary summarisePsd(const PsdCurve& curve, double original_size);

}  // namespace rockfrac
