#include "voronoi/meshTopology.hpp"

namespace rockfrac {

namespace {

// The face of cell c whose neighbour is `neighbour`, or -1.
int faceTowards(const VoronoiMesh& mesh, int c, int neighbour)
{
    for (int f = mesh.cellFaceOffset[c]; f < mesh.cellFaceOffset[c + 1]; ++f)
        if (mesh.faceNeighbour[f] == neighbour) return f;
    return -1;
}

}  // namespace

PolyhedronView cellView(const VoronoiMesh& mesh, int c)
{
    PolyhedronView view;
    view.vertices = mesh.vertices.data() + mesh.cellVertexOffset[c];
    view.faceVertexOffset = mesh.faceVertexOffset.data() + mesh.cellFaceOffset[c];
    view.faceVertices = mesh.faceVertices.data();
    view.nFaces = mesh.cellFaceOffset[c + 1] - mesh.cellFaceOffset[c];
    return view;
}

std::vector<int> faceOwners(const VoronoiMesh& mesh)
{
    std::vector<int> owner(mesh.nFaces());
    for (int c = 0; c < mesh.nCells(); ++c)
        for (int f = mesh.cellFaceOffset[c]; f < mesh.cellFaceOffset[c + 1]; ++f) owner[f] = c;
    return owner;
}

std::vector<FacePair> internalFacePairs(const VoronoiMesh& mesh)
{
    std::vector<FacePair> pairs;
    for (int c = 0; c < mesh.nCells(); ++c)
        for (int f = mesh.cellFaceOffset[c]; f < mesh.cellFaceOffset[c + 1]; ++f) {
            const int neighbour = mesh.faceNeighbour[f];
            if (neighbour <= c) continue;  // boundary, or paired from the lower cell
            const int g = faceTowards(mesh, neighbour, c);
            if (g >= 0) pairs.push_back({f, g});
        }
    return pairs;
}

int repairNeighbours(VoronoiMesh& mesh)
{
    int repaired = 0;
    for (int c = 0; c < mesh.nCells(); ++c)
        for (int f = mesh.cellFaceOffset[c]; f < mesh.cellFaceOffset[c + 1]; ++f) {
            const int neighbour = mesh.faceNeighbour[f];
            if (neighbour == boundaryFace || faceTowards(mesh, neighbour, c) >= 0) continue;
            mesh.faceNeighbour[f] = boundaryFace;
            ++repaired;
        }
    return repaired;
}

std::vector<VoronoiBond> bondsForFacePairs(const VoronoiMesh& mesh, const std::vector<FacePair>& pairs)
{
    // Pair p's bonds start at firstBond[p]; the array is sized once and each
    // pair fills its own slots, so the parallel loop gives the serial result.
    const int nPairs = static_cast<int>(pairs.size());
    std::vector<std::size_t> firstBond(nPairs + 1, 0);
    for (int p = 0; p < nPairs; ++p) {
        const int f = pairs[p].faceI;
        firstBond[p + 1] = firstBond[p] + (mesh.faceVertexOffset[f + 1] - mesh.faceVertexOffset[f]);
    }
    const std::vector<int> owner = faceOwners(mesh);
    std::vector<VoronoiBond> bonds(firstBond[nPairs]);
#pragma omp parallel for schedule(static)
    for (int p = 0; p < nPairs; ++p) {
        const FacePair& pair = pairs[p];
        const int cellI = owner[pair.faceI], cellJ = owner[pair.faceJ];
        const PolyhedronView cell = cellView(mesh, cellI);
        const int localFace = pair.faceI - mesh.cellFaceOffset[cellI];
        const int nVertices = cell.faceSize(localFace);
        const Vec3 normal = mesh.faceNormal[pair.faceI];
        const Vec3 onPlane = faceCentre(cell, localFace);

        VoronoiBond bond;
        bond.cellI = cellI;
        bond.cellJ = cellJ;
        bond.faceI = pair.faceI;
        bond.faceJ = pair.faceJ;
        bond.normalI = normal;
        bond.lI = dot(normal, onPlane - mesh.centroids[cellI]);
        bond.lJ = dot(normal, mesh.centroids[cellJ] - onPlane);
        bond.area = mesh.faceArea[pair.faceI] / nVertices;
        for (int k = 0; k < nVertices; ++k) {
            bond.point = cell.faceVertex(localFace, k);
            bonds[firstBond[p] + k] = bond;
        }
    }
    return bonds;
}

}  // namespace rockfrac
