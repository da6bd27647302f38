#pragma once
// A bondedDemFoam case: what the solver reads from the case directory and what
// it writes back (parameters, loading, whole-state restart files, VTK).
//
//   constant/rockProperties   rock, steel, bond and contact parameters (DemParameters)
//   constant/loading          plates, gravity, settling stage, stop criterion (Loading)
//   constant/voronoiMesh/     the bonded cells (voronoiMesh)
//   <time>/demState           whole state for `startFrom latestTime`
//   VTK/cells_<n>.vtu, VTK/bonds_<n>.vtp and their .series files
#include <filesystem>
#include <string>
#include <vector>

#include "dem/demModel.hpp"
#include "voronoi/voronoiMesh.hpp"

namespace rockfrac {

class Dictionary;

DemParameters readDemParameters(const Dictionary& rockProperties);
// The top-level entries of constant/rockProperties that readDemParameters reads.
const std::vector<std::string>& demRockPropertiesEntries();

// Two horizontal rigid plates (normal ±z) and what drives them.
struct PlateSpec {
    Vec3 normal;    // into the specimen
    Vec3 velocity;  // [m/s] once loading has started
};

struct Loading {
    PlateSpec lower, upper;
    double startGap = 0.0;           // plate-to-specimen distance at the start [m]
    Vec3 gravity;                    // [m/s^2]
    double settlingTime = 0.0;       // plates at rest, gravity on, before loading [s]
    double stopForceFraction = 0.0;  // stop after the peak once F < fraction * peak (0: off)
    double stopDisplacement = 0.0;   // stop at this plate approach [m] (0: off)
    double minPeakForce = 0.0;       // the peak must exceed this before the drop criterion applies [N]
};

Loading readLoading(const Dictionary& loading);
// The top-level entries of constant/loading (plates) that readLoading reads.
const std::vector<std::string>& demLoadingEntries();

// Cell polyhedra in their body frames, for drawing cells as they move.
struct CellShapes {
    std::vector<int> cellVertexOffset;                                // as VoronoiMesh
    std::vector<Vec3> bodyVertices;                                   // body frame of each cell
    std::vector<int> cellFaceOffset, faceVertexOffset, faceVertices;  // faceVertices: global vertex ids
};
// Take the shapes from the mesh and the model's initial poses (call before any step).
CellShapes captureCellShapes(const VoronoiMesh& mesh, const DemModel& model);

// VTK output of the current state: cells (damage, velocity, id) and bonds (D).
void writeDemVtk(const std::filesystem::path& caseDir, int index, const DemModel& model,
                 const CellShapes& shapes, bool restarted);

// controlDict `backend cpu|cuda;` (default cpu): true for cuda. Asking for cuda where this
// build or machine has none is one UserError naming the entry (demCuda/cudaDemModel.hpp).
class Dictionary;
bool readCudaBackend(const Dictionary& controlDict);
// The entries of controlDict a DEM run (plates or crusher) reads beyond the time loop's:
// backend and the time step's rayleighFraction / criticalFraction (chooseDemTimeStep).
const std::vector<std::string>& demControlEntries();

// Peak memory [bytes] of a DEM run on a mesh of these sizes: the mesh as read, the model's
// arrays, neighbour and contact lists, the code and libraries (an upper estimate;
// docs/reliability.md compares it with measured peaks).
struct VoronoiMeshSizes;
std::uint64_t estimateDemMemoryBytes(const VoronoiMeshSizes& sizes);

// Whole state (cells, bonds, contacts, walls, clock, energies) of a model.
void writeDemState(const std::filesystem::path& file, const DemModel& model, long step, double peakForce,
                   bool loadingStarted);
struct DemRestart {
    long step = 0;
    double time = 0.0;
    double peakForce = 0.0;
    bool loadingStarted = false;
};
DemRestart readDemState(const std::filesystem::path& file, DemModel& model);

}  // namespace rockfrac
