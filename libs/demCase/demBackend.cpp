#include "demCase/demBackend.hpp"

#include <cstdio>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/timeControl.hpp"
#include "demCuda/cudaDemModel.hpp"

namespace rockfrac {

DemBackend::DemBackend(DemModel& model, bool useCuda)
    : model_(model), device_(useCuda ? std::make_unique<CudaDemModel>(model) : nullptr)
{
}

DemBackend::~DemBackend() = default;

void DemBackend::evaluateForces(double dt)
{
    if (device_)
        device_->evaluateForces(dt);
    else
        model_.evaluateForces(dt);
}

void DemBackend::step(double dt)
{
    if (device_)
        device_->step(dt);
    else
        model_.step(dt);
}

void DemBackend::download()
{
    if (device_) device_->downloadState();
}

void DemBackend::upload()
{
    if (device_) device_->upload();
}

void chooseDemTimeStep(const Dictionary& controlDict, TimeControl& time, double rayleighStep,
                       const CriticalTimeStep& critical, const std::string& whose)
{
    const int given = int(time.deltaTGiven()) + int(controlDict.found("rayleighFraction")) +
                      int(controlDict.found("criticalFraction"));
    if (given != 1)
        throw UserError(controlDict.fileName() +
                        ": give exactly one of 'deltaT' [s], 'rayleighFraction' (the step as a fraction of "
                        "the Rayleigh step, e.g. 0.02) or 'criticalFraction' (the step as a fraction of the "
                        "largest stable step of the bonds and contacts, e.g. 0.8)");
    if (controlDict.found("rayleighFraction"))
        time.setDeltaT(controlDict.getScalar("rayleighFraction", Bounds::open(0, 1)) * rayleighStep);
    if (controlDict.found("criticalFraction"))
        time.setDeltaT(controlDict.getScalar("criticalFraction", Bounds::closed(1e-9, 1)) * critical.value);
    if (time.deltaT() > critical.value) {
        char buffer[400];
        std::snprintf(buffer, sizeof(buffer),
                      ": the time step %.4g s is above the largest stable step %.4g s of %s (bonds: highest "
                      "frequency %.4g rad/s, damping ratio %.3g; contacts %.4g s); set deltaT <= %.4g or use "
                      "criticalFraction (e.g. 0.8)",
                      time.deltaT(), critical.value, whose.c_str(), critical.bond_frequency,
                      critical.bond_damping_ratio, critical.contact, critical.value);
        throw UserError(controlDict.fileName() + buffer);
    }
}

}  // namespace rockfrac
