#pragma once
// A feFractureSolver case: what the solver reads from the case directory and what
// it writes back (material, loading, whole-state restart files, VTK).
//
//   constant/rockProperties   material model, elasticity, KST, DFH (readFemParameters)
//   constant/loading          rigid plates or the distributed arc load, gravity settling,
//                             stop and failure criteria, extensometer (readFemLoading)
//   constant/feMesh/specimen.msh   the tetrahedra (meshRock with system/feMeshDict)
//   <time>/femState           whole state for `startFrom latestTime`
//   VTK/fem_<step>.vtu and VTK/fem.vtu.series
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fem/femModel.hpp"

namespace rockfrac {

class Dictionary;

// Material model, elasticity, KST and DFH from constant/rockProperties (the
// massDamping, time step and mass scaling come from controlDict, the contact
// penalties from constant/loading).
fem::FemParameters readFemParameters(const Dictionary& rockProperties);
// The top-level entries of constant/rockProperties that readFemParameters reads.
const std::vector<std::string>& femRockPropertiesEntries();
// The entries of controlDict the FEM run reads beyond the time loop's (FeFractureRun's
// readSolverControls): timeStepSafety, massScalingTimeStep, massDamping.
const std::vector<std::string>& femControlEntries();

// Two horizontal rigid plates (lower normal +z, upper -z).
struct FemPlateSpec {
    Vec3 velocity;          // [m/s] once loading has started
    double friction = 0.6;  // Coulomb coefficient (paper: 0.6)
};

// Uniform radial pressure p = pressureRate * (t - settlingTime) on the two arcs of the
// cylindrical surface of a disc (axis y) around +z and -z, half-angle `halfAngle` each
// (the distributed load of the Hondros solution).
struct ArcLoadSpec {
    double halfAngle = 0.0;     // [rad]
    double pressureRate = 0.0;  // [Pa/s]
};

struct FemLoading {
    enum class Kind { plates, arcLoad };
    Kind kind = Kind::plates;
    FemPlateSpec lower, upper;
    double startGap = 0.0;  // upper plate to specimen at the start [m]; the lower plate touches
    double contactPenaltyScale = 1.0;
    double tangentialPenaltyRatio = 1.0;
    double contactCrushingPressure = 0.0;  // plates/crushingPressure [Pa], 0 = off
    ArcLoadSpec arc;
    Vec3 gravity;                            // [m/s^2]
    double settlingTime = 0.0;               // plates at rest (arc load zero), gravity on, before loading [s]
    double stopForceFraction = 0.0;          // stop after the peak once F < fraction * peak (0: off)
    double minPeakForce = 0.0;               // the peak must exceed this before the stop applies [N]
    double failureDropFraction = 0.2;        // FailureLoadDetector's X
    double extensometerLength = 20e-3;       // [m], along z through the centre
    std::optional<Vec3> extensometerCentre;  // default: centre of the mesh's bounding box

    // Approach speed of the plates (lower minus upper velocity along z) [m/s].
    double approachSpeed() const { return lower.velocity.z - upper.velocity.z; }
};

FemLoading readFemLoading(const Dictionary& loading);
// The top-level entries of constant/loading that readFemLoading reads.
const std::vector<std::string>& femLoadingEntries();

// Lumped nodal forces of a uniform radial pressure of 1 Pa on the two arcs of a disc
// with axis y through `centre` (3 per node), from the boundary faces whose centroid lies on
// the curved surface within the half-angle of +z or -z. `topForce` receives the downward
// resultant on the upper arc [N per Pa].
std::vector<double> arcLoadUnitForces(const fem::TetMesh& mesh, const Vec3& centre, double halfAngle,
                                      double& topForce);

// What the run adds to the model state for a bitwise restart.
struct FemRunState {
    long step = 0;
    double peakForce = 0.0;  // running maximum of the force (stop criterion)
    // At the running maximum of the failure-load detector (drop fraction X): time, gap
    // change, extensometer, KE / W_ext.
    double peakTime = 0.0, peakGap = 0.0, peakElongation = 0.0, kineticRatioAtPeak = 0.0;
    // FailureLoadDetector state for the drop fractions 10 %, X, 30 %: maximum, failed, time.
    std::vector<double> detectorMaximum, detectorFailed, detectorTime;
};

void writeFemState(const std::filesystem::path& file, fem::FemModel& model, const FemRunState& run);
// Restores model and run state (the plates must have been added already).
FemRunState readFemState(const std::filesystem::path& file, fem::FemModel& model);

// VTK/fem_<index>.vtu (reference points, displacement, D1-D3, equivalent plastic strain,
// principal stresses) and VTK/fem.vtu.series.
void writeFemVtk(const std::filesystem::path& caseDir, long index, const fem::FemModel& model,
                 bool restarted);

}  // namespace rockfrac
