#pragma once
// DFH failure stresses: the Weibull weakest-link law with a volume effect.
//
//   P_F = 1 - exp[ -(sigma_F / sigma_0)^m  V_el / V_ref ],   sigma_w = sigma_0 Gamma(1 + 1/m)
//
// (paper Eqs. 3-4). Inverting with a uniform u = P_F in (0, 1):
//   sigma_F = sigma_0 (V_ref / V_el)^(1/m) (-ln(1 - u))^(1/m),
// so an element of volume V_ref has mean strength sigma_w, and smaller elements
// are stronger by (V_ref / V_el)^(1/m).
#include <array>
#include <cstdint>

#include "core/vec3.hpp"

namespace rockfrac::fem {

class WeibullStrength {
public:
    // UserError unless m > 0, sigma_w > 0 and V_ref > 0.
    WeibullStrength(double weibullModulus, double meanStrength, double referenceVolume);

    double modulus() const { return modulus_; }
    double scaleStress() const { return scaleStress_; }  // sigma_0
    // sigma_F for failure probability u in (0, 1) and element volume V_el.
    double quantile(double u, double elementVolume) const;
    // The three thresholds of an element, ascending: draws 0, 1, 2 of the
    // counter-based stream (seed, element id), so they depend on nothing else.
    std::array<double, 3> elementThresholds(std::uint64_t seed, std::uint64_t element,
                                            double elementVolume) const;

private:
    double modulus_;
    double scaleStress_;
    double referenceVolume_;
};

}  // namespace rockfrac::fem
