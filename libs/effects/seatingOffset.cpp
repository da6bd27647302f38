#include "effects/seatingOffset.hpp"

namespace rockfrac {

const EffectDescriptor SeatingOffset::descriptor{
    "seatingOffset",
    "a seating gap that closes under a small force (toe region)",
    "toe at the start, displacement at peak up by the gap, same stiffness and peak",
    "depth",
    "m",
    0.0,
    0.3,
    ProbeScale::peakDisplacement,
    0.0,
    1e-3,
    {"closureForce"},
    &makeEffect<SeatingOffset>};

}  // namespace rockfrac
