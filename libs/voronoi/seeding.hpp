#pragma once
// Seed points of the Voronoi tessellation (physics.md §3.2): a chosen number
// of uniformly random points in the domain, no two closer than the pruning
// distance pd. pd is a minimum spacing; the cell count is what the user asks
// for (directly, or through the meso constant V / nCells).
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec3.hpp"
#include "voronoi/domain.hpp"
#include "voronoi/sizeField.hpp"

namespace rockfrac {

// Exactly nCells points inside `domain`, pairwise at least pruningDistance
// apart (0 = no pruning), by dart throwing (random sequential addition) with a
// background grid. The same arguments give the same points on every machine.
//
// UserError if nCells < 2, if pruningDistance is negative or not finite, or if
// nCells points do not fit: after a run of failed throws the message gives the
// count reached (an estimate of the largest count that fits at this pd) and a
// pruning distance that would fit nCells. Never loops forever, never returns
// fewer points.
std::vector<Vec3> placeSeeds(const Domain& domain, int nCells, double pruningDistance, std::uint64_t seed);

// The same with a graded size field (sizeField.hpp): throws are thinned to the density
// (base / h(x))^3, and two seeds are pruned closer than pruningDistance x the mean of their
// sizes / base (pruningDistance applies at the base size). Deterministic in `seed`.
std::vector<Vec3> placeSeeds(const Domain& domain, int nCells, double pruningDistance, std::uint64_t seed,
                             const SizeField& field);

// Reorder points along a Morton (Z-order) curve over their bounding box (21 bits per
// axis, ties kept in their order). Cells numbered this way have their neighbours
// nearby in memory, which the DEM's bond kernel reads for every bond: with the
// seeding order (random) a 10^4-cell block spends much of each step waiting for
// the second cell of each interface (docs/benchmarks.md). voronoiMeshDict: cellOrder.
void orderAlongMortonCurve(std::vector<Vec3>& points);

// Cell count that keeps the meso constant V / nCells [m^3] (the rocks of the
// paper keep 2.2e-7 m^3, that of the 100-cell BDT disc): round(V / mesoConstant).
// UserError if mesoConstant is not positive or the count does not fit an int.
int cellCountFromMesoConstant(double domainVolume, double mesoConstant);

// The entries of system/voronoiMeshDict (voronoiMesh's readRequest).
inline const std::vector<std::string>& voronoiMeshDictEntries()
{
    static const std::vector<std::string> entries = {
        "nCells", "mesoConstant", "pruningDistance", "seed", "dilationFraction", "cellOrder", "sizeField"};
    return entries;
}

}  // namespace rockfrac
