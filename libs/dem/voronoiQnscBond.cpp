#include "dem/voronoiQnscBond.hpp"

#include <cstdio>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/selector.hpp"
#include "dem/bondKernelAvx2.hpp"

namespace rockfrac {

VoronoiQnscBondLaw::VoronoiQnscBondLaw() : VoronoiQnscBondLaw(Parameters{}) {}

VoronoiQnscBondLaw::VoronoiQnscBondLaw(const Parameters& p) : BondLawOf(p)
{
    p.check(type());
    requireLawValue(p.fracture_energy_I > 0.0, p.fracture_energy_I, "mode I fracture energy G_I", type());
    requireLawValue(p.fracture_energy_II > 0.0, p.fracture_energy_II, "mode II fracture energy G_II", type());
    requireLawValue(p.bk_exponent > 0.0, p.bk_exponent, "Benzeggagh-Kenane exponent", type());
    requireLawValue(p.rupture_tolerance >= 0.0 && p.rupture_tolerance <= 1.0, p.rupture_tolerance,
                    "rupture tolerance", type());
    coefficients_.normal_modulus = p.normalModulus();
    coefficients_.shear_modulus = p.shearModulus();
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
    static const Dimensions energyPerArea = Dimensions::fromUnits("N/m");
    std::vector<std::string> entries = ElasticBondParameters::entries();
    entries.insert(entries.end(), {"GI", "GII", "bkExponent"});
    requireKnownEntries(d, entries);
    Parameters p;
    p.read(d);
    p.fracture_energy_I = d.getScalar("GI", Bounds::positive(), &energyPerArea);
    p.fracture_energy_II = d.getScalar("GII", Bounds::positive(), &energyPerArea);
    p.bk_exponent = d.getScalarOrDefault("bkExponent", p.bk_exponent, Bounds::positive());
    return p;
}

const char* VoronoiQnscBondLaw::type() const
{
    return "voronoiQNSC";
}

// G_I times the mean bond area: the energy one average bond dissipates breaking in mode I.
double VoronoiQnscBondLaw::energyFloor(double total_bond_area, int n_bonds, double /*mean_length*/) const
{
    return parameters_.fracture_energy_I * total_bond_area / n_bonds;
}

template <>
void BondLawOf<VoronoiQnscLaw, VoronoiQnscParameters>::run(const BondKernelArgs& args) const
{
    // The intact bonds four at a time where the CPU can (bit for bit the scalar kernel's result).
    if (!args.only_interfaces && bondLanesEnabled())
        runVoronoiQnscBondLanes(args, coefficients_);
    else
        runBondKernel<VoronoiQnscLaw>(args, coefficients_);
}

bool voronoiQnscInterfaceScalar(const BondKernelArgs& a, const VoronoiQnscLaw::Coefficients& c, int k,
                                BondBlockSums& block)
{
    return bondInterfaceKernel<VoronoiQnscLaw>(a, c, k, block);
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
