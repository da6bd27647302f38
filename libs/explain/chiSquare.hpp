#pragma once
// The chi-square survival function P(X >= x) for k degrees of freedom, from the
// regularised upper incomplete gamma function Q(k/2, x/2) (series below a + 1,
// Lentz continued fraction above).
namespace rockfrac::explain {

double chiSquareSurvival(double x, double degreesOfFreedom);

}  // namespace rockfrac::explain
