#pragma once
// Hertz–Mindlin (no slip) contact with restitution damping and a Coulomb-capped
// incremental tangential spring (physics.md §3.3), applied between dilated
// cells with the dilation radius as the contact radius.
#include <cmath>

#include "dem/contactKernels.hpp"

namespace rockfrac {

struct HertzMindlinLaw {
    RF_HD static ContactOutput evaluate(const ContactConstants& k, const ContactInput& in,
                                        Vec3& tangential_spring)
    {
        ContactOutput out;
        const Vec3& n = in.normal;
        const double contact_radius = std::sqrt(in.effective_radius * in.overlap);   // sqrt(R* delta)
        const double normal_stiffness = 2.0 * k.effective_modulus * contact_radius;  // S_n
        const double tangential_stiffness = 8.0 * k.effective_shear_modulus * contact_radius;  // S_t
        // Viscous coefficients from the restitution: -2 sqrt(5/6) beta_e sqrt(S m*) (beta_e < 0).
        const double damping_factor = -2.0 * std::sqrt(5.0 / 6.0) * k.restitution_beta;
        const double normal_damping = damping_factor * std::sqrt(normal_stiffness * in.effective_mass);
        const double tangential_damping =
            damping_factor * std::sqrt(tangential_stiffness * in.effective_mass);

        const double normal_velocity = dot(in.relative_velocity, n);  // > 0 when separating
        const Vec3 tangential_velocity = in.relative_velocity - normal_velocity * n;
        const double elastic_normal_force = (4.0 / 3.0) * k.effective_modulus * contact_radius * in.overlap;
        double normal_force = elastic_normal_force - normal_damping * normal_velocity;
        if (normal_force < 0.0) normal_force = 0.0;  // a contact pushes, never pulls
        // The dashpot's share of the force is what it adds to the spring's; its power is
        // that share times the separation rate: c v_n^2, or, when the contact would pull and
        // the force is cut to zero, the whole spring force F_el v_n (the spring's energy
        // released while separating is lost, not given back to the cells).
        out.damping_power = (elastic_normal_force - normal_force) * normal_velocity;

        // The stored spring is turned into the current tangent plane (magnitude kept),
        // then incremented by -S_t times the tangential slip of this step.
        Vec3 spring = tangential_spring - dot(tangential_spring, n) * n;
        const double kept = norm(spring);
        if (kept > 0.0) spring *= norm(tangential_spring) / kept;
        spring -= (tangential_stiffness * in.dt) * tangential_velocity;
        Vec3 tangential_force = spring - tangential_damping * tangential_velocity;
        const double limit = k.friction * normal_force;
        const double spring_magnitude = norm(spring);
        if (spring_magnitude > limit) {
            // Sliding: the spring is capped at mu F_n; the excess slip dissipates mu F_n per metre.
            const double capped = spring_magnitude > 0.0 ? limit / spring_magnitude : 0.0;
            if (tangential_stiffness > 0.0)
                out.friction_dissipation = limit * (spring_magnitude - limit) / tangential_stiffness;
            spring *= capped;
            tangential_force = spring;
        } else {
            out.damping_power += tangential_damping * norm2(tangential_velocity);
        }
        tangential_spring = spring;
        out.force_on_b = normal_force * n + tangential_force;
        out.stiffness = normal_stiffness;
        out.elastic_energy = 0.4 * elastic_normal_force * in.overlap +  // 8/15 E* sqrt(R*) delta^(5/2)
                             (tangential_stiffness > 0.0 ? 0.5 * norm2(spring) / tangential_stiffness : 0.0);
        return out;
    }

    // The patch form (cell against a wall, docs/theory-dem.md §7): every point i has its own
    // Hertz spring, F_i = 4/3 E* sqrt(R* d_i) d_i along its normal at its point, so the
    // elastic force is the gradient of sum_i 8/15 E* sqrt(R*) d_i^(5/2) and continuous as
    // points come and go. The normal dashpot of the whole patch, c = f sqrt(S m*) with
    // S = sum S_i, is shared among the points in proportion to S_i. One tangential
    // spring per patch acts at the stiffness centre p_t = sum S_i p_i / S, with stiffness
    // sum S_t,i, slip velocity (affine in the point) sum S_i v_i / S, and the Coulomb cap
    // mu sum F_i. With one point this is exactly evaluate().
    RF_HD static ContactPatchOutput evaluatePatch(const ContactConstants& k, const ContactPatchInput& in,
                                                  Vec3& tangential_spring)
    {
        ContactPatchOutput out;
        const double damping_factor = -2.0 * std::sqrt(5.0 / 6.0) * k.restitution_beta;
        double stiffness = 0.0;  // S = sum S_n,i
        Vec3 centre, normal_sum, velocity;
        for (int i = 0; i < in.n_points; ++i) {
            const PatchPoint& p = in.points[i];
            const double s = 2.0 * k.effective_modulus * std::sqrt(in.effective_radius * p.overlap);
            stiffness += s;
            centre += s * p.point;
            normal_sum += s * p.normal;
            velocity += s * p.relative_velocity;
        }
        if (!(stiffness > 0.0)) return out;
        out.stiffness = stiffness;
        const double normal_damping = damping_factor * std::sqrt(stiffness * in.effective_mass);
        double normal_total = 0.0;
        for (int i = 0; i < in.n_points; ++i) {
            const PatchPoint& p = in.points[i];
            const double contact_radius = std::sqrt(in.effective_radius * p.overlap);
            const double share = 2.0 * k.effective_modulus * contact_radius / stiffness;
            const double elastic = (4.0 / 3.0) * k.effective_modulus * contact_radius * p.overlap;
            const double normal_velocity = dot(p.relative_velocity, p.normal);
            double force = elastic - share * normal_damping * normal_velocity;
            if (force < 0.0) force = 0.0;
            out.damping_power += (elastic - force) * normal_velocity;  // as in evaluate()
            out.elastic_energy += 0.4 * elastic * p.overlap;
            normal_total += force;
            out.force += force * p.normal;
            out.torque += cross(p.point - in.centre, force * p.normal) + force * p.torque_per_force;
        }
        // One tangential spring at the stiffness centre.
        const double inverse = 1.0 / stiffness;
        centre *= inverse;
        velocity *= inverse;
        const Vec3 n = normalised(normal_sum);
        const double tangential_stiffness = 4.0 * k.effective_shear_modulus / k.effective_modulus * stiffness;
        const double tangential_damping =
            damping_factor * std::sqrt(tangential_stiffness * in.effective_mass);
        const Vec3 tangential_velocity = velocity - dot(velocity, n) * n;
        Vec3 spring = tangential_spring - dot(tangential_spring, n) * n;
        const double kept = norm(spring);
        if (kept > 0.0) spring *= norm(tangential_spring) / kept;
        spring -= (tangential_stiffness * in.dt) * tangential_velocity;
        Vec3 tangential_force = spring - tangential_damping * tangential_velocity;
        const double limit = k.friction * normal_total;
        const double spring_magnitude = norm(spring);
        if (spring_magnitude > limit) {
            const double capped = spring_magnitude > 0.0 ? limit / spring_magnitude : 0.0;
            out.friction_dissipation = limit * (spring_magnitude - limit) / tangential_stiffness;
            spring *= capped;
            tangential_force = spring;
        } else {
            out.damping_power += tangential_damping * norm2(tangential_velocity);
        }
        tangential_spring = spring;
        out.elastic_energy += 0.5 * norm2(spring) / tangential_stiffness;
        out.force += tangential_force;
        out.torque += cross(centre - in.centre, tangential_force);
        return out;
    }
};

// The host side (docs/models/contact/hertzMindlin.md): no coefficients of its own (E* and G*
// come from rock/ and steel/, friction and restitution from the pairings).
class HertzMindlinContactLaw final : public ContactLawModel {
public:
    const char* type() const override;
    void runPairs(const PairKernelArgs& args) const override;
    void runWalls(const WallKernelArgs& args) const override;
};

}  // namespace rockfrac
