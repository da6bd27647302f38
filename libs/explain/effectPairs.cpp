// The pairs of effects explainGap refits together (effectPairs.hpp).
#include "explain/effectPairs.hpp"

#include <algorithm>
#include <cstddef>

namespace rockfrac::explain {

std::vector<std::pair<int, int>> pairsToScreen(const std::vector<int>& ranked, int maxPairs)
{
    std::vector<std::pair<int, int>> pairs;
    const std::size_t n = std::min(ranked.size(), static_cast<std::size_t>(pairRankedEffects));
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a + 1; b < n; ++b)
            if (static_cast<int>(pairs.size()) < maxPairs) pairs.emplace_back(ranked[a], ranked[b]);
    return pairs;
}

}  // namespace rockfrac::explain
