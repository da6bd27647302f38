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
#include <string>

#include "core/application.hpp"
#include "core/timeLoop.hpp"

namespace rockfrac {

class DemModel;

// A decomposed run (bondedDemFoam -parallel; the MPI side is parallel/mpi/demExchange.hpp):
// after the set-up, every rank cuts the whole model down to its own cells and ghosts; at write
// times the writing rank gathers the whole state and writes what a serial run writes.
class DemDecomposer {
public:
    virtual ~DemDecomposer() = default;
    virtual void decompose(DemModel& model) = 0;  // collective
    virtual bool writes() const = 0;
    // Collective: true on every rank when `mine` is true on one.
    virtual bool anyRank(bool mine) = 0;
    // Collective: the whole model's state on the writing rank (null on the others).
    virtual const DemModel* gather(const DemModel& local) = 0;
    virtual std::string describe() const = 0;  // the log's line, after decompose
};

// decomposer: null for a serial run.
std::unique_ptr<TimedRun> newBondedDemRun(const Application& app, TimeLoop& loop,
                                          DemDecomposer* decomposer = nullptr);

}  // namespace rockfrac
