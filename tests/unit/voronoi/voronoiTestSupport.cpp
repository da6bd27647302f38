#include "voronoiTestSupport.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <utility>

#include "voronoi/meshTopology.hpp"
#include "voronoi/randomStream.hpp"

namespace rockfrac::test {

namespace {

template <class T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool sameBond(const VoronoiBond& a, const VoronoiBond& b)
{
    return a.cellI == b.cellI && a.cellJ == b.cellJ && a.faceI == b.faceI && a.faceJ == b.faceJ &&
           std::memcmp(&a.point, &b.point, sizeof(Vec3)) == 0 &&
           std::memcmp(&a.normalI, &b.normalI, sizeof(Vec3)) == 0 && std::memcmp(&a.lI, &b.lI, 8) == 0 &&
           std::memcmp(&a.lJ, &b.lJ, 8) == 0 && std::memcmp(&a.area, &b.area, 8) == 0;
}

std::string describe(const char* what, int index)
{
    std::ostringstream s;
    s << what << " " << index;
    return s.str();
}

}  // namespace

Domain bdtDisc()
{
    return Domain::disc({0, 0, 0}, {0, 0, 1}, 44.8e-3, 13.8e-3);
}

Domain randomConvexRock(int nPlanes, std::uint64_t seed, double scale, const Vec3& centre)
{
    RandomStream random(seed);
    std::vector<HalfSpace> planes;
    for (int i = 0; i < nPlanes; ++i) {
        // Uniform direction on the sphere: z uniform in [-1, 1], azimuth uniform.
        const double z = random.uniform(-1.0, 1.0), phi = random.uniform(0.0, 6.283185307179586);
        const double r = std::sqrt(1.0 - z * z);
        const Vec3 n{r * std::cos(phi), r * std::sin(phi), z};
        planes.push_back({n, scale * random.uniform(0.8, 1.2) + dot(n, centre)});
    }
    for (int octant = 0; octant < 8; ++octant) {
        const Vec3 n =
            normalised(Vec3{octant & 1 ? 1.0 : -1.0, octant & 2 ? 1.0 : -1.0, octant & 4 ? 1.0 : -1.0});
        planes.push_back({n, 1.5 * scale + dot(n, centre)});
    }
    return Domain::fromPlanes(planes);
}

Domain rockOfVolume(double volume, std::uint64_t seed)
{
    const double unitVolume = randomConvexRock(20, seed).volume();
    return randomConvexRock(20, seed, std::cbrt(volume / unitVolume));
}

bool identical(const VoronoiMesh& a, const VoronoiMesh& b)
{
    if (a.seed != b.seed || std::memcmp(&a.pruningDistance, &b.pruningDistance, 8) != 0 ||
        std::memcmp(&a.domainVolume, &b.domainVolume, 8) != 0 ||
        std::memcmp(&a.dilationRadius, &b.dilationRadius, 8) != 0)
        return false;
    if (!sameBytes(a.seeds, b.seeds) || !sameBytes(a.centroids, b.centroids) ||
        !sameBytes(a.volumes, b.volumes) || !sameBytes(a.inertia, b.inertia) ||
        !sameBytes(a.cellVertexOffset, b.cellVertexOffset) || !sameBytes(a.vertices, b.vertices) ||
        !sameBytes(a.cellFaceOffset, b.cellFaceOffset) ||
        !sameBytes(a.faceVertexOffset, b.faceVertexOffset) || !sameBytes(a.faceVertices, b.faceVertices) ||
        !sameBytes(a.faceNeighbour, b.faceNeighbour) || !sameBytes(a.faceNormal, b.faceNormal) ||
        !sameBytes(a.faceArea, b.faceArea) || a.bonds.size() != b.bonds.size())
        return false;
    for (std::size_t i = 0; i < a.bonds.size(); ++i)
        if (!sameBond(a.bonds[i], b.bonds[i])) return false;
    return true;
}

// Every internal face has exactly one partner face on its neighbour, pointing
// back, with the opposite area vector (equal areas, opposite normals).
std::string checkSharedFaces(const VoronoiMesh& mesh, double length)
{
    const double areaTolerance = 1e-9 * length * length;
    for (int c = 0; c < mesh.nCells(); ++c)
        for (int f = mesh.cellFaceOffset[c]; f < mesh.cellFaceOffset[c + 1]; ++f) {
            const int j = mesh.faceNeighbour[f];
            if (j == boundaryFace) continue;
            int partners = 0, g = -1;
            for (int h = mesh.cellFaceOffset[j]; h < mesh.cellFaceOffset[j + 1]; ++h)
                if (mesh.faceNeighbour[h] == c) ++partners, g = h;
            if (partners != 1) return describe("face without exactly one partner:", f);
            const Vec3 sum = mesh.faceArea[f] * mesh.faceNormal[f] + mesh.faceArea[g] * mesh.faceNormal[g];
            if (norm(sum) > areaTolerance) return describe("partner faces not opposite:", f);
            if (std::fabs(mesh.faceArea[f] - mesh.faceArea[g]) > areaTolerance + 1e-9 * mesh.faceArea[f])
                return describe("partner faces of different area:", f);
            if (mesh.faceArea[f] > 1e-6 * length * length &&
                norm(mesh.faceNormal[f] + mesh.faceNormal[g]) > 1e-6)
                return describe("partner normals not opposite:", f);
        }
    return {};
}

// Each cell is a closed, consistently oriented, convex polyhedron: every
// directed edge appears once and its reverse once (closed and oriented),
// V - E + F = 2, and no vertex lies outside any face plane.
std::string checkClosedConvexCells(const VoronoiMesh& mesh, double length)
{
    for (int c = 0; c < mesh.nCells(); ++c) {
        const PolyhedronView cell = cellView(mesh, c);
        std::map<std::pair<int, int>, int> directedEdges;
        for (int f = 0; f < cell.nFaces; ++f)
            for (int k = 0; k < cell.faceSize(f); ++k) {
                const int a = cell.faceVertices[cell.faceVertexOffset[f] + k];
                const int b = cell.faceVertices[cell.faceVertexOffset[f] + (k + 1) % cell.faceSize(f)];
                ++directedEdges[{a, b}];
            }
        for (const auto& [edge, count] : directedEdges)
            if (count != 1 || directedEdges.count({edge.second, edge.first}) != 1)
                return describe("cell not closed or not consistently oriented:", c);
        const int nVertices = mesh.cellVertexOffset[c + 1] - mesh.cellVertexOffset[c];
        const int nEdges = static_cast<int>(directedEdges.size()) / 2;
        if (nVertices - nEdges + cell.nFaces != 2) return describe("Euler characteristic not 2 for cell", c);
        for (int f = 0; f < cell.nFaces; ++f) {
            const Vec3 n = mesh.faceNormal[mesh.cellFaceOffset[c] + f];
            const Vec3 onFace = faceCentre(cell, f);
            for (int v = 0; v < nVertices; ++v)
                if (dot(n, cell.vertices[v] - onFace) > 1e-9 * length) return describe("cell not convex:", c);
        }
        if (!(mesh.volumes[c] > 0)) return describe("cell without volume:", c);
    }
    return {};
}

// One bond per vertex of the lower cell's face of each internal pair, with
// the pair's geometry, and nothing else.
std::string checkBonds(const VoronoiMesh& mesh)
{
    std::size_t expected = 0;
    for (int c = 0; c < mesh.nCells(); ++c)
        for (int f = mesh.cellFaceOffset[c]; f < mesh.cellFaceOffset[c + 1]; ++f)
            if (mesh.faceNeighbour[f] > c)
                expected += mesh.faceVertexOffset[f + 1] - mesh.faceVertexOffset[f];
    if (mesh.bonds.size() != expected) return "bond count is not the number of vertices of internal faces";
    for (int b = 0; b < mesh.nBonds(); ++b) {
        const VoronoiBond& bond = mesh.bonds[b];
        if (!(bond.cellI < bond.cellJ) || mesh.faceNeighbour[bond.faceI] != bond.cellJ ||
            mesh.faceNeighbour[bond.faceJ] != bond.cellI)
            return describe("bond between the wrong cells:", b);
        const int n = mesh.faceVertexOffset[bond.faceI + 1] - mesh.faceVertexOffset[bond.faceI];
        if (std::fabs(bond.area * n - mesh.faceArea[bond.faceI]) > 1e-12 * mesh.faceArea[bond.faceI])
            return describe("bond area is not A/n:", b);
        if (!(bond.lI > 0) || !(bond.lJ > 0))
            return describe("bond with a non-positive centroid distance:", b);
        if (bond.normalI != mesh.faceNormal[bond.faceI])
            return describe("bond normal is not cell I's face normal:", b);
    }
    return {};
}

// Faces on no neighbour must lie on one of the domain's planes (a boundary
// face anywhere else would be a hole in the mesh).
std::string checkBoundaryFacesOnPlanes(const VoronoiMesh& mesh, const Domain& domain, double length)
{
    for (int c = 0; c < mesh.nCells(); ++c) {
        const PolyhedronView cell = cellView(mesh, c);
        for (int f = 0; f < cell.nFaces; ++f) {
            if (mesh.faceNeighbour[mesh.cellFaceOffset[c] + f] != boundaryFace) continue;
            const bool onAPlane =
                std::any_of(domain.planes().begin(), domain.planes().end(), [&](const HalfSpace& h) {
                    for (int k = 0; k < cell.faceSize(f); ++k)
                        if (std::fabs(h.signedDistance(cell.faceVertex(f, k))) > 1e-9 * length) return false;
                    return true;
                });
            if (!onAPlane) return describe("boundary face off the domain planes in cell", c);
        }
    }
    return {};
}

double sumOfVolumes(const VoronoiMesh& mesh)
{
    double sum = 0.0;
    for (double v : mesh.volumes) sum += v;
    return sum;
}

double minimumSeedDistance(const std::vector<Vec3>& seeds)
{
    double minimum = INFINITY;
    for (std::size_t i = 0; i < seeds.size(); ++i)
        for (std::size_t j = i + 1; j < seeds.size(); ++j)
            minimum = std::min(minimum, norm(seeds[i] - seeds[j]));
    return minimum;
}

}  // namespace rockfrac::test
