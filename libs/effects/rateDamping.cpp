#include "effects/rateDamping.hpp"

namespace rockfrac {

const EffectDescriptor RateDamping::descriptor{"rateDamping",
                                               "more rate dependence: the bond damping beta scaled",
                                               "more gradual softening after the peak",
                                               "betaFactor",
                                               "-",
                                               1.0,
                                               4.0,
                                               ProbeScale::absolute,
                                               0.05,
                                               10.0,
                                               {},
                                               &makeEffect<RateDamping>};

}  // namespace rockfrac
