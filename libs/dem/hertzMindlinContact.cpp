#include "dem/hertzMindlinContact.hpp"

namespace rockfrac {

const char* HertzMindlinContactLaw::type() const
{
    return "hertzMindlin";
}

void HertzMindlinContactLaw::runPairs(const PairKernelArgs& args) const
{
    runPairKernel<HertzMindlinLaw>(args);
}

void HertzMindlinContactLaw::runWalls(const WallKernelArgs& args) const
{
    runWallKernel<HertzMindlinLaw>(args);
}

}  // namespace rockfrac
