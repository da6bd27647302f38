#pragma once
// The files of a bonded Voronoi mesh in a case: constant/voronoiMesh/ holds an
// ASCII header `meshInfo` (version, counts, provenance, checksums) and four
// little-endian binary files `cells`, `vertices`, `faces` and `bonds`
// (docs/file-formats.md). Bonds are stored as the bonded face
// pairs; their geometry is rebuilt on reading by the same function the
// tessellation uses, so a read mesh is bit-identical to the written one. Each binary
// payload's checksum is core/checksum.hpp's fnv1aWords.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "voronoi/voronoiMesh.hpp"

namespace rockfrac {

// Where the mesh lives, relative to the case directory.
inline const std::filesystem::path voronoiMeshDirectory{"constant/voronoiMesh"};

// Write `mesh` into caseDir/constant/voronoiMesh (created if needed). Each file
// is written to a temporary name and renamed, meshInfo last. UserError naming
// the file on an I/O failure; std::invalid_argument if the mesh's arrays are
// inconsistent (a programming error).
void writeVoronoiMesh(const std::filesystem::path& caseDir, const VoronoiMesh& mesh);

// Read and fully validate caseDir/constant/voronoiMesh. Any missing,
// truncated, corrupt or inconsistent file gives a UserError naming the file
// and what is wrong; it never crashes or allocates more than the files hold.
VoronoiMesh readVoronoiMesh(const std::filesystem::path& caseDir);

// The sizes meshInfo announces, read and checked as readVoronoiMesh does but
// without the binary files: what a solver needs to estimate its memory before
// reading the mesh (core/memoryLimit.hpp).
struct VoronoiMeshSizes {
    std::uint64_t nCells = 0, nVertices = 0, nFaces = 0, nFaceVertices = 0, nBondedFaces = 0, nBonds = 0;
};
VoronoiMeshSizes readVoronoiMeshSizes(const std::filesystem::path& caseDir);

}  // namespace rockfrac
