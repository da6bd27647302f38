// meshRock: the specimen of a case, as a watertight surface and (on request) a
// tetrahedral mesh for feFractureSolver.
//
// Reads  system/meshRockDict            (geometry disc | stl | generated)
//        system/feMeshDict              (optional: tetrahedral mesh via gmsh)
// Writes constant/triSurface/specimen.stl   the solid the meshes fill
//        constant/triSurface/scan.stl       the user's scan, transformed (stl only)
//        constant/geometryProperties        volume, centroid, inertia, extents, hull planes
//        constant/feMesh/specimen.msh       tetrahedra (with feMeshDict)
//        VTK/specimen.vtp, VTK/feMesh.vtu   for ParaView
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "core/application.hpp"
#include "core/dictionary.hpp"
#include "core/knownEntries.hpp"
#include "core/memoryLimit.hpp"
#include "geometry/specimen.hpp"
#include "geometry/tetMesher.hpp"
#include "io/vtkOutput.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

namespace {

const AppInfo info{
    "meshRock",
    "Makes the specimen of a case from system/meshRockDict: a Brazilian disc, a user's STL scan\n"
    "(checked for holes, transformed, placed on the lower plate; its convex hull is what the\n"
    "Voronoi mesher fills) or a generated irregular rock of given volume and shape. Writes the\n"
    "surface, its mass properties, and, when system/feMeshDict exists, a tetrahedral mesh.",
    "[options]",
    {"meshRock -case tutorials/BDT/granite", "meshRock -case tutorials/SPB/granite/rock1 -dry-run"},
    {},
};

void report(const Specimen& s)
{
    const auto& p = s.properties;
    std::printf("Specimen: %s, volume %.6g m^3 (d_eq %.4g mm)\n", s.source.c_str(), p.volume,
                1e3 * s.equivalentDiameter());
    std::printf("  centroid (%.4g %.4g %.4g) m, principal extents %.4g x %.4g x %.4g mm\n", p.centroid.x,
                p.centroid.y, p.centroid.z, 1e3 * p.principalExtents.x, 1e3 * p.principalExtents.y,
                1e3 * p.principalExtents.z);
    std::printf("  principal second moments of volume (%.4g %.4g %.4g) m^5\n", p.principalMoments.x,
                p.principalMoments.y, p.principalMoments.z);
    if (s.kind == Specimen::Kind::convexHull)
        std::printf("  convex hull: %zu planes, %zu triangles%s\n", s.planes.size(),
                    s.surface.triangles.size(), s.scan ? "" : "");
    if (s.scan) std::printf("  hull/scan volume ratio %.4f\n", s.hullToScanVolume);
    if (s.scan && s.droppedTriangles > 0)
        std::printf(
            "Warning: %d zero-area triangles of the scan (two of their corners the same point) were "
            "dropped; the surface is closed without them\n",
            s.droppedTriangles);
    // Both solvers fill the convex hull (the paper's way): a concave scan gains volume.
    if (s.scan && s.hullToScanVolume > 1.05)
        std::printf(
            "Warning: the convex hull (%.4g mm^3) is %.1f %% larger than the scan (%.4g mm^3): both solvers "
            "mesh "
            "the hull, so this rock's concave parts are filled (cells that follow a concave surface are not "
            "available yet)\n",
            1e9 * s.properties.volume, 100.0 * (s.hullToScanVolume - 1.0),
            1e9 * s.properties.volume / s.hullToScanVolume);
}

TetMeshRequest readTetRequest(const Dictionary& d)
{
    checkKnownEntries(d, feMeshDictEntries());
    checkKnownSubEntries(d, "contactRefinement", {"elementSize", "distance"});
    TetMeshRequest r;
    if (d.found("elementSize")) r.elementSize = d.getScalar("elementSize", Bounds::positive());
    if (d.found("elementCount")) {
        const double count = d.getScalar("elementCount", Bounds::closed(1, 2e9));
        if (count != std::floor(count))
            throw UserError(d.location("elementCount").str() + ": elementCount must be a whole number (got " +
                            formatNumber(count) + ")");
        r.elementCount = static_cast<int>(count);
    }
    if (r.elementSize > 0 && r.elementCount > 0)
        throw UserError(d.fileName() + ": give either 'elementSize' or 'elementCount', not both");
    if (!(r.elementSize > 0) && r.elementCount <= 0)
        throw UserError(d.fileName() + ": missing 'elementSize' [m] or 'elementCount' (> 0)");
    r.optimise = d.getOrDefault<int>("optimise", 1);
    if (d.found("contactRefinement")) {
        // Finer elements under the plates: both entries required (no silent size).
        const Dictionary& c = d.subDict("contactRefinement");
        r.contactSize = c.getScalar("elementSize", Bounds::positive());
        r.contactDistance = c.getScalar("distance", Bounds::positive());
        if (!(r.elementSize > 0))
            throw UserError(d.fileName() +
                            ": 'contactRefinement' needs 'elementSize' [m], not 'elementCount'");
        if (!(r.contactSize < r.elementSize))
            throw UserError(d.fileName() + ": contactRefinement/elementSize must be below elementSize (" +
                            std::to_string(r.elementSize) + " m): it is the finer size under the plates");
    }
    return r;
}

void makeTetMesh(const Application& app, const Specimen& s, const TetMeshRequest& request)
{
    const fs::path msh = app.path("constant/feMesh/specimen.msh");
    const TetMeshingResult mesh = s.kind == Specimen::Kind::disc
                                      ? meshDiscWithGmsh(s.diameter, s.thickness, s.centre, request, msh)
                                      : meshSurfaceWithGmsh(s.surface, request, msh);
    std::vector<double> quality;
    quality.reserve(mesh.tets.size());
    for (const auto& t : mesh.tets)
        quality.push_back(tetQuality(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]));
    writeTetsVtu(app.path("VTK/feMesh.vtu"), mesh.nodes, mesh.tets, {Field::scalar("quality", quality)}, {},
                 0.0);
    std::printf("Tetrahedral mesh: %zu tets, %zu nodes, element size %.3g mm\n", mesh.tets.size(),
                mesh.nodes.size(), 1e3 * mesh.elementSize);
    if (request.contactSize > 0)
        std::printf(
            "  contact refinement: %.3g mm within %.3g mm of the lowest and highest points along z,\n"
            "  graded to %.3g mm over another %.3g mm\n",
            1e3 * request.contactSize, 1e3 * request.contactDistance, 1e3 * mesh.elementSize,
            1e3 * request.contactDistance);
    std::printf("  volume %.6g m^3, error %+.3f %% of the solid; quality min %.3f mean %.3f\n", mesh.volume,
                100 * mesh.relativeVolumeError(), mesh.minQuality, mesh.meanQuality);
    std::printf("  written to %s\n", msh.string().c_str());
}

// The surface (and the scan) are made by now; the tetrahedra's count follows from the
// specimen's volume and the element size. Measured peaks (docs/reliability.md): a disc of 512
// triangles 62 MB, of 400 000 triangles 88 MB (the code and libraries: CGAL, VTK); with gmsh,
// 2 900 tetrahedra 90 MB, 13 305 91 MB, 100 281 119 MB (1.2 kB each beyond the libraries).
// Returns the -dry-run line (core/memoryLimit.hpp: estimateLine).
std::string checkMeshRockMemory(const Specimen& specimen, const std::optional<TetMeshRequest>& tetRequest)
{
    const double triangles = static_cast<double>(specimen.surface.triangles.size()) +
                             (specimen.scan ? static_cast<double>(specimen.scan->triangles.size()) : 0.0);
    double bytes = 80e6 + 150.0 * triangles;
    std::string counts = std::to_string(static_cast<std::uint64_t>(triangles)) + " surface triangles";
    if (tetRequest) {
        // A regular tetrahedron of edge a has volume a^3 / (6 sqrt 2).
        const double tets = tetRequest->elementCount > 0 ? tetRequest->elementCount
                                                         : specimen.properties.volume * 6.0 * std::sqrt(2.0) /
                                                               std::pow(tetRequest->elementSize, 3);
        bytes += 25e6 + std::min(tets, 1e15) * 1500.0;  // gmsh loaded, and each tetrahedron
        counts += ", about " + formatNumber(std::round(tets)) + " tetrahedra";
        checkMemoryFits(static_cast<std::uint64_t>(bytes),
                        "system/feMeshDict: about " + formatNumber(std::round(tets)) + " tetrahedra",
                        "raise elementSize (or lower elementCount) in system/feMeshDict");
    } else {
        checkMemoryFits(static_cast<std::uint64_t>(bytes), "system/meshRockDict: " + counts,
                        "use a coarser surface (fewer facets)");
    }
    return estimateLine(static_cast<std::uint64_t>(bytes), counts);
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, [](Application& app) {
        const Dictionary dict = Dictionary::readFile(app.path("system/meshRockDict"));
        const Specimen specimen = buildSpecimen(dict, app.casePath());
        std::optional<TetMeshRequest> tetRequest;
        if (fs::exists(app.path("system/feMeshDict")))
            tetRequest = readTetRequest(Dictionary::readFile(app.path("system/feMeshDict")));
        const std::string estimate = checkMeshRockMemory(specimen, tetRequest);
        report(specimen);
        if (app.dryRun()) {
            std::printf("%s\n", estimate.c_str());
            std::printf("Dry run: inputs are valid, nothing written.\n");
            return 0;
        }
        writeStl(app.path("constant/triSurface/specimen.stl"), specimen.surface, "specimen");
        if (specimen.scan) writeStl(app.path("constant/triSurface/scan.stl"), *specimen.scan, "scan");
        writeSpecimen(app.casePath(), specimen);
        writeTrianglesVtp(app.path("VTK/specimen.vtp"), specimen.surface.points, specimen.surface.triangles,
                          0.0);
        if (tetRequest) makeTetMesh(app, specimen, *tetRequest);
        std::printf("End: specimen written to %s\n", app.path("constant").string().c_str());
        return 0;
    });
}
