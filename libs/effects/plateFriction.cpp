#include "effects/plateFriction.hpp"

namespace rockfrac {

const EffectDescriptor PlateFriction::descriptor{"plateFriction",
                                                 "the rock-steel friction at the plates scaled",
                                                 "a more or less confined contact zone (shape dependent)",
                                                 "frictionFactor",
                                                 "-",
                                                 1.0,
                                                 -0.75,
                                                 ProbeScale::absolute,
                                                 0.0,
                                                 2.0,
                                                 {},
                                                 &makeEffect<PlateFriction>};

}  // namespace rockfrac
