// cudaBackendInfo: what this build and this machine offer for `backend cuda;` in a
// bondedDemFoam controlDict (libs/demCuda): whether the CUDA backend was compiled,
// for which GPU architectures, and which device it would use now. Exit 0 when a
// device is usable, 3 when the backend is compiled but no GPU is present, 4 when the
// build has no CUDA backend, 5 when a GPU is present (the NVIDIA driver's device node)
// but the runtime cannot use it (a driver older than the CUDA runtime, a broken
// install): scripts skip the `gpu` tests on 3 and 4 only, and fail on 5.
//
// Sample run:
//   cudaBackendInfo
#include <cstdio>
#include <filesystem>

#include "core/application.hpp"
#include "demCuda/cudaDemModel.hpp"

using namespace rockfrac;

namespace {

// The NVIDIA driver's traces of a GPU: present even when the CUDA runtime cannot use it.
bool nvidiaGpuPresent()
{
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists("/dev/nvidia0", ec)) return true;
    const fs::path gpus = "/proc/driver/nvidia/gpus";
    return fs::is_directory(gpus, ec) && fs::directory_iterator(gpus, ec) != fs::directory_iterator();
}

const AppInfo info{
    "cudaBackendInfo",
    "Report the CUDA backend of bondedDemFoam: compiled or not, the GPU architectures in the binary, and "
    "the device it would use. Exit code 0: a device is usable; 3: compiled, no GPU present; 4: not "
    "compiled; 5: a GPU is present but the CUDA runtime cannot use it (driver older than the runtime?).",
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
        if (backend.devices > 0) return 0;
        if (nvidiaGpuPresent()) {
            std::printf(
                "gpu present: yes (the NVIDIA driver lists one), but the CUDA runtime cannot use it\n");
            return 5;
        }
        return 3;
    });
}
