// bondedDemFoam: the bonded Voronoi DEM solver (physics.md §3).
//
// Rigid Voronoi cells (dilated polyhedra) glued at their face vertices by
// cohesive bonds that soften and break (Eqs. 5-20, Algorithm 1), then touching
// by Hertz-Mindlin contact, loaded by rigid plates.
//
// Reads  system/controlDict, constant/rockProperties, constant/loading,
//        constant/voronoiMesh/ (voronoiMesh)
// Writes <time>/demState (restart), postProcessing/plateForce/0/plateForce.dat,
//        VTK/cells_<step>.vtu, VTK/bonds_<step>.vtp and their .series files
#include "core/application.hpp"
#include "demCase/demRun.hpp"

using namespace rockfrac;

namespace {
const AppInfo info{
    "bondedDemFoam",
    "Bonded Voronoi DEM: cells glued at their face vertices by softening bonds, Hertz-Mindlin contact\n"
    "after breakage, rigid plates with prescribed velocity. Writes the plate force, broken bonds and\n"
    "the energy balance to postProcessing/plateForce, the whole state at write times (restart with\n"
    "startFrom latestTime) and cells/bonds for ParaView. SIGINT/SIGTERM write the state and exit\n"
    "with 130/143.",
    "[options]",
    {"bondedDemFoam -case tutorials/BDT/granite", "bondedDemFoam -case tutorials/BDT/granite -dry-run"},
    {},
};
}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, [](Application& app) {
        BondedDemRun run(app);
        run.printSetup();
        return run.execute();
    });
}
