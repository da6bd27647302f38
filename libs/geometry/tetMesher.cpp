#include "geometry/tetMesher.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "core/atomicFile.hpp"
#include "core/error.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

double tetQuality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
    const double volume = std::abs(dot(b - a, cross(c - a, d - a))) / 6.0;
    const double sumL2 =
        norm2(b - a) + norm2(c - a) + norm2(d - a) + norm2(c - b) + norm2(d - b) + norm2(d - c);
    return sumL2 > 0 ? 12.0 * std::pow(3.0 * volume, 2.0 / 3.0) / sumL2 : 0.0;
}

namespace {

// gmsh is a process-wide singleton: one session at a time, always finalised.
class GmshSession {
public:
    GmshSession()
    {
        mutex().lock();
        gmsh::initialize();
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.NumThreads", 1);  // reproducible meshes
        gmsh::model::add("rockfrac");
    }
    ~GmshSession()
    {
        gmsh::finalize();
        mutex().unlock();
    }
    GmshSession(const GmshSession&) = delete;
    GmshSession& operator=(const GmshSession&) = delete;

private:
    static std::mutex& mutex()
    {
        static std::mutex m;
        return m;
    }
};

double sizeForCount(double volume, int count)
{
    // A regular tetrahedron of edge h has volume h³/(6√2); gmsh meshes are
    // less regular, so this first guess is corrected once by the count obtained.
    return std::cbrt(6.0 * std::sqrt(2.0) * volume / count);
}

void setSize(double h, double smallestSize)
{
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0.5 * smallestSize);
    gmsh::option::setNumber("Mesh.MeshSizeMax", h);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
}

// The graded size of a contact-refined mesh at height z: the contact size up to `distance`
// from the lowest or highest point (where the plates touch), then linear to the global size
// over as much again. Only z counts, so the whole slab under each plate is fine: a rock's
// contact point is not known before it settles, a disc's contact line runs across it.
double contactGradedSize(double z, double zMin, double zMax, double h, const TetMeshRequest& request)
{
    const double fromPlate = std::min(z - zMin, zMax - z);
    const double ramp = std::clamp((fromPlate - request.contactDistance) / request.contactDistance, 0.0, 1.0);
    return request.contactSize + ramp * (h - request.contactSize);
}

void checkContactRefinement(const TetMeshRequest& request)
{
    if (request.contactSize == 0.0 && request.contactDistance == 0.0) return;
    if (!(request.elementSize > 0))
        throw UserError(
            "contact refinement needs 'elementSize' (not 'elementCount'): the graded mesh's count "
            "is not a size");
    if (!(request.contactSize > 0 && request.contactSize < request.elementSize))
        throw UserError("contact refinement: its element size must be > 0 and below the mesh's elementSize");
    if (!(request.contactDistance > 0)) throw UserError("contact refinement: its distance must be > 0");
}

// Extract nodes and linear tets of the current model, renumbered from 0.
TetMeshingResult extractMesh()
{
    TetMeshingResult result;
    std::vector<std::size_t> nodeTags;
    std::vector<double> coords, parametric;
    gmsh::model::mesh::getNodes(nodeTags, coords, parametric, -1, -1, false, false);
    std::map<std::size_t, int> index;
    for (std::size_t i = 0; i < nodeTags.size(); ++i) {
        index[nodeTags[i]] = static_cast<int>(i);
        result.nodes.push_back({coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]});
    }
    std::vector<std::size_t> elementTags, elementNodes;
    gmsh::model::mesh::getElementsByType(4, elementTags, elementNodes);  // 4 = 4-node tetrahedron
    double qualitySum = 0;
    result.minQuality = 1.0;
    for (std::size_t e = 0; e < elementTags.size(); ++e) {
        std::array<int, 4> t;
        for (int k = 0; k < 4; ++k) t[k] = index.at(elementNodes[4 * e + k]);
        const Vec3 &a = result.nodes[t[0]], &b = result.nodes[t[1]], &c = result.nodes[t[2]],
                   &d = result.nodes[t[3]];
        double v = dot(b - a, cross(c - a, d - a)) / 6.0;
        if (v < 0) {
            std::swap(t[2], t[3]);
            v = -v;
        }
        result.volume += v;
        const double q = tetQuality(a, b, c, d);
        qualitySum += q;
        result.minQuality = std::min(result.minQuality, q);
        result.tets.push_back(t);
    }
    result.meanQuality = result.tets.empty() ? 0 : qualitySum / result.tets.size();
    return result;
}

template <class BuildGeometry>
TetMeshingResult meshWithGmsh(double solidVolume, const TetMeshRequest& request, const fs::path& mshFile,
                              BuildGeometry build)
{
    if (!(request.elementSize > 0) && request.elementCount <= 0)
        throw UserError("a tetrahedral mesh needs 'elementSize' (> 0) or 'elementCount' (> 0)");
    checkContactRefinement(request);
    const bool contactRefined = request.contactSize > 0;
    double h =
        request.elementSize > 0 ? request.elementSize : sizeForCount(solidVolume, request.elementCount);
    TetMeshingResult result;
    const int passes = (request.elementSize > 0) ? 1 : 2;
    for (int pass = 0; pass < passes; ++pass) {
        GmshSession session;
        build();
        setSize(h, contactRefined ? request.contactSize : h);
        if (contactRefined) {
            double xMin, yMin, zMin, xMax, yMax, zMax;
            gmsh::model::getBoundingBox(-1, -1, xMin, yMin, zMin, xMax, yMax, zMax);
            // gmsh takes the smallest of this and its other size constraints.
            gmsh::model::mesh::setSizeCallback([=, &request](int, int, double, double, double z) {
                return contactGradedSize(z, zMin, zMax, h, request);
            });
        }
        gmsh::option::setNumber("Mesh.Optimize", request.optimise > 0 ? 1 : 0);
        gmsh::model::mesh::generate(3);
        if (contactRefined) gmsh::model::mesh::removeSizeCallback();  // it refers to this call's request
        result = extractMesh();
        if (result.tets.empty())
            throw UserError("gmsh produced no tetrahedra; check that the surface is closed");
        if (pass + 1 < passes) {
            h *= std::cbrt(static_cast<double>(result.tets.size()) / request.elementCount);
            continue;
        }
        writeViaTemporary(mshFile, [](const fs::path& tmp) {
            // gmsh chooses the format from the extension: keep ".msh" last.
            const fs::path named = tmp.parent_path() / (tmp.filename().string() + ".msh");
            gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
            gmsh::write(named.string());
            // gmsh does not report a short write: a complete .msh ends with a section's $End tag.
            std::error_code ec;
            if (!fileTailContains(named, "$End", 64)) {
                fs::remove(named, ec);
                return false;
            }
            fs::rename(named, tmp, ec);
            return !ec;
        });
    }
    result.elementSize = h;
    result.solidVolume = solidVolume;
    return result;
}

}  // namespace

TetMeshingResult meshDiscWithGmsh(double diameter, double thickness, const Vec3& centre,
                                  const TetMeshRequest& request, const fs::path& mshFile)
{
    const double solidVolume = M_PI * 0.25 * diameter * diameter * thickness;
    return meshWithGmsh(solidVolume, request, mshFile, [&] {
        gmsh::model::occ::addCylinder(centre.x, centre.y - 0.5 * thickness, centre.z, 0, thickness, 0,
                                      0.5 * diameter);
        gmsh::model::occ::synchronize();
    });
}

TetMeshingResult meshSurfaceWithGmsh(const TriSurface& surface, const TetMeshRequest& request,
                                     const fs::path& mshFile)
{
    const double solidVolume = massProperties(surface).volume;
    return meshWithGmsh(solidVolume, request, mshFile, [&] {
        // Every triangle becomes a plane surface of gmsh's built-in kernel,
        // bounded by lines shared with its neighbours, so the surface mesh is
        // conforming and the volume is exactly the solid's (flat facets). A
        // scan with very many small triangles should be decimated first: the
        // mesh cannot be coarser than its triangles.
        std::vector<int> pointTags(surface.points.size());
        for (std::size_t i = 0; i < surface.points.size(); ++i)
            pointTags[i] =
                gmsh::model::geo::addPoint(surface.points[i].x, surface.points[i].y, surface.points[i].z);
        std::map<std::pair<int, int>, int> lineOf;  // (a, b) with a < b -> line tag from a to b
        auto edge = [&](int a, int b) {
            const auto key = std::make_pair(std::min(a, b), std::max(a, b));
            auto it = lineOf.find(key);
            if (it == lineOf.end())
                it = lineOf
                         .emplace(key, gmsh::model::geo::addLine(pointTags[key.first], pointTags[key.second]))
                         .first;
            return a < b ? it->second : -it->second;
        };
        std::vector<int> surfaceTags;
        for (const auto& t : surface.triangles) {
            const int loop =
                gmsh::model::geo::addCurveLoop({edge(t[0], t[1]), edge(t[1], t[2]), edge(t[2], t[0])});
            surfaceTags.push_back(gmsh::model::geo::addPlaneSurface({loop}));
        }
        const int shell = gmsh::model::geo::addSurfaceLoop(surfaceTags);
        gmsh::model::geo::addVolume({shell});
        gmsh::model::geo::synchronize();
    });
}

}  // namespace rockfrac
