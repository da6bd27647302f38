#pragma once
// Tetrahedral meshes for the FEM solver, made through the gmsh API.
//
// A disc is meshed from its exact CAD cylinder (OpenCASCADE kernel); any other
// solid from its closed triangulated surface (the surface is classified into
// patches, a geometry is rebuilt on it, and the volume is meshed). The mesh is
// written as gmsh .msh (what feFractureSolver reads) and checked: element
// count, volume error against the solid, and shape quality.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/triSurface.hpp"

namespace rockfrac {

struct TetMeshRequest {
    double elementSize = 0.0;  // target edge length [m]; or
    int elementCount = 0;      // target number of tetrahedra (size derived, one correction pass)
    int optimise = 1;          // gmsh Netgen/standard optimisation passes
    // Finer elements where the plates touch (optional, with elementSize only): contactSize
    // within contactDistance of the solid's lowest and highest z (the plates' axis), growing
    // linearly to elementSize over another contactDistance. 0 = a uniform mesh.
    double contactSize = 0.0;
    double contactDistance = 0.0;
};

// The entries of system/feMeshDict (meshRock's readTetRequest) and of its contactRefinement.
inline const std::vector<std::string>& feMeshDictEntries()
{
    static const std::vector<std::string> entries = {"elementSize", "elementCount", "optimise",
                                                     "contactRefinement"};
    return entries;
}

struct TetMeshingResult {
    std::vector<Vec3> nodes;
    std::vector<std::array<int, 4>> tets;        // positively oriented
    double elementSize = 0.0;                    // size used [m]
    double volume = 0.0;                         // Σ tet volumes [m^3]
    double solidVolume = 0.0;                    // volume of the solid meshed [m^3]
    double minQuality = 0.0, meanQuality = 0.0;  // mean-ratio quality, 1 = regular tetrahedron
    double relativeVolumeError() const { return (volume - solidVolume) / solidVolume; }
};

// Disc with its axis along y centred at `centre` (same placement as discSurface).
TetMeshingResult meshDiscWithGmsh(double diameter, double thickness, const Vec3& centre,
                                  const TetMeshRequest& request, const std::filesystem::path& mshFile);
// A closed, outward-oriented triangulated surface.
TetMeshingResult meshSurfaceWithGmsh(const TriSurface& surface, const TetMeshRequest& request,
                                     const std::filesystem::path& mshFile);

// Mean-ratio quality 12 (3V)^(2/3) / Σ l² of one tetrahedron (1 regular, 0 flat).
double tetQuality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace rockfrac
