#pragma once
// The crusher's restart: <time>/crusherState beside the model's <time>/demState.
//
// The model of a crusher run is not the case's mesh: the feed inserts rocks and the
// destructor removes fragments. demState (demCase.hpp) holds the state of the cells there
// are; crusherState holds what it takes to build that model again and everything else the
// run carries on with: every rock fed (its class, drawn size and pose), which rock and which
// cell of it each current cell is, the feed factory's counters, the destructor's books, the
// walls' work, the mantle's spin, the choke, and the machine.dat window in progress. A
// restart inserts every rock fed again, in order, as the factory did (its class's template
// scaled to its size, at its pose), removes the cells gone since (the order is kept), reads
// demState into that model and the rest into the run: the continued run is the
// uninterrupted one, bit for bit.
//
//   FeedRecord fed;                        // kept by the run
//   fed.add(rock);  fed.compact(newIndex); // after each feed and discharge
//   writeCrusherState(staging / "crusherState", state);
//   CrusherState state = readCrusherState(dir / "crusherState");
//   rebuildCrusherModel(state.fed, factory, model, shapes, file);  then readDemState(model)
#include <filesystem>
#include <vector>

#include "crusher/feedRock.hpp"
#include "demCase/demCase.hpp"

namespace rockfrac {

// One rock the feed put into the model: enough to put it there again.
struct FedRock {
    int index = 0;       // the rock's number (its random stream)
    int feed_class = 0;  // its size class, whose template it copies
    int n_cells = 0;     // of that template
    double size = 0.0;   // drawn sieve size [m]
    WallMotion pose;     // where it was put: x = translation + R x_mesh, and its velocity
};

// Every rock fed, and the origin of each cell of the model.
struct FeedRecord {
    std::vector<FedRock> rocks;  // in the order fed, those discharged since too
    // Per cell of the model, in its order: the rock (into `rocks`) and that rock's cell it is.
    std::vector<int> cell_rock, cell_local;

    // A rock the factory just inserted (its cells the model's last ones).
    void add(const InsertedRock& rock);
    // Cells removed (DestructorResult::new_index: old cell -> new, -1 removed).
    void compact(const std::vector<int>& new_index);
};

// What a crusher run carries from one step to the next beyond the model's state.
struct CrusherState {
    long step = 0;
    double time = 0.0;
    FeedRecord fed;
    // The feed factory's counters (FeedFactory::restoreCounters).
    double mass_fed = 0.0;
    int rocks_fed = 0;
    std::vector<int> rocks_fed_by_class;
    long attempts_spent = 0;
    // The destructor's books.
    double mass_discharged = 0.0;
    int fragments_discharged = 0;
    std::vector<double> wall_work;  // per wall of the model (DemModel::wallWork)
    // The mantle's spin (MantleSpin::restore).
    double spin_angle = 0.0, spin_rate = 0.0, spin_torque_work = 0.0, spin_bearing_dissipated = 0.0;
    bool choke_lowered = false;
    // The machine.dat window in progress: sums since its last row.
    Vec3 sum_force, sum_torque;
    double sum_power = 0.0, last_power = 0.0;
    long sample_steps = 0;
    // The step check's counters (the log's summary; DemCounters).
    long split_steps = 0, substeps = 0, neighbour_rebuilds = 0;
    int most_substeps = 0;
};

void writeCrusherState(const std::filesystem::path& file, const CrusherState& state);
// UserError naming the file when it is torn, corrupt or inconsistent.
CrusherState readCrusherState(const std::filesystem::path& file);

// Shapes of the inserted cells for VTK (body-frame polyhedra), kept in step with the model:
// a rock's cells just inserted, and cells removed (new_index as FeedRecord::compact).
void appendShapes(CellShapes& shapes, const InsertedRock& rock, const DemModel& model);
void compactShapes(CellShapes& shapes, const std::vector<int>& new_index);

// The model of a restart (cells only; the walls are the case's): every rock of `fed` inserted
// again in order as the factory inserted it, with its shapes, then the cells that are gone
// removed (DemModel::removeCellsOnly; the order is kept). The state is then read into it
// (readDemState). UserError naming `file` when the rocks do not fit this case's feed.
void rebuildCrusherModel(const FeedRecord& fed, const FeedFactory& factory, DemModel& model,
                         CellShapes& shapes, const std::filesystem::path& file);

}  // namespace rockfrac
