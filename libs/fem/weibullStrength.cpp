#include "fem/weibullStrength.hpp"

#include <algorithm>
#include <cmath>

#include "core/counterRandom.hpp"
#include "core/error.hpp"

namespace rockfrac::fem {

WeibullStrength::WeibullStrength(double weibullModulus, double meanStrength, double referenceVolume)
    : modulus_(weibullModulus), scaleStress_(0.0), referenceVolume_(referenceVolume)
{
    if (!(weibullModulus > 0.0)) throw UserError("DFH: the Weibull modulus m must be > 0");
    if (!(meanStrength > 0.0)) throw UserError("DFH: the Weibull stress sigma_w must be > 0");
    if (!(referenceVolume > 0.0))
        throw UserError(
            "DFH: the reference volume V_ref must be > 0 (a case entry fixed by the calibration "
            "together with sigma_w; see docs/theory.md)");
    scaleStress_ = meanStrength / std::tgamma(1.0 + 1.0 / weibullModulus);
}

double WeibullStrength::quantile(double u, double elementVolume) const
{
    const double exposure = -std::log1p(-u);  // (sigma_F/sigma_0)^m V_el/V_ref
    return scaleStress_ * std::pow(exposure * referenceVolume_ / elementVolume, 1.0 / modulus_);
}

std::array<double, 3> WeibullStrength::elementThresholds(std::uint64_t seed, std::uint64_t element,
                                                         double elementVolume) const
{
    std::array<double, 3> thresholds;
    for (std::uint64_t draw = 0; draw < 3; ++draw)
        thresholds[draw] = quantile(uniform01(seed, element, draw), elementVolume);
    std::sort(thresholds.begin(), thresholds.end());
    return thresholds;
}

}  // namespace rockfrac::fem
