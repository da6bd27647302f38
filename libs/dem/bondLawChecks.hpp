#pragma once
// Checks of a bond law's values, shared by the laws (a law built from a dictionary has its
// entries checked there with file and line; these guard laws built in code).
#include <cmath>
#include <sstream>
#include <string>

#include "core/error.hpp"

namespace rockfrac {

inline void requireLawValue(bool ok, double value, const char* what, const char* law)
{
    if (ok && std::isfinite(value)) return;
    std::ostringstream message;
    message << "bond law " << law << ": " << what << " is out of range, got " << value;
    throw UserError(message.str());
}

inline void requireElasticBond(double youngs_modulus, double poisson_ratio, const char* law)
{
    requireLawValue(youngs_modulus > 0.0, youngs_modulus, "Young's modulus E", law);
    requireLawValue(poisson_ratio >= 0.0 && poisson_ratio <= 0.49, poisson_ratio, "Poisson's ratio", law);
}

}  // namespace rockfrac
