#include "dem/voronoiQnscBond.hpp"

namespace rockfrac {

void runVoronoiQnscBonds(const BondKernelArgs& args)
{
    runBondKernel<VoronoiQnscLaw>(args);
}

}  // namespace rockfrac
