// The CUDA backend in a build without it (-DROCKFRAC_CUDA=OFF, or no nvcc at configure
// time): the same interface, and one clear error when it is asked for.
#include "core/error.hpp"
#include "demCuda/cudaDemModel.hpp"

namespace rockfrac {

struct CudaDemModel::Buffers {};

CudaBackendInfo cudaBackendInfo()
{
    CudaBackendInfo info;
    info.status =
        "this build of rockfrac has no CUDA backend (configured without nvcc or with -DROCKFRAC_CUDA=OFF); "
        "rebuild with nvcc installed and -DROCKFRAC_CUDA=ON";
    return info;
}

std::string cudaBackendSummary()
{
    return "cuda (not in this build)";
}

CudaDemModel::CudaDemModel(DemModel& host) : host_(host)
{
    throw UserError(cudaBackendInfo().status);
}

CudaDemModel::~CudaDemModel() = default;

double CudaDemModel::step(double)
{
    return host_.time();
}
void CudaDemModel::evaluateForces(double) {}
void CudaDemModel::downloadState() {}
void CudaDemModel::upload() {}
std::size_t CudaDemModel::deviceBytes() const
{
    return 0;
}
std::size_t CudaDemModel::estimateDeviceBytes(const DemModel&)
{
    return 0;
}
std::string CudaDemModel::deviceName() const
{
    return "none";
}
void CudaDemModel::computeForces(double) {}
void CudaDemModel::measure(double) {}
void CudaDemModel::rebuildListsOnHost() {}
void CudaDemModel::uploadLists() {}

}  // namespace rockfrac
