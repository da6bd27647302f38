#pragma once
// The specimen: the solid a case simulates, as meshRock makes it and every
// later application reads it (constant/geometryProperties).
//
// Three sources (system/meshRockDict, keyword `geometry`):
//   disc       a Brazilian disc (diameter, thickness), axis along y, loaded along z;
//   stl        a user's scan: read, checked for watertightness, transformed; the
//              Voronoi mesher fills its convex hull (reported: hull/scan volume);
//   generated  a random irregular convex rock of given volume and shape ratios.
// Plates are horizontal (normal z) and gravity is −z in every rockfrac case.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/convexHull.hpp"
#include "geometry/triSurface.hpp"

namespace rockfrac {

class Dictionary;

struct Specimen {
    enum class Kind { disc, convexHull };
    Kind kind = Kind::disc;
    std::string source;  // "disc", "stl" or "generated"

    TriSurface surface;              // what the meshes fill (disc facets or convex hull)
    std::optional<TriSurface> scan;  // the user's scan itself (stl only)
    MassProperties properties;       // of the filled solid (exact cylinder for a disc)

    // disc
    double diameter = 0.0, thickness = 0.0;
    Vec3 centre;
    // convexHull
    std::vector<HalfSpace> planes;
    double hullToScanVolume = 1.0;  // stl only
    int droppedTriangles = 0;       // stl only: collapsed (zero-area) triangles removed

    double equivalentDiameter() const;  // (6V/π)^(1/3)
};

// Build from system/meshRockDict. `caseDir` resolves relative file names.
Specimen buildSpecimen(const Dictionary& meshRockDict, const std::filesystem::path& caseDir);
// The top-level entries of system/meshRockDict (buildSpecimen).
const std::vector<std::string>& meshRockDictEntries();

// constant/geometryProperties
void writeSpecimen(const std::filesystem::path& caseDir, const Specimen& specimen);
Specimen readSpecimen(const std::filesystem::path& caseDir);

}  // namespace rockfrac
