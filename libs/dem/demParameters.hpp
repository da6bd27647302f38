#pragma once
// Parameters of the bonded Voronoi DEM (physics.md §3.3–3.4).
//
// A plain struct that the application fills from constant/rockProperties and
// constant/loading. The defaults are the paper's values (Table 2) so that a test or a
// study states only what it changes; the dictionaries remain the place where a case
// records its parameters. The bond and contact laws are selected models that own their
// coefficients (bondLawModel.hpp, contactLaw.hpp); what every law shares is here.
#include <memory>
#include <string>

#include "core/vec3.hpp"
#include "dem/bondLawModel.hpp"
#include "dem/contactLaw.hpp"

namespace rockfrac {

// How the bond damping coefficient beta of Eqs. 18–19 is read (physics.md,
// "Open question — the unit of beta"; docs/theory-dem.md §Damping).
enum class DampingReading {
    absolute,         // beta in seconds, used as printed in Eqs. 18–19
    criticalFraction  // beta = zeta, a fraction of each bond's critical damping
};

// "absolute" / "criticalFraction"; anything else is a UserError naming both.
DampingReading dampingReadingFromName(const std::string& name);
const char* dampingReadingName(DampingReading reading);

struct DemParameters {
    // Rock (the cells): mass, inertia and Hertz contact (Table 2).
    double rock_youngs_modulus = 77e9;  // [Pa]
    double rock_poisson_ratio = 0.21;   // [-]
    double rock_density = 2540.0;       // [kg/m^3]

    // Bonds (Eqs. 5–20): the law, which owns its coefficients (bond/<model>), and what
    // every law shares: the dashpot and the size effect.
    std::shared_ptr<const BondLawModel> bond_law = defaultBondLaw();
    double bond_damping = 1e-4;  // beta: seconds or fraction, see damping_reading
    DampingReading damping_reading = DampingReading::absolute;
    // Weibull size effect of the bond strength (docs/theory-dem.md §3, an option beyond the
    // paper): sigma-bar and C of an interface of area A are scaled by (A_ref / A)^(1/m), the
    // weakest-link scaling the FEM applies to its elements, so that a mesh of larger cells
    // is not stronger than the one the bonds were calibrated on. m = 0: off (the paper's model).
    double bond_size_effect_modulus = 0.0;         // m [-]
    double bond_size_effect_reference_area = 0.0;  // A_ref [m^2]
    // The factor on an interface of area A [m^2] (1 when off).
    double bondSizeFactor(double interface_area) const;

    // Contacts (Hertz–Mindlin, Table 2).
    std::shared_ptr<const ContactLawModel> contact_law = defaultContactLaw();
    // Cell–cell contact: false = one Hertz point at the GJK closest points of the cores (the
    // paper's); true = a patch of feature pairs, seated at a face neighbour's first broken
    // bond, which keeps the energy of pressed fragments (docs/theory-dem.md §6).
    bool cell_contact_patch = false;
    double rock_rock_friction = 0.6;
    double rock_rock_restitution = 0.15;
    double rock_steel_friction = 0.95;
    double rock_steel_restitution = 0.3;
    double steel_youngs_modulus = 210e9;  // [Pa]
    double steel_poisson_ratio = 0.3;     // [-]

    // Dilated polyhedra: 0 means "take VoronoiMesh::dilationRadius".
    double dilation_radius = 0.0;  // r_d [m]
    // Verlet skin of the neighbour lists: 0 means "take r_d".
    double skin_distance = 0.0;  // [m]

    Vec3 gravity{0.0, 0.0, -9.81};  // [m/s^2]

    // Safety: the energy balance error that is called "growing without input",
    // relative to the largest energy scale of the run (docs/theory-dem.md §Safety).
    double energy_growth_tolerance = 0.1;

    // Throws UserError naming the first impossible value.
    void validate() const;
};

}  // namespace rockfrac
