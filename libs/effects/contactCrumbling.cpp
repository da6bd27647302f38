#include "effects/contactCrumbling.hpp"

namespace rockfrac {

const EffectDescriptor ContactCrumbling::descriptor{
    "contactCrumbling",
    "the rock under each plate crushes early (weakened bonds within a contact zone)",
    "soft start that stiffens (toe), larger displacement at peak, lower peak",
    "strengthLoss",
    "-",
    0.0,
    0.6,
    ProbeScale::absolute,
    0.0,
    0.95,
    {"depth"},
    &makeEffect<ContactCrumbling>};

}  // namespace rockfrac
