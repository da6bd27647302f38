#pragma once
// The brittle bond of the bonded-particle model (Potyondy & Cundall 2004, "A bonded-particle
// model for rock", Int. J. Rock Mech. Min. Sci. 41:1329–1364, §2.2): the linear elastic bond
// of Eqs. 5–8 up to its strength, then broken at once — no softening, no fracture energy
// entry. It breaks when the normal stress reaches the tensile strength or the shear stress
// the Mohr–Coulomb strength, each tested on its own (the BPM's "sigma_max >= sigma_c or
// tau_max >= tau_c", with tau-bar = C - mu sigma as the voronoiQNSC law's):
//     sigma >= sigma-bar   or   tau >= C - mu sigma.
// The energy it dissipates is the strain energy the bond held when it broke (booked as
// fracture), so the energy a crack costs scales with the bonds' length, not a G_f.
#include <cmath>
#include <string>

#include "dem/bondLawModel.hpp"

namespace rockfrac {

class Dictionary;

struct BrittleBpmLaw {
    struct Coefficients {
        double normal_modulus = 0.0;    // k_n (Eq. 7) [Pa]
        double shear_modulus = 0.0;     // k_t (Eq. 8) [Pa]
        double tensile_strength = 0.0;  // sigma-bar [Pa]
        double cohesion = 0.0;          // C [Pa]
        double friction = 0.0;          // mu [-]
    };

    RF_HD static void scaleStrength(Coefficients& m, double factor)
    {
        m.tensile_strength *= factor;
        m.cohesion *= factor;
    }

    // The failure test on the undamaged stresses (tau2 = tau^2): tension cut-off or
    // Mohr–Coulomb shear; a non-positive shear strength (sigma >= C/mu) fails.
    RF_HD static bool fails(const Coefficients& m, double sigma, double tau2)
    {
        if (sigma >= m.tensile_strength) return true;
        const double shear_strength = m.cohesion - m.friction * sigma;
        if (shear_strength <= 0.0) return true;
        return tau2 >= shear_strength * shear_strength;
    }

    RF_HD RF_FORCE_INLINE static BondOutput evaluate(const Coefficients& m, const BondInput& in,
                                                     BondHistory& h)
    {
        BondOutput out;
        if (h.stage == bondBroken) return out;
        const double l = in.reference_length, inverse_l = 1.0 / l;
        const double normal_opening = dot(in.opening, in.normal);            // d_n
        const Vec3 shear_opening = in.opening - normal_opening * in.normal;  // d_t t
        const double shear_opening2 = norm2(shear_opening);
        const double sigma = m.normal_modulus * normal_opening * inverse_l;
        const double tau2 = m.shear_modulus * m.shear_modulus * shear_opening2 * inverse_l * inverse_l;
        if (fails(m, sigma, tau2)) {
            // Broken at once (D: 0 -> 1); the history records where (onset = rupture).
            const double tensile_opening = normal_opening > 0.0 ? normal_opening : 0.0;
            const double tensile = sigma > 0.0 ? sigma : 0.0;
            h.onset_displacement = std::sqrt(tensile_opening * tensile_opening + shear_opening2);
            h.onset_stress = std::sqrt(tensile * tensile + tau2);
            h.rupture_displacement = h.max_displacement = h.onset_displacement;
            h.damage = 1.0;
            h.stage = bondBroken;
            out.fracture_dissipation =
                0.5 * in.bond_area * inverse_l *
                (m.normal_modulus * normal_opening * normal_opening + m.shear_modulus * shear_opening2);
            return out;
        }
        elasticBondResponse(m.normal_modulus, m.shear_modulus, in, l, inverse_l, normal_opening,
                            shear_opening, sigma, 0.0, out);
        return out;
    }
};

// The host side: the law's coefficients from bond/brittleBPM (docs/models/bond/brittleBPM.md).
class BrittleBpmBondLaw final : public BondLawModel {
public:
    struct Parameters {
        double youngs_modulus = 46e9;    // E of Eq. 7 [Pa]
        double poisson_ratio = 0.25;     // nu of Eqs. 7–8 [-]
        double tensile_strength = 28e6;  // sigma-bar [Pa]
        double cohesion = 42e6;          // C [Pa]
        double friction = 0.8;           // mu [-]
    };

    BrittleBpmBondLaw();  // the defaults of Parameters
    explicit BrittleBpmBondLaw(const Parameters& parameters);
    static Parameters read(const Dictionary& coefficients);

    const Parameters& parameters() const { return parameters_; }
    const BrittleBpmLaw::Coefficients& coefficients() const { return coefficients_; }

    const char* type() const override;
    double normalModulus() const override;
    double shearModulus() const override;
    double energyFloor(double total_bond_area, int n_bonds, double mean_length) const override;
    void run(const BondKernelArgs& args) const override;
    std::string describe() const override;

private:
    Parameters parameters_;
    BrittleBpmLaw::Coefficients coefficients_;
};

}  // namespace rockfrac
