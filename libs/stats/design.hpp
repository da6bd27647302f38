#pragma once
// Designs of experiments for parameter studies (runCases).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rockfrac::stats {

// Every combination of levels: `levels[j]` choices for factor j. Row r holds
// one level index per factor; the last factor varies fastest.
std::vector<std::vector<std::size_t>> fullFactorial(const std::vector<std::size_t>& levels);

// A Latin hypercube in the unit cube [0, 1)^dimensions: each dimension is cut
// into `samples` equal strata and every stratum holds exactly one point, at a
// random position inside it. Reproducible from `seed` on any machine.
std::vector<std::vector<double>> latinHypercube(std::size_t samples, std::size_t dimensions,
                                                std::uint64_t seed);

}  // namespace rockfrac::stats
