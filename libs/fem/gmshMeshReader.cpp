// Reading tetrahedral meshes through the gmsh C++ API (any msh version gmsh reads).
#include <gmsh.h>
#include <omp.h>

#include <algorithm>
#include <unordered_map>

#include "core/error.hpp"
#include "fem/tetMesh.hpp"

namespace rockfrac::fem {

namespace {

constexpr int gmshLinearTetType = 4;

// gmsh 4.8 has no isInitialized(); an uninitialised library answers option
// queries with 0 while an initialised one never has Mesh.Algorithm = 0.
bool gmshIsInitialised()
{
    try {
        double algorithm = 0.0;
        gmsh::option::getNumber("Mesh.Algorithm", algorithm);
        return algorithm != 0.0;
    } catch (...) {
        return false;
    }
}

// Compact numbering of the nodes the tets use, in order of first use.
struct NodeNumbering {
    std::unordered_map<std::size_t, int> indexOfTag;
    std::vector<std::size_t> tags;
    int indexOf(std::size_t tag)
    {
        auto [it, inserted] = indexOfTag.emplace(tag, static_cast<int>(tags.size()));
        if (inserted) tags.push_back(tag);
        return it->second;
    }
};

void readTets(TetMesh& mesh, NodeNumbering& numbering)
{
    std::vector<std::size_t> elementTags, nodeTags;
    gmsh::model::mesh::getElementsByType(gmshLinearTetType, elementTags, nodeTags);
    mesh.tets.resize(elementTags.size());
    mesh.tetFileTags = elementTags;
    for (std::size_t e = 0; e < elementTags.size(); ++e)
        for (int k = 0; k < 4; ++k) mesh.tets[e][k] = numbering.indexOf(nodeTags[4 * e + k]);
}

void readCoordinates(TetMesh& mesh, const NodeNumbering& numbering)
{
    std::vector<std::size_t> nodeTags;
    std::vector<double> coordinates, parametric;
    gmsh::model::mesh::getNodes(nodeTags, coordinates, parametric, -1, -1, false, false);
    mesh.nodes.resize(numbering.tags.size());
    for (std::size_t i = 0; i < nodeTags.size(); ++i) {
        auto it = numbering.indexOfTag.find(nodeTags[i]);
        if (it != numbering.indexOfTag.end())
            mesh.nodes[it->second] = {coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]};
    }
}

void readPhysicalGroups(TetMesh& mesh, const NodeNumbering& numbering)
{
    mesh.tetTags.assign(mesh.numTets(), 0);
    std::unordered_map<std::size_t, std::size_t> tetOfTag;
    for (std::size_t e = 0; e < mesh.numTets(); ++e) tetOfTag[mesh.tetFileTags[e]] = e;
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups);
    for (const auto& [dim, tag] : groups) {
        std::string name;
        gmsh::model::getPhysicalName(dim, tag, name);
        if (name.empty()) name = "group" + std::to_string(dim) + "_" + std::to_string(tag);
        std::vector<std::size_t> nodeTags;
        std::vector<double> coordinates;
        gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, nodeTags, coordinates);
        auto& nodes = mesh.nodeGroups[name];
        for (std::size_t t : nodeTags) {
            auto it = numbering.indexOfTag.find(t);
            if (it != numbering.indexOfTag.end()) nodes.push_back(it->second);
        }
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        if (dim != 3) continue;
        std::vector<int> entities;
        gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
        for (int entity : entities) {
            std::vector<std::size_t> elementTags, elementNodes;
            gmsh::model::mesh::getElementsByType(gmshLinearTetType, elementTags, elementNodes, entity);
            for (std::size_t t : elementTags) mesh.tetTags[tetOfTag.at(t)] = tag;
        }
    }
}

}  // namespace

TetMesh tetMeshFromGmshModel()
{
    TetMesh mesh;
    NodeNumbering numbering;
    readTets(mesh, numbering);
    readCoordinates(mesh, numbering);
    readPhysicalGroups(mesh, numbering);
    checkTetQuality(mesh);
    return mesh;
}

TetMesh readGmshMesh(const std::string& path)
{
    // gmsh::initialize() calls omp_set_num_threads(General.NumThreads = 1) for the whole
    // process: remember the caller's thread count and give it back afterwards.
    const int callerThreads = omp_get_max_threads();
    const bool ownSession = !gmshIsInitialised();
    if (ownSession) {
        gmsh::initialize(0, nullptr, false);
        gmsh::option::setNumber("General.Terminal", 0);
    }
    // Clean up whatever happens: finalise our own session, or drop the model we added.
    struct Cleanup {
        bool ownSession;
        int callerThreads;
        ~Cleanup()
        {
            // A destructor must not throw (std::terminate); gmsh throws std::string.
            try {
                if (ownSession)
                    gmsh::finalize();
                else
                    gmsh::model::remove();
            } catch (...) {
            }
            omp_set_num_threads(callerThreads);
        }
    } cleanup{ownSession, callerThreads};
    // gmsh reports a truncated or corrupt file by throwing a std::string (its C++
    // API) or an exception; either becomes a UserError naming the file.
    const std::string advice = "; re-run meshRock to write the mesh again";
    try {
        gmsh::open(path);
        return tetMeshFromGmshModel();
    } catch (const UserError& e) {
        throw UserError("'" + path + "': " + e.what());
    } catch (const std::exception& e) {
        throw UserError("cannot read gmsh mesh '" + path + "': " + e.what() + advice);
    } catch (const std::string& e) {
        throw UserError("cannot read gmsh mesh '" + path + "': " + e + advice);
    } catch (...) {
        throw UserError("cannot read gmsh mesh '" + path + "': gmsh failed" + advice);
    }
}

}  // namespace rockfrac::fem
