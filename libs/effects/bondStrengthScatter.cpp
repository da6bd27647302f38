#include "effects/bondStrengthScatter.hpp"

namespace rockfrac {

const EffectDescriptor BondStrengthScatter::descriptor{
    "bondStrengthScatter",
    "random bond strengths with a Weibull size effect",
    "wider spread and lower mean of the failure loads, same stiffness",
    "inverseModulus",
    "-",
    0.0,
    0.3,
    ProbeScale::absolute,
    0.0,
    1.0,
    {"seed"},
    &makeEffect<BondStrengthScatter>};

}  // namespace rockfrac
