#include "crusher/crusherFigures.hpp"

#include <cmath>
#include <stdexcept>

namespace rockfrac {

CrusherFigure specificEnergy(double power_mean, double power_spread, double throughput_mean,
                             double throughput_spread)
{
    CrusherFigure f;
    if (!std::isfinite(power_mean) || !std::isfinite(throughput_mean)) {
        f.why = "the mean power or throughput is not finite";
        return f;
    }
    if (!(throughput_mean > 0.0)) {
        f.why = "no throughput in the steady window (nothing discharged)";
        return f;
    }
    f.available = true;
    f.value = power_mean / throughput_mean / 3600.0;
    const double rp = power_mean != 0.0 ? power_spread / power_mean : 0.0;
    const double rq = throughput_spread / throughput_mean;
    f.spread = std::abs(f.value) * std::sqrt(rp * rp + rq * rq);
    return f;
}

double uniformFeedPassingSize(double lo, double hi, double fraction)
{
    if (!(lo > 0.0) || !(hi >= lo) || !(fraction > 0.0) || !(fraction <= 1.0))
        throw std::invalid_argument("uniformFeedPassingSize: needs 0 < lo <= hi and 0 < fraction <= 1");
    const double lo4 = std::pow(lo, 4), hi4 = std::pow(hi, 4);
    return std::pow(lo4 + fraction * (hi4 - lo4), 0.25);
}

CrusherFigure sizeRatio(double a, double b, const std::string& why_not)
{
    CrusherFigure f;
    if (!(a > 0.0) || !(b > 0.0) || !std::isfinite(a) || !std::isfinite(b)) {
        f.why = why_not;
        return f;
    }
    f.available = true;
    f.value = a / b;
    return f;
}

}  // namespace rockfrac
