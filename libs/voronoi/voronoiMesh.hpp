#pragma once
// The bonded Voronoi mesh: what voronoiMesh writes and bondedDemFoam reads.
//
// Cells are convex polyhedra (a Voronoi tessellation clipped to the domain).
// Two cells that share a face are glued at the face's vertices: one bond per
// face vertex, each owning A/n of the face area A (n = number of vertices of
// the face), with l_i, l_j the distances from each cell's centroid to the
// face plane (physics.md §3.3). Storage is compressed (CSR) so a 10^5-cell
// mesh is a handful of flat arrays.
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace rockfrac {

// Neighbour value of a face on the domain boundary (not shared by two cells).
constexpr int boundaryFace = -1;

struct VoronoiBond {
    int cellI = -1;     // lower cell index
    int cellJ = -1;     // higher cell index
    int faceI = -1;     // global face index (into faceNeighbour etc.) on cell I
    int faceJ = -1;     // the matching face on cell J
    Vec3 point;         // the face vertex, where both anchor points start (d = 0)
    Vec3 normalI;       // outward unit normal of cell I's face (cell J's is -normalI)
    double lI = 0.0;    // distance from cell I's centroid to the face plane [m]
    double lJ = 0.0;    // distance from cell J's centroid to the face plane [m]
    double area = 0.0;  // A/n: the share of the face area this bond carries [m^2]
};

struct VoronoiMesh {
    static constexpr int formatVersion = 1;

    // Provenance of the tessellation.
    std::uint64_t seed = 0;        // random seed of the seeding
    double pruningDistance = 0.0;  // minimum distance between two seeds [m]
    double domainVolume = 0.0;     // volume of the domain that was filled [m^3]
    double dilationRadius = 0.0;   // radius of the sphere the cells are dilated by [m]

    // Per cell.
    std::vector<Vec3> seeds;      // generator points
    std::vector<Vec3> centroids;  // centre of volume [m]
    std::vector<double> volumes;  // [m^3]
    std::vector<Mat3> inertia;    // second moment of volume about the centroid [m^5] (x density = inertia)

    // Vertices of each cell, in global coordinates: cell c owns
    // vertices[cellVertexOffset[c] .. cellVertexOffset[c+1]).
    std::vector<int> cellVertexOffset;
    std::vector<Vec3> vertices;

    // Faces of each cell: cell c owns faces cellFaceOffset[c] .. cellFaceOffset[c+1]).
    // Face f lists its vertices (indices into the cell's own vertex range, counter-
    // clockwise seen from outside) in faceVertices[faceVertexOffset[f] .. [f+1]).
    std::vector<int> cellFaceOffset;
    std::vector<int> faceVertexOffset;
    std::vector<int> faceVertices;
    std::vector<int> faceNeighbour;  // neighbouring cell, or boundaryFace
    std::vector<Vec3> faceNormal;    // outward unit normal
    std::vector<double> faceArea;    // [m^2]

    // Bonds, stored once per (cell pair, face vertex).
    std::vector<VoronoiBond> bonds;

    int nCells() const { return static_cast<int>(volumes.size()); }
    int nFaces() const { return static_cast<int>(faceNeighbour.size()); }
    int nBonds() const { return static_cast<int>(bonds.size()); }

    // faceVertices as indices into `vertices` (each cell's own range): the face lists of the
    // cells as polyhedra over all the mesh's vertices, as VTK writes them.
    std::vector<int> globalFaceVertices() const
    {
        std::vector<int> global(faceVertices.size());
        for (int c = 0; c < nCells(); ++c)
            for (int f = cellFaceOffset[c]; f < cellFaceOffset[c + 1]; ++f)
                for (int k = faceVertexOffset[f]; k < faceVertexOffset[f + 1]; ++k)
                    global[k] = cellVertexOffset[c] + faceVertices[k];
        return global;
    }
};

}  // namespace rockfrac
