#pragma once
// A parallel sum whose result does not depend on the thread count: the index range
// is cut into fixed blocks, each summed in order, then the block sums in order.
#include <vector>

namespace rockfrac::fem {

template <class Term>
double deterministicSum(long long count, Term term)
{
    constexpr long long blockSize = 4096;
    const long long numBlocks = (count + blockSize - 1) / blockSize;
    std::vector<double> blockSums(static_cast<std::size_t>(numBlocks), 0.0);
#pragma omp parallel for schedule(static)
    for (long long b = 0; b < numBlocks; ++b) {
        double sum = 0.0;
        const long long end = (b + 1) * blockSize < count ? (b + 1) * blockSize : count;
        for (long long i = b * blockSize; i < end; ++i) sum += term(i);
        blockSums[b] = sum;
    }
    double total = 0.0;
    for (double s : blockSums) total += s;
    return total;
}

}  // namespace rockfrac::fem
