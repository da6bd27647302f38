#pragma once
// The bonded Voronoi mesh of a domain (physics.md §3.2): Voro++ computes the
// Voronoi cell of every seed, clipped by the domain's planes and cylinder;
// each cell's vertices, outward faces, neighbours, volume, centroid and
// inertia go into the compressed arrays of VoronoiMesh, and every internal
// face is bonded at its vertices.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "voronoi/domain.hpp"
#include "voronoi/sizeField.hpp"
#include "voronoi/voronoiMesh.hpp"

namespace rockfrac {

// Tessellate `domain` around `seeds` (all inside the domain; UserError if
// not). The dilation radius is dilationFraction x meanCellSize. The cells are
// computed in parallel (OpenMP); the result does not depend on the thread
// count. seed and pruningDistance of the result are left 0: see
// generateVoronoiMesh.
// Domains of more than maxPlaneWalls planes (Voro++ takes at most 2048 walls; the default
// keeps a margin) have their cells clipped by the planes one by one instead: the same cells up to
// round-off, for any number of planes.
VoronoiMesh tessellate(const Domain& domain, const std::vector<Vec3>& seeds, double dilationFraction = 0.1,
                       std::size_t maxPlaneWalls = 1000);

// How the cells of a generated mesh are numbered: in the order the seeds were placed
// (random in space), or along a Morton curve (neighbours close in memory: faster DEM
// steps on large meshes, the same geometry).
enum class CellOrder { seeding, morton };

// placeSeeds then tessellate, recording the seed and pruning distance. With a size field the
// seeds follow it (placeSeeds' graded form; nCells from gradedCellCount); without one the
// uniform seeding, unchanged.
VoronoiMesh generateVoronoiMesh(const Domain& domain, int nCells, double pruningDistance, std::uint64_t seed,
                                double dilationFraction = 0.1, CellOrder order = CellOrder::seeding,
                                const SizeField* field = nullptr);

// Mean cell size: the mean over cells of the volume-equivalent diameter
// (6 V / pi)^(1/3) [m]. For the paper's 300-cell BDT disc (D 44.8 mm,
// t 13.8 mm) it is about 5.1 mm (the paper quotes 5.5 mm).
double meanCellSize(const VoronoiMesh& mesh);

}  // namespace rockfrac
