#pragma once
// The CUDA backend of the bonded DEM (controlDict `backend cuda;`, docs/benchmarks.md).
//
// A CudaDemModel takes a DemModel built on the host, uploads its arrays to device
// memory (plain cudaMalloc, no managed memory) and steps them there with the same
// RF_HD kernels the OpenMP path runs (dem/bondLaw.hpp, dem/contactKernels.hpp,
// dem/cellKernels.hpp), one GPU thread per interface, contact item or cell.
//
// On the device, every step: kinematic caches, bond forces and damage, cell-cell
// contacts (GJK) and wall contacts, the gather, both halves of the integrator, the
// energy and finiteness sums, the per-wall reactions and the displacement since the
// last neighbour-list build. On the host: wall motion (a few numbers per wall,
// uploaded each step), the energy bookkeeping from per-block partial sums, and the
// neighbour-list rebuild (positions and contact histories are downloaded, the
// DemModel rebuilds its lists, and the new lists are uploaded), which happens only
// when a cell has moved half the skin distance or a face has lost its last bond.
//
// The DemModel stays the owner of the state for everything else: after step() its
// time, energies, counters, status and wall reactions are current; cell, bond and
// contact arrays are current after downloadState() (do that before output or a
// restart write). Change the cell state only through the DemModel followed by
// upload().
//
// In a build without CUDA (-DROCKFRAC_CUDA=OFF or no nvcc) the class exists and its
// constructor throws a UserError saying so (cudaBackendStub.cpp).
#include <cstddef>
#include <memory>
#include <string>

#include "dem/demModel.hpp"

namespace rockfrac {

// What this build and this machine offer for `backend cuda;`.
struct CudaBackendInfo {
    bool compiled = false;      // built with ROCKFRAC_CUDA (nvcc)
    std::string architectures;  // device code in the binary, e.g. "sm_80 sm_90"
    int devices = 0;            // CUDA devices usable now
    std::string status;         // one line: the device found, or why there is none
};

CudaBackendInfo cudaBackendInfo();

// What the binary holds, for -help: "cuda (compiled for sm_80 sm_90)" or "cuda (not in
// this build)". It does not touch the driver (cudaBackendInfo() does).
std::string cudaBackendSummary();

class CudaDemModel {
public:
    // Uploads host's state; UserError when this build or machine has no CUDA device,
    // or the bond or contact law has no CUDA kernel.
    explicit CudaDemModel(DemModel& host);
    ~CudaDemModel();
    CudaDemModel(const CudaDemModel&) = delete;
    CudaDemModel& operator=(const CudaDemModel&) = delete;

    // DemModel::step and DemModel::evaluateForces, on the device.
    double step(double dt);
    void evaluateForces(double dt);
    // Copy the device state into the host DemModel (cells, bond and contact histories).
    void downloadState();
    // Copy the host DemModel's whole state to the device (after changing it on the host).
    void upload();

    const DemModel& host() const { return host_; }
    std::size_t deviceBytes() const;  // device memory held [bytes]
    // The device memory upload() would take for host, from its array sizes (no GPU
    // needed; 0 in a build without CUDA). Neighbour lists as the host holds them now.
    static std::size_t estimateDeviceBytes(const DemModel& host);
    std::string deviceName() const;

private:
    struct Buffers;               // device arrays (cudaDemModel.cu)
    DemModel::DeviceSide side();  // what this backend may do to host_ (DemModel::DeviceKey)
    void computeForces(double dt);
    void bondForces(double dt);
    void contactForces(double dt);
    void wallReactions(double dt);
    void gather();
    void singleStep(double dt);
    void measure(double sync_dt);
    void rebuildListsOnHost();
    void uploadLists();

    DemModel& host_;
    std::unique_ptr<Buffers> device_;
};

}  // namespace rockfrac
