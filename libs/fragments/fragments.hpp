#pragma once
// Fragments of a bonded Voronoi DEM state (physics.md §4, docs/theory-fragments.md).
//
// A fragment is a connected component of the graph whose nodes are the cells and
// whose edges are the intact bonds (stage elastic or softening; a broken bond,
// D = 1, joins nothing). Two cells are in the same fragment when they are joined
// by a chain of cell pairs each glued by at least one intact bond.
//
//   const auto bond_cells = demBondCells(mesh);                 // once per mesh
//   const auto initial = initialCellOrientations(mesh, density);  // once per mesh
//   FragmentAnalysis a = analyseFragments(mesh, bond_cells, stage, poses, initial, density);
//
// Fragments are numbered 0, 1, ... in the order of their smallest cell id, so the
// numbering depends on the partition only, never on the order of the unions.
#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "dem/quat.hpp"
#include "voronoi/voronoiMesh.hpp"

namespace rockfrac {

// The two cells (i < j) of every DEM bond, in the order of DemModel's bond arrays
// and therefore of the bond.* arrays of <time>/demState: the mesh's bonds stably
// sorted by cell pair, so that each interface's bonds are contiguous.
std::vector<std::array<int, 2>> demBondCells(const VoronoiMesh& mesh);

struct FragmentLabels {
    std::vector<int> fragment_of_cell;  // 0 .. n_fragments-1
    int n_fragments = 0;
};

// Union–find over the intact bonds. bond_stage: BondStage per bond (bondBroken = 2
// separates, anything else joins). std::invalid_argument on mismatched sizes or a
// cell index out of range.
FragmentLabels labelFragments(int n_cells, const std::vector<std::array<int, 2>>& bond_cells,
                              const std::vector<std::uint8_t>& bond_stage);

// Where the cells are at one instant: centroid and orientation (body -> world).
struct CellPoses {
    std::vector<Vec3> position;
    std::vector<Quat> orientation;
};

// The body frame of each cell as DemModel sets it at t = 0 (principal axes of
// inertia, right-handed, from the same eigen-solver on the same input, so the
// result is bitwise DemModel's cells().orientation). density [kg/m^3] matters only
// for that bitwise agreement (the eigen-solver scales its input).
std::vector<Quat> initialCellOrientations(const VoronoiMesh& mesh, double density);

// The mesh vertices moved with their cells: x = p(t) + R(q(t)) R(q0)^T (x0 - c0),
// evaluated in the order bondedDemFoam draws cells (body vertices first), so the
// points equal those of its VTK output.
std::vector<Vec3> movedVertices(const VoronoiMesh& mesh, const std::vector<Quat>& initial_orientation,
                                const CellPoses& poses);

struct Fragment {
    int first_cell = -1;  // smallest cell id (the fragment's identity)
    int n_cells = 0;
    double volume = 0.0;               // [m^3]
    double mass = 0.0;                 // [kg]
    Vec3 centroid;                     // [m]
    double equivalent_diameter = 0.0;  // (6 V / pi)^(1/3) [m]
    Vec3 principal_extents;            // extents of the vertices along the principal axes of
                                       // inertia of the fragment, descending [m]
    double sieve_size = 0.0;           // the intermediate principal extent [m]
};

struct FragmentAnalysis {
    FragmentLabels labels;
    std::vector<Fragment> fragments;  // indexed by fragment id
    std::vector<Vec3> vertices;       // moved mesh vertices (for drawing)
    double total_mass = 0.0;          // [kg]
    double total_volume = 0.0;        // [m^3]
};

// Labels, then mass, volume, centroid, sizes of every fragment.
FragmentAnalysis analyseFragments(const VoronoiMesh& mesh, const std::vector<std::array<int, 2>>& bond_cells,
                                  const std::vector<std::uint8_t>& bond_stage, const CellPoses& poses,
                                  const std::vector<Quat>& initial_orientation, double density);

// (6 V / pi)^(1/3).
double volumeEquivalentDiameter(double volume);

}  // namespace rockfrac
