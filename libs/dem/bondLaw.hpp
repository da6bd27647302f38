#pragma once
// The bond law interface: what one bond between two cells sees and returns, and the
// interface kernel that applies a law to every bond of a cell pair (CPU and CUDA).
//
// A law is a struct with its coefficients and three static RF_HD functions:
//     struct Coefficients { double normal_modulus, shear_modulus; ... };  // k_n, k_t first
//     BondOutput evaluate(const Coefficients&, const BondInput&, BondHistory&)
//     void scaleStrength(Coefficients&, double factor)   // a weaker or stronger interface
// Its host side (bondLawModel.hpp) reads the coefficients from the law's own
// sub-dictionary; a new law is a new file pair (see voronoiQnscBond.*, brittleBpmBond.*)
// plus one line in bondLawTable.cpp and, for the GPU, one in libs/demCuda.
#include <cstdint>
#include <string>
#include <vector>

#include "core/parallel.hpp"
#include "core/vec3.hpp"
#include "dem/quat.hpp"

namespace rockfrac {

// Life of a bond: elastic ("init" = true in Algorithm 1), softening, broken (D = 1).
enum BondStage : unsigned char { bondElastic = 0, bondSoftening = 1, bondBroken = 2 };

// Damage history of one bond (Algorithm 1), loaded from and stored to the SoA arrays.
struct BondHistory {
    unsigned char stage = bondElastic;
    double onset_displacement = 0.0;    // d_e0 [m]
    double onset_stress = 0.0;          // sigma_e0 [Pa]
    double rupture_displacement = 0.0;  // d_f [m]
    double max_displacement = 0.0;      // d_max [m]
    double damage = 0.0;                // D [-]
};

// The part of the history that only a bond past its onset has. The model keeps it
// in a pool claimed per interface at the first onset of one of its bonds, so an
// intact specimen carries none of it (docs/theory-dem.md §7, docs/benchmarks.md).
struct BondSoftening {
    double onset_displacement = 0.0;    // d_e0 [m]
    double onset_stress = 0.0;          // sigma_e0 [Pa]
    double rupture_displacement = 0.0;  // d_f [m]
    double max_displacement = 0.0;      // d_max [m]
    double damage = 0.0;                // D [-]
};

// Kinematics of one bond, in world coordinates.
struct BondInput {
    Vec3 opening;                   // d = x_j - x_i of the two anchor points [m]
    Vec3 normal;                    // n = (n_i - n_j)/|n_i - n_j|, pointing from cell i to cell j
    Vec3 relative_velocity;         // velocity of anchor j minus that of anchor i [m/s]
    double reference_length = 0.0;  // l_ij = l_i + l_j [m]
    double bond_area = 0.0;         // A/n [m^2]
    double damping_beta = 0.0;      // beta of Eqs. 18–19 in seconds (already converted) [s]
};

struct BondOutput {
    Vec3 force_on_i;                    // F of Eq. 20 acting on cell i; cell j gets -F [N]
    double strain_energy = 0.0;         // recoverable elastic energy stored now [J]
    double damping_power = 0.0;         // dashpot dissipation rate, >= 0 [W]
    double fracture_dissipation = 0.0;  // energy dissipated by damage growth in this call [J]
};

// The elastic bond of Eqs. 5–8, degraded by D (Eqs. 16–17: no damage in compression), with
// the stiffness-proportional dashpot of Eqs. 18–19 from the anchor points' relative velocity
// (it always opposes the relative motion, docs/theory-dem.md): force, strain energy and
// dashpot power into out. Every law's intact bond is this one (damage 0).
RF_HD inline void elasticBondResponse(double normal_modulus, double shear_modulus, const BondInput& in,
                                      double l, double inverse_l, double normal_opening,
                                      const Vec3& shear_opening, double sigma_trial, double damage,
                                      BondOutput& out)
{
    const double intact = 1.0 - damage;
    const double sigma = normal_opening < 0.0 ? sigma_trial : intact * sigma_trial;
    const Vec3 shear_stress = (intact * shear_modulus * inverse_l) * shear_opening;  // tau t
    const double normal_rate = dot(in.relative_velocity, in.normal) * inverse_l;     // eps-dot
    const Vec3 shear_rate =
        (in.relative_velocity - (normal_rate * l) * in.normal) * inverse_l;  // gamma-dot t
    const double beta = in.damping_beta;
    out.force_on_i = in.bond_area * ((sigma + beta * normal_modulus * normal_rate) * in.normal +
                                     shear_stress + (beta * shear_modulus) * shear_rate);
    out.strain_energy = 0.5 * in.bond_area * (sigma * normal_opening + dot(shear_stress, shear_opening));
    out.damping_power = in.bond_area * beta * l *
                        (normal_modulus * normal_rate * normal_rate + shear_modulus * norm2(shear_rate));
}

// Sums over a block of interfaces, reduced in block order (deterministic).
struct BondBlockSums {
    double strain_energy = 0.0;
    double damping_power = 0.0;
    double fracture_dissipation = 0.0;
    int bonds_broken_now = 0;
    // Interfaces of the block whose first onset found no softening slot: nothing of them
    // was written or summed; the model claims their slots and evaluates them again.
    int pending_onsets = 0;

    RF_HD void add(const BondBlockSums& o)
    {
        strain_energy += o.strain_energy;
        damping_power += o.damping_power;
        fracture_dissipation += o.fracture_dissipation;
        bonds_broken_now += o.bonds_broken_now;
        pending_onsets += o.pending_onsets;
    }
};

// intact_bonds[k] of an interface whose first onset is waiting for its softening slot.
constexpr int bondOnsetPending = -1;

// Raw views of everything a bond kernel reads and writes (no containers, so a
// CUDA backend can pass device pointers). Interfaces are cell pairs that share a
// face; interface k owns bonds [bond_offset[k], bond_offset[k+1]).
struct BondKernelArgs {
    int n_interfaces = 0;
    int block_size = 256;
    // Cells (world frame; rotation and world angular velocity refreshed each step).
    const Vec3* position = nullptr;
    const Vec3* velocity = nullptr;
    const Vec3* angular_velocity_world = nullptr;
    const Mat3* rotation = nullptr;
    // Interfaces.
    const int* cell_i = nullptr;
    const int* cell_j = nullptr;
    const int* bond_offset = nullptr;
    const Vec3* normal_i_body = nullptr;
    const Vec3* normal_j_body = nullptr;
    const double* length_i = nullptr;
    const double* length_j = nullptr;
    const double* bond_area = nullptr;
    const double* damping_beta = nullptr;    // per interface, seconds
    const double* strength_scale = nullptr;  // per interface factor on sigma-bar and C; nullptr = 1
    // Softening pool entry of the interface's first bond, -1 while every bond is elastic.
    const int* softening_slot = nullptr;
    int* intact_bonds = nullptr;  // bondOnsetPending: evaluate again once the slot is claimed
    Vec3* force_on_i = nullptr;   // sum over the interface's bonds
    Vec3* torque_on_i = nullptr;  // about cell i's centroid
    Vec3* torque_on_j = nullptr;  // about cell j's centroid
    // Anchor nodes: the face nodes of each cell in its body frame, shared by the cell's bonds.
    const int* anchor_node_offset = nullptr;
    const Vec3* anchor_nodes = nullptr;
    // Bonds: each end's node within its cell's list, the stage, and the softening pool.
    const std::uint16_t* node_i = nullptr;
    const std::uint16_t* node_j = nullptr;
    unsigned char* stage = nullptr;
    BondSoftening* softening = nullptr;
    BondBlockSums* block_sums = nullptr;  // one per block of block_size interfaces
    // Set: evaluate only these interfaces, in this order, adding to their blocks' sums
    // (the second pass for interfaces whose first onset was pending).
    const int* only_interfaces = nullptr;
    int n_only = 0;
    // A decomposed model (dem/demExchange.hpp): only interfaces with counted[k] are evaluated
    // (the others are another rank's, their results sent here); null: every interface.
    const unsigned char* counted = nullptr;
};

RF_HD inline BondHistory loadBondHistory(unsigned char stage, const BondSoftening& s)
{
    BondHistory h;
    h.stage = stage;
    h.onset_displacement = s.onset_displacement;
    h.onset_stress = s.onset_stress;
    h.rupture_displacement = s.rupture_displacement;
    h.max_displacement = s.max_displacement;
    h.damage = s.damage;
    return h;
}

RF_HD inline BondSoftening softeningOf(const BondHistory& h)
{
    BondSoftening s;
    s.onset_displacement = h.onset_displacement;
    s.onset_stress = h.onset_stress;
    s.rupture_displacement = h.rupture_displacement;
    s.max_displacement = h.max_displacement;
    s.damage = h.damage;
    return s;
}

// All bonds of interface k: kinematics from the two rigid cells, the law, and the
// interface's total force and torques (summed in bond order). Returns false, having
// written nothing but intact_bonds[k] = bondOnsetPending, when a bond of an interface
// without a softening slot reaches its onset: the caller claims the slot and calls
// again with the same state, which gives the same evaluation, now stored.
template <class Law>
RF_HD inline bool bondInterfaceKernel(const BondKernelArgs& a, const typename Law::Coefficients& coefficients,
                                      int k, BondBlockSums& block)
{
    if (a.counted && !a.counted[k]) return true;  // another rank's (dem/demExchange.hpp)
    const int ci = a.cell_i[k], cj = a.cell_j[k];
    // The two cells' state as local copies: the history stores below go through
    // pointers the compiler cannot prove distinct from these arrays, so references would be
    // re-read for every bond (profile-driven, docs/benchmarks.md).
    const Mat3 Ri = a.rotation[ci];
    const Mat3 Rj = a.rotation[cj];
    const Vec3 xi = a.position[ci], xj = a.position[cj];
    const Vec3 vi = a.velocity[ci], vj = a.velocity[cj];
    const Vec3 wi = a.angular_velocity_world[ci], wj = a.angular_velocity_world[cj];
    const Vec3* nodes_i = a.anchor_nodes + a.anchor_node_offset[ci];
    const Vec3* nodes_j = a.anchor_nodes + a.anchor_node_offset[cj];
    // The bond normal rotates with both cells (n_j is the outward normal of cell j's face).
    const Vec3 normal = normalised(Ri * a.normal_i_body[k] - Rj * a.normal_j_body[k]);
    BondInput in;
    in.normal = normal;
    in.reference_length = a.length_i[k] + a.length_j[k];
    in.bond_area = a.bond_area[k];
    in.damping_beta = a.damping_beta[k];
    // A model effect or the size effect may scale this interface's strengths; without one
    // the shared coefficients are used as they are (no copy per interface).
    typename Law::Coefficients scaled;
    const typename Law::Coefficients* material = &coefficients;
    if (a.strength_scale) {
        scaled = coefficients;
        Law::scaleStrength(scaled, a.strength_scale[k]);
        material = &scaled;
    }
    const int first = a.bond_offset[k];
    const int slot = a.softening_slot[k];
    BondBlockSums sums;
    Vec3 force, torque_i, torque_j;
    int intact = 0;
    for (int b = first; b < a.bond_offset[k + 1]; ++b) {
        const unsigned char stage = a.stage[b];
        if (stage == bondBroken) continue;
        const Vec3 arm_i = Ri * nodes_i[a.node_i[b]];
        const Vec3 arm_j = Rj * nodes_j[a.node_j[b]];
        in.opening = (xj + arm_j) - (xi + arm_i);
        in.relative_velocity = (vj + cross(wj, arm_j)) - (vi + cross(wi, arm_i));
        // An elastic bond's history is its stage only (D = 0): the softening fields
        // exist from the onset on and are written back only when the law has changed
        // them, which spares most of the bond kernel's memory traffic in a mostly
        // intact specimen (docs/benchmarks.md).
        BondHistory history;
        if (stage != bondElastic) history = loadBondHistory(stage, a.softening[slot + (b - first)]);
        const BondOutput out = Law::evaluate(*material, in, history);
        if (history.stage != bondElastic) {
            if (slot < 0) {
                a.intact_bonds[k] = bondOnsetPending;
                ++block.pending_onsets;
                return false;
            }
            a.stage[b] = history.stage;
            a.softening[slot + (b - first)] = softeningOf(history);
        }
        sums.strain_energy += out.strain_energy;
        sums.damping_power += out.damping_power;
        sums.fracture_dissipation += out.fracture_dissipation;
        if (history.stage == bondBroken) {
            ++sums.bonds_broken_now;
            continue;
        }
        ++intact;
        force += out.force_on_i;
        torque_i += cross(arm_i, out.force_on_i);
        torque_j -= cross(arm_j, out.force_on_i);
    }
    block.add(sums);
    a.intact_bonds[k] = intact;
    a.force_on_i[k] = force;
    a.torque_on_i[k] = torque_i;
    a.torque_on_j[k] = torque_j;
    return true;
}

// Start loading what interface k will read from its second cell: interfaces are sorted by
// their first cell, so cell i's data streams through the cache, but cell j is anywhere in
// memory and its anchor nodes (indexed through node_j) would otherwise be waited for on
// every bond (measured: 2x slower steps at 10^4 cells without this). CPU only.
// GCC deletes a loop of __builtin_prefetch as a loop without side effects; the asm
// statement is kept.
inline void prefetchLine(const void* p)
{
#if defined(__x86_64__) || defined(__i386__)
    asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(p)));
#else
    __builtin_prefetch(p);
#endif
}

inline void prefetchInterface(const BondKernelArgs& a, int k)
{
    const int cj = a.cell_j[k];
    const Vec3* nodes = a.anchor_nodes + a.anchor_node_offset[cj];
    for (int b = a.bond_offset[k]; b < a.bond_offset[k + 1]; ++b) prefetchLine(nodes + a.node_j[b]);
    prefetchLine(a.rotation + cj);
    prefetchLine(a.position + cj);
    prefetchLine(a.velocity + cj);
    prefetchLine(a.angular_velocity_world + cj);
}

// The OpenMP loop over blocks of interfaces (static schedule; a block's sums do
// not depend on the thread count), or the serial second pass over only_interfaces.
template <class Law>
void runBondKernel(const BondKernelArgs& a, const typename Law::Coefficients& coefficients)
{
    if (a.only_interfaces) {
        for (int i = 0; i < a.n_only; ++i) {
            const int k = a.only_interfaces[i];
            bondInterfaceKernel<Law>(a, coefficients, k, a.block_sums[k / a.block_size]);
        }
        return;
    }
    const int n_blocks = (a.n_interfaces + a.block_size - 1) / a.block_size;
#pragma omp parallel for schedule(static) if (n_blocks > 1)
    for (int block = 0; block < n_blocks; ++block) {
        BondBlockSums sums;
        const int end =
            a.n_interfaces < (block + 1) * a.block_size ? a.n_interfaces : (block + 1) * a.block_size;
        // Two interfaces ahead: the anchor-node offset of cell j, then its nodes.
        for (int k = block * a.block_size; k < end; ++k) {
            if (k + 4 < a.n_interfaces) prefetchLine(a.anchor_node_offset + a.cell_j[k + 4]);
            if (k + 2 < a.n_interfaces) prefetchInterface(a, k + 2);
            bondInterfaceKernel<Law>(a, coefficients, k, sums);
        }
        a.block_sums[block] = sums;
    }
}

}  // namespace rockfrac
