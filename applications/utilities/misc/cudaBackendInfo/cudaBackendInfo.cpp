// cudaBackendInfo: what this build and this machine offer for `backend cuda;` in a
// bondedDemFoam controlDict (libs/demCuda): whether the CUDA backend was compiled,
// for which GPU architectures, and which device it would use now. Exit 0 when a
// device is usable, 3 when the backend is compiled but no device is present, 4 when
// the build has no CUDA backend, so scripts (the `gpu` tests) can decide to skip.
//
// Sample run:
//   cudaBackendInfo
#include <cstdio>

#include "core/application.hpp"
#include "demCuda/cudaDemModel.hpp"

using namespace rockfrac;

namespace {
const AppInfo info{
    "cudaBackendInfo",
    "Report the CUDA backend of bondedDemFoam: compiled or not, the GPU architectures in the binary, and "
    "the device it would use. Exit code 0: a device is usable; 3: compiled, no device; 4: not compiled.",
    "[options]",
    {"cudaBackendInfo"},
    {},
    0,
    0,
    false,
};
}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, [](Application&) {
        const CudaBackendInfo backend = cudaBackendInfo();
        std::printf("compiled: %s\n", backend.compiled ? "yes" : "no");
        std::printf("architectures: %s\n", backend.compiled ? backend.architectures.c_str() : "none");
        std::printf("devices: %d\n", backend.devices);
        std::printf("status: %s\n", backend.status.c_str());
        if (!backend.compiled) return 4;
        return backend.devices > 0 ? 0 : 3;
    });
}
