#include "dem/elasticBondParameters.hpp"

#include <cmath>
#include <sstream>

#include "core/dictionary.hpp"
#include "core/error.hpp"

namespace rockfrac {

void requireLawValue(bool ok, double value, const char* what, const char* law)
{
    if (ok && std::isfinite(value)) return;
    std::ostringstream message;
    message << "bond law " << law << ": " << what << " is out of range, got " << value;
    throw UserError(message.str());
}

double ElasticBondParameters::normalModulus() const
{
    const double E = youngs_modulus, nu = poisson_ratio;
    return E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));  // Eq. 7
}

double ElasticBondParameters::shearModulus() const
{
    return youngs_modulus / (2.0 * (1.0 + poisson_ratio));  // Eq. 8
}

void ElasticBondParameters::check(const char* law) const
{
    requireLawValue(youngs_modulus > 0.0, youngs_modulus, "Young's modulus E", law);
    requireLawValue(poisson_ratio >= 0.0 && poisson_ratio <= 0.49, poisson_ratio, "Poisson's ratio", law);
    requireLawValue(tensile_strength > 0.0, tensile_strength, "tensile strength", law);
    requireLawValue(cohesion > 0.0, cohesion, "cohesion", law);
    requireLawValue(friction >= 0.0 && friction <= 1e3, friction, "friction coefficient", law);
}

void ElasticBondParameters::read(const Dictionary& d)
{
    static const Dimensions pascal = Dimensions::fromUnits("Pa");
    youngs_modulus = d.getScalar("E", Bounds::positive(), &pascal);
    poisson_ratio = d.getScalar("poissonRatio", Bounds::closedOpen(0, 0.5));
    tensile_strength = d.getScalar("tensileStrength", Bounds::positive(), &pascal);
    cohesion = d.getScalar("cohesion", Bounds::positive(), &pascal);
    friction = d.getScalar("frictionCoefficient", Bounds::nonNegative());
}

std::vector<std::string> ElasticBondParameters::entries()
{
    return {"E", "poissonRatio", "tensileStrength", "cohesion", "frictionCoefficient"};
}

}  // namespace rockfrac
