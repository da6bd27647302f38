#pragma once
// The backend a bonded-DEM run steps on (controlDict `backend cpu|cuda;`): the host
// DemModel with OpenMP, or its CUDA mirror (demCuda/cudaDemModel.hpp).
//
// The host model stays the owner of the state. With CUDA its time, energies, counters,
// status and wall reactions are current after every step, its cell arrays only after
// download(); what changes the state on the host (cells fed or removed) goes to the
// device with upload(). On the CPU download() and upload() do nothing.
//
// chooseDemTimeStep: the step of a DEM run (plates or crusher) from its controlDict.
#include <memory>
#include <string>

#include "dem/demModel.hpp"

namespace rockfrac {

class CudaDemModel;
class Dictionary;
class TimeControl;

class DemBackend {
public:
    DemBackend(DemModel& model, bool useCuda);  // useCuda: uploads the model to the device
    ~DemBackend();
    DemBackend(const DemBackend&) = delete;
    DemBackend& operator=(const DemBackend&) = delete;

    void evaluateForces(double dt);
    void step(double dt);
    void download();
    void upload();
    const CudaDemModel* device() const { return device_.get(); }  // null on the CPU

private:
    DemModel& model_;
    std::unique_ptr<CudaDemModel> device_;
};

// Exactly one of controlDict's deltaT [s], rayleighFraction (of the Rayleigh step) or
// criticalFraction (of the largest stable step) sets time's deltaT; a step above the stable
// one is refused, naming `whose` stable step it is ("this mesh and these parameters").
void chooseDemTimeStep(const Dictionary& controlDict, TimeControl& time, double rayleighStep,
                       const CriticalTimeStep& critical, const std::string& whose);

}  // namespace rockfrac
