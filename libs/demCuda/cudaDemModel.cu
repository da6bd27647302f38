// The CUDA backend of the bonded DEM: the device mirror of the model's array groups
// (deviceArrays.cuh), and a step as one kernel per stage (cudaDemKernels.cuh), each a thin
// loop-replacement over the RF_HD functions the OpenMP path runs (cudaDemModel.hpp says
// what runs where).
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
#include "dem/hertzMindlinContact.hpp"
#include "dem/kernelViews.hpp"
#include "dem/voronoiQnscBond.hpp"
#include "demCuda/cudaDemKernels.cuh"
#include "demCuda/cudaDemModel.hpp"

#ifndef ROCKFRAC_CUDA_ARCHITECTURES
#define ROCKFRAC_CUDA_ARCHITECTURES "unknown"
#endif

namespace rockfrac {

namespace {

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
    // The array groups (demState.hpp) on the device. Bonds: the softening history with one
    // entry per bond, each interface's slot at its first bond, so the device never claims one.
    CellArraysOf<DeviceArray> cells;
    InterfaceArraysOf<DeviceArray> interfaces;
    BondStorageOf<DeviceArray> bonds;
    ContactPairArraysOf<DeviceArray> pairs;
    WallContactArraysOf<DeviceArray> wall_items;
    // Per-cell caches, and the gather lists (DemModel::GatherLists).
    DeviceArray<Mat3> rotation;
    DeviceArray<Vec3> angular_velocity_world, position_at_build;
    DeviceArray<float> contact_frequency2;
    struct {
        DeviceArray<int> interface_offset, interfaces, pair_offset, pairs, wall_item_offset;
    } lists;
    // Walls.
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
        std::size_t total = mirrorBytes(cells) + mirrorBytes(interfaces) + mirrorBytes(bonds) +
                            mirrorBytes(pairs) + mirrorBytes(wall_items);
        for (std::size_t b :
             {rotation.bytes(), angular_velocity_world.bytes(), position_at_build.bytes(),
              contact_frequency2.bytes(), lists.interface_offset.bytes(), lists.interfaces.bytes(),
              lists.pair_offset.bytes(), lists.pairs.bytes(), lists.wall_item_offset.bytes(), walls.bytes(),
              triangle_vertices.bytes(), triangle_features.bytes(), reactions.bytes(), bond_sums.bytes(),
              pair_sums.bytes(), item_sums.bytes(), cell_sums.bytes()})
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

DemModel::DeviceSide CudaDemModel::side()
{
    return host_.deviceSide({});
}

std::size_t CudaDemModel::deviceBytes() const
{
    return device_->bytes();
}

// What upload() allocates for host, from the host arrays' sizes (no device needed).
std::size_t CudaDemModel::estimateDeviceBytes(const DemModel& host)
{
    const std::size_t n = host.cells().size();
    const InterfaceArrays& f = host.interfaces();
    const ContactPairArrays& p = host.contactPairs();
    const WallContactArrays& w = host.wallContacts();
    std::size_t total = mirrorBytesFor(host.cells()) + mirrorBytesFor<poolField>(f) +
                        mirrorBytesFor<poolField>(host.bondStorage()) + mirrorBytesFor(p) + mirrorBytesFor(w);
    // The softening pool as the device keeps it: a slot per interface, an entry per bond.
    total += f.size() * sizeof(int) + host.nBonds() * sizeof(BondSoftening);
    // Rotation, world angular velocity, position at the list build, contact frequency.
    total += n * (sizeof(Mat3) + 2 * sizeof(Vec3) + sizeof(float));
    const DemModel::GatherLists lists = host.gatherLists();
    total += sizeBytes(lists.interface_offset) + sizeBytes(lists.interfaces) + sizeBytes(lists.pair_offset) +
             sizeBytes(lists.pairs) + sizeBytes(lists.wall_item_offset) + sizeBytes(host.triangleVertices()) +
             sizeBytes(host.triangleFeatures());
    total += (f.size() / threads_per_block + 1) * sizeof(BondSums) +
             (p.size() / threads_per_block + w.size() / threads_per_block + 2) * sizeof(ContactSums) +
             (n / threads_per_block + 1) * sizeof(CellSums);
    return total;
}

std::string CudaDemModel::deviceName() const
{
    return device_->device_name;
}

// ---- Mirror ----------------------------------------------------------------------------

void CudaDemModel::upload()
{
    Buffers& d = *device_;
    DemModel::DeviceSide h = side();
    uploadFields(h.cells(), d.cells);
    uploadFields<poolField>(h.interfaces(), d.interfaces);
    uploadFields<poolField>(h.bonds(), d.bonds);
    // The pool as one entry per bond, each interface's slot at its first bond.
    const std::vector<int>& bond_offset = h.interfaces().bond_offset;
    d.interfaces.softening_slot.upload(std::vector<int>(bond_offset.begin(), bond_offset.end() - 1));
    d.bonds.softening.upload(host_.softeningPerBond());
    d.rotation.upload(h.rotation());
    d.angular_velocity_world.upload(h.angularVelocityWorld());
    const DemModel::GatherLists lists = host_.gatherLists();
    d.lists.interface_offset.upload(lists.interface_offset);
    d.lists.interfaces.upload(lists.interfaces);
    d.triangle_vertices.upload(host_.triangleVertices());
    d.triangle_features.upload(host_.triangleFeatures());
    uploadLists();
    if (host_.listsValid()) d.position_at_build.upload(h.positionAtBuild());
    d.bond_sums.resize(blocksFor(d.interfaces.size()));
    d.cell_sums.resize(blocksFor(d.cells.size()));
}

// The neighbour lists and contact items the host DemModel holds now.
void CudaDemModel::uploadLists()
{
    Buffers& d = *device_;
    DemModel::DeviceSide h = side();
    uploadFields(h.pairs(), d.pairs);
    uploadFields(h.wallItems(), d.wall_items);
    const DemModel::GatherLists lists = host_.gatherLists();
    d.lists.pair_offset.upload(lists.pair_offset);
    d.lists.pairs.upload(lists.pairs);
    d.lists.wall_item_offset.upload(lists.wall_item_offset);
    d.pair_sums.resize(blocksFor(d.pairs.size()));
    d.item_sums.resize(blocksFor(d.wall_items.size()));
    d.reactions.resize(host_.nWalls());
}

// Lists on the host: what the rebuild reads (positions, intact-bond counts, the histories
// it carries by key) down, the DemModel's own rebuild, the new lists up.
void CudaDemModel::rebuildListsOnHost()
{
    Buffers& d = *device_;
    DemModel::DeviceSide h = side();
    d.cells.position.download(h.cells().position);
    d.interfaces.intact_bonds.download(h.interfaces().intact_bonds);
    downloadFields<carriedField>(d.pairs, h.pairs());
    downloadFields<carriedField>(d.wall_items, h.wallItems());
    h.rebuildLists();
    uploadLists();
    d.position_at_build.copyFrom(d.cells.position);
}

void CudaDemModel::downloadState()
{
    Buffers& d = *device_;
    DemModel::DeviceSide h = side();
    downloadFields(d.cells, h.cells());
    d.rotation.download(h.rotation());
    d.angular_velocity_world.download(h.angularVelocityWorld());
    downloadFields<0u, poolField>(d.interfaces, h.interfaces());
    downloadFields<0u, poolField>(d.bonds, h.bonds());
    std::vector<BondSoftening> per_bond;
    d.bonds.softening.download(per_bond);
    h.setSofteningPerBond(per_bond);
    downloadFields(d.pairs, h.pairs());
    downloadFields(d.wall_items, h.wallItems());
}

// ---- A force evaluation and a step ----------------------------------------------------

// DemModel::computeForces, stage by stage on the device.
void CudaDemModel::computeForces(double dt)
{
    Buffers& d = *device_;
    DemModel::DeviceSide h = side();
    const int n_cells = host_.cells().size();
    if (n_cells > 0)
        refreshKernel<<<blocksFor(n_cells), threads_per_block>>>(
            n_cells, d.cells.orientation.data(), d.cells.angular_velocity.data(), d.rotation.data(),
            d.angular_velocity_world.data());
    check(cudaGetLastError(), "kinematics kernel");
    d.walls.upload(h.refreshWallPoses());
    bondForces(dt);

    // Neighbour lists: stale after half a skin of motion or a face's first bond breaking.
    bool stale = !host_.listsValid() || d.position_at_build.size() != static_cast<std::size_t>(n_cells);
    if (!stale && n_cells > 0) {
        const int blocks = blocksFor(n_cells);
        moveSinceBuildKernel<<<blocks, threads_per_block>>>(n_cells, d.cells.position.data(),
                                                            d.position_at_build.data(), d.cell_sums.data());
        check(cudaGetLastError(), "displacement kernel");
        double move2 = 0.0;
        for (const CellSums& s : downloadPartials(d.cell_sums, blocks)) move2 = std::max(move2, s.max_move2);
        stale = h.listsStale(std::sqrt(move2));
    }
    if (stale || h.crackedSinceListBuild()) rebuildListsOnHost();

    contactForces(dt);
    wallReactions(dt);
    gather();
    h.forcesComputed();
}

void CudaDemModel::bondForces(double dt)
{
    Buffers& d = *device_;
    DemModel::DeviceSide h = side();
    BondKernelArgs ba;
    viewBondArrays(ba, d.cells, d.interfaces, d.bonds, d.rotation, d.angular_velocity_world);
    const int bond_blocks = blocksFor(ba.n_interfaces);
    if (bond_blocks > 0)
        deviceBondLaw (*host_.parameters().bond_law)(*host_.parameters().bond_law, ba, bond_blocks,
                                                     d.bond_sums.data());
    check(cudaGetLastError(), "bond kernel");
    DemEnergies& energies = h.energies();
    DemForceRates& rates = h.forceRates();
    DemCounters& counters = h.counters();
    double strain = 0.0;
    int broken = 0, open = 0, cracked = 0;
    rates.bond_damping = 0.0;
    for (const BondSums& s : downloadPartials(d.bond_sums, bond_blocks)) {
        strain += s.strain_energy;
        rates.bond_damping += s.damping_power;
        energies.fracture += s.fracture_dissipation;
        broken += s.bonds_broken;
        open += s.interfaces_open;
        cracked += s.interfaces_cracked;
    }
    energies.bond_damping += rates.bond_damping * 0.5 * dt;  // second half kick (DemModel::step)
    energies.bond_strain = strain;
    counters.bonds_broken = broken;
    counters.interfaces_open = open;
    counters.interfaces_cracked = cracked;
}

void CudaDemModel::contactForces(double dt)
{
    Buffers& d = *device_;
    DemModel::DeviceSide h = side();
    const CellContactView cells = cellContactView(d.cells, d.rotation, d.angular_velocity_world);
    PairKernelArgs pa;
    pa.constants = h.rockRock();
    pa.dt = dt;
    pa.cells = cells;
    viewPairArrays(pa, d.interfaces, d.pairs);
    pa.patch = host_.parameters().cell_contact_patch;
    const int pair_blocks = blocksFor(pa.n_pairs);
    if (pair_blocks > 0)
        pairKernelCuda<ContactLawOnDevice><<<pair_blocks, threads_per_block>>>(pa, d.pair_sums.data());
    check(cudaGetLastError(), "contact pair kernel");

    WallKernelArgs wa;
    wa.constants = h.rockSteel();
    wa.dt = dt;
    wa.cells = cells;
    wa.walls = d.walls.data();
    wa.triangle_vertices = d.triangle_vertices.data();
    wa.triangle_features = d.triangle_features.data();
    viewWallItemArrays(wa, d.wall_items);
    const int item_blocks = blocksFor(wa.n_items);
    if (item_blocks > 0)
        wallKernelCuda<ContactLawOnDevice><<<item_blocks, threads_per_block>>>(wa, d.item_sums.data());
    check(cudaGetLastError(), "wall contact kernel");

    DemEnergies& energies = h.energies();
    DemForceRates& rates = h.forceRates();
    DemCounters& counters = h.counters();
    energies.contact_elastic = 0.0;
    counters.core_intersections = 0;
    rates.contact_damping = 0.0;
    for (auto* counter : {&counters.contacts_active, &counters.wall_contacts_active}) {
        const bool pairs = counter == &counters.contacts_active;
        int active = 0;
        for (const ContactSums& s :
             downloadPartials(pairs ? d.pair_sums : d.item_sums, pairs ? pair_blocks : item_blocks)) {
            active += s.active;
            counters.core_intersections += s.cores_intersect;
            energies.contact_elastic += s.elastic_energy;
            rates.contact_damping += s.damping_power;
            energies.friction += s.friction_dissipation;
        }
        *counter = active;
        if (pairs) counters.pair_core_intersections = counters.core_intersections;
    }
    energies.contact_damping += rates.contact_damping * 0.5 * dt;
}

// What the cells exert on each wall, and the wall's work over the second half kick.
void CudaDemModel::wallReactions(double dt)
{
    Buffers& d = *device_;
    DemModel::DeviceSide h = side();
    const int n_walls = host_.nWalls();
    if (n_walls == 0) return;
    const WallContactArraysOf<DeviceArray>& w = d.wall_items;
    wallReactionKernel<<<blocksFor(n_walls), threads_per_block>>>(
        n_walls, w.size(), d.walls.data(), w.wall.data(), w.cell.data(), w.force_on_cell.data(),
        w.torque_on_cell.data(), w.wall_power.data(), d.cells.position.data(), d.reactions.data());
    check(cudaGetLastError(), "wall reaction kernel");
    std::vector<WallReaction> reactions;
    d.reactions.download(reactions);
    for (int k = 0; k < n_walls; ++k) {
        WallState& wall = h.wall(k);
        wall.reaction = reactions[k].reaction;
        wall.reaction_torque = reactions[k].reaction_torque;
        wall.power = reactions[k].power;
        wall.work += reactions[k].power * 0.5 * dt;
        h.energies().wall_work += reactions[k].power * 0.5 * dt;
    }
}

// Each cell's forces (DemModel::gatherForces), and the stiffest cell for the step check.
void CudaDemModel::gather()
{
    Buffers& d = *device_;
    const int n_cells = host_.cells().size();
    GatherArgs ga;
    ga.gravity = host_.parameters().gravity;
    ga.pair_torques = host_.parameters().cell_contact_patch;
    if (d.contact_frequency2.size() != static_cast<std::size_t>(n_cells))
        d.contact_frequency2.resize(n_cells);
    viewGatherArrays(ga, d.cells, d.interfaces, d.pairs, d.wall_items, d.lists, d.contact_frequency2);
    if (n_cells > 0) gatherKernel<<<blocksFor(n_cells), threads_per_block>>>(n_cells, ga);
    check(cudaGetLastError(), "gather kernel");
    double stiffest = 0.0;
    if (n_cells > 0) {
        const int blocks = blocksFor(n_cells);
        stiffestCellKernel<<<blocks, threads_per_block>>>(n_cells, d.contact_frequency2.data(),
                                                          d.cell_sums.data());
        check(cudaGetLastError(), "stiffest cell kernel");
        for (const CellSums& s : downloadPartials(d.cell_sums, blocks))
            stiffest = std::max(stiffest, s.max_contact_frequency2);
    }
    host_.setContactFrequencyBound(stiffest);
}

void CudaDemModel::measure(double sync_dt)
{
    Buffers& d = *device_;
    const int n = host_.cells().size();
    const IntegrationArgs a = integrationView(d.cells, d.rotation, host_.parameters().gravity);
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
    side().finishMeasurement(translation, rotation, non_finite);
}

void CudaDemModel::evaluateForces(double dt)
{
    computeForces(dt);
    measure(0.0);
}

// DemModel::step on the device, with the same split into substeps.
double CudaDemModel::step(double dt)
{
    if (!host_.forcesValid()) computeForces(0.0);
    return side().stepInParts(dt, [this](double part) { singleStep(part); });
}

void CudaDemModel::singleStep(double dt)
{
    Buffers& d = *device_;
    DemModel::DeviceSide h = side();
    h.beginStep(dt);
    const int n = host_.cells().size();
    const IntegrationArgs a = integrationView(d.cells, d.rotation, host_.parameters().gravity);
    const int blocks = blocksFor(n);
    if (blocks > 0) kickDriftKernel<<<blocks, threads_per_block>>>(n, a, dt, d.cell_sums.data());
    check(cudaGetLastError(), "drift kernel");
    for (const CellSums& s : downloadPartials(d.cell_sums, blocks))
        h.energies().gravity_work += s.gravity_work;
    h.moveWalls(dt);
    computeForces(dt);
    if (blocks > 0) kickKernel<<<blocks, threads_per_block>>>(n, a, dt);
    check(cudaGetLastError(), "kick kernel");
    h.endStep(dt);
    measure(dt);
}

}  // namespace rockfrac
