// Geometry of linear tetrahedra: volumes, heights, quality checks, boundary.
#include "fem/tetMesh.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "core/error.hpp"

namespace rockfrac::fem {

std::string TetMesh::describeTet(std::size_t e) const
{
    std::ostringstream s;
    s << "tet " << e;
    if (e < tetFileTags.size()) s << " (gmsh element " << tetFileTags[e] << ")";
    return s.str();
}

double tetSignedVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
    return dot(b - a, cross(c - a, d - a)) / 6.0;
}

double tetSmallestHeight(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
    // Face areas; the altitude onto a face is 3V / area, smallest on the largest face.
    const double areas[4] = {0.5 * norm(cross(c - b, d - b)), 0.5 * norm(cross(c - a, d - a)),
                             0.5 * norm(cross(b - a, d - a)), 0.5 * norm(cross(b - a, c - a))};
    const double largestArea = *std::max_element(areas, areas + 4);
    return 3.0 * std::abs(tetSignedVolume(a, b, c, d)) / largestArea;
}

namespace {

template <class Function>
std::vector<double> perTet(const TetMesh& mesh, Function f)
{
    std::vector<double> values(mesh.numTets());
    for (std::size_t e = 0; e < mesh.numTets(); ++e) {
        const auto& t = mesh.tets[e];
        values[e] = f(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]);
    }
    return values;
}

double longestEdge(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
    const Vec3* p[4] = {&a, &b, &c, &d};
    double longest = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) longest = std::max(longest, norm(*p[i] - *p[j]));
    return longest;
}

}  // namespace

std::vector<double> tetVolumes(const TetMesh& mesh)
{
    return perTet(mesh, tetSignedVolume);
}

std::vector<double> tetSmallestHeights(const TetMesh& mesh)
{
    return perTet(mesh, tetSmallestHeight);
}

void checkTetQuality(const TetMesh& mesh)
{
    if (mesh.numTets() == 0) throw UserError("the mesh holds no linear tetrahedra");
    // A tet is degenerate when its volume is negligible against its size: a flat
    // ("sliver") tet of zero volume would give an infinite stable-step limit ratio.
    constexpr double degenerateVolumeRatio = 1e-12;
    for (std::size_t e = 0; e < mesh.numTets(); ++e) {
        const auto& t = mesh.tets[e];
        for (int k = 0; k < 4; ++k)
            if (t[k] < 0 || static_cast<std::size_t>(t[k]) >= mesh.numNodes())
                throw UserError("mesh: " + mesh.describeTet(e) + " refers to a missing node");
        const Vec3 &a = mesh.nodes[t[0]], &b = mesh.nodes[t[1]], &c = mesh.nodes[t[2]], &d = mesh.nodes[t[3]];
        const double volume = tetSignedVolume(a, b, c, d);
        const double edge = longestEdge(a, b, c, d);
        if (volume < 0.0) {
            std::ostringstream s;
            s << "mesh: " << mesh.describeTet(e) << " is inverted (volume " << volume << " m^3)";
            throw UserError(s.str());
        }
        if (!(volume > degenerateVolumeRatio * edge * edge * edge)) {
            std::ostringstream s;
            s << "mesh: " << mesh.describeTet(e) << " is degenerate (volume " << volume
              << " m^3, longest edge " << edge << " m)";
            throw UserError(s.str());
        }
    }
}

std::vector<std::array<int, 4>> boundaryFaces(const TetMesh& mesh)
{
    // Each face by its sorted node triple; a face shared by two tets is interior.
    std::map<std::array<int, 3>, std::array<int, 4>> faces;
    constexpr int faceNodes[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    for (const auto& t : mesh.tets)
        for (int f = 0; f < 4; ++f) {
            std::array<int, 3> key = {t[faceNodes[f][0]], t[faceNodes[f][1]], t[faceNodes[f][2]]};
            std::sort(key.begin(), key.end());
            auto [it, inserted] = faces.emplace(key, std::array<int, 4>{key[0], key[1], key[2], t[f]});
            if (!inserted) it->second[3] = -1;
        }
    std::vector<std::array<int, 4>> boundary;
    for (const auto& [key, face] : faces)
        if (face[3] >= 0) boundary.push_back(face);
    return boundary;
}

std::vector<int> boundaryNodes(const TetMesh& mesh)
{
    std::vector<char> onBoundary(mesh.numNodes(), 0);
    for (const auto& face : boundaryFaces(mesh))
        for (int k = 0; k < 3; ++k) onBoundary[face[k]] = 1;
    std::vector<int> nodes;
    for (std::size_t n = 0; n < onBoundary.size(); ++n)
        if (onBoundary[n]) nodes.push_back(static_cast<int>(n));
    return nodes;
}

}  // namespace rockfrac::fem
