#include "dem/voronoiQnscBond.hpp"

#include <cstdio>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/selector.hpp"
#include "dem/bondLawChecks.hpp"

namespace rockfrac {

VoronoiQnscBondLaw::VoronoiQnscBondLaw() : VoronoiQnscBondLaw(Parameters{}) {}

VoronoiQnscBondLaw::VoronoiQnscBondLaw(const Parameters& p) : parameters_(p)
{
    requireElasticBond(p.youngs_modulus, p.poisson_ratio, type());
    requireLawValue(p.tensile_strength > 0.0, p.tensile_strength, "tensile strength", type());
    requireLawValue(p.cohesion > 0.0, p.cohesion, "cohesion", type());
    requireLawValue(p.friction >= 0.0 && p.friction <= 1e3, p.friction, "friction coefficient", type());
    requireLawValue(p.fracture_energy_I > 0.0, p.fracture_energy_I, "mode I fracture energy G_I", type());
    requireLawValue(p.fracture_energy_II > 0.0, p.fracture_energy_II, "mode II fracture energy G_II", type());
    requireLawValue(p.bk_exponent > 0.0, p.bk_exponent, "Benzeggagh-Kenane exponent", type());
    requireLawValue(p.rupture_tolerance >= 0.0 && p.rupture_tolerance <= 1.0, p.rupture_tolerance,
                    "rupture tolerance", type());
    const double E = p.youngs_modulus, nu = p.poisson_ratio;
    coefficients_.normal_modulus = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));  // Eq. 7
    coefficients_.shear_modulus = E / (2.0 * (1.0 + nu));                             // Eq. 8
    coefficients_.tensile_strength = p.tensile_strength;
    coefficients_.cohesion = p.cohesion;
    coefficients_.friction = p.friction;
    coefficients_.fracture_energy_I = p.fracture_energy_I;
    coefficients_.fracture_energy_II = p.fracture_energy_II;
    coefficients_.bk_exponent = p.bk_exponent;
    coefficients_.rupture_tolerance = p.rupture_tolerance;
}

VoronoiQnscBondLaw::Parameters VoronoiQnscBondLaw::read(const Dictionary& d)
{
    static const Dimensions pascal = Dimensions::fromUnits("Pa");
    static const Dimensions energyPerArea = Dimensions::fromUnits("N/m");
    requireKnownEntries(d, {"E", "poissonRatio", "tensileStrength", "cohesion", "frictionCoefficient", "GI",
                            "GII", "bkExponent"});
    Parameters p;
    p.youngs_modulus = d.getScalar("E", Bounds::positive(), &pascal);
    p.poisson_ratio = d.getScalar("poissonRatio", Bounds::closedOpen(0, 0.5));
    p.tensile_strength = d.getScalar("tensileStrength", Bounds::positive(), &pascal);
    p.cohesion = d.getScalar("cohesion", Bounds::positive(), &pascal);
    p.friction = d.getScalar("frictionCoefficient", Bounds::nonNegative());
    p.fracture_energy_I = d.getScalar("GI", Bounds::positive(), &energyPerArea);
    p.fracture_energy_II = d.getScalar("GII", Bounds::positive(), &energyPerArea);
    p.bk_exponent = d.getScalarOrDefault("bkExponent", p.bk_exponent, Bounds::positive());
    return p;
}

const char* VoronoiQnscBondLaw::type() const
{
    return "voronoiQNSC";
}

double VoronoiQnscBondLaw::normalModulus() const
{
    return coefficients_.normal_modulus;
}

double VoronoiQnscBondLaw::shearModulus() const
{
    return coefficients_.shear_modulus;
}

// G_I times the mean bond area: the energy one average bond dissipates breaking in mode I.
double VoronoiQnscBondLaw::energyFloor(double total_bond_area, int n_bonds, double /*mean_length*/) const
{
    return parameters_.fracture_energy_I * total_bond_area / n_bonds;
}

void VoronoiQnscBondLaw::run(const BondKernelArgs& args) const
{
    runBondKernel<VoronoiQnscLaw>(args, coefficients_);
}

std::string VoronoiQnscBondLaw::describe() const
{
    char line[256];
    std::snprintf(line, sizeof line,
                  "%s, E %.4g GPa, tensile %.4g MPa, cohesion %.4g MPa, mu %.3g, G_I %.3g N/m", type(),
                  1e-9 * parameters_.youngs_modulus, 1e-6 * parameters_.tensile_strength,
                  1e-6 * parameters_.cohesion, parameters_.friction, parameters_.fracture_energy_I);
    return line;
}

}  // namespace rockfrac
