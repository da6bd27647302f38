// feFractureSolver: explicit FEM with the KST-DFH rock model (physics.md §2).
//
// Linear tetrahedra, central differences with lumped mass, KST pressure-dependent
// shear plasticity and DFH probabilistic anisotropic tensile damage (three Weibull
// thresholds per element), loaded by rigid plates with Coulomb friction or by a
// distributed radial pressure on two arcs of a disc (the Hondros check).
//
// Reads  system/controlDict, constant/rockProperties, constant/loading,
//        constant/feMesh/specimen.msh (meshRock with system/feMeshDict)
// Writes <time>/femState (restart), postProcessing/plateForce/0/plateForce.dat,
//        postProcessing/extensometer/0/extensometer.dat,
//        postProcessing/failureLoad/0/failureLoad.dat,
//        VTK/fem_<step>.vtu and VTK/fem.vtu.series
//
// Sample runs:
//   feFractureSolver -case tutorials/BDT/graniteFEM
//   feFractureSolver -case tutorials/BDT/graniteFEM -dry-run
#include "core/application.hpp"
#include "core/timeLoop.hpp"
#include "femCase/femCase.hpp"
#include "femCase/femRun.hpp"

using namespace rockfrac;

namespace {
const AppInfo info{
    "feFractureSolver",
    "Explicit FEM on linear tetrahedra with the KST-DFH rock model (KST shear plasticity, DFH Weibull\n"
    "tensile damage), loaded by rigid plates with friction or by a radial pressure on two arcs of a\n"
    "disc. Writes the plate force, the virtual extensometer, the energies and the cracked elements to\n"
    "postProcessing, the failure load (first drop of more than 20 % below the running maximum), the\n"
    "whole state at write times (restart with startFrom latestTime) and tetrahedra with D1-D3,\n"
    "plastic strain and principal stresses for ParaView. SIGINT/SIGTERM write the state and exit\n"
    "with 130/143.",
    "[options]",
    {"feFractureSolver -case tutorials/BDT/graniteFEM",
     "feFractureSolver -case tutorials/BDT/graniteFEM -dry-run"},
    {},
};
}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, [](Application& app) {
        // system/controlDict: time and write control, the FEM's step controls, its functions.
        TimeLoop loop(app, {femControlEntries(), {"plateForce", "centreStress"}});
        const std::unique_ptr<TimedRun> run = newFeFractureRun(app, loop);  // reads and checks every input
        run->printSetup();
        // Until endTime or the stop criterion: per step the stage, the step, the rows and
        // the write rules; SIGINT/SIGTERM write the state (libs/core/timeLoop.hpp).
        return loop.run(*run);
    });
}
