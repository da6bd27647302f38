#include "dem/brittleBpmBond.hpp"

#include <cstdio>

#include "core/dictionary.hpp"
#include "core/selector.hpp"
#include "dem/bondLawChecks.hpp"

namespace rockfrac {

BrittleBpmBondLaw::BrittleBpmBondLaw() : BrittleBpmBondLaw(Parameters{}) {}

BrittleBpmBondLaw::BrittleBpmBondLaw(const Parameters& p) : parameters_(p)
{
    requireElasticBond(p.youngs_modulus, p.poisson_ratio, type());
    requireLawValue(p.tensile_strength > 0.0, p.tensile_strength, "tensile strength", type());
    requireLawValue(p.cohesion > 0.0, p.cohesion, "cohesion", type());
    requireLawValue(p.friction >= 0.0 && p.friction <= 1e3, p.friction, "friction coefficient", type());
    const double E = p.youngs_modulus, nu = p.poisson_ratio;
    coefficients_.normal_modulus = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));  // Eq. 7
    coefficients_.shear_modulus = E / (2.0 * (1.0 + nu));                             // Eq. 8
    coefficients_.tensile_strength = p.tensile_strength;
    coefficients_.cohesion = p.cohesion;
    coefficients_.friction = p.friction;
}

BrittleBpmBondLaw::Parameters BrittleBpmBondLaw::read(const Dictionary& d)
{
    static const Dimensions pascal = Dimensions::fromUnits("Pa");
    requireKnownEntries(d, {"E", "poissonRatio", "tensileStrength", "cohesion", "frictionCoefficient"});
    Parameters p;
    p.youngs_modulus = d.getScalar("E", Bounds::positive(), &pascal);
    p.poisson_ratio = d.getScalar("poissonRatio", Bounds::closedOpen(0, 0.5));
    p.tensile_strength = d.getScalar("tensileStrength", Bounds::positive(), &pascal);
    p.cohesion = d.getScalar("cohesion", Bounds::positive(), &pascal);
    p.friction = d.getScalar("frictionCoefficient", Bounds::nonNegative());
    return p;
}

const char* BrittleBpmBondLaw::type() const
{
    return "brittleBPM";
}

double BrittleBpmBondLaw::normalModulus() const
{
    return coefficients_.normal_modulus;
}

double BrittleBpmBondLaw::shearModulus() const
{
    return coefficients_.shear_modulus;
}

// The strain energy of a bond of the mean area and length at its tensile strength:
// sigma-bar^2 A l / (2 k_n), what it releases when it breaks in tension.
double BrittleBpmBondLaw::energyFloor(double total_bond_area, int n_bonds, double mean_length) const
{
    const double s = parameters_.tensile_strength;
    return 0.5 * s * s * (total_bond_area / n_bonds) * mean_length / coefficients_.normal_modulus;
}

void BrittleBpmBondLaw::run(const BondKernelArgs& args) const
{
    runBondKernel<BrittleBpmLaw>(args, coefficients_);
}

std::string BrittleBpmBondLaw::describe() const
{
    char line[256];
    std::snprintf(line, sizeof line,
                  "%s, E %.4g GPa, tensile %.4g MPa, cohesion %.4g MPa, mu %.3g (no softening)", type(),
                  1e-9 * parameters_.youngs_modulus, 1e-6 * parameters_.tensile_strength,
                  1e-6 * parameters_.cohesion, parameters_.friction);
    return line;
}

}  // namespace rockfrac
