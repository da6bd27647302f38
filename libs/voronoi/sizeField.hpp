#pragma once
// A graded cell size for voronoiMesh (voronoiMeshDict's optional `sizeField`): finer cells near
// given points, lines or planes (e.g. where the plates touch a Brazilian disc), graded back to the
// base size. The target size is a volume-equivalent diameter (6 V / pi)^(1/3):
//
//     h(x) = min(base, min over regions r of (size_r + (grading - 1) d_r(x)))
//
// with d_r the distance to region r. A cell of size h centred at d has its neighbour, one
// cell further (d + h), at size h + (grading - 1) h = grading h: the ratio between neighbouring
// cells is bounded by `grading`, and h reaches the base size at d = (base - size) / (grading - 1).
// The seeds are drawn with density (base / h)^3 and pruned at a local distance
// pruningDistance x h / base (seeding.hpp's placeSeeds with a field).
#include <string>
#include <vector>

#include "core/dictionary.hpp"
#include "core/vec3.hpp"
#include "voronoi/domain.hpp"

namespace rockfrac {

struct SizeRegion {
    enum class Kind { point, line, plane };
    std::string name;
    Kind kind = Kind::point;
    Vec3 point;
    Vec3 direction;     // unit: the line's direction or the plane's normal (unused for a point)
    double size = 0.0;  // target cell size at the region [m]

    // Distance from p to the point, the line or the plane [m].
    double distance(const Vec3& p) const;
};

struct SizeField {
    double baseSize = 0.0;  // size far from every region [m]
    double grading = 1.3;   // bound on the size ratio of neighbouring cells (> 1)
    std::vector<SizeRegion> regions;

    // Target cell size at p [m] (the formula above).
    double size(const Vec3& p) const;
    // The smallest region size [m] (baseSize when there is no region).
    double smallest() const;
    // Distance from a region within which the field is finer than the base [m].
    double gradedWidth(const SizeRegion& r) const { return (baseSize - r.size) / (grading - 1.0); }
};

// The smallest region size voronoiMesh allows, in dilation radii of the base cells
// (dilationFraction x base size). Set when the 300-cell granite disc graded to a quarter of the
// base at the contacts (1.29 mm, 3.5 radii) stopped on the DEM's energy check at its first step
// with dilationFraction 0.1: cells too thin for the radius had a shrunk core sticking out of
// them. The DEM now gives such cells their own radius (dilatedCellCore) and that disc runs; the
// floor is kept until finer fields are validated.
constexpr double smallestSizeInDilationRadii = 4.0;

// The entries of voronoiMeshDict's sizeField and of one of its regions.
const std::vector<std::string>& sizeFieldEntries();
const std::vector<std::string>& sizeRegionEntries();

// Read `sizeField { grading 1.3; regions { <name> { type point|line|plane; point (x y z);
// direction (..) | normal (..); size <m>; } ... } }` (the sub-dictionary itself). UserError
// naming file:line and what to do for: grading not in (1, 2]; no region; a size below
// minimumSize (smallestSizeInDilationRadii dilation radii of the base cells) or not below baseSize; a point
// (or a line's point) outside `box`, or a plane that misses it; a zero direction or normal.
SizeField readSizeField(const Dictionary& field, double baseSize, double minimumSize, const BoundingBox& box);

// Cell count that keeps the base cells at baseCellVolume [m^3]: round(integral of
// (base / h)^3 dV / baseCellVolume), by the midpoint rule on a 64^3 grid over the domain's box
// (no randomness: the count depends on the field and the domain only).
int gradedCellCount(const Domain& domain, const SizeField& field, double baseCellVolume);

// Volume-equivalent diameter (6 V / pi)^(1/3) of a volume [m].
double equivalentDiameter(double volume);

}  // namespace rockfrac
