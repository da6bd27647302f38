#pragma once
// The bond law interface: what one bond between two cells sees and returns,
// the interface kernel that applies a law to every bond of a cell pair, and the
// selection table (bondLawTable.cpp) that maps a keyword to a law.
//
// A law is a struct with one static RF_HD function
//     BondOutput evaluate(const BondMaterial&, const BondInput&, BondHistory&)
// A new law is a new file (the struct and its runner, see voronoiQnscBond.*)
// plus one line in bondLawTable.cpp.
#include <string>
#include <vector>

#include "core/parallel.hpp"
#include "core/vec3.hpp"
#include "dem/quat.hpp"

namespace rockfrac {

// Bond constants shared by every bond of a run.
struct BondMaterial {
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

// Sums over a block of interfaces, reduced in block order (deterministic).
struct BondBlockSums {
    double strain_energy = 0.0;
    double damping_power = 0.0;
    double fracture_dissipation = 0.0;
    int bonds_broken_now = 0;
};

// Raw views of everything a bond kernel reads and writes (no containers, so a
// CUDA backend can pass device pointers). Interfaces are cell pairs that share a
// face; interface k owns bonds [bond_offset[k], bond_offset[k+1]).
struct BondKernelArgs {
    BondMaterial material;
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
    int* intact_bonds = nullptr;
    Vec3* force_on_i = nullptr;   // sum over the interface's bonds
    Vec3* torque_on_i = nullptr;  // about cell i's centroid
    Vec3* torque_on_j = nullptr;  // about cell j's centroid
    // Bonds.
    const Vec3* anchor_i_body = nullptr;
    const Vec3* anchor_j_body = nullptr;
    unsigned char* stage = nullptr;
    double* onset_displacement = nullptr;
    double* onset_stress = nullptr;
    double* rupture_displacement = nullptr;
    double* max_displacement = nullptr;
    double* damage = nullptr;
    BondBlockSums* block_sums = nullptr;  // one per block of block_size interfaces
};

RF_HD inline BondHistory loadBondHistory(const BondKernelArgs& a, int b)
{
    BondHistory h;
    h.stage = a.stage[b];
    h.onset_displacement = a.onset_displacement[b];
    h.onset_stress = a.onset_stress[b];
    h.rupture_displacement = a.rupture_displacement[b];
    h.max_displacement = a.max_displacement[b];
    h.damage = a.damage[b];
    return h;
}

RF_HD inline void storeBondHistory(const BondKernelArgs& a, int b, const BondHistory& h)
{
    a.stage[b] = h.stage;
    a.onset_displacement[b] = h.onset_displacement;
    a.onset_stress[b] = h.onset_stress;
    a.rupture_displacement[b] = h.rupture_displacement;
    a.max_displacement[b] = h.max_displacement;
    a.damage[b] = h.damage;
}

// All bonds of interface k: kinematics from the two rigid cells, the law, and the
// interface's total force and torques (summed in bond order).
template <class Law>
RF_HD inline void bondInterfaceKernel(const BondKernelArgs& a, int k, BondBlockSums& sums)
{
    const int ci = a.cell_i[k], cj = a.cell_j[k];
    // The two cells' state as local copies: the history stores below go through double
    // pointers the compiler cannot prove distinct from these arrays, so references would be
    // re-read for every bond (profile-driven, docs/benchmarks.md).
    const Mat3 Ri = a.rotation[ci];
    const Mat3 Rj = a.rotation[cj];
    const Vec3 xi = a.position[ci], xj = a.position[cj];
    const Vec3 vi = a.velocity[ci], vj = a.velocity[cj];
    const Vec3 wi = a.angular_velocity_world[ci], wj = a.angular_velocity_world[cj];
    // The bond normal rotates with both cells (n_j is the outward normal of cell j's face).
    const Vec3 normal = normalised(Ri * a.normal_i_body[k] - Rj * a.normal_j_body[k]);
    BondInput in;
    in.normal = normal;
    in.reference_length = a.length_i[k] + a.length_j[k];
    in.bond_area = a.bond_area[k];
    in.damping_beta = a.damping_beta[k];
    // A model effect may scale this interface's strengths; without one the shared
    // constants are used as they are (no copy per interface).
    BondMaterial scaled;
    const BondMaterial* material = &a.material;
    if (a.strength_scale) {
        scaled = a.material;
        scaled.tensile_strength *= a.strength_scale[k];
        scaled.cohesion *= a.strength_scale[k];
        material = &scaled;
    }
    Vec3 force, torque_i, torque_j;
    int intact = 0;
    for (int b = a.bond_offset[k]; b < a.bond_offset[k + 1]; ++b) {
        if (a.stage[b] == bondBroken) continue;
        const Vec3 arm_i = Ri * a.anchor_i_body[b];
        const Vec3 arm_j = Rj * a.anchor_j_body[b];
        in.opening = (xj + arm_j) - (xi + arm_i);
        in.relative_velocity = (vj + cross(wj, arm_j)) - (vi + cross(wi, arm_i));
        // An elastic bond's history is its stage and D (= 0) only: the softening
        // fields are read once damage has begun, and written back only when the law
        // has changed them (after the onset), which spares most of the bond
        // kernel's memory traffic in a mostly intact specimen (docs/benchmarks.md).
        BondHistory history;
        if (a.stage[b] == bondElastic) {
            history.stage = bondElastic;
            history.damage = a.damage[b];
        } else {
            history = loadBondHistory(a, b);
        }
        const BondOutput out = Law::evaluate(*material, in, history);
        if (history.stage != bondElastic) storeBondHistory(a, b, history);
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
    a.intact_bonds[k] = intact;
    a.force_on_i[k] = force;
    a.torque_on_i[k] = torque_i;
    a.torque_on_j[k] = torque_j;
}

// The OpenMP loop over blocks of interfaces (static schedule; a block's sums do
// not depend on the thread count).
template <class Law>
void runBondKernel(const BondKernelArgs& a)
{
    const int n_blocks = (a.n_interfaces + a.block_size - 1) / a.block_size;
#pragma omp parallel for schedule(static) if (n_blocks > 1)
    for (int block = 0; block < n_blocks; ++block) {
        BondBlockSums sums;
        const int end =
            a.n_interfaces < (block + 1) * a.block_size ? a.n_interfaces : (block + 1) * a.block_size;
        for (int k = block * a.block_size; k < end; ++k) bondInterfaceKernel<Law>(a, k, sums);
        a.block_sums[block] = sums;
    }
}

using BondLawRunner = void (*)(const BondKernelArgs&);

// The law registered under name; a UserError listing the known names otherwise.
BondLawRunner bondLawRunner(const std::string& name);
std::vector<std::string> bondLawNames();

}  // namespace rockfrac
