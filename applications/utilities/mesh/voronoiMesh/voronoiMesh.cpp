// voronoiMesh: fill the specimen with bonded Voronoi cells.
//
// Reads  constant/geometryProperties    (meshRock: disc or convex hull)
//        system/voronoiMeshDict         (nCells or mesoConstant, pruningDistance, seed, sizeField)
// Writes constant/voronoiMesh/          cells, faces and bonds (docs/file-formats.md)
//        VTK/voronoiMesh.vtu            cells (id, volume, neighbours) for ParaView
//        VTK/bonds.vtp                  one line per bond, along the face normal
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "core/application.hpp"
#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/knownEntries.hpp"
#include "core/memoryLimit.hpp"
#include "geometry/specimen.hpp"
#include "io/vtkOutput.hpp"
#include "voronoi/seeding.hpp"
#include "voronoi/tessellation.hpp"
#include "voronoi/voronoiMeshIO.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

namespace {

const AppInfo info{
    "voronoiMesh",
    "Fills the specimen made by meshRock with Voronoi cells bonded at their face vertices:\n"
    "nCells seeds (or V/mesoConstant) placed at random no closer than the pruning distance,\n"
    "tessellated by Voro++ and clipped to the disc or the rock's convex hull; one bond per\n"
    "vertex of every internal face, carrying A/n of the face area.",
    "[options]",
    {"voronoiMesh -case tutorials/BDT/granite", "voronoiMesh -case tutorials/SPB/granite/rock1 -dry-run"},
    {},
};

struct MeshRequest {
    int nCells = 0;
    double pruningDistance = 0;
    std::uint64_t seed = 0;
    double dilationFraction = 0.1;
    CellOrder order = CellOrder::seeding;
    std::optional<SizeField> sizeField;  // graded meshes: nCells is then the graded count
    int baseCells = 0;                   // nCells of the base size (the uniform request)
};

// The optional graded size field: its base size is that of the uniform request (V / nCells or
// mesoConstant), its smallest allowed size a few dilation radii of the base cells.
void readSizeFieldRequest(const Dictionary& d, const Domain& domain, MeshRequest& r)
{
    r.baseCells = r.nCells;
    if (!d.found("sizeField")) return;
    const double baseVolume = domain.volume() / r.nCells;
    const double baseSize = equivalentDiameter(baseVolume);
    r.sizeField =
        readSizeField(d.subDict("sizeField"), baseSize,
                      smallestSizeInDilationRadii * r.dilationFraction * baseSize, domain.boundingBox());
    r.nCells = gradedCellCount(domain, *r.sizeField, baseVolume);
}

MeshRequest readRequest(const Dictionary& d, const Domain& domain)
{
    const double domainVolume = domain.volume();
    checkKnownEntries(d, voronoiMeshDictEntries());
    MeshRequest r;
    if (d.found("nCells") == d.found("mesoConstant"))
        throw UserError(d.fileName() + ": give exactly one of 'nCells' (a count) or 'mesoConstant' " +
                        "(volume per cell [m^3], e.g. 2.2e-7)");
    if (d.found("nCells")) {
        r.nCells = d.get<int>("nCells");
    } else {
        const double meso = d.getScalar("mesoConstant", Bounds::positive());
        try {
            r.nCells = cellCountFromMesoConstant(domainVolume, meso);
        } catch (const UserError& e) {
            throw UserError(d.location("mesoConstant").str() + ": mesoConstant " + formatNumber(meso) +
                            " m^3 in " + formatNumber(domainVolume) + " m^3: " + e.what());
        }
    }
    if (r.nCells < 2)
        throw UserError(d.fileName() + ": " + std::to_string(r.nCells) +
                        " cell(s) requested; a bonded mesh needs at least 2 cells");
    r.pruningDistance = d.getScalar("pruningDistance", Bounds::nonNegative());
    r.seed = d.get<std::uint64_t>("seed");
    r.dilationFraction = d.getScalarOrDefault("dilationFraction", 0.1, Bounds::open(0, 0.5));
    // Optional: number the cells along a Morton curve (faster DEM steps on large meshes).
    if (d.found("cellOrder") && d.getWord("cellOrder", {"seeding", "morton"}) == "morton")
        r.order = CellOrder::morton;
    readSizeFieldRequest(d, domain, r);
    return r;
}

Domain domainOf(const Specimen& s, const fs::path& caseDir)
{
    if (s.kind == Specimen::Kind::disc) return Domain::disc(s.centre, {0, 1, 0}, s.diameter, s.thickness);
    try {
        return Domain::fromPlanes(s.planes);
    } catch (const UserError& e) {  // the planes are those of geometryProperties
        throw UserError((caseDir / "constant/geometryProperties").string() +
                        ": convexHull/planes: " + e.what() + "; run meshRock again to remake the specimen");
    }
}

// The hull planes must enclose the volume meshRock recorded beside them: a plane changed by
// hand (moved, or its normal negated without its offset) would mesh another rock, silently.
void checkHullVolume(const Specimen& s, const Domain& domain, const fs::path& caseDir)
{
    if (s.kind != Specimen::Kind::convexHull) return;
    const double recorded = s.properties.volume;
    if (std::abs(domain.volume() - recorded) <= 1e-6 * recorded) return;
    throw UserError(
        (caseDir / "constant/geometryProperties").string() + ": the convexHull planes enclose " +
        formatNumber(domain.volume()) + " m^3, but its 'volume' is " + formatNumber(recorded) +
        " m^3: the planes (or the volume) were changed after meshRock wrote them; run meshRock again");
}

// The graded mesh in the log: a histogram of the cell sizes (volume-equivalent diameters) and,
// per region, the cells whose seed lies where the field is finer than the base.
void reportSizes(const VoronoiMesh& mesh, const SizeField& field)
{
    const double base = field.baseSize;
    constexpr int bins = 12;  // of base / 8 each, the last open-ended
    int count[bins] = {};
    for (double v : mesh.volumes)
        ++count[std::min(bins - 1, static_cast<int>(equivalentDiameter(v) / (base / 8.0)))];
    std::printf("Cell size histogram (volume-equivalent diameter, base size %.4g mm):\n", 1e3 * base);
    for (int b = 0; b < bins; ++b) {
        const int bar = static_cast<int>(std::lround(60.0 * count[b] / mesh.nCells()));
        char upper[32] = "";
        if (b + 1 < bins) std::snprintf(upper, sizeof upper, "%.3g", 1e3 * (b + 1) * base / 8);
        std::printf("  %6.3g-%-6s mm %6d %s\n", 1e3 * b * base / 8, upper, count[b],
                    std::string(bar, '#').c_str());
    }
    for (const SizeRegion& r : field.regions) {
        const double width = field.gradedWidth(r);
        int n = 0, nFinest = 0;
        double sum = 0, sumFinest = 0;
        for (int c = 0; c < mesh.nCells(); ++c) {
            const double d = r.distance(mesh.seeds[c]);
            if (d >= width) continue;
            ++n;
            sum += equivalentDiameter(mesh.volumes[c]);
            if (d < r.size) ++nFinest, sumFinest += equivalentDiameter(mesh.volumes[c]);
        }
        std::printf(
            "Graded region %s: size %.4g mm, back to the base within %.4g mm (grading %.3g): %d cells, "
            "mean size %.4g mm; %d within %.4g mm, mean size %.4g mm\n",
            r.name.c_str(), 1e3 * r.size, 1e3 * width, field.grading, n, n ? 1e3 * sum / n : 0.0, nFinest,
            1e3 * r.size, nFinest ? 1e3 * sumFinest / nFinest : 0.0);
    }
}

void writeVtk(const Application& app, const VoronoiMesh& mesh, const SizeField* field)
{
    // Cells: every cell lists its own vertices (cells do not share points).
    PolyhedronSet cells;
    cells.points = mesh.vertices;
    cells.cellFaceOffset = mesh.cellFaceOffset;
    cells.faceVertexOffset = mesh.faceVertexOffset;
    cells.faceVertices = mesh.globalFaceVertices();
    std::vector<double> neighbours(mesh.nCells());
    std::vector<int> ids(mesh.nCells());
    for (int c = 0; c < mesh.nCells(); ++c) {
        ids[c] = c;
        for (int f = mesh.cellFaceOffset[c]; f < mesh.cellFaceOffset[c + 1]; ++f)
            if (mesh.faceNeighbour[f] >= 0) neighbours[c] += 1;
    }
    std::vector<Field> fields = {Field::integer("cellId", ids), Field::scalar("volume", mesh.volumes),
                                 Field::scalar("neighbours", neighbours)};
    std::vector<double> size(mesh.nCells()), target(mesh.nCells());
    if (field) {  // graded meshes only: a uniform mesh's file stays as it was
        for (int c = 0; c < mesh.nCells(); ++c) {
            size[c] = equivalentDiameter(mesh.volumes[c]);
            target[c] = field->size(mesh.seeds[c]);
        }
        fields.push_back(Field::scalar("size", size));
        fields.push_back(Field::scalar("targetSize", target));
    }
    writePolyhedraVtu(app.path("VTK/voronoiMesh.vtu"), cells, fields, 0.0);

    // Bonds: a segment through the bond point along the face normal, from the
    // plane of cell I's centroid to that of cell J's (length l_i + l_j).
    std::vector<Vec3> points;
    std::vector<std::array<int, 2>> lines;
    std::vector<double> area, length;
    for (const auto& b : mesh.bonds) {
        const int first = static_cast<int>(points.size());
        points.push_back(b.point - b.lI * b.normalI);
        points.push_back(b.point + b.lJ * b.normalI);
        lines.push_back({first, first + 1});
        area.push_back(b.area);
        length.push_back(b.lI + b.lJ);
    }
    writeLinesVtp(app.path("VTK/bonds.vtp"), points, lines,
                  {Field::scalar("area", area), Field::scalar("length", length)}, {}, 0.0);
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, [](Application& app) {
        const Specimen specimen = readSpecimen(app.casePath());
        const Dictionary dict = Dictionary::readFile(app.path("system/voronoiMeshDict"));
        const Domain domain = domainOf(specimen, app.casePath());
        checkHullVolume(specimen, domain, app.casePath());
        const MeshRequest request = readRequest(dict, domain);
        // Measured: 119 600 cells peak at 1.88 GB with the VTK output (15.7 kB per cell);
        // 300 cells at 23 MB (the code and libraries).
        const std::uint64_t estimate = 30000000u + static_cast<std::uint64_t>(request.nCells) * 16000u;
        const std::string cells = std::to_string(request.nCells) + " cells";
        checkMemoryFits(estimate, "system/voronoiMeshDict: " + cells,
                        "request fewer cells (nCells or a larger mesoConstant in system/voronoiMeshDict)");
        if (app.dryRun()) std::printf("%s\n", estimateLine(estimate, cells).c_str());
        const SizeField* field = request.sizeField ? &*request.sizeField : nullptr;
        if (field)
            std::printf(
                "Size field: base size %.4g mm (%d cells uniform), grading %.3g, %zu region(s), "
                "smallest %.4g mm: %d cells\n",
                1e3 * field->baseSize, request.baseCells, field->grading, field->regions.size(),
                1e3 * field->smallest(), request.nCells);
        std::printf("Seeding %d cells, pruning distance %.4g mm, seed %llu, domain volume %.6g m^3\n",
                    request.nCells, 1e3 * request.pruningDistance,
                    static_cast<unsigned long long>(request.seed), domain.volume());
        const VoronoiMesh mesh = [&] {
            try {
                return generateVoronoiMesh(domain, request.nCells, request.pruningDistance, request.seed,
                                           request.dilationFraction, request.order, field);
            } catch (const UserError& e) {  // the settings that cannot be met are in this file
                throw UserError(dict.fileName() + ": " + e.what());
            }
        }();
        double volume = 0;
        for (double v : mesh.volumes) volume += v;
        const double volumeError = (volume - domain.volume()) / domain.volume();
        std::printf(
            "voronoiMesh: %d cells, mean size %.4g mm, %d bonds, volume error %+.3g %%, "
            "meso constant %.4g m^3, dilation radius %.4g mm\n",
            mesh.nCells(), 1e3 * meanCellSize(mesh), mesh.nBonds(), 100 * volumeError, volume / mesh.nCells(),
            1e3 * mesh.dilationRadius);
        if (field) reportSizes(mesh, *field);
        if (app.dryRun()) {
            std::printf("Dry run: nothing written.\n");
            return 0;
        }
        writeVoronoiMesh(app.casePath(), mesh);
        writeVtk(app, mesh, field);
        std::printf("End: written constant/voronoiMesh, VTK/voronoiMesh.vtu, VTK/bonds.vtp\n");
        return 0;
    });
}
