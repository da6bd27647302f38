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
// times the writing rank gathers the whole state and writes what a serial run writes. When the
// cells have moved far or the ranks' costs drift apart, or when cells are added or removed
// (the crusher's feed and destructor), the whole state is gathered on every rank, changed
// there alike, and cut anew: redistribute().
class DemDecomposer {
public:
    virtual ~DemDecomposer() = default;
    virtual void decompose(DemModel& model) = 0;  // collective
    virtual bool writes() const = 0;
    // Collective: true on every rank when `mine` is true on one.
    virtual bool anyRank(bool mine) = 0;
    // Collective: the whole model's state on the writing rank (null on the others).
    virtual const DemModel* gather(const DemModel& local) = 0;
    // Collective: the whole model's state on every rank, to change alike before redistribute().
    virtual DemModel& gatherEverywhere(const DemModel& local) = 0;
    // Collective: `local` cut anew from the whole model gatherEverywhere() gave (with whatever
    // was changed in it since): cells migrate to the rank their centroid now falls in, the
    // cost weights are the items as last listed. The run continues bit for bit.
    virtual void redistribute(DemModel& local) = 0;
    // Why the cells should be cut anew now (empty: they need not), the same on every rank.
    virtual std::string redistributionDue() const = 0;
    virtual long redistributions() const = 0;          // so far
    virtual double redistributionSeconds() const = 0;  // their wall time so far (gathers included)
    virtual double redistributionBytes() const = 0;    // the whole states gathered on every rank so far
    virtual long wholeGathers() const = 0;             // how many (a feed event that placed nothing too)
    virtual std::string describe() const = 0;          // the log's line, after decompose
};

// The log's line on a decomposed run's cuts and gathers so far.
std::string describeCuts(const DemDecomposer& decomposer);

// After a step of a decomposed run: when the decomposer says a redistribution is due, the
// cells are cut anew and the log says why (collective).
void redistributeWhenDue(DemDecomposer& decomposer, DemModel& local, long step);

// decomposer: null for a serial run.
std::unique_ptr<TimedRun> newBondedDemRun(const Application& app, TimeLoop& loop,
                                          DemDecomposer* decomposer = nullptr);

}  // namespace rockfrac
