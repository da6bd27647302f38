#pragma once
// The bond law of the paper (section 4.1, Eqs. 5–20, Algorithm 1):
// linear elastic bond with a quadratic nominal stress criterion (QNSC) for the
// onset of damage, linear softening in the effective displacement, no damage
// in compression, and a stiffness-proportional dashpot.
#include <cmath>
#include <string>

#include "dem/bondLawModel.hpp"

namespace rockfrac {

class Dictionary;

struct VoronoiQnscLaw {
    // The coefficients every bond of a run shares.
    struct Coefficients {
        double normal_modulus = 0.0;      // k_n = E(1-nu)/((1+nu)(1-2nu))  (Eq. 7) [Pa]
        double shear_modulus = 0.0;       // k_t = E/(2(1+nu))  (Eq. 8) [Pa]
        double tensile_strength = 0.0;    // sigma-bar [Pa]
        double cohesion = 0.0;            // C [Pa]
        double friction = 0.0;            // mu [-]
        double fracture_energy_I = 0.0;   // G_I [N/m]
        double fracture_energy_II = 0.0;  // G_II [N/m]
        double bk_exponent = 2.0;         // eta [-]
        double rupture_tolerance = 0.0;   // Remark 1.1, relative to d_e0
    };

    // An interface `factor` times as strong: sigma-bar and C scaled (size effect, model effects).
    RF_HD static void scaleStrength(Coefficients& m, double factor)
    {
        m.tensile_strength *= factor;
        m.cohesion *= factor;
    }

    // QNSC (Eq. 12) with tau-bar = C - mu sigma; >= 1 at or beyond the onset.
    // A non-positive Mohr–Coulomb strength (sigma >= C/mu) counts as beyond it.
    RF_HD static double qnscIndex(const Coefficients& m, double sigma, double tau)
    {
        const double tensile = sigma > 0.0 ? sigma / m.tensile_strength : 0.0;
        const double shear_strength = m.cohesion - m.friction * sigma;
        if (shear_strength <= 0.0) return 2.0;
        const double shear = tau / shear_strength;
        return tensile * tensile + shear * shear;
    }

    // The fraction s in (0, 1] of the current (sigma, tau) at which the QNSC is
    // exactly 1, assuming the bond was loaded along a straight path from zero
    // within the step (exact for monotonic proportional loading). The index is
    // increasing in s, so bisection converges to round-off.
    RF_HD static double onsetFraction(const Coefficients& m, double sigma, double tau)
    {
        double low = 0.0, high = 1.0;
        for (int iteration = 0; iteration < 60; ++iteration) {
            const double mid = 0.5 * (low + high);
            if (qnscIndex(m, mid * sigma, mid * tau) >= 1.0)
                high = mid;
            else
                low = mid;
        }
        return high;
    }

    // Benzeggagh–Kenane: G_f = G_I + (G_II - G_I) (G_shear/G_total)^eta with the
    // mode mixity from the tractions at onset, G_shear/G_total = tau^2/(<sigma>^2 + tau^2).
    RF_HD static double fractureEnergy(const Coefficients& m, double sigma_onset, double tau_onset)
    {
        const double tensile = sigma_onset > 0.0 ? sigma_onset : 0.0;
        const double total = tensile * tensile + tau_onset * tau_onset;
        const double mixity = total > 0.0 ? tau_onset * tau_onset / total : 0.0;
        return m.fracture_energy_I +
               (m.fracture_energy_II - m.fracture_energy_I) * std::pow(mixity, m.bk_exponent);
    }

    // Algorithm 1, steps 4–5 with Remarks 1.1–1.3. Returns the damage before this call.
    RF_HD static double updateDamage(const Coefficients& m, double sigma, double tau,
                                     double effective_displacement, BondHistory& h)
    {
        const double damage_before = h.damage;
        if (h.stage == bondElastic) {
            if (qnscIndex(m, sigma, tau) < 1.0) return damage_before;
            // Onset (QNSC = 1): record d_e0, sigma_e0 and d_f = 2 G_f / sigma_e0 (Eq. 14).
            const double s = onsetFraction(m, sigma, tau);
            const double tensile = sigma > 0.0 ? sigma : 0.0;
            h.onset_displacement = s * effective_displacement;
            h.onset_stress = s * std::sqrt(tensile * tensile + tau * tau);
            h.rupture_displacement = 2.0 * fractureEnergy(m, sigma, tau) / h.onset_stress;
            // Remark 1.1: a rupture displacement at or below the onset (snap-back) is
            // moved just past it, which lowers G_f to sigma_e0 d_f / 2 (Eq. 14).
            if (h.rupture_displacement <= h.onset_displacement)
                h.rupture_displacement = h.onset_displacement * (1.0 + m.rupture_tolerance);
            h.max_displacement = h.onset_displacement;
            h.stage = bondSoftening;
        }
        if (effective_displacement > h.max_displacement) h.max_displacement = effective_displacement;
        double damage = 1.0;  // Remark 1.2: d_max beyond d_f breaks the bond
        if (h.max_displacement <= h.rupture_displacement) {
            const double d0 = h.onset_displacement, df = h.rupture_displacement, dmax = h.max_displacement;
            damage = dmax > 0.0 ? df * (dmax - d0) / (dmax * (df - d0)) : 0.0;  // Eq. 13
        }
        if (damage > h.damage) h.damage = damage < 1.0 ? damage : 1.0;  // Remark 1.3
        if (h.damage >= 1.0) h.stage = bondBroken;
        return damage_before;
    }

    // The QNSC onset test without square roots or divisions (the hot path of an
    // intact bond): (<sigma>/sigma-bar)^2 + tau^2/tau-bar^2 >= 1.
    RF_HD static bool onsetReached(const Coefficients& m, double sigma, double tau2)
    {
        const double shear_strength = m.cohesion - m.friction * sigma;
        if (shear_strength <= 0.0) return true;
        const double tensile = sigma > 0.0 ? sigma / m.tensile_strength : 0.0;
        return tau2 >= (1.0 - tensile * tensile) * shear_strength * shear_strength;
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
        // Undamaged stresses (Eqs. 5–8), used for the onset test.
        const double sigma_trial = m.normal_modulus * normal_opening * inverse_l;
        const double tau_trial2 = m.shear_modulus * m.shear_modulus * shear_opening2 * inverse_l * inverse_l;
        if (h.stage != bondElastic || onsetReached(m, sigma_trial, tau_trial2)) {
            const double tensile_opening = normal_opening > 0.0 ? normal_opening : 0.0;
            const double effective_displacement =
                std::sqrt(tensile_opening * tensile_opening + shear_opening2);  // Eq. 10
            const double damage_before =
                updateDamage(m, sigma_trial, std::sqrt(tau_trial2), effective_displacement, h);
            // Energy that damage releases: D multiplies the tensile and shear parts only.
            const double damageable_energy =
                0.5 * in.bond_area * inverse_l *
                (m.normal_modulus * tensile_opening * tensile_opening + m.shear_modulus * shear_opening2);
            out.fracture_dissipation = damageable_energy * (h.damage - damage_before);
            if (h.stage == bondBroken) {  // D = 1: force and stiffness removed
                // A bond broken in shear under compression loses its (undamaged)
                // compressive energy with it: released, booked with the fracture.
                if (normal_opening < 0.0)
                    out.fracture_dissipation +=
                        0.5 * in.bond_area * inverse_l * m.normal_modulus * normal_opening * normal_opening;
                return out;
            }
        }
        // Degraded stresses (Eqs. 16–17) and the dashpot (Eqs. 18–19).
        elasticBondResponse(m.normal_modulus, m.shear_modulus, in, l, inverse_l, normal_opening,
                            shear_opening, sigma_trial, h.damage, out);
        return out;
    }
};

// The host side: the law's coefficients from bond/voronoiQNSC (docs/models/bond/voronoiQNSC.md).
class VoronoiQnscBondLaw final : public BondLawModel {
public:
    // What a user gives, with the paper's Table 2 values as defaults.
    struct Parameters {
        double youngs_modulus = 46e9;      // E of Eq. 7 [Pa]
        double poisson_ratio = 0.25;       // nu of Eqs. 7–8 [-]
        double tensile_strength = 28e6;    // sigma-bar of Eq. 12 [Pa]
        double cohesion = 42e6;            // C of tau-bar = C - mu sigma [Pa]
        double friction = 0.8;             // mu = tan(phi) of tau-bar [-]
        double fracture_energy_I = 10.0;   // G_I [N/m]
        double fracture_energy_II = 10.0;  // G_II [N/m]
        double bk_exponent = 2.0;          // eta of Benzeggagh–Kenane [-]
        // Remark 1.1: if d_f <= d_e0 then d_f = d_e0 (1 + rupture_tolerance).
        double rupture_tolerance = 1e-6;  // [-]
    };

    VoronoiQnscBondLaw();  // the defaults of Parameters
    explicit VoronoiQnscBondLaw(const Parameters& parameters);
    // Reads bond/voronoiQNSC (units and bounds checked; unknown entries refused).
    static Parameters read(const Dictionary& coefficients);

    const Parameters& parameters() const { return parameters_; }
    const VoronoiQnscLaw::Coefficients& coefficients() const { return coefficients_; }

    const char* type() const override;
    double normalModulus() const override;
    double shearModulus() const override;
    double energyFloor(double total_bond_area, int n_bonds, double mean_length) const override;
    void run(const BondKernelArgs& args) const override;
    std::string describe() const override;

private:
    Parameters parameters_;
    VoronoiQnscLaw::Coefficients coefficients_;
};

}  // namespace rockfrac
