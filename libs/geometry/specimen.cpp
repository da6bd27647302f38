#include "geometry/specimen.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/atomicFile.hpp"
#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/knownEntries.hpp"
#include "core/selector.hpp"
#include "geometry/surfaceTopology.hpp"
#include "io/foamFile.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

double Specimen::equivalentDiameter() const
{
    return std::cbrt(6.0 * properties.volume / M_PI);
}

namespace {

// Where plane `index` of the convexHull's `planes` list starts (its opening parenthesis),
// or the entry's location when the list is not written as nested parentheses.
SourceLocation planeLocation(const Dictionary& hull, std::size_t index)
{
    int depth = 0;
    std::size_t seen = 0;
    for (const Token& t : hull.tokens("planes")) {
        if (t.isPunctuation(')')) --depth;
        if (!t.isPunctuation('(')) continue;
        if (++depth == 2 && seen++ == index) return t.where;
    }
    return hull.location("planes");
}

// A hull plane n.x <= c must keep the specimen's centroid inside: a plane with the centroid
// on its outer side has its normal pointing into the rock, which leaves nothing to mesh.
void checkPlaneFacesOutward(const Dictionary& hull, std::size_t index, const HalfSpace& plane,
                            const Vec3& centroid)
{
    if (dot(plane.normal, centroid) < plane.offset) return;
    throw UserError(planeLocation(hull, index).str() + ": convexHull/planes: plane " + std::to_string(index) +
                    " has the specimen's centroid on its outer side, so its normal points into the rock and "
                    "the hull is empty; flip its normal (negate all four values nx ny nz c) or run meshRock "
                    "again to remake the specimen");
}

// Total area of the triangles.
double surfaceArea(const TriSurface& s)
{
    double area = 0;
    for (const auto& t : s.triangles)
        area += 0.5 * norm(cross(s.points[t[1]] - s.points[t[0]], s.points[t[2]] - s.points[t[0]]));
    return area;
}

// Exact mass properties of a solid cylinder with its axis along y.
MassProperties discProperties(double diameter, double thickness, const Vec3& centre)
{
    const double r = 0.5 * diameter, t = thickness;
    MassProperties p;
    p.volume = M_PI * r * r * t;
    p.centroid = centre;
    const double axial = 0.5 * p.volume * r * r;                      // about y
    const double transverse = p.volume * (3 * r * r + t * t) / 12.0;  // about x and z
    p.inertia(0, 0) = transverse;
    p.inertia(1, 1) = axial;
    p.inertia(2, 2) = transverse;
    symmetricEigen(p.inertia, p.principalMoments, p.principalAxes);
    p.boundsMin = centre - Vec3{r, 0.5 * t, r};
    p.boundsMax = centre + Vec3{r, 0.5 * t, r};
    p.principalExtents = {diameter, diameter, t};
    return p;
}

// Rest a rock as it lies on a plate under gravity, in its most stable position:
// on the hull facet nearest to the centroid. For a convex body that facet always
// holds the centroid's foot point, so the rock is in equilibrium on it and has
// its lowest centre of mass there (a rock set down by hand in a single particle
// breakage test settles the same way). Its outward normal becomes -z; in the
// plate plane the longest principal direction is turned onto x.
Mat3 restingRotation(const TriSurface& surface, const MassProperties& props)
{
    const std::vector<HalfSpace> planes = convexHull(surface.points).planes;
    const HalfSpace* base = &planes.front();
    for (const auto& p : planes)
        if (-p.signedDistance(props.centroid) < -base->signedDistance(props.centroid)) base = &p;
    const Vec3 ez = -1.0 * base->normal;
    // Principal moments ascending: the axis of the smallest moment is the longest
    // direction of the body; if it stands on the base, the next one.
    Vec3 ex;
    for (int j = 0; j < 3; ++j) {
        const Vec3 a{props.principalAxes(0, j), props.principalAxes(1, j), props.principalAxes(2, j)};
        ex = a - dot(a, ez) * ez;
        if (norm(ex) > 0.3) break;
    }
    ex = normalised(ex);
    const Vec3 ey = cross(ez, ex);
    Mat3 R;
    const Vec3 rows[3] = {ex, ey, ez};
    for (int i = 0; i < 3; ++i) {
        R(i, 0) = rows[i].x;
        R(i, 1) = rows[i].y;
        R(i, 2) = rows[i].z;
    }
    return R;
}

void placeOnPlate(TriSurface& surface, std::optional<TriSurface>& scan)
{
    // The hull's centroid, not a scan's: both solvers fill the convex hull (as the paper did),
    // so the hull is the body that has to rest in equilibrium.
    const MassProperties props = massProperties(surface);
    const Mat3 R = restingRotation(surface, props);
    transformSurface(surface, 1.0, R, -(R * props.centroid));
    if (scan) transformSurface(*scan, 1.0, R, -(R * props.centroid));
    double zMin = 1e300;
    for (const auto& p : surface.points) zMin = std::min(zMin, p.z);
    const Vec3 lift{0, 0, -zMin};
    transformSurface(surface, 1.0, Mat3::identity(), lift);
    if (scan) transformSurface(*scan, 1.0, Mat3::identity(), lift);
}

Specimen fromHull(ConvexHull hull, const std::string& source)
{
    Specimen s;
    s.kind = Specimen::Kind::convexHull;
    s.source = source;
    s.surface = std::move(hull.surface);
    s.planes = std::move(hull.planes);
    return s;
}

// Recompute the hull planes and properties after the surface has moved.
void finishHull(Specimen& s)
{
    s.planes = convexHull(s.surface.points).planes;
    s.properties = massProperties(s.surface);
}

Specimen buildDisc(const Dictionary& d)
{
    requireKnownEntries(d, {"diameter", "thickness", "centre", "nSegments"});
    Specimen s;
    s.kind = Specimen::Kind::disc;
    s.source = "disc";
    // A dimension set is optional, but checked when given ([kg] 44.8e-3 is refused).
    static const Dimensions metre = Dimensions::fromUnits("m");
    s.diameter = d.getScalar("diameter", Bounds::positive(), &metre);
    s.thickness = d.getScalar("thickness", Bounds::positive(), &metre);
    s.centre = d.getOrDefault<Vec3>("centre", Vec3{});
    const int nSegments = d.getOrDefault<int>("nSegments", 128);
    if (nSegments < 8)
        throw UserError(d.fileName() + ": disc/nSegments = " + std::to_string(nSegments) +
                        " is too coarse; expected at least 8 facets around the disc");
    if (nSegments > 100000)
        throw UserError(d.location("nSegments").str() + ": disc/nSegments = " + std::to_string(nSegments) +
                        " facets is more than the 100000 a display surface needs (the Voronoi mesher fills "
                        "the exact cylinder); use 128 to 1024");
    s.surface = discSurface(s.diameter, s.thickness, s.centre, nSegments);
    s.properties = discProperties(s.diameter, s.thickness, s.centre);
    return s;
}

// A scan must be closed; an open one whose vertices nearly coincide was exported unwelded.
void checkClosed(const TriSurface& scan, const fs::path& file)
{
    const SurfaceCheck check = checkSurface(scan);
    if (check.watertight()) return;
    Vec3 lo = scan.points.empty() ? Vec3{} : scan.points[0], hi = lo;
    for (const Vec3& p : scan.points)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    const double gap = 1e-6 * norm(hi - lo);
    const int close = check.boundaryEdges > 0 ? nearDuplicateVertices(scan, gap) : 0;
    char hint[240] = "";
    if (close > 0)
        std::snprintf(hint, sizeof(hint),
                      "; %d vertices lie within %.3g (in the file's units) of another one without being "
                      "the same point: merge close vertices (MeshLab's Merge Close Vertices)",
                      close, gap);
    throw UserError(file.string() + ": the scan is not a closed surface (" + check.reason() + hint +
                    "); repair it (e.g. close holes in MeshLab) and export it again");
}

// Zero-area triangles of three distinct points in a line cannot be dropped.
void checkNoNeedles(const TriSurface& scan, const fs::path& file)
{
    const std::vector<int> needles = needleTriangles(scan);
    if (needles.empty()) return;
    const auto& t = scan.triangles[needles[0]];
    const Vec3 at = (scan.points[t[0]] + scan.points[t[1]] + scan.points[t[2]]) / 3.0;
    char where[200];
    std::snprintf(where, sizeof(where),
                  "%zu triangles of zero area with three vertices on a line, e.g. %d near (%.6g %.6g %.6g)",
                  needles.size(), needles[0], at.x, at.y, at.z);
    throw UserError(file.string() + ": the scan has degenerate triangles (" + where +
                    ", in the file's units): remove them (e.g. MeshLab's Remove Zero Area Faces, or "
                    "Remove Duplicate Vertices and Faces) and export it again");
}

// A closed scan must be one shell...
void checkOneShell(const TriSurface& scan, const fs::path& file)
{
    const std::vector<std::vector<int>> shells = surfaceShells(scan);
    if (shells.size() > 1)
        throw UserError(file.string() + ": the scan has " + std::to_string(shells.size()) +
                        " separate closed surfaces (shells: " + std::to_string(shells[0].size()) +
                        " triangles, " + std::to_string(shells[1].size()) +
                        (shells.size() > 2 ? ", ..." : "") +
                        "); a specimen is one rock: keep its shell only (e.g. MeshLab's Remove Isolated "
                        "pieces) and export it again");
}

// ... that does not cross itself (a scan enclosing a volume; in metres, placed).
void checkNotCrossing(const TriSurface& scan, const fs::path& file)
{
    const std::vector<std::array<int, 2>> crossing = selfIntersections(scan, 10);
    if (crossing.empty()) return;
    const auto& t = scan.triangles[crossing[0][0]];
    const Vec3 at = (scan.points[t[0]] + scan.points[t[1]] + scan.points[t[2]]) / 3.0;
    char where[160];
    std::snprintf(where, sizeof(where), "triangles %d and %d intersect near (%.6g %.6g %.6g) m",
                  crossing[0][0], crossing[0][1], at.x, at.y, at.z);
    throw UserError(file.string() + ": the scan crosses itself (" + where +
                    (crossing.size() > 1 ? "; at least " + std::to_string(crossing.size()) + " pairs" : "") +
                    "): its inside is not defined; repair the self-intersections (e.g. MeshLab's Select "
                    "self intersecting faces, then remove and close) and export it again");
}

Specimen buildFromStl(const Dictionary& d, const fs::path& caseDir)
{
    requireKnownEntries(d, {"file", "scale", "rotate", "translate", "placeOnPlate"});
    const std::string fileName = d.get<std::string>("file");
    const fs::path file = fs::path(fileName).is_absolute() ? fs::path(fileName) : caseDir / fileName;
    TriSurface scan = readStl(file);
    const int collapsed = dropCollapsedTriangles(scan);
    checkClosed(scan, file);
    checkOneShell(scan, file);
    checkNoNeedles(scan, file);
    const double scale = d.getScalarOrDefault("scale", 1.0, Bounds::positive());
    const Mat3 rotation = rotationFromDegrees(d.getOrDefault<Vec3>("rotate", Vec3{}));
    const Vec3 translation = d.getOrDefault<Vec3>("translate", Vec3{});
    transformSurface(scan, scale, rotation, translation);
    const double scanVolume = massProperties(scan).volume;
    // A closed surface of area A encloses at most A^1.5 / (6 sqrt(pi)) (a sphere): one that
    // encloses next to nothing is flat, whichever way its triangles face.
    if (!(std::abs(scanVolume) > 1e-9 * std::pow(surfaceArea(scan), 1.5)))
        throw UserError(file.string() +
                        ": the scan is flat: it encloses no volume (its triangles lie in one plane, or a "
                        "sheet covers itself on both sides); export the rock as a closed solid");
    if (!(scanVolume > 0))
        throw UserError(file.string() +
                        ": the scan encloses a negative volume (inward-facing triangles); "
                        "flip its normals and export it again");
    checkNotCrossing(scan, file);
    Specimen s = fromHull(convexHull(scan.points), "stl");
    s.scan = std::move(scan);
    if (d.getOrDefault<bool>("placeOnPlate", false)) placeOnPlate(s.surface, s.scan);
    finishHull(s);
    s.hullToScanVolume = s.properties.volume / scanVolume;
    s.droppedTriangles = collapsed;
    return s;
}

Specimen buildGenerated(const Dictionary& d)
{
    requireKnownEntries(
        d, {"volume", "elongation", "flatness", "roughness", "nPoints", "roundness", "seed", "placeOnPlate"});
    RockShape shape;
    shape.volume = d.getScalar("volume", Bounds::positive());
    shape.elongation = d.getScalarOrDefault("elongation", shape.elongation, Bounds::open(0, 1.000001));
    shape.flatness = d.getScalarOrDefault("flatness", shape.flatness, Bounds::open(0, 1.000001));
    shape.roughness = d.getScalarOrDefault("roughness", shape.roughness, Bounds::closedOpen(0, 1));
    shape.nPoints = d.getOrDefault<int>("nPoints", shape.nPoints);
    shape.roundness = d.getScalarOrDefault("roundness", shape.roundness, Bounds::closedOpen(0, 0.9));
    shape.seed = d.get<std::uint64_t>("seed");
    Specimen s = fromHull(generateRock(shape), "generated");
    std::optional<TriSurface> noScan;
    if (d.getOrDefault<bool>("placeOnPlate", true)) placeOnPlate(s.surface, noScan);
    finishHull(s);
    return s;
}

}  // namespace

const std::vector<std::string>& meshRockDictEntries()
{
    // The blocks of the kinds not selected may stay (a case switches by `geometry`).
    static const std::vector<std::string> entries = {"geometry", "disc", "stl", "generated"};
    return entries;
}

Specimen buildSpecimen(const Dictionary& dict, const fs::path& caseDir)
{
    checkKnownEntries(dict, meshRockDictEntries());
    const std::string kind = dict.getWord("geometry", {"disc", "stl", "generated"});
    if (kind == "disc") return buildDisc(dict.subDict("disc"));
    if (kind == "stl") return buildFromStl(dict.subDict("stl"), caseDir);
    return buildGenerated(dict.subDict("generated"));
}

void writeSpecimen(const fs::path& caseDir, const Specimen& s)
{
    writeFileAtomically(caseDir / "constant" / "geometryProperties", [&](std::ostream& out) {
        out << foamFileHeader("geometryProperties", "The specimen made by meshRock (SI units).");
        out << entryLine("type", s.kind == Specimen::Kind::disc ? "disc" : "convexHull");
        out << entryLine("source", s.source);
        out << entryLine("surface", "\"constant/triSurface/specimen.stl\"");
        out << entryLine("volume", numberText(s.properties.volume));
        out << entryLine("equivalentDiameter", numberText(s.equivalentDiameter()));
        out << entryLine("centroid", vectorText(s.properties.centroid));
        out << "// second moment of volume about the centroid [m^5]; times density = inertia\n";
        out << entryLine("inertia", tensorText(s.properties.inertia));
        out << entryLine("principalExtents", vectorText(s.properties.principalExtents));
        out << entryLine("boundsMin", vectorText(s.properties.boundsMin));
        out << entryLine("boundsMax", vectorText(s.properties.boundsMax));
        if (s.kind == Specimen::Kind::disc) {
            out << "\ndisc\n{\n";
            out << entryLine("diameter", numberText(s.diameter), 1);
            out << entryLine("thickness", numberText(s.thickness), 1);
            out << entryLine("centre", vectorText(s.centre), 1);
            out << entryLine("axis", "(0 1 0)", 1);
            out << "}\n";
        } else {
            out << "\nconvexHull\n{\n";
            out << entryLine("hullToScanVolume", numberText(s.hullToScanVolume), 1);
            out << "    // half-spaces n.x <= c as (nx ny nz c)\n    planes " << s.planes.size()
                << "\n    (\n";
            for (const auto& p : s.planes)
                out << "        (" << numberText(p.normal.x) << " " << numberText(p.normal.y) << " "
                    << numberText(p.normal.z) << " " << numberText(p.offset) << ")\n";
            out << "    );\n}\n";
        }
    });
}

Specimen readSpecimen(const fs::path& caseDir)
{
    const fs::path file = caseDir / "constant" / "geometryProperties";
    if (!fs::exists(file))
        throw UserError("missing " + file.string() + "; run meshRock first to make the specimen");
    const Dictionary d = Dictionary::readFile(file);
    Specimen s;
    const std::string type = d.getWord("type", {"disc", "convexHull"});
    s.source = d.getOrDefault<std::string>("source", type);
    s.properties.volume = d.getScalar("volume", Bounds::positive());
    s.properties.centroid = d.get<Vec3>("centroid");
    const auto inertia = d.get<std::vector<double>>("inertia");
    if (inertia.size() != 9) throw UserError(file.string() + ": 'inertia' needs 9 values");
    for (int k = 0; k < 9; ++k) s.properties.inertia(k / 3, k % 3) = inertia[k];
    symmetricEigen(s.properties.inertia, s.properties.principalMoments, s.properties.principalAxes);
    s.properties.principalExtents = d.get<Vec3>("principalExtents");
    s.properties.boundsMin = d.get<Vec3>("boundsMin");
    s.properties.boundsMax = d.get<Vec3>("boundsMax");
    if (type == "disc") {
        s.kind = Specimen::Kind::disc;
        const Dictionary& disc = d.subDict("disc");
        s.diameter = disc.getScalar("diameter", Bounds::positive());
        s.thickness = disc.getScalar("thickness", Bounds::positive());
        s.centre = disc.get<Vec3>("centre");
    } else {
        s.kind = Specimen::Kind::convexHull;
        const Dictionary& hull = d.subDict("convexHull");
        s.hullToScanVolume = hull.getOrDefault<double>("hullToScanVolume", 1.0);
        for (const auto& row : hull.get<std::vector<std::vector<double>>>("planes")) {
            if (row.size() != 4) throw UserError(file.string() + ": each plane needs 4 values (nx ny nz c)");
            const Vec3 normal{row[0], row[1], row[2]};
            if (!(norm(normal) > 0) || !std::isfinite(norm(normal)) || !std::isfinite(row[3]))
                throw UserError(
                    hull.location("planes").str() + ": convexHull/planes: plane " +
                    std::to_string(s.planes.size()) +
                    " has a zero or non-finite normal; run meshRock again to remake the specimen");
            s.planes.push_back({normalised(normal), row[3]});
            checkPlaneFacesOutward(hull, s.planes.size() - 1, s.planes.back(), s.properties.centroid);
        }
        if (s.planes.size() < 4) throw UserError(file.string() + ": a convex hull needs at least 4 planes");
    }
    const fs::path surfaceFile = caseDir / "constant" / "triSurface" / "specimen.stl";
    if (fs::exists(surfaceFile)) s.surface = readStl(surfaceFile);
    return s;
}

}  // namespace rockfrac
