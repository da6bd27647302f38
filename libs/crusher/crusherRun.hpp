#pragma once
// A bondedDemFoam run of a cone crusher (constant/loading has a `machine` section):
// the gyrating mantle and the fixed concave as triangulated walls, the feed factory,
// the choke plane, the destructor below the discharge (docs/theory-crusher.md).
//
// The run is a TimedRun (core/timeLoop.hpp): its step, its rows and its time directories
// (<time>/demState and <time>/crusherState, crusherState.hpp, and VTK/cells_<step>.vtu); the
// loop, the write rules, signals and restart are TimeLoop's.
//
//   TimeLoop loop(app, {demControlEntries(), {"machine"}});
//   const std::unique_ptr<TimedRun> run = newCrusherRun(app, loop);  // reads and checks every input
//   run->printSetup();
//   return loop.run(*run);
//
// Writes postProcessing/machine/0/machine.dat (means over each sampling window of the
// mantle force, torque about the pivot and power; masses inside, fed and discharged,
// energies), postProcessing/discharge/0/discharge.dat (one row per fragment that left),
// <time>/demState and <time>/crusherState at write times and at a signal (not at step 0: a
// fresh start needs none), and VTK/cells_<step>.vtu. Both series continue from a restart's time.
#include <memory>

#include "core/application.hpp"
#include "core/timeLoop.hpp"

namespace rockfrac {

class DemDecomposer;

// decomposer: null for a serial run; with -parallel the feed and the destructor change the
// whole model, gathered on every rank, which is then cut anew (demCase/demRun.hpp).
std::unique_ptr<TimedRun> newCrusherRun(const Application& app, TimeLoop& loop,
                                        DemDecomposer* decomposer = nullptr);

}  // namespace rockfrac
