// The CUDA backend of the bonded DEM: device arrays, one kernel per stage of a step,
// each a thin loop-replacement over the RF_HD functions the OpenMP path runs
// (cudaDemModel.hpp says what runs where).
//
// Sums over items (energies, counts, largest displacement) are reduced per thread
// block in a fixed tree order and the block partials added on the host in block
// order: run-to-run reproducible on one GPU, but in a different order than the
// CPU's blocks of 256/512 items, and nvcc contracts a*b+c into FMAs and has its own
// sin/cos/atan2, so CPU and GPU agree to round-off, not bitwise (docs/benchmarks.md).
#include <cuda_runtime.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "dem/brittleBpmBond.hpp"
#include "dem/cellKernels.hpp"
#include "dem/hertzMindlinContact.hpp"
#include "dem/voronoiQnscBond.hpp"
#include "demCuda/cudaDemModel.hpp"

#ifndef ROCKFRAC_CUDA_ARCHITECTURES
#define ROCKFRAC_CUDA_ARCHITECTURES "unknown"
#endif

namespace rockfrac {

namespace {

constexpr int threads_per_block = 256;

void check(cudaError_t status, const char* what)
{
    if (status != cudaSuccess)
        throw UserError(
            std::string("CUDA backend: ") + what + " failed: " + cudaGetErrorString(status) +
            (status == cudaErrorMemoryAllocation ? " (the model does not fit in device memory)" : ""));
}

int blocksFor(int n)
{
    return (n + threads_per_block - 1) / threads_per_block;
}

// A device array of trivially copyable T: cudaMalloc'd, grown (never shrunk) on upload.
template <class T>
class DeviceArray {
public:
    DeviceArray() = default;
    ~DeviceArray() { cudaFree(data_); }
    DeviceArray(const DeviceArray&) = delete;
    DeviceArray& operator=(const DeviceArray&) = delete;

    // Size n; the contents are undefined when the array had to grow.
    void resize(std::size_t n)
    {
        if (n > capacity_) {
            cudaFree(data_);
            data_ = nullptr;
            capacity_ = 0;
            check(cudaMalloc(reinterpret_cast<void**>(&data_), n * sizeof(T)), "cudaMalloc");
            capacity_ = n;
        }
        size_ = n;
    }
    void upload(const std::vector<T>& v)
    {
        resize(v.size());
        if (!v.empty())
            check(cudaMemcpy(data_, v.data(), v.size() * sizeof(T), cudaMemcpyHostToDevice), "upload");
    }
    void download(std::vector<T>& v) const
    {
        v.resize(size_);
        if (size_ > 0)
            check(cudaMemcpy(v.data(), data_, size_ * sizeof(T), cudaMemcpyDeviceToHost), "download");
    }
    void copyFrom(const DeviceArray& other)
    {
        resize(other.size_);
        if (size_ > 0)
            check(cudaMemcpy(data_, other.data_, size_ * sizeof(T), cudaMemcpyDeviceToDevice), "device copy");
    }
    T* data() const { return data_; }
    std::size_t size() const { return size_; }
    std::size_t bytes() const { return capacity_ * sizeof(T); }

private:
    T* data_ = nullptr;
    std::size_t size_ = 0, capacity_ = 0;
};

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
__global__ void __launch_bounds__(threads_per_block)
    bondKernel(BondKernelArgs a, typename Law::Coefficients coefficients, BondSums* partials)
{
    const int k = blockIdx.x * blockDim.x + threadIdx.x;
    BondSums s{0.0, 0.0, 0.0, 0, 0, 0};
    if (k < a.n_interfaces) {
        BondBlockSums sums;
        bondInterfaceKernel<Law>(a, coefficients, k, sums);
        s.strain_energy = sums.strain_energy;
        s.damping_power = sums.damping_power;
        s.fracture_dissipation = sums.fracture_dissipation;
        s.bonds_broken = a.bond_offset[k + 1] - a.bond_offset[k] - a.intact_bonds[k];
        s.interfaces_open = a.intact_bonds[k] == 0;
        s.interfaces_cracked = s.bonds_broken > 0;
    }
    blockSum(s, partials);
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

// The laws with a CUDA kernel (the CPU tables: bondLawTable.cpp, contactLawTable.cpp): the
// bond laws by keyword, each launched with the coefficients its host model owns.
using BondLaunch = void (*)(const BondLawModel& law, const BondKernelArgs& args, int blocks,
                            BondSums* partials);

template <class Law, class Model>
void launchBonds(const BondLawModel& law, const BondKernelArgs& args, int blocks, BondSums* partials)
{
    const typename Law::Coefficients& coefficients = static_cast<const Model&>(law).coefficients();
    bondKernel<Law><<<blocks, threads_per_block>>>(args, coefficients, partials);
}

const std::pair<const char*, BondLaunch> device_bond_laws[] = {
    {"voronoiQNSC", &launchBonds<VoronoiQnscLaw, VoronoiQnscBondLaw>},
    {"brittleBPM", &launchBonds<BrittleBpmLaw, BrittleBpmBondLaw>},
};

BondLaunch deviceBondLaw(const BondLawModel& law)
{
    for (const auto& entry : device_bond_laws)
        if (std::string(law.type()) == entry.first) return entry.second;
    return nullptr;
}

using ContactLawOnDevice = HertzMindlinLaw;
constexpr const char* contact_law_on_device = "hertzMindlin";

}  // namespace

// ---- Device arrays ---------------------------------------------------------------------

struct CudaDemModel::Buffers {
    // Cells.
    DeviceArray<Vec3> position, velocity, angular_velocity, force, torque, principal_inertia, core_vertices;
    DeviceArray<Quat> orientation;
    DeviceArray<double> mass, dilation_radius, bounding_radius;
    DeviceArray<int> core_vertex_offset, core_edge_offset, core_plane_offset;
    DeviceArray<unsigned char> core_edges;
    DeviceArray<CorePlane> core_planes;
    DeviceArray<Mat3> rotation;
    DeviceArray<Vec3> angular_velocity_world, position_at_build;
    // Interfaces and bonds.
    DeviceArray<int> cell_i, cell_j, bond_offset, intact_bonds;
    DeviceArray<Vec3> normal_i, normal_j, force_on_i, torque_on_i, torque_on_j;
    DeviceArray<double> length_i, length_j, bond_area, damping_beta;
    DeviceArray<double> strength_scale;  // empty when no model effect scales the strengths
    // Bonds: the host's anchor nodes, and the softening history with one entry per bond
    // (slot of interface k = its first bond), so the device never claims a slot.
    DeviceArray<int> anchor_node_offset, softening_slot;
    DeviceArray<Vec3> anchor_nodes;
    DeviceArray<std::uint16_t> node_i, node_j;
    DeviceArray<unsigned char> stage;
    DeviceArray<BondSoftening> softening;
    DeviceArray<int> cell_interface_offset, cell_interfaces;
    // Contact pairs.
    DeviceArray<int> pair_a, pair_b, pair_interface, cell_pair_offset, cell_pairs;
    DeviceArray<Vec3> pair_spring, pair_last_normal, pair_force_on_b, pair_point_or_torque;
    DeviceArray<float> pair_margin;
    DeviceArray<double> pair_seat;  // empty for point contacts
    DeviceArray<unsigned char> pair_status;
    DeviceArray<float> pair_stiffness;
    // Wall items and walls.
    DeviceArray<int> item_cell, item_wall, item_triangle_offset, item_triangles, cell_wall_item_offset;
    DeviceArray<Vec3> item_spring, item_last_normal, item_force, item_torque;
    DeviceArray<double> item_elastic, item_damping, item_friction, item_power;
    DeviceArray<unsigned char> item_status;
    DeviceArray<float> item_stiffness, cell_contact_frequency2;
    DeviceArray<WallPose> walls;
    DeviceArray<Vec3> triangle_vertices;
    DeviceArray<std::uint16_t> triangle_features;
    DeviceArray<WallReaction> reactions;
    // Block partials.
    DeviceArray<BondSums> bond_sums;
    DeviceArray<ContactSums> pair_sums, item_sums;
    DeviceArray<CellSums> cell_sums;
    std::string device_name;

    std::size_t bytes() const
    {
        std::size_t total = 0;
        for (std::size_t b : {position.bytes(),
                              velocity.bytes(),
                              angular_velocity.bytes(),
                              force.bytes(),
                              torque.bytes(),
                              principal_inertia.bytes(),
                              core_vertices.bytes(),
                              orientation.bytes(),
                              mass.bytes(),
                              dilation_radius.bytes(),
                              bounding_radius.bytes(),
                              core_vertex_offset.bytes(),
                              core_edge_offset.bytes(),
                              core_edges.bytes(),
                              core_plane_offset.bytes(),
                              core_planes.bytes(),
                              rotation.bytes(),
                              angular_velocity_world.bytes(),
                              position_at_build.bytes(),
                              cell_i.bytes(),
                              cell_j.bytes(),
                              bond_offset.bytes(),
                              intact_bonds.bytes(),
                              normal_i.bytes(),
                              normal_j.bytes(),
                              force_on_i.bytes(),
                              torque_on_i.bytes(),
                              torque_on_j.bytes(),
                              length_i.bytes(),
                              length_j.bytes(),
                              bond_area.bytes(),
                              damping_beta.bytes(),
                              strength_scale.bytes(),
                              anchor_node_offset.bytes(),
                              softening_slot.bytes(),
                              anchor_nodes.bytes(),
                              node_i.bytes(),
                              node_j.bytes(),
                              stage.bytes(),
                              softening.bytes(),
                              cell_interface_offset.bytes(),
                              cell_interfaces.bytes(),
                              pair_a.bytes(),
                              pair_b.bytes(),
                              pair_interface.bytes(),
                              cell_pair_offset.bytes(),
                              cell_pairs.bytes(),
                              pair_spring.bytes(),
                              pair_last_normal.bytes(),
                              pair_force_on_b.bytes(),
                              pair_point_or_torque.bytes(),
                              pair_margin.bytes(),
                              pair_seat.bytes(),
                              pair_status.bytes(),
                              pair_stiffness.bytes(),
                              item_cell.bytes(),
                              item_wall.bytes(),
                              item_triangle_offset.bytes(),
                              item_triangles.bytes(),
                              cell_wall_item_offset.bytes(),
                              item_spring.bytes(),
                              item_last_normal.bytes(),
                              item_force.bytes(),
                              item_torque.bytes(),
                              item_elastic.bytes(),
                              item_damping.bytes(),
                              item_friction.bytes(),
                              item_power.bytes(),
                              item_status.bytes(),
                              item_stiffness.bytes(),
                              cell_contact_frequency2.bytes(),
                              walls.bytes(),
                              triangle_vertices.bytes(),
                              triangle_features.bytes(),
                              reactions.bytes(),
                              bond_sums.bytes(),
                              pair_sums.bytes(),
                              item_sums.bytes(),
                              cell_sums.bytes()})
            total += b;
        return total;
    }
};

// ---- Backend information -----------------------------------------------------------------

CudaBackendInfo cudaBackendInfo()
{
    CudaBackendInfo info;
    info.compiled = true;
    info.architectures = ROCKFRAC_CUDA_ARCHITECTURES;
    int count = 0;
    const cudaError_t status = cudaGetDeviceCount(&count);
    if (status != cudaSuccess) {
        info.status =
            std::string("no usable CUDA device (cudaGetDeviceCount: ") + cudaGetErrorString(status) + ")";
        cudaGetLastError();  // clear the sticky error state
        return info;
    }
    info.devices = count;
    if (count == 0) {
        info.status = "no CUDA device on this machine";
        return info;
    }
    cudaDeviceProp properties{};
    check(cudaGetDeviceProperties(&properties, 0), "cudaGetDeviceProperties");
    info.status = std::to_string(count) + " CUDA device(s), using " + properties.name + " (sm_" +
                  std::to_string(properties.major) + std::to_string(properties.minor) + ", " +
                  std::to_string(properties.totalGlobalMem >> 20) + " MiB)";
    return info;
}

std::string cudaBackendSummary()
{
    return std::string("cuda (compiled for ") + ROCKFRAC_CUDA_ARCHITECTURES + ")";
}

// ---- The model -------------------------------------------------------------------------------

CudaDemModel::CudaDemModel(DemModel& host) : host_(host)
{
    const CudaBackendInfo info = cudaBackendInfo();
    if (info.devices == 0) throw UserError("CUDA backend: " + info.status);
    if (!deviceBondLaw(*host_.parameters().bond_law)) {
        std::string known;
        for (const auto& entry : device_bond_laws)
            known += std::string(known.empty() ? "" : ", ") + entry.first;
        throw UserError(std::string("CUDA backend: the bond law '") + host_.parameters().bond_law->type() +
                        "' has no CUDA kernel (only " + known + ")");
    }
    if (std::string(host_.parameters().contact_law->type()) != contact_law_on_device)
        throw UserError(std::string("CUDA backend: the contact law '") +
                        host_.parameters().contact_law->type() + "' has no CUDA kernel (only " +
                        contact_law_on_device + ")");
    device_ = std::make_unique<Buffers>();
    device_->device_name = info.status;
    upload();
}

CudaDemModel::~CudaDemModel() = default;

std::size_t CudaDemModel::deviceBytes() const
{
    return device_->bytes();
}

namespace {

template <class T>
std::size_t arrayBytes(const std::vector<T>& v)
{
    return v.size() * sizeof(T);
}

}  // namespace

// What upload() allocates for host, from the host arrays' sizes (no device needed).
std::size_t CudaDemModel::estimateDeviceBytes(const DemModel& host)
{
    const CellArrays& c = host.cells_;
    const std::size_t n = c.position.size();
    std::size_t total =
        arrayBytes(c.position) + arrayBytes(c.velocity) + arrayBytes(c.orientation) +
        arrayBytes(c.angular_velocity) + arrayBytes(c.force) + arrayBytes(c.torque) + arrayBytes(c.mass) +
        arrayBytes(c.principal_inertia) + arrayBytes(c.dilation_radius) + arrayBytes(c.bounding_radius) +
        arrayBytes(c.core_vertex_offset) + arrayBytes(c.core_vertices) + arrayBytes(c.core_edge_offset) +
        arrayBytes(c.core_edges) + arrayBytes(c.core_plane_offset) + arrayBytes(c.core_planes);
    total += n * (sizeof(Mat3) + 2 * sizeof(Vec3));  // rotation, world angular velocity, position at build
    const InterfaceArrays& f = host.interfaces_;
    total += arrayBytes(f.cell_i) + arrayBytes(f.cell_j) + arrayBytes(f.bond_offset) +
             arrayBytes(f.intact_bonds) + arrayBytes(f.normal_i) + arrayBytes(f.normal_j) +
             arrayBytes(f.length_i) + arrayBytes(f.length_j) + arrayBytes(f.bond_area) +
             arrayBytes(f.damping_beta) + arrayBytes(f.strength_scale) + arrayBytes(f.force_on_i) +
             arrayBytes(f.torque_on_i) + arrayBytes(f.torque_on_j);
    const BondStorage& b = host.bonds_;
    total += arrayBytes(c.anchor_node_offset) + arrayBytes(c.anchor_nodes) + arrayBytes(f.softening_slot) +
             arrayBytes(b.node_i) + arrayBytes(b.node_j) + arrayBytes(b.stage) +
             b.stage.size() * sizeof(BondSoftening);
    total += arrayBytes(host.cell_interface_offset_) + arrayBytes(host.cell_interfaces_);
    const ContactPairArrays& p = host.pairs_;
    total += arrayBytes(p.cell_a) + arrayBytes(p.cell_b) + arrayBytes(p.interface) +
             arrayBytes(p.tangential_spring) + arrayBytes(p.last_normal) + arrayBytes(p.separation_margin) +
             arrayBytes(p.seat) + arrayBytes(p.force_on_b) + arrayBytes(p.point_or_torque) +
             arrayBytes(p.status) + arrayBytes(p.stiffness) + arrayBytes(host.cell_pair_offset_) +
             arrayBytes(host.cell_pairs_);
    const WallContactArrays& w = host.wall_items_;
    total += arrayBytes(w.cell) + arrayBytes(w.wall) + arrayBytes(w.triangle_offset) +
             arrayBytes(w.triangles) + arrayBytes(w.tangential_spring) + arrayBytes(w.last_normal) +
             arrayBytes(w.force_on_cell) + arrayBytes(w.torque_on_cell) + arrayBytes(w.elastic_energy) +
             arrayBytes(w.damping_power) + arrayBytes(w.friction_dissipation) + arrayBytes(w.wall_power) +
             arrayBytes(w.status) + arrayBytes(w.stiffness) + n * sizeof(float) +
             arrayBytes(host.cell_wall_item_offset_) + arrayBytes(host.triangle_vertices_) +
             arrayBytes(host.triangle_features_);
    total +=
        (f.cell_i.size() / threads_per_block + 1) * sizeof(BondSums) +
        (p.cell_a.size() / threads_per_block + w.cell.size() / threads_per_block + 2) * sizeof(ContactSums) +
        (n / threads_per_block + 1) * sizeof(CellSums);
    return total;
}

std::string CudaDemModel::deviceName() const
{
    return device_->device_name;
}

void CudaDemModel::upload()
{
    Buffers& d = *device_;
    const CellArrays& c = host_.cells_;
    d.position.upload(c.position);
    d.velocity.upload(c.velocity);
    d.orientation.upload(c.orientation);
    d.angular_velocity.upload(c.angular_velocity);
    d.force.upload(c.force);
    d.torque.upload(c.torque);
    d.mass.upload(c.mass);
    d.principal_inertia.upload(c.principal_inertia);
    d.dilation_radius.upload(c.dilation_radius);
    d.bounding_radius.upload(c.bounding_radius);
    d.core_vertex_offset.upload(c.core_vertex_offset);
    d.core_vertices.upload(c.core_vertices);
    d.core_edge_offset.upload(c.core_edge_offset);
    d.core_edges.upload(c.core_edges);
    d.core_plane_offset.upload(c.core_plane_offset);
    d.core_planes.upload(c.core_planes);
    d.rotation.upload(host_.rotation_);
    d.angular_velocity_world.upload(host_.angular_velocity_world_);
    const InterfaceArrays& f = host_.interfaces_;
    d.cell_i.upload(f.cell_i);
    d.cell_j.upload(f.cell_j);
    d.bond_offset.upload(f.bond_offset);
    d.intact_bonds.upload(f.intact_bonds);
    d.normal_i.upload(f.normal_i);
    d.normal_j.upload(f.normal_j);
    d.length_i.upload(f.length_i);
    d.length_j.upload(f.length_j);
    d.bond_area.upload(f.bond_area);
    d.damping_beta.upload(f.damping_beta);
    d.strength_scale.upload(f.strength_scale);
    d.force_on_i.upload(f.force_on_i);
    d.torque_on_i.upload(f.torque_on_i);
    d.torque_on_j.upload(f.torque_on_j);
    const BondStorage& b = host_.bonds_;
    d.anchor_node_offset.upload(c.anchor_node_offset);
    d.anchor_nodes.upload(c.anchor_nodes);
    d.node_i.upload(b.node_i);
    d.node_j.upload(b.node_j);
    d.stage.upload(b.stage);
    d.softening.upload(host_.softeningPerBond());
    d.softening_slot.upload(std::vector<int>(f.bond_offset.begin(), f.bond_offset.end() - 1));
    d.cell_interface_offset.upload(host_.cell_interface_offset_);
    d.cell_interfaces.upload(host_.cell_interfaces_);
    d.triangle_vertices.upload(host_.triangle_vertices_);
    d.triangle_features.upload(host_.triangle_features_);
    uploadLists();
    if (host_.lists_valid_) d.position_at_build.upload(host_.position_at_build_);
    d.bond_sums.resize(blocksFor(f.size()));
    d.cell_sums.resize(blocksFor(c.size()));
}

// The neighbour lists and contact items the host DemModel holds now.
void CudaDemModel::uploadLists()
{
    Buffers& d = *device_;
    const ContactPairArrays& p = host_.pairs_;
    d.pair_a.upload(p.cell_a);
    d.pair_b.upload(p.cell_b);
    d.pair_interface.upload(p.interface);
    d.pair_spring.upload(p.tangential_spring);
    d.pair_last_normal.upload(p.last_normal);
    d.pair_margin.upload(p.separation_margin);
    d.pair_seat.upload(p.seat);
    d.pair_force_on_b.upload(p.force_on_b);
    d.pair_point_or_torque.upload(p.point_or_torque);
    d.pair_status.upload(p.status);
    d.pair_stiffness.upload(p.stiffness);
    d.cell_pair_offset.upload(host_.cell_pair_offset_);
    d.cell_pairs.upload(host_.cell_pairs_);
    const WallContactArrays& w = host_.wall_items_;
    d.item_cell.upload(w.cell);
    d.item_wall.upload(w.wall);
    d.item_triangle_offset.upload(w.triangle_offset);
    d.item_triangles.upload(w.triangles);
    d.item_spring.upload(w.tangential_spring);
    d.item_last_normal.upload(w.last_normal);
    d.item_force.upload(w.force_on_cell);
    d.item_torque.upload(w.torque_on_cell);
    d.item_elastic.upload(w.elastic_energy);
    d.item_damping.upload(w.damping_power);
    d.item_friction.upload(w.friction_dissipation);
    d.item_power.upload(w.wall_power);
    d.item_status.upload(w.status);
    d.item_stiffness.upload(w.stiffness);
    d.cell_wall_item_offset.upload(host_.cell_wall_item_offset_);
    d.pair_sums.resize(blocksFor(p.size()));
    d.item_sums.resize(blocksFor(w.size()));
    d.reactions.resize(host_.walls_.size());
}

// Lists on the host: positions, intact-bond counts and contact histories down, the
// DemModel's own rebuild (carrying histories by key), the new lists up.
void CudaDemModel::rebuildListsOnHost()
{
    Buffers& d = *device_;
    d.position.download(host_.cells_.position);
    d.intact_bonds.download(host_.interfaces_.intact_bonds);
    d.pair_spring.download(host_.pairs_.tangential_spring);
    d.pair_last_normal.download(host_.pairs_.last_normal);
    d.item_spring.download(host_.wall_items_.tangential_spring);
    d.item_last_normal.download(host_.wall_items_.last_normal);
    host_.rebuildNeighbourLists();
    uploadLists();
    d.position_at_build.copyFrom(d.position);
}

void CudaDemModel::downloadState()
{
    Buffers& d = *device_;
    CellArrays& c = host_.cells_;
    d.position.download(c.position);
    d.velocity.download(c.velocity);
    d.orientation.download(c.orientation);
    d.angular_velocity.download(c.angular_velocity);
    d.force.download(c.force);
    d.torque.download(c.torque);
    d.rotation.download(host_.rotation_);
    d.angular_velocity_world.download(host_.angular_velocity_world_);
    InterfaceArrays& f = host_.interfaces_;
    d.intact_bonds.download(f.intact_bonds);
    d.force_on_i.download(f.force_on_i);
    d.torque_on_i.download(f.torque_on_i);
    d.torque_on_j.download(f.torque_on_j);
    d.stage.download(host_.bonds_.stage);
    std::vector<BondSoftening> per_bond;
    d.softening.download(per_bond);
    host_.setSofteningPerBond(per_bond);
    ContactPairArrays& p = host_.pairs_;
    d.pair_spring.download(p.tangential_spring);
    d.pair_last_normal.download(p.last_normal);
    d.pair_margin.download(p.separation_margin);
    d.pair_seat.download(p.seat);
    d.pair_force_on_b.download(p.force_on_b);
    d.pair_point_or_torque.download(p.point_or_torque);
    d.pair_status.download(p.status);
    WallContactArrays& w = host_.wall_items_;
    d.item_spring.download(w.tangential_spring);
    d.item_last_normal.download(w.last_normal);
    d.item_force.download(w.force_on_cell);
    d.item_torque.download(w.torque_on_cell);
    d.item_elastic.download(w.elastic_energy);
    d.item_damping.download(w.damping_power);
    d.item_friction.download(w.friction_dissipation);
    d.item_power.download(w.wall_power);
    d.item_status.download(w.status);
}

// DemModel::computeForces, stage by stage on the device.
void CudaDemModel::computeForces(double dt)
{
    Buffers& d = *device_;
    DemModel& h = host_;
    const int n_cells = h.cells_.size();
    if (n_cells > 0)
        refreshKernel<<<blocksFor(n_cells), threads_per_block>>>(n_cells, d.orientation.data(),
                                                                 d.angular_velocity.data(), d.rotation.data(),
                                                                 d.angular_velocity_world.data());
    check(cudaGetLastError(), "kinematics kernel");
    h.wall_poses_.clear();
    for (const WallState& w : h.walls_) h.wall_poses_.push_back(h.wallPose(w));
    d.walls.upload(h.wall_poses_);

    // Bonds.
    BondKernelArgs ba;
    ba.n_interfaces = h.interfaces_.size();
    ba.position = d.position.data();
    ba.velocity = d.velocity.data();
    ba.angular_velocity_world = d.angular_velocity_world.data();
    ba.rotation = d.rotation.data();
    ba.cell_i = d.cell_i.data();
    ba.cell_j = d.cell_j.data();
    ba.bond_offset = d.bond_offset.data();
    ba.normal_i_body = d.normal_i.data();
    ba.normal_j_body = d.normal_j.data();
    ba.length_i = d.length_i.data();
    ba.length_j = d.length_j.data();
    ba.bond_area = d.bond_area.data();
    ba.damping_beta = d.damping_beta.data();
    ba.strength_scale = d.strength_scale.size() > 0 ? d.strength_scale.data() : nullptr;
    ba.softening_slot = d.softening_slot.data();
    ba.intact_bonds = d.intact_bonds.data();
    ba.force_on_i = d.force_on_i.data();
    ba.torque_on_i = d.torque_on_i.data();
    ba.torque_on_j = d.torque_on_j.data();
    ba.anchor_node_offset = d.anchor_node_offset.data();
    ba.anchor_nodes = d.anchor_nodes.data();
    ba.node_i = d.node_i.data();
    ba.node_j = d.node_j.data();
    ba.stage = d.stage.data();
    ba.softening = d.softening.data();
    const int bond_blocks = blocksFor(ba.n_interfaces);
    if (bond_blocks > 0)
        deviceBondLaw (*h.parameters().bond_law)(*h.parameters().bond_law, ba, bond_blocks,
                                                 d.bond_sums.data());
    check(cudaGetLastError(), "bond kernel");
    double strain = 0.0;
    int broken = 0, open = 0, cracked = 0;
    h.force_rates_.bond_damping = 0.0;
    for (const BondSums& s : downloadPartials(d.bond_sums, bond_blocks)) {
        strain += s.strain_energy;
        h.force_rates_.bond_damping += s.damping_power;
        h.energies_.fracture += s.fracture_dissipation;
        broken += s.bonds_broken;
        open += s.interfaces_open;
        cracked += s.interfaces_cracked;
    }
    h.energies_.bond_damping += h.force_rates_.bond_damping * 0.5 * dt;  // second half kick (DemModel::step)
    h.energies_.bond_strain = strain;
    h.counters_.bonds_broken = broken;
    h.counters_.interfaces_open = open;
    h.counters_.interfaces_cracked = cracked;

    // Neighbour lists: stale after half a skin of motion or a face's first bond breaking.
    bool stale = !h.lists_valid_ || d.position_at_build.size() != static_cast<std::size_t>(n_cells);
    if (!stale && n_cells > 0) {
        const int blocks = blocksFor(n_cells);
        moveSinceBuildKernel<<<blocks, threads_per_block>>>(n_cells, d.position.data(),
                                                            d.position_at_build.data(), d.cell_sums.data());
        check(cudaGetLastError(), "displacement kernel");
        double move2 = 0.0;
        for (const CellSums& s : downloadPartials(d.cell_sums, blocks)) move2 = std::max(move2, s.max_move2);
        stale = h.neighbourListsStale(std::sqrt(move2));
    }
    if (stale || h.counters_.interfaces_cracked != h.interfaces_cracked_at_build_) rebuildListsOnHost();

    // Contacts.
    CellContactView cells;
    cells.position = d.position.data();
    cells.velocity = d.velocity.data();
    cells.angular_velocity_world = d.angular_velocity_world.data();
    cells.rotation = d.rotation.data();
    cells.mass = d.mass.data();
    cells.dilation_radius = d.dilation_radius.data();
    cells.bounding_radius = d.bounding_radius.data();
    cells.core_vertex_offset = d.core_vertex_offset.data();
    cells.core_vertices = d.core_vertices.data();
    cells.core_edge_offset = d.core_edge_offset.data();
    cells.core_edges = d.core_edges.data();
    cells.core_plane_offset = d.core_plane_offset.data();
    cells.core_planes = d.core_planes.data();

    PairKernelArgs pa;
    pa.constants = h.rock_rock_;
    pa.dt = dt;
    pa.n_pairs = h.pairs_.size();
    pa.cells = cells;
    pa.intact_bonds = d.intact_bonds.data();
    pa.bond_offset = d.bond_offset.data();
    pa.cell_a = d.pair_a.data();
    pa.cell_b = d.pair_b.data();
    pa.interface = d.pair_interface.data();
    pa.separation_margin = d.pair_margin.data();
    pa.seat = d.pair_seat.data();
    pa.items = {d.pair_spring.data(),   d.pair_last_normal.data(), nullptr, nullptr, nullptr,
                d.pair_status.data(),  // energies: summed per thread, not stored
                d.pair_stiffness.data()};
    pa.force_on_b = d.pair_force_on_b.data();
    pa.point_or_torque = d.pair_point_or_torque.data();
    pa.patch = host_.parameters_.cell_contact_patch;
    const int pair_blocks = blocksFor(pa.n_pairs);
    if (pair_blocks > 0)
        pairKernelCuda<ContactLawOnDevice><<<pair_blocks, threads_per_block>>>(pa, d.pair_sums.data());
    check(cudaGetLastError(), "contact pair kernel");

    WallKernelArgs wa;
    wa.constants = h.rock_steel_;
    wa.dt = dt;
    wa.n_items = h.wall_items_.size();
    wa.cells = cells;
    wa.walls = d.walls.data();
    wa.triangle_vertices = d.triangle_vertices.data();
    wa.triangle_features = d.triangle_features.data();
    wa.item_cell = d.item_cell.data();
    wa.item_wall = d.item_wall.data();
    wa.item_triangle_offset = d.item_triangle_offset.data();
    wa.item_triangles = d.item_triangles.data();
    wa.items = {d.item_spring.data(),   d.item_last_normal.data(), d.item_elastic.data(),
                d.item_damping.data(),  d.item_friction.data(),    d.item_status.data(),
                d.item_stiffness.data()};
    wa.force_on_cell = d.item_force.data();
    wa.torque_on_cell = d.item_torque.data();
    wa.wall_power = d.item_power.data();
    const int item_blocks = blocksFor(wa.n_items);
    if (item_blocks > 0)
        wallKernelCuda<ContactLawOnDevice><<<item_blocks, threads_per_block>>>(wa, d.item_sums.data());
    check(cudaGetLastError(), "wall contact kernel");

    h.energies_.contact_elastic = 0.0;
    h.counters_.core_intersections = 0;
    h.force_rates_.contact_damping = 0.0;
    for (auto* counter : {&h.counters_.contacts_active, &h.counters_.wall_contacts_active}) {
        const bool pairs = counter == &h.counters_.contacts_active;
        int active = 0;
        for (const ContactSums& s :
             downloadPartials(pairs ? d.pair_sums : d.item_sums, pairs ? pair_blocks : item_blocks)) {
            active += s.active;
            h.counters_.core_intersections += s.cores_intersect;
            h.energies_.contact_elastic += s.elastic_energy;
            h.force_rates_.contact_damping += s.damping_power;
            h.energies_.friction += s.friction_dissipation;
        }
        *counter = active;
        if (pairs) h.counters_.pair_core_intersections = h.counters_.core_intersections;
    }
    h.energies_.contact_damping += h.force_rates_.contact_damping * 0.5 * dt;

    // Wall reactions.
    const int n_walls = h.nWalls();
    if (n_walls > 0) {
        wallReactionKernel<<<blocksFor(n_walls), threads_per_block>>>(
            n_walls, wa.n_items, d.walls.data(), d.item_wall.data(), d.item_cell.data(), d.item_force.data(),
            d.item_torque.data(), d.item_power.data(), d.position.data(), d.reactions.data());
        check(cudaGetLastError(), "wall reaction kernel");
        std::vector<WallReaction> reactions;
        d.reactions.download(reactions);
        for (int w = 0; w < n_walls; ++w) {
            WallState& wall = h.walls_[w];
            wall.reaction = reactions[w].reaction;
            wall.reaction_torque = reactions[w].reaction_torque;
            wall.power = reactions[w].power;
            wall.work += reactions[w].power * 0.5 * dt;
            h.energies_.wall_work += reactions[w].power * 0.5 * dt;
        }
    }

    // Gather.
    GatherArgs ga;
    ga.gravity = h.parameters_.gravity;
    ga.mass = d.mass.data();
    ga.interface_offset = d.cell_interface_offset.data();
    ga.interface_entries = d.cell_interfaces.data();
    ga.interface_force_on_i = d.force_on_i.data();
    ga.interface_torque_on_i = d.torque_on_i.data();
    ga.interface_torque_on_j = d.torque_on_j.data();
    ga.pair_offset = d.cell_pair_offset.data();
    ga.pair_entries = d.cell_pairs.data();
    ga.pair_force_on_b = d.pair_force_on_b.data();
    ga.pair_point_or_torque = d.pair_point_or_torque.data();
    ga.pair_torques = host_.parameters_.cell_contact_patch;
    ga.pair_cell_b = d.pair_b.data();
    ga.position = d.position.data();
    ga.wall_item_offset = d.cell_wall_item_offset.data();
    ga.wall_force_on_cell = d.item_force.data();
    ga.wall_torque_on_cell = d.item_torque.data();
    ga.force = d.force.data();
    ga.torque = d.torque.data();
    ga.pair_stiffness = d.pair_stiffness.data();
    ga.wall_stiffness = d.item_stiffness.data();
    ga.principal_inertia = d.principal_inertia.data();
    ga.bounding_radius = d.bounding_radius.data();
    if (d.cell_contact_frequency2.size() != static_cast<std::size_t>(n_cells))
        d.cell_contact_frequency2.resize(n_cells);
    ga.contact_frequency2 = d.cell_contact_frequency2.data();
    if (n_cells > 0) gatherKernel<<<blocksFor(n_cells), threads_per_block>>>(n_cells, ga);
    check(cudaGetLastError(), "gather kernel");
    // The stiffest cell for the step check (DemModel::gatherForces).
    h.max_contact_frequency2_ = 0.0;
    if (n_cells > 0) {
        const int blocks = blocksFor(n_cells);
        stiffestCellKernel<<<blocks, threads_per_block>>>(n_cells, d.cell_contact_frequency2.data(),
                                                          d.cell_sums.data());
        check(cudaGetLastError(), "stiffest cell kernel");
        for (const CellSums& s : downloadPartials(d.cell_sums, blocks))
            h.max_contact_frequency2_ = std::max(h.max_contact_frequency2_, s.max_contact_frequency2);
    }
    h.forces_valid_ = true;
}

namespace {

IntegrationArgs integrationArgs(const DemParameters& parameters, DeviceArray<double>& mass,
                                DeviceArray<Vec3>& inertia, DeviceArray<Vec3>& force,
                                DeviceArray<Vec3>& torque, DeviceArray<Mat3>& rotation,
                                DeviceArray<Vec3>& position, DeviceArray<Vec3>& velocity,
                                DeviceArray<Quat>& orientation, DeviceArray<Vec3>& angular_velocity)
{
    IntegrationArgs a;
    a.gravity = parameters.gravity;
    a.mass = mass.data();
    a.principal_inertia = inertia.data();
    a.force = force.data();
    a.torque = torque.data();
    a.rotation = rotation.data();
    a.position = position.data();
    a.velocity = velocity.data();
    a.orientation = orientation.data();
    a.angular_velocity = angular_velocity.data();
    return a;
}

}  // namespace

void CudaDemModel::measure(double sync_dt)
{
    Buffers& d = *device_;
    const int n = host_.cells_.size();
    const IntegrationArgs a =
        integrationArgs(host_.parameters_, d.mass, d.principal_inertia, d.force, d.torque, d.rotation,
                        d.position, d.velocity, d.orientation, d.angular_velocity);
    const int blocks = blocksFor(n);
    if (blocks > 0) measureKernel<<<blocks, threads_per_block>>>(n, a, sync_dt, d.cell_sums.data());
    check(cudaGetLastError(), "energy kernel");
    double translation = 0.0, rotation = 0.0;
    int non_finite = -1;
    for (const CellSums& s : downloadPartials(d.cell_sums, blocks)) {
        translation += s.kinetic_translation;
        rotation += s.kinetic_rotation;
        if (non_finite < 0) non_finite = s.non_finite_cell;
    }
    host_.finishMeasurement(translation, rotation, non_finite);
}

void CudaDemModel::evaluateForces(double dt)
{
    computeForces(dt);
    measure(0.0);
}

// DemModel::step on the device, with the same split into substeps.
double CudaDemModel::step(double dt)
{
    if (!host_.forces_valid_) computeForces(0.0);
    return host_.stepInParts(dt, [this](double part) { singleStep(part); });
}

void CudaDemModel::singleStep(double dt)
{
    Buffers& d = *device_;
    DemModel& h = host_;
    h.last_dt_ = dt;
    h.bookFirstHalfKick(dt);
    const int n = h.cells_.size();
    const IntegrationArgs a =
        integrationArgs(h.parameters_, d.mass, d.principal_inertia, d.force, d.torque, d.rotation, d.position,
                        d.velocity, d.orientation, d.angular_velocity);
    const int blocks = blocksFor(n);
    if (blocks > 0) kickDriftKernel<<<blocks, threads_per_block>>>(n, a, dt, d.cell_sums.data());
    check(cudaGetLastError(), "drift kernel");
    for (const CellSums& s : downloadPartials(d.cell_sums, blocks))
        h.energies_.gravity_work += s.gravity_work;
    h.moveWalls(dt);
    computeForces(dt);
    if (blocks > 0) kickKernel<<<blocks, threads_per_block>>>(n, a, dt);
    check(cudaGetLastError(), "kick kernel");
    h.time_ += dt;
    ++h.counters_.steps;
    measure(dt);
}

}  // namespace rockfrac
