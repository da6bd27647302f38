#pragma once
// The backend the DEM unit tests step their models on. The same test sources are built
// twice: test_dem (the CPU backend, OpenMP; ctest label unit) and, in a build with the
// CUDA backend, test_demOnCuda (tests/unit/demCuda; label gpu, skipped without a GPU),
// compiled with ROCKFRAC_TEST_ON_CUDA so that every step and every force evaluation
// below runs the device kernels instead of the host ones.
//
// The host DemModel stays the owner of the state, as in bondedDemFoam: a CudaDemModel
// uploads it, steps it on the device and downloads it again, so a test may read or set
// the host arrays between calls exactly as it does on the CPU backend.
#include "dem/demModel.hpp"

#ifdef ROCKFRAC_TEST_ON_CUDA
#include "demCuda/cudaDemModel.hpp"
#endif

namespace rockfrac::test {

#ifdef ROCKFRAC_TEST_ON_CUDA

// One explicit step of model on the device; returns the new time.
inline double step(DemModel& model, double dt)
{
    CudaDemModel device(model);
    const double time = device.step(dt);
    device.downloadState();
    return time;
}

// n steps on the device without touching the host in between; stops at a bad status.
inline void steps(DemModel& model, double dt, int n)
{
    CudaDemModel device(model);
    for (int i = 0; i < n && model.status().ok(); ++i) device.step(dt);
    device.downloadState();
}

// Forces at the current state (DemModel::evaluateForces) on the device.
inline void evaluateForces(DemModel& model, double dt)
{
    CudaDemModel device(model);
    device.evaluateForces(dt);
    device.downloadState();
}

#else

inline double step(DemModel& model, double dt)
{
    return model.step(dt);
}

inline void steps(DemModel& model, double dt, int n)
{
    for (int i = 0; i < n && model.status().ok(); ++i) model.step(dt);
}

inline void evaluateForces(DemModel& model, double dt)
{
    model.evaluateForces(dt);
}

#endif

}  // namespace rockfrac::test
