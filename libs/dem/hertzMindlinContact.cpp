#include "dem/hertzMindlinContact.hpp"

namespace rockfrac {

void runHertzMindlinPairs(const PairKernelArgs& args)
{
    runPairKernel<HertzMindlinLaw>(args);
}
void runHertzMindlinWalls(const WallKernelArgs& args)
{
    runWallKernel<HertzMindlinLaw>(args);
}

}  // namespace rockfrac
