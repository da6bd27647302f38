#pragma once
// Connectivity of a VoronoiMesh and the bonds derived from it. The bond
// geometry is a pure function of the stored cells and faces, so the writer
// stores only which face pairs are bonded and the reader rebuilds bit-identical
// bonds with the same function the tessellation used.
#include <vector>

#include "voronoi/polyhedron.hpp"
#include "voronoi/voronoiMesh.hpp"

namespace rockfrac {

// Cell c of the mesh as a polyhedron (vertex indices local to the cell).
PolyhedronView cellView(const VoronoiMesh& mesh, int c);

// The cell owning each face.
std::vector<int> faceOwners(const VoronoiMesh& mesh);

// Two faces that are the same interface seen from its two cells:
// owner(faceI) < owner(faceJ).
struct FacePair {
    int faceI = -1;
    int faceJ = -1;
};

// Every internal face pair, ordered by faceI. Uses faceNeighbour; a face whose
// neighbour has no face pointing back is not paired (see repairNeighbours).
std::vector<FacePair> internalFacePairs(const VoronoiMesh& mesh);

// Turn faces whose neighbour has no face pointing back into boundary faces
// (they can appear where Voro++'s tolerance drops a sliver face on one side
// only). Returns how many faces were changed.
int repairNeighbours(VoronoiMesh& mesh);

// One bond per vertex of faceI for every pair: area A/n, normalI the outward
// normal of faceI, lI and lJ the distances of the two centroids from faceI's
// plane (through the mean of its vertices).
std::vector<VoronoiBond> bondsForFacePairs(const VoronoiMesh& mesh, const std::vector<FacePair>& pairs);

}  // namespace rockfrac
