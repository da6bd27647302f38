#pragma once
// bondedDemFoam with plates: a bonded Voronoi specimen loaded between two rigid plates.
//
// The run is a TimedRun (core/timeLoop.hpp): its step (CPU or CUDA backend), its
// plateForce.dat rows, its stop criterion and its time directories (<time>/demState,
// VTK/cells_<step>.vtu); the loop, the write rules, signals and restart are TimeLoop's.
//
//   TimeLoop loop(app, {demControlEntries(), {"plateForce"}});
//   const std::unique_ptr<TimedRun> run = newBondedDemRun(app, loop);  // reads and checks every input
//   run->printSetup();
//   return loop.run(*run);
#include <memory>

#include "core/application.hpp"
#include "core/timeLoop.hpp"

namespace rockfrac {

std::unique_ptr<TimedRun> newBondedDemRun(const Application& app, TimeLoop& loop);

}  // namespace rockfrac
