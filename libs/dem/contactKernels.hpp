#pragma once
// The contact kernels' runners: a law applied to every cell–cell pair and every
// cell–wall item, in blocks whose sums do not depend on the thread count.
#include "core/parallel.hpp"
#include "dem/contactLaw.hpp"
#include "dem/pairContact.hpp"
#include "dem/wallContact.hpp"

namespace rockfrac {

// Blocks of pairs, each summed in pair order (static schedule: the sums do not
// depend on the thread count).
template <class Law>
void runPairKernel(const PairKernelArgs& a)
{
    const int n_blocks = (a.n_pairs + a.block_size - 1) / a.block_size;
#pragma omp parallel for schedule(static) if (n_blocks > 1)
    for (int block = 0; block < n_blocks; ++block) {
        ContactBlockSums sums;
        const int end = a.n_pairs < (block + 1) * a.block_size ? a.n_pairs : (block + 1) * a.block_size;
        for (int p = block * a.block_size; p < end; ++p) pairKernel<Law>(a, p, sums);
        a.block_sums[block] = sums;
    }
}

// An item against a triangulated liner searches tens to hundreds of candidate triangles per
// core vertex, against one plane for a plate: the work is the candidate count, not the item
// count (a few hundred cells on the liners of a crusher already fill two threads), and it is
// uneven (an item out of reach returns after the centre's search), so the items are dealt
// out dynamically. Each item writes its own slots: the result does not depend on the order.
template <class Law>
void runWallKernel(const WallKernelArgs& a)
{
    const long work = a.n_items > 0 ? a.n_items + a.item_triangle_offset[a.n_items] : 0;
#pragma omp parallel for schedule(dynamic, 8) if (work >= parallelMinimumItems())
    for (int item = 0; item < a.n_items; ++item) wallKernel<Law>(a, item);
}

}  // namespace rockfrac
