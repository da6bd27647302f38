#pragma once
// The chi-square survival function P(X >= x) for k degrees of freedom, from the
// regularised upper incomplete gamma function Q(k/2, x/2) (series below a + 1,
// Lentz continued fraction above); and the absolute test of a model on held-out specimens.
#include <cstddef>
#include <vector>

namespace rockfrac::explain {

double chiSquareSurvival(double x, double degreesOfFreedom);

// A feature error beyond this many standard errors is named as one that remains.
constexpr double remainingZ = 2.0;

// The absolute test after the relative one (docs/explainGap.md, step 8): are the
// normalised held-out feature errors z of a model consistent with the scatter? Nothing is
// fitted on the held-out specimens, so sum z^2 has as many degrees of freedom as features.
// A given chiSquare (>= 0: the quadratic form of correlated errors) replaces sum z^2.
struct HeldOutTest {
    double chiSquare = 0.0;
    int degreesOfFreedom = 0;
    double pValue = 1.0;
    bool consistent = true;  // p >= significance
    // The features (indices into z) with |z| > remainingZ, largest first; when none is so far
    // off but the test rejects, the largest one alone.
    std::vector<std::size_t> remaining;
};
HeldOutTest heldOutTest(const std::vector<double>& z, double significance, double chiSquare = -1.0);

}  // namespace rockfrac::explain
