#include "effects/machineCompliance.hpp"

namespace rockfrac {

const EffectDescriptor MachineCompliance::descriptor{
    "machineCompliance",
    "a linear spring in series with the specimen (frame, platens)",
    "uniformly softer curve, larger displacement at peak, same peak and shape",
    "compliance",
    "m/N",
    0.0,
    0.5,
    ProbeScale::peakCompliance,
    0.0,
    1e-6,
    {},
    &makeEffect<MachineCompliance>};

}  // namespace rockfrac
