#pragma once
// The Voronoi cells of the rocks fed, as particles: the finest product a crusher run can make
// with its feed meshes (every bond broken), and so the bound of its discharge PSD's fine end
// (docs/theory-crusher.md, "The cells' PSD").
//
//   const std::vector<CellSizes> perClass = {templateCellSizes(rock, density), ...};
//   const CellSizes cells = fedCellSizes(state.fed.rocks, templates, perClass);
//   PsdCurve curve = cumulativePassing(cells.sieve_size, cells.mass);
#include <vector>

#include "crusher/crusherState.hpp"
#include "crusher/feedRock.hpp"

namespace rockfrac {

struct CellSizes {
    std::vector<double> sieve_size;  // [m] per cell
    std::vector<double> mass;        // [kg] per cell
};

// Each cell of a template rock as a one-cell fragment, measured as fragmentPSD measures a
// fragment (libs/fragments: sieve size = the intermediate principal extent of its vertices;
// mass = density x volume).
CellSizes templateCellSizes(const FeedRockTemplate& rock, double density);

// Every cell of every rock fed, in the order fed: its class's template cells scaled to the
// rock's drawn size s / template sieve size (sieve sizes x s, masses x s^3, as
// scaleVoronoiMesh scales the rock). per_class[i] = templateCellSizes(templates[i], ...).
// std::invalid_argument for a rock whose class has no template or whose cell count is not
// its template's.
CellSizes fedCellSizes(const std::vector<FedRock>& rocks, const std::vector<FeedRockTemplate>& templates,
                       const std::vector<CellSizes>& per_class);

}  // namespace rockfrac
