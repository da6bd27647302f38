#pragma once
// The paper's bond law over four interfaces at a time (AVX2 lanes, CPU only), for the
// intact bonds that are most of every step's work (docs/benchmarks.md).
//
// Each lane takes one interface and walks its bonds in their order; a lane's force, torques
// and energy sums are added up in that order, bond by bond, with the same floating-point
// operations in the same order as bondInterfaceKernel (no fused multiply-add), so the result
// is the scalar kernel's to the bit (tests/unit/dem/testBondLanes.cpp). An interface with a
// softening bond, or a bond reaching its onset in this step, is handed back to the scalar
// kernel, in its place in the block order, before anything of it is written.
#include "dem/bondLaw.hpp"
#include "dem/voronoiQnscBond.hpp"

namespace rockfrac {

// The scalar kernel of one interface (bondInterfaceKernel<VoronoiQnscLaw>), compiled without
// AVX2 in voronoiQnscBond.cpp: what the lanes hand back.
bool voronoiQnscInterfaceScalar(const BondKernelArgs& a, const VoronoiQnscLaw::Coefficients& c, int k,
                                BondBlockSums& block);

// True when this CPU runs AVX2 and the environment does not ask for the scalar kernel
// (ROCKFRAC_BOND_KERNEL=scalar, read once: the twin runs of docs/benchmarks.md).
bool bondLanesEnabled();

// runBondKernel<VoronoiQnscLaw> with the lanes: the same blocks, the same OpenMP schedule,
// the same block sums. Only for the full pass (not a.only_interfaces); needs bondLanesEnabled().
void runVoronoiQnscBondLanes(const BondKernelArgs& a, const VoronoiQnscLaw::Coefficients& c);

}  // namespace rockfrac
