#pragma once
// Helpers shared by the files of DemModel (libs/dem/demModel*.cpp); not part of its interface.
#include <cstddef>
#include <vector>

namespace rockfrac::demDetail {

constexpr double pi = 3.14159265358979323846;
constexpr int cell_block_size = 512;

// Build CSR lists "which items does each cell take part in": entry 2*item + side,
// in increasing item order, so the gather sums in a fixed order.
void buildCellIncidence(int n_cells, const std::vector<int>& first, const std::vector<int>& second,
                        std::vector<int>& offset, std::vector<int>& entries);

}  // namespace rockfrac::demDetail
