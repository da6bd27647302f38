#pragma once
// Linear tetrahedral mesh: the geometry the explicit FEM solver works on.
//
// Node coordinates, four node ids per tetrahedron (positively oriented: the
// signed volume is > 0), and the physical groups of the gmsh file so a case can
// name boundaries and regions.
#include <array>
#include <map>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace rockfrac::fem {

struct TetMesh {
    std::vector<Vec3> nodes;
    std::vector<std::array<int, 4>> tets;
    // Physical-group tag of each tet (0 when the file has no volume groups).
    std::vector<int> tetTags;
    // Original gmsh element tags, so errors name the element the user sees in gmsh.
    std::vector<std::size_t> tetFileTags;
    // Physical groups by name: the nodes of each group of any dimension.
    std::map<std::string, std::vector<int>> nodeGroups;

    std::size_t numNodes() const { return nodes.size(); }
    std::size_t numTets() const { return tets.size(); }
    // Name of element e for messages: "tet e (gmsh element T)".
    std::string describeTet(std::size_t e) const;
};

// Signed volume of a tetrahedron (positive for the right-handed ordering gmsh uses).
double tetSignedVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Smallest altitude of a tetrahedron, 3V / (largest face area): the length
// that sets its highest eigenfrequency and therefore the stable explicit step.
double tetSmallestHeight(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

std::vector<double> tetVolumes(const TetMesh& mesh);
std::vector<double> tetSmallestHeights(const TetMesh& mesh);

// Throws UserError naming the first element whose volume is not positive
// (inverted or degenerate, relative to the cube of its longest edge).
void checkTetQuality(const TetMesh& mesh);

// Reads a gmsh mesh file (msh 2 or 4) through the gmsh API and keeps its linear
// tetrahedra (type 4); other elements are ignored, unused nodes are dropped.
// UserError if the file cannot be read, holds no tetrahedra, or has a bad one.
TetMesh readGmshMesh(const std::string& path);

// The same from the mesh currently held by the gmsh API (after gmsh::model::mesh::generate),
// for programs and tests that build their geometry through gmsh directly.
TetMesh tetMeshFromGmshModel();

// Nodes on the boundary: the nodes of faces that belong to exactly one tet.
std::vector<int> boundaryNodes(const TetMesh& mesh);
// Faces on the boundary, in a fixed order: (a, b, c, opposite) with a < b < c the
// face's nodes and `opposite` the fourth node of its tet (which side is inside).
std::vector<std::array<int, 4>> boundaryFaces(const TetMesh& mesh);

}  // namespace rockfrac::fem
