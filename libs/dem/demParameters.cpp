#include "dem/demParameters.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace rockfrac {

DampingReading dampingReadingFromName(const std::string& name)
{
    if (name == "absolute") return DampingReading::absolute;
    if (name == "criticalFraction") return DampingReading::criticalFraction;
    throw UserError("unknown bond damping reading '" + name + "'; known: absolute criticalFraction");
}

const char* dampingReadingName(DampingReading reading)
{
    return reading == DampingReading::absolute ? "absolute" : "criticalFraction";
}

namespace {

void requirePositive(double value, const char* name)
{
    if (!(value > 0.0) || !std::isfinite(value)) {
        std::ostringstream message;
        message << "DEM parameter " << name << " must be positive and finite, got " << value;
        throw UserError(message.str());
    }
}

void requireRange(double value, double low, double high, const char* name)
{
    if (!(value >= low && value <= high)) {
        std::ostringstream message;
        message << "DEM parameter " << name << " must lie in [" << low << ", " << high << "], got " << value;
        throw UserError(message.str());
    }
}

}  // namespace

double DemParameters::bondSizeFactor(double interface_area) const
{
    if (!(bond_size_effect_modulus > 0.0)) return 1.0;
    return std::pow(bond_size_effect_reference_area / interface_area, 1.0 / bond_size_effect_modulus);
}

void DemParameters::validate() const
{
    requirePositive(rock_youngs_modulus, "rock Young's modulus");
    requireRange(rock_poisson_ratio, 0.0, 0.49, "rock Poisson's ratio");
    requirePositive(rock_density, "rock density");
    if (!bond_law) throw UserError("DEM parameters: no bond law");
    if (!contact_law) throw UserError("DEM parameters: no contact law");
    requireRange(bond_damping, 0.0, 1e3, "bond damping coefficient");
    requireRange(bond_size_effect_modulus, 0.0, 1e3, "Weibull modulus of the bond size effect");
    if (bond_size_effect_modulus > 0.0)
        requirePositive(bond_size_effect_reference_area, "reference area of the bond size effect");
    requireRange(rock_rock_friction, 0.0, 1e3, "rock-rock friction");
    requireRange(rock_steel_friction, 0.0, 1e3, "rock-steel friction");
    requireRange(rock_rock_restitution, 1e-6, 1.0, "rock-rock restitution");
    requireRange(rock_steel_restitution, 1e-6, 1.0, "rock-steel restitution");
    requirePositive(steel_youngs_modulus, "steel Young's modulus");
    requireRange(steel_poisson_ratio, 0.0, 0.49, "steel Poisson's ratio");
    requireRange(dilation_radius, 0.0, 1e30, "dilation radius");
    requireRange(skin_distance, 0.0, 1e30, "skin distance");
    requirePositive(energy_growth_tolerance, "energy growth tolerance");
}

}  // namespace rockfrac
