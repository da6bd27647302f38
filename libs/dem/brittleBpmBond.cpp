#include "dem/brittleBpmBond.hpp"

#include <cstdio>

#include "core/dictionary.hpp"
#include "core/selector.hpp"

namespace rockfrac {

BrittleBpmBondLaw::BrittleBpmBondLaw() : BrittleBpmBondLaw(Parameters{}) {}

BrittleBpmBondLaw::BrittleBpmBondLaw(const Parameters& p) : BondLawOf(p)
{
    p.check(type());
    coefficients_.normal_modulus = p.normalModulus();
    coefficients_.shear_modulus = p.shearModulus();
    coefficients_.tensile_strength = p.tensile_strength;
    coefficients_.cohesion = p.cohesion;
    coefficients_.friction = p.friction;
}

BrittleBpmBondLaw::Parameters BrittleBpmBondLaw::read(const Dictionary& d)
{
    requireKnownEntries(d, ElasticBondParameters::entries());
    Parameters p;
    p.read(d);
    return p;
}

const char* BrittleBpmBondLaw::type() const
{
    return "brittleBPM";
}

// The strain energy of a bond of the mean area and length at its tensile strength:
// sigma-bar^2 A l / (2 k_n), what it releases when it breaks in tension.
double BrittleBpmBondLaw::energyFloor(double total_bond_area, int n_bonds, double mean_length) const
{
    const double s = parameters_.tensile_strength;
    return 0.5 * s * s * (total_bond_area / n_bonds) * mean_length / coefficients_.normal_modulus;
}

template <>
void BondLawOf<BrittleBpmLaw, ElasticBondParameters>::run(const BondKernelArgs& args) const
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
