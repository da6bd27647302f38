#pragma once
// The CUDA backend's kernels: one thread per item, each calling the RF_HD function the
// OpenMP path runs, and the per-block sums they reduce in a fixed tree order (the host
// adds the block partials in block order; cudaDemModel.cu).
#include <cuda_runtime.h>

#include <vector>

#include "dem/cellKernels.hpp"
#include "dem/contactKernels.hpp"
#include "demCuda/deviceArrays.cuh"

namespace rockfrac {
namespace {

// ---- Per-block sums ------------------------------------------------------------------

struct BondSums {
    double strain_energy, damping_power, fracture_dissipation;
    int bonds_broken, interfaces_open, interfaces_cracked;
};
RF_HD inline BondSums combine(const BondSums& a, const BondSums& b)
{
    return {a.strain_energy + b.strain_energy,
            a.damping_power + b.damping_power,
            a.fracture_dissipation + b.fracture_dissipation,
            a.bonds_broken + b.bonds_broken,
            a.interfaces_open + b.interfaces_open,
            a.interfaces_cracked + b.interfaces_cracked};
}

struct ContactSums {
    double elastic_energy, damping_power, friction_dissipation;
    int active, cores_intersect;
};
RF_HD inline ContactSums combine(const ContactSums& a, const ContactSums& b)
{
    return {a.elastic_energy + b.elastic_energy, a.damping_power + b.damping_power,
            a.friction_dissipation + b.friction_dissipation, a.active + b.active,
            a.cores_intersect + b.cores_intersect};
}

struct CellSums {
    double kinetic_translation, kinetic_rotation, gravity_work;
    double max_move2;               // largest squared displacement since the list build (a maximum)
    int non_finite_cell;            // lowest index of a non-finite cell, -1 for none
    double max_contact_frequency2;  // the step check (DemModel::setStepLimit; a maximum)
};
RF_HD inline CellSums combine(const CellSums& a, const CellSums& b)
{
    const int nf = a.non_finite_cell < 0
                       ? b.non_finite_cell
                       : (b.non_finite_cell < 0 || a.non_finite_cell < b.non_finite_cell ? a.non_finite_cell
                                                                                         : b.non_finite_cell);
    return {a.kinetic_translation + b.kinetic_translation,
            a.kinetic_rotation + b.kinetic_rotation,
            a.gravity_work + b.gravity_work,
            a.max_move2 > b.max_move2 ? a.max_move2 : b.max_move2,
            nf,
            a.max_contact_frequency2 > b.max_contact_frequency2 ? a.max_contact_frequency2
                                                                : b.max_contact_frequency2};
}

// Tree sum of one value per thread over the block (fixed order); thread 0 writes it.
template <class S>
__device__ void blockSum(const S& mine, S* partials)
{
    __shared__ alignas(S) unsigned char storage[threads_per_block * sizeof(S)];
    S* shared = reinterpret_cast<S*>(storage);
    const int t = threadIdx.x;
    shared[t] = mine;
    __syncthreads();
    for (int half = threads_per_block / 2; half > 0; half /= 2) {
        if (t < half) shared[t] = combine(shared[t], shared[t + half]);
        __syncthreads();
    }
    if (t == 0) partials[blockIdx.x] = shared[0];
}

// The partials of n_blocks blocks, downloaded (the caller adds them in block order).
template <class S>
std::vector<S> downloadPartials(const DeviceArray<S>& partials, int n_blocks)
{
    std::vector<S> host(n_blocks);
    if (n_blocks > 0)
        check(cudaMemcpy(host.data(), partials.data(), n_blocks * sizeof(S), cudaMemcpyDeviceToHost),
              "download of block sums");
    return host;
}

RF_HD inline ContactSums contactTerms(const ContactItemOutputs& o, int item)
{
    ContactSums s{0.0, 0.0, 0.0, 0, 0};
    if (o.status[item] == contactNone) return s;
    s.active = 1;
    s.cores_intersect = o.status[item] == contactCoresIntersect;
    s.elastic_energy = o.elastic_energy[item];
    s.damping_power = o.damping_power[item];
    s.friction_dissipation = o.friction_dissipation[item];
    return s;
}

// ---- Kernels: one thread per item, each calling the shared RF_HD function --------------
// __launch_bounds__: the contact kernels need ~255 registers per thread (GJK, the wall
// patch); the bound makes ptxas keep a block of threads_per_block within the register file.
// The wall kernel's patch buffer (max_patch_points points) lives in local memory (~6 kB
// of stack per thread).

__global__ void __launch_bounds__(threads_per_block)
    refreshKernel(int n, const Quat* orientation, const Vec3* angular_velocity, Mat3* rotation,
                  Vec3* angular_velocity_world)
{
    const int c = blockIdx.x * blockDim.x + threadIdx.x;
    if (c < n) refreshCellKinematics(orientation, angular_velocity, rotation, angular_velocity_world, c);
}

template <class Law>
__global__ void __launch_bounds__(threads_per_block) pairKernelCuda(PairKernelArgs a, ContactSums* partials)
{
    const int p = blockIdx.x * blockDim.x + threadIdx.x;
    ContactSums s{0.0, 0.0, 0.0, 0, 0};
    if (p < a.n_pairs) {
        ContactBlockSums t;
        pairKernel<Law>(a, p, t);
        s = {t.elastic_energy, t.damping_power, t.friction_dissipation, t.active, t.cores_intersect};
    }
    blockSum(s, partials);
}

template <class Law>
__global__ void __launch_bounds__(threads_per_block) wallKernelCuda(WallKernelArgs a, ContactSums* partials)
{
    const int item = blockIdx.x * blockDim.x + threadIdx.x;
    ContactSums s{0.0, 0.0, 0.0, 0, 0};
    if (item < a.n_items) {
        wallKernel<Law>(a, item);
        s = contactTerms(a.items, item);
    }
    blockSum(s, partials);
}

// What the cells exert on each wall this step, summed over its items in item order
// (the CPU's order): one thread per wall. Walls are few (plates, mantle, concave).
struct WallReaction {
    Vec3 reaction, reaction_torque;
    double power;
};

__global__ void __launch_bounds__(threads_per_block)
    wallReactionKernel(int n_walls, int n_items, const WallPose* walls, const int* item_wall,
                       const int* item_cell, const Vec3* force_on_cell, const Vec3* torque_on_cell,
                       const double* wall_power, const Vec3* position, WallReaction* out)
{
    const int w = blockIdx.x * blockDim.x + threadIdx.x;
    if (w >= n_walls) return;
    WallReaction r{Vec3{}, Vec3{}, 0.0};
    for (int i = 0; i < n_items; ++i) {
        if (item_wall[i] != w) continue;
        const Vec3 force = force_on_cell[i];
        r.reaction -= force;
        r.reaction_torque -= cross(position[item_cell[i]] - walls[w].origin, force) + torque_on_cell[i];
        r.power += wall_power[i];
    }
    out[w] = r;
}

__global__ void __launch_bounds__(threads_per_block) gatherKernel(int n, GatherArgs a)
{
    const int c = blockIdx.x * blockDim.x + threadIdx.x;
    if (c < n) gatherCellForces(a, c);
}

__global__ void __launch_bounds__(threads_per_block)
    kickDriftKernel(int n, IntegrationArgs a, double dt, CellSums* partials)
{
    const int c = blockIdx.x * blockDim.x + threadIdx.x;
    CellSums s{0.0, 0.0, 0.0, 0.0, -1, 0.0};
    if (c < n) s.gravity_work = kickDriftCell(a, c, dt);
    blockSum(s, partials);
}

__global__ void __launch_bounds__(threads_per_block) kickKernel(int n, IntegrationArgs a, double dt)
{
    const int c = blockIdx.x * blockDim.x + threadIdx.x;
    if (c < n) kickCell(a, c, dt);
}

__global__ void __launch_bounds__(threads_per_block)
    measureKernel(int n, IntegrationArgs a, double sync_dt, CellSums* partials)
{
    const int c = blockIdx.x * blockDim.x + threadIdx.x;
    CellSums s{0.0, 0.0, 0.0, 0.0, -1, 0.0};
    if (c < n) {
        const CellEnergyTerms t = measureCell(a, c, sync_dt);
        s.kinetic_translation = t.kinetic_translation;
        s.kinetic_rotation = t.kinetic_rotation;
        s.non_finite_cell = t.finite ? -1 : c;
    }
    blockSum(s, partials);
}

__global__ void __launch_bounds__(threads_per_block)
    moveSinceBuildKernel(int n, const Vec3* position, const Vec3* position_at_build, CellSums* partials)
{
    const int c = blockIdx.x * blockDim.x + threadIdx.x;
    CellSums s{0.0, 0.0, 0.0, 0.0, -1, 0.0};
    if (c < n) s.max_move2 = norm2(position[c] - position_at_build[c]);
    blockSum(s, partials);
}

__global__ void __launch_bounds__(threads_per_block)
    stiffestCellKernel(int n, const float* contact_frequency2, CellSums* partials)
{
    const int c = blockIdx.x * blockDim.x + threadIdx.x;
    CellSums s{0.0, 0.0, 0.0, 0.0, -1, 0.0};
    if (c < n) s.max_contact_frequency2 = contact_frequency2[c];
    blockSum(s, partials);
}

}  // namespace
}  // namespace rockfrac
