#pragma once
// Specimens that fail differently from the rest of their set (docs/explainGap.md, "Odd
// specimens"): a disc that loses a contact cell under a plate at a few per cent of its
// splitting load takes that drop as its failure, and a disc crushed flat without a split
// carries several times the others' load. Either is another failure mode, not scatter, and
// moves a mean and a standard deviation far more than its share.
//
// The rule is on the failure peak alone and is robust: a specimen is odd when its peak lies
// below oddLowRatio or above oddHighRatio times the median peak of its set (the median is not
// moved by the odd ones while they are fewer than half). Normal scatter of a rock's failure
// load (a coefficient of variation of 10-30 %) never reaches a factor of two.
#include <cstddef>
#include <vector>

namespace rockfrac::explain {

constexpr double oddLowRatio = 0.5;
constexpr double oddHighRatio = 2.0;
// A set with more odd specimens than this fraction has no single failure mode to summarise.
constexpr double tooManyOddFraction = 0.25;

struct OddSpecimen {
    std::size_t index = 0;  // in the set
    double peak = 0.0;      // its failure peak [N]
    double ratio = 0.0;     // peak / the set's median peak
};

// The median of values (the mean of the middle two for an even count); 0 for none.
double medianOf(std::vector<double> values);

// The odd specimens of a set of failure peaks, in the set's order; none in a set of fewer
// than 3 (no median to stand for the rest).
std::vector<OddSpecimen> oddFailures(const std::vector<double>& peaks);

// More than tooManyOddFraction of a set of n is odd (and at least one).
bool tooManyOdd(std::size_t odd, std::size_t n);

}  // namespace rockfrac::explain
