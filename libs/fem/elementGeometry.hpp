#pragma once
// Precomputed per-element data of linear tetrahedra, laid out for the kernels.
//
// A linear tet has constant shape-function gradients, so everything the element
// loop needs besides the nodal displacements is computed once: node ids (4 per
// element), gradients dN_a/dx (4 x 3 per element, node-major), volume and
// smallest height. Each array is contiguous over elements (structure of arrays).
#include <vector>

#include "fem/tetMesh.hpp"

namespace rockfrac::fem {

struct ElementGeometry {
    std::vector<int> nodeIds;       // 4 per element
    std::vector<double> gradients;  // 12 per element: dN_a/dx_j at [12 e + 3 a + j]
    std::vector<double> volumes;    // 1 per element
    std::vector<double> heights;    // smallest altitude, 1 per element

    std::size_t numElements() const { return volumes.size(); }
};

ElementGeometry makeElementGeometry(const TetMesh& mesh);

}  // namespace rockfrac::fem
