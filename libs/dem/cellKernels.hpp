#pragma once
// Per-cell kernels of a DEM step: the kinematic caches, the gather of item forces,
// the two halves of the integrator and the per-cell terms of the energy check.
//
// One function per cell over raw arrays (RF_HD, no containers, no exceptions), so
// that DemModel's OpenMP loops and the CUDA backend (libs/demCuda) run the same
// source. Sums over cells (gravity work, kinetic energy) are returned per cell and
// added by the caller in its own fixed order.
#include "core/vec3.hpp"
#include "dem/quat.hpp"

namespace rockfrac {

// The rotation matrix and the world angular velocity of cell c, cached once per force
// evaluation because every bond, contact and wall item of the cell uses them.
RF_HD inline void refreshCellKinematics(const Quat* orientation, const Vec3* angular_velocity_body,
                                        Mat3* rotation, Vec3* angular_velocity_world, int c)
{
    rotation[c] = rotationMatrix(orientation[c]);
    angular_velocity_world[c] = rotation[c] * angular_velocity_body[c];
}

// What the gather reads: the per-item results and, per cell, CSR lists of the items
// it takes part in (entry = 2 * item + side; side 1 = the item's second cell).
struct GatherArgs {
    Vec3 gravity;
    const double* mass = nullptr;
    const int* interface_offset = nullptr;
    const int* interface_entries = nullptr;
    const Vec3* interface_force_on_i = nullptr;
    const Vec3* interface_torque_on_i = nullptr;
    const Vec3* interface_torque_on_j = nullptr;
    const int* pair_offset = nullptr;
    const int* pair_entries = nullptr;
    const Vec3* pair_force_on_b = nullptr;
    // Per pair: its contact point (point contacts) or the torque on b about its centroid
    // (patch contacts, pair_torques), see PairKernelArgs::point_or_torque.
    const Vec3* pair_point_or_torque = nullptr;
    bool pair_torques = false;
    const int* pair_cell_b = nullptr;
    const Vec3* position = nullptr;
    const int* wall_item_offset = nullptr;  // wall items are sorted by cell: a range per cell
    const Vec3* wall_force_on_cell = nullptr;
    const Vec3* wall_torque_on_cell = nullptr;
    Vec3* force = nullptr;   // out: total force incl. gravity
    Vec3* torque = nullptr;  // out: about the centroid
    // The step check (DemModel::step): the items' normal contact stiffnesses, summed per
    // cell into a bound of the highest squared frequency its contacts can give it (out).
    const float* pair_stiffness = nullptr;
    const float* wall_stiffness = nullptr;
    const Vec3* principal_inertia = nullptr;
    const double* bounding_radius = nullptr;
    float* contact_frequency2 = nullptr;
};

// Bound of the highest squared frequency the contacts of cell c can give it [rad^2/s^2]:
// the sum S of its contacts' normal stiffnesses on its mass and, acting at up to its
// bounding radius R, on its smallest moment of inertia: S (1/m + R^2/I_min), with 2/m for
// cell pairs (the partner moves too). The trace of the mass-normalised contact stiffness
// with every point at the largest arm; the start estimate (criticalTimeStep's contact
// step) is this for one rock-steel point at an overlap of 0.1 r_d (docs/theory-dem.md §2).
RF_HD inline double contactFrequency2(double pair_stiffness, double wall_stiffness, double mass,
                                      const Vec3& inertia, double bounding_radius)
{
    const double smallest = inertia.x < inertia.y ? (inertia.x < inertia.z ? inertia.x : inertia.z)
                                                  : (inertia.y < inertia.z ? inertia.y : inertia.z);
    const double turning = bounding_radius * bounding_radius / smallest;
    return pair_stiffness * (2.0 / mass + turning) + wall_stiffness * (1.0 / mass + turning);
}

// Cell c sums the items it takes part in, in a fixed order: no atomics, and the
// same floating-point sums whatever the number of threads (or GPU blocks).
RF_HD inline void gatherCellForces(const GatherArgs& a, int c)
{
    Vec3 force = a.mass[c] * a.gravity, torque;
    for (int e = a.interface_offset[c]; e < a.interface_offset[c + 1]; ++e) {
        const int k = a.interface_entries[e] >> 1;
        if (a.interface_entries[e] & 1) {
            force -= a.interface_force_on_i[k];
            torque += a.interface_torque_on_j[k];
        } else {
            force += a.interface_force_on_i[k];
            torque += a.interface_torque_on_i[k];
        }
    }
    double pair_stiffness = 0.0, wall_stiffness = 0.0;
    for (int e = a.pair_offset[c]; e < a.pair_offset[c + 1]; ++e) {
        const int p = a.pair_entries[e] >> 1;
        pair_stiffness += a.pair_stiffness[p];
        if (a.pair_torques) {
            // A patch stores the force and torque on b (not a's too: 24 bytes less per
            // pair); a's follows from the balance of the pair's internal forces: about a's
            // centroid the opposite forces give -T_b - (x_b - x_a) x F_b.
            if (a.pair_entries[e] & 1) {
                force += a.pair_force_on_b[p];
                torque += a.pair_point_or_torque[p];
            } else {
                const Vec3 arm = a.position[a.pair_cell_b[p]] - a.position[c];
                force -= a.pair_force_on_b[p];
                torque += -1.0 * a.pair_point_or_torque[p] - cross(arm, a.pair_force_on_b[p]);
            }
            continue;
        }
        // A point contact stores its force and contact point (not two torques: 24 bytes
        // less per pair); the torque is formed here as the pair kernel would have formed it.
        const Vec3 arm = a.pair_point_or_torque[p] - a.position[c];
        if (a.pair_entries[e] & 1) {
            force += a.pair_force_on_b[p];
            torque += cross(arm, a.pair_force_on_b[p]);
        } else {
            force -= a.pair_force_on_b[p];
            torque += -cross(arm, a.pair_force_on_b[p]);
        }
    }
    for (int i = a.wall_item_offset[c]; i < a.wall_item_offset[c + 1]; ++i) {
        force += a.wall_force_on_cell[i];
        torque += a.wall_torque_on_cell[i];
        wall_stiffness += a.wall_stiffness[i];
    }
    a.force[c] = force;
    a.torque[c] = torque;
    a.contact_frequency2[c] = static_cast<float>(contactFrequency2(
        pair_stiffness, wall_stiffness, a.mass[c], a.principal_inertia[c], a.bounding_radius[c]));
}

// The cell state the integrator advances.
struct IntegrationArgs {
    Vec3 gravity;
    const double* mass = nullptr;
    const Vec3* principal_inertia = nullptr;
    const Vec3* force = nullptr;
    const Vec3* torque = nullptr;
    const Mat3* rotation = nullptr;  // of the last force evaluation (for the torque's body frame)
    Vec3* position = nullptr;
    Vec3* velocity = nullptr;
    Quat* orientation = nullptr;
    Vec3* angular_velocity = nullptr;  // body frame
};

// First half kick and drift (velocity Verlet) and the rotation update: forward Euler
// on SO(3) with the exact rotation of the body-frame angular momentum by the same
// increment (the gyroscopic term), which keeps |L| and, without torque, the world
// angular momentum exactly (docs/theory-dem.md §Integration). Returns the work of
// gravity over the drift of cell c.
RF_HD inline double kickDriftCell(const IntegrationArgs& a, int c, double dt)
{
    const double mass = a.mass[c];
    a.velocity[c] += (0.5 * dt / mass) * a.force[c];
    const Vec3 step = dt * a.velocity[c];
    a.position[c] += step;
    const double gravity_work = mass * dot(a.gravity, step);

    const Vec3 inertia = a.principal_inertia[c];
    const Vec3 omega = a.angular_velocity[c];
    const Quat increment = quatFromRotationVector(dt * omega);
    a.orientation[c] = normalised(a.orientation[c] * increment);
    const Vec3 momentum{inertia.x * omega.x, inertia.y * omega.y, inertia.z * omega.z};
    const Vec3 turned = transposeTimes(rotationMatrix(increment), momentum);
    a.angular_velocity[c] = {turned.x / inertia.x, turned.y / inertia.y, turned.z / inertia.z};
    return gravity_work;
}

// Second half kick, and the torque's forward Euler increment of the angular velocity.
RF_HD inline void kickCell(const IntegrationArgs& a, int c, double dt)
{
    a.velocity[c] += (0.5 * dt / a.mass[c]) * a.force[c];
    const Vec3 torque_body = transposeTimes(a.rotation[c], a.torque[c]);
    const Vec3 inertia = a.principal_inertia[c];
    a.angular_velocity[c] +=
        dt * Vec3{torque_body.x / inertia.x, torque_body.y / inertia.y, torque_body.z / inertia.z};
}

struct CellEnergyTerms {
    double kinetic_translation = 0.0;
    double kinetic_rotation = 0.0;
    bool finite = true;  // position, velocity and angular velocity are finite
};

// Kinetic energy of cell c and the finiteness check. Angular velocities live at half
// steps (forward Euler in the torque after the orientation update = leapfrog
// staggering); the energy uses the value synchronised by half a step sync_dt.
RF_HD inline CellEnergyTerms measureCell(const IntegrationArgs& a, int c, double sync_dt)
{
    CellEnergyTerms t;
    const Vec3 inertia = a.principal_inertia[c];
    const Vec3 torque_body = transposeTimes(a.rotation[c], a.torque[c]);
    const Vec3 w =
        a.angular_velocity[c] - (0.5 * sync_dt) * Vec3{torque_body.x / inertia.x, torque_body.y / inertia.y,
                                                       torque_body.z / inertia.z};
    t.kinetic_translation = 0.5 * a.mass[c] * norm2(a.velocity[c]);
    t.kinetic_rotation = 0.5 * (inertia.x * w.x * w.x + inertia.y * w.y * w.y + inertia.z * w.z * w.z);
    const double check = norm2(a.position[c]) + norm2(a.velocity[c]) + norm2(w);
    t.finite = std::isfinite(check);
    return t;
}

}  // namespace rockfrac
