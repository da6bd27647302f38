// bondedDemFoam: the bonded Voronoi DEM solver (physics.md §3).
//
// Rigid Voronoi cells (dilated polyhedra) glued at their face vertices by
// cohesive bonds that soften and break (Eqs. 5-20, Algorithm 1), then touching
// by Hertz-Mindlin contact, loaded by rigid plates.
//
// Reads  system/controlDict, constant/rockProperties, constant/loading,
//        constant/voronoiMesh/ (voronoiMesh)
// A `machine` section in constant/loading instead of `plates` runs a cone crusher
// (libs/crusher, docs/user-guide-crusher.md): mantle and concave from meshCrusher,
// the feed factory, the choke plane and the destructor; it writes
// postProcessing/machine/0/machine.dat and postProcessing/discharge/0/discharge.dat.
// Writes <time>/demState (restart), postProcessing/plateForce/0/plateForce.dat,
//        VTK/cells_<step>.vtu, VTK/bonds_<step>.vtp and their .series files
#include <filesystem>

#include "core/application.hpp"
#include "core/dictionary.hpp"
#include "core/timeLoop.hpp"
#include "crusher/crusherRun.hpp"
#include "crusher/machineLoading.hpp"
#include "demCase/demCase.hpp"
#include "demCase/demRun.hpp"
#include "demCuda/cudaDemModel.hpp"

using namespace rockfrac;

namespace {
const AppInfo info{
    "bondedDemFoam",
    "Bonded Voronoi DEM: cells glued at their face vertices by softening bonds, Hertz-Mindlin contact\n"
    "after breakage, rigid plates with prescribed velocity. Writes the plate force, broken bonds and\n"
    "the energy balance to postProcessing/plateForce, the whole state at write times (restart with\n"
    "startFrom latestTime) and cells/bonds for ParaView. SIGINT/SIGTERM write the state and exit\n"
    "with 130/143.\n"
    "Backends (controlDict 'backend cpu|cuda;', default cpu): cpu (OpenMP); " +
        cudaBackendSummary() + ".",
    "[options]",
    {"bondedDemFoam -case tutorials/BDT/granite", "bondedDemFoam -case tutorials/BDT/granite -dry-run",
     "bondedDemFoam -case tutorials/CH660/tiny"},
    {},
};
}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, [](Application& app) {
        const auto loading = app.path("constant/loading");
        const bool crusher =
            std::filesystem::exists(loading) && isMachineLoading(Dictionary::readFile(loading));
        // system/controlDict: time and write control, the DEM step, the run's function.
        TimeLoop loop(app, {demControlEntries(), {crusher ? "machine" : "plateForce"}});
        // Reads and checks every input: plates on a specimen, or a cone crusher.
        const std::unique_ptr<TimedRun> run = crusher ? newCrusherRun(app, loop) : newBondedDemRun(app, loop);
        run->printSetup();
        // Until endTime or the stop criterion: per step the stage, the step, the rows and
        // the write rules; SIGINT/SIGTERM write the state (libs/core/timeLoop.hpp).
        return loop.run(*run);
    });
}
