// The Catch2 runner of test_demOnCuda (the DEM unit tests on the CUDA backend): without
// a usable GPU it says why and exits 77, which ctest reports as skipped.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <cstdio>

#include "demCuda/cudaDemModel.hpp"

int main(int argc, char** argv)
{
    const rockfrac::CudaBackendInfo info = rockfrac::cudaBackendInfo();
    if (info.devices == 0) {
        std::printf("SKIP: the DEM unit tests on the CUDA backend need a GPU: %s\n", info.status.c_str());
        return 77;
    }
    std::printf("DEM unit tests on the CUDA backend: %s\n", info.status.c_str());
    return Catch::Session().run(argc, argv);
}
