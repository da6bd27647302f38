#pragma once
// The figures of a crusher run that compare across machine sizes (docs/theory-crusher.md,
// "Figures per tonne"): specific energy, the feed's F80, P80 against the CSS and the
// reduction ratio. Pure functions of crusherPost's means; crusherPost writes them.
//
//   CrusherFigure e = specificEnergy(powerMean, powerSpread, throughputMean, throughputSpread);
//   if (e.available) ... e.value [kWh/t] ... else ... e.why ...
#include <string>

namespace rockfrac {

// A figure that may not be computable from a run (nothing discharged yet, zero throughput):
// then `available` is false and `why` says what is missing (never an inf or a nan).
struct CrusherFigure {
    bool available = false;
    double value = 0.0;
    double spread = 0.0;  // 0 where a figure has none
    std::string why;
};

// Specific energy [kWh/t] = mean power [W] / mean throughput [kg/s] / 3600 (1 kWh/t =
// 3600 J/kg). Over rows of equal length this is the mantle's energy over the window divided
// by the mass discharged in it. Spread: first-order propagation of the two row-to-row
// spreads as independent, E sqrt((sP/P)^2 + (sQ/Q)^2). Not available for a throughput that
// is not positive or a mean that is not finite.
CrusherFigure specificEnergy(double power_mean, double power_spread, double throughput_mean,
                             double throughput_spread);

// The mass-weighted size at a passing fraction (0 < fraction <= 1) of a feed whose sieve
// sizes are drawn uniformly in number over [lo, hi] (feed/sizeRange) and whose rocks are
// copies of one template scaled to their size (mass proportional to size^3): passing
// P(x) = (x^4 - lo^4) / (hi^4 - lo^4), so x = (lo^4 + fraction (hi^4 - lo^4))^(1/4).
// std::invalid_argument unless 0 < lo <= hi and 0 < fraction <= 1.
double uniformFeedPassingSize(double lo, double hi, double fraction);

// a / b (P80 / CSS, F80 / P80); not available, with why_not as the reason, unless a and b
// are both positive and finite.
CrusherFigure sizeRatio(double a, double b, const std::string& why_not);

}  // namespace rockfrac
