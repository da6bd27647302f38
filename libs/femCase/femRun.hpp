#pragma once
// A feFractureSolver run: a tetrahedral specimen with the KST-DFH rock model, loaded by
// rigid plates or by a pressure on two arcs of a disc.
//
// The run is a TimedRun (core/timeLoop.hpp): its step, its rows (plateForce, extensometer,
// centreStress), its stop criterion and its time directories (<time>/femState,
// VTK/fem_<step>.vtu); the loop, the write rules, signals and restart are TimeLoop's.
//
//   TimeLoop loop(app, {femControlEntries(), {"plateForce", "centreStress"}});
//   const std::unique_ptr<TimedRun> run = newFeFractureRun(app, loop);  // reads and checks every input
//   run->printSetup();
//   return loop.run(*run);
#include <memory>

#include "core/application.hpp"
#include "core/timeLoop.hpp"

namespace rockfrac {

std::unique_ptr<TimedRun> newFeFractureRun(const Application& app, TimeLoop& loop);

}  // namespace rockfrac
