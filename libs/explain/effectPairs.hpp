#pragma once
// Pairs of effects (docs/explainGap.md, "Pairs"): when no single effect passes the absolute
// test, the top-ranked effects of the screening are refitted two at a time with the baseline.
// Which pairs, and in which order, is a pure rule.
#include <utility>
#include <vector>

namespace rockfrac::explain {

// At most this many effects of the screening's ranking enter pairs (three effects, three pairs).
constexpr int pairRankedEffects = 3;
// The most pairs a study may ask for (explainGapDict `pairs`).
constexpr int maximumPairs = 3;

// The pairs of the first pairRankedEffects entries of `ranked` (best first), the best-ranked
// pairs first ((1st, 2nd), (1st, 3rd), (2nd, 3rd)), at most maxPairs of them.
std::vector<std::pair<int, int>> pairsToScreen(const std::vector<int>& ranked, int maxPairs);

// Akaike's criterion of a fit with `parameters` free: chi-square + 2 per parameter.
inline double akaike(double chiSquare, int parameters)
{
    return chiSquare + 2.0 * parameters;
}

}  // namespace rockfrac::explain
