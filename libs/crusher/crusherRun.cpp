#include "crusher/crusherRun.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/memoryLimit.hpp"
#include "crusher/crusherState.hpp"
#include "crusher/destructor.hpp"
#include "crusher/feedRock.hpp"
#include "crusher/machineLoading.hpp"
#include "demCase/demBackend.hpp"
#include "demCase/demCase.hpp"
#include "demCase/demRun.hpp"
#include "demCuda/cudaDemModel.hpp"
#include "geometry/triSurface.hpp"
#include "io/timeSeries.hpp"
#include "voronoi/voronoiMeshIO.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

namespace {

WallMotion wallMotion(const MantlePose& p)
{
    // The spin about the mean axis z first, then the gyration (crusherGeometry.hpp).
    return {p.translation,
            quatFromRotationVector(p.rotation_vector) * quatFromRotationVector(Vec3{0.0, 0.0, p.spin_angle}),
            p.velocity, p.angular_velocity};
}

// The liner as a wall of the model, and its profile for the feed (linerClearance.hpp).
RevolvedLiner addLiner(DemModel& model, const fs::path& stl, const WallMotion& motion, SurfaceFacing facing)
{
    const TriSurface surface = readStl(stl);
    const int wall = model.addTriSurface(surface.points, surface.triangles, motion);
    return revolvedLiner(surface, wall, facing, stl.string());
}

// The most the feed brings by endTime: massRate x endTime (at most totalMass) in rocks of the
// lightest class's smallest size, one more for the last rock's overshoot, each with the most
// cells, vertices, faces and bonds of any class's template; as if none left (an upper
// estimate). Refused before any cell exists when it cannot fit; returns the -dry-run line.
std::string checkFeedMemory(const fs::path& loadingFile, const FeedSpec& feed, double endTime,
                            double smallestRockMass)
{
    double mass = feed.mass_rate * endTime;
    if (feed.total_mass > 0) mass = std::min(mass, feed.total_mass);
    const auto rocks = static_cast<std::uint64_t>(std::min(std::floor(mass / smallestRockMass) + 1.0, 1e7));
    VoronoiMeshSizes one;
    for (const FeedClass& c : feed.classes) {
        const VoronoiMeshSizes t = readVoronoiMeshSizes(c.rock_case);
        one.nCells = std::max(one.nCells, t.nCells);
        one.nVertices = std::max(one.nVertices, t.nVertices);
        one.nFaces = std::max(one.nFaces, t.nFaces);
        one.nFaceVertices = std::max(one.nFaceVertices, t.nFaceVertices);
        one.nBondedFaces = std::max(one.nBondedFaces, t.nBondedFaces);
        one.nBonds = std::max(one.nBonds, t.nBonds);
    }
    const VoronoiMeshSizes all{one.nCells * rocks,        one.nVertices * rocks,    one.nFaces * rocks,
                               one.nFaceVertices * rocks, one.nBondedFaces * rocks, one.nBonds * rocks};
    const std::uint64_t bytes = estimateDemMemoryBytes(all);
    const std::string counts = "up to " + std::to_string(all.nCells) + " cells, " +
                               std::to_string(all.nBonds) + " bonds (" + std::to_string(rocks) +
                               " feed rocks)";
    checkMemoryFits(bytes,
                    loadingFile.string() + ": feed of " + formatNumber(mass) + " kg by endTime, " + counts,
                    "feed less (feed/massRate or feed/totalMass) or stop earlier (endTime)");
    return estimateLine(bytes, counts);
}

// The crusher's run: reads and checks every input in its constructor (UserError before
// any step); TimeLoop drives it.
class CrusherRun final : public TimedRun {
public:
    CrusherRun(const Application& a, TimeLoop& loop, DemDecomposer* decomposer);
    void printSetup() const override;
    long start(bool restarted) override;
    Sampling sampling() const override { return {sampleInterval, Sampling::Rows::windowMeans}; }
    void beforeStep(long step) override;
    StepResult advance(double deltaT) override;
    void afterStep(long step) override;
    void sample() override
    {
        std::vector<double> row = machineRow();
        if (writes()) machineSeries->append(row);
    }
    // The ranks of a decomposed run stop together, at the first step a signal reached one.
    bool interruptedEverywhere(bool here) override { return decomposer ? decomposer->anyRank(here) : here; }
    void writeTime(long step) override;
    std::string writeFailure(long step) override;
    double time() const override { return model->time(); }
    std::string progress() const override;
    void report(bool interrupted) override;

private:
    const Application& app;
    // -parallel: `model` holds this rank's cells and ghosts; the feed and the destructor work
    // on the whole model gathered on every rank, which is then cut anew (DemDecomposer).
    DemDecomposer* decomposer = nullptr;
    DemParameters parameters;
    MachineLoading loading;
    std::unique_ptr<FeedFactory> factory;
    std::unique_ptr<DemModel> model;
    // controlDict `backend cuda;`: the steps run on the device; the host model stays the
    // owner of the state and is synchronised around what changes it on the host (feed,
    // destructor, output), as in bondedDemFoam.
    bool useCuda = false;
    std::unique_ptr<DemBackend> backend;  // made by start()
    std::unique_ptr<TimeSeriesWriter> machineSeries, dischargeSeries;
    CellShapes shapes;
    int mantle = -1, concave = -1, choke = -1;
    bool chokeLowered = false;
    long sampleInterval = 100;  // steps between machine.dat rows (functions/machine/writeInterval)
    double rayleighStep = 0.0;
    CriticalTimeStep critical;
    int stepClass = 0;  // the feed class whose smallest rock sets the stable step

    // Restart (crusherState.hpp): every rock fed and the origin of each cell.
    FeedRecord fed;
    bool restarted = false;
    long restartStep = 0;  // the step the state of a restart records

    // Bookkeeping. The cells inside and their mass change only when cells are fed or
    // discharged: counted then, over the whole model in its order.
    int cellsInside = 0;
    double massInside = 0.0;
    double massDischarged = 0.0, mantleWork = 0.0;
    int fragmentsDischarged = 0;
    // Means over the steps since the last machine.dat row.
    Vec3 sumForce, sumTorque;
    double sumPower = 0.0;
    MantleSpin spin{MantleSpinSpec{}};  // free spin of the mantle (fixed: stays at rest)
    MantlePose pose;                    // of the mantle during the current step
    double lastPower = 0.0;             // the drive's power in the last step [W]
    long sampleSteps = 0;
    // The solver's throughput: cells times steps (substeps too) over the wall time.
    std::chrono::steady_clock::time_point wallStart;
    double cellSteps = 0.0;

    bool writes() const { return !decomposer || decomposer->writes(); }
    void countInside(const DemModel& whole);
    std::string feedClassLine(int i) const;
    static std::vector<Column> machineColumns();
    std::vector<double> machineRow();
    void writeVtk(long step);
    void discharge();
    CrusherState state(long step, const DemModel& whole) const;
    void restoreState();
};

CrusherRun::CrusherRun(const Application& a, TimeLoop& loop, DemDecomposer* d)
    : TimedRun(loop), app(a), decomposer(d)
{
    useCuda = readCudaBackend(controlDict);
    if (decomposer && useCuda)
        throw UserError(controlDict.location("backend").str() +
                        ": backend cuda under -parallel is not built yet; set 'backend cpu;' in " +
                        controlDict.fileName());
    parameters = readDemParameters(Dictionary::readFile(a.path("constant/rockProperties")));
    loading = readMachineLoading(Dictionary::readFile(a.path("constant/loading")), a.casePath());
    spin = MantleSpin(loading.spin);
    parameters.gravity = loading.gravity;
    std::vector<FeedRockTemplate> rocks;
    for (const FeedClass& c : loading.feed.classes)
        rocks.push_back(makeFeedRockTemplate(readVoronoiMesh(c.rock_case), parameters.rock_density));
    factory = std::make_unique<FeedFactory>(loading.feed, std::move(rocks));
    model = std::make_unique<DemModel>(parameters);
    const MantlePose start = mantlePose(loading.machine.kinematics, 0.0);
    std::vector<RevolvedLiner> liners;
    liners.push_back(
        addLiner(*model, loading.machine.mantle_stl, wallMotion(start), SurfaceFacing::awayFromAxis));
    liners.push_back(addLiner(*model, loading.machine.concave_stl, WallMotion{}, SurfaceFacing::towardsAxis));
    mantle = liners[0].wall;
    concave = liners[1].wall;
    factory->setLiners(std::move(liners));
    if (loading.choke.enabled) choke = model->addPlate({0, 0, loading.choke.level}, {0, 0, 1});
    // The step of the smallest rock of each size class (its bonds and contacts are the
    // stiffest per mass of the class, whose cells scale with it); the shortest wins.
    double smallestRockMass = 0.0;
    for (int i = 0; i < factory->classes(); ++i) {
        const DemModel probe(factory->smallestRock(i), parameters);
        const CriticalTimeStep c = probe.criticalTimeStep();
        double mass = 0.0;
        for (double m : probe.cells().mass) mass += m;
        if (i == 0 || c.value < critical.value) {
            critical = c;
            stepClass = i;
        }
        rayleighStep = i == 0 ? probe.rayleighTimeStep() : std::min(rayleighStep, probe.rayleighTimeStep());
        smallestRockMass = i == 0 ? mass : std::min(smallestRockMass, mass);
    }
    const std::string estimate =
        checkFeedMemory(a.path("constant/loading"), loading.feed, runTime.endTime(), smallestRockMass);
    if (a.dryRun()) std::printf("%s\n", estimate.c_str());
    chooseDemTimeStep(controlDict, runTime, rayleighStep, critical,
                      factory->classes() == 1
                          ? std::string("the smallest feed rock")
                          : "the smallest feed rock of class " + loading.feed.classes[stepClass].name);
    // Steps too long for a cell pressed into many contact points are split (DemModel::step).
    model->setStepLimit(runTime.deltaT() / critical.value, critical.bond_frequency,
                        critical.bond_damping_ratio);
    sampleInterval = readSampleInterval(controlDict, "machine", sampleInterval);
    if (runTime.restarting()) restoreState();
}

void CrusherRun::countInside(const DemModel& whole)
{
    cellsInside = whole.cells().size();
    massInside = 0.0;
    for (double c : whole.cells().mass) massInside += c;
}

std::vector<Column> CrusherRun::machineColumns()
{
    return {{"Time", "s"},        {"forceX", "N"},       {"forceY", "N"},          {"forceZ", "N"},
            {"torqueX", "N m"},   {"torqueY", "N m"},    {"torqueZ", "N m"},       {"power", "W"},
            {"massInside", "kg"}, {"massFed", "kg"},     {"massDischarged", "kg"}, {"cells", "-"},
            {"rocksFed", "-"},    {"fragmentsOut", "-"}, {"brokenBonds", "-"},     {"mantleWork", "J"},
            {"kinetic", "J"},     {"stored", "J"},       {"dissipated", "J"},      {"fracture", "J"},
            {"exchanged", "J"},   {"gravityWork", "J"},  {"balanceError", "J"},    {"spinRate", "rad/s"},
            {"spinEnergy", "J"},  {"bearingLoss", "J"},  {"driveWork", "J"}};
}

// The means since the last row (an empty window counts as one step).
std::vector<double> CrusherRun::machineRow()
{
    const double n = std::max<long>(1, sampleSteps);
    const DemEnergies& e = model->energies();
    std::vector<double> row{model->time(),
                            sumForce.x / n,
                            sumForce.y / n,
                            sumForce.z / n,
                            sumTorque.x / n,
                            sumTorque.y / n,
                            sumTorque.z / n,
                            sumPower / n,
                            massInside,
                            factory->massFed(),
                            massDischarged,
                            double(cellsInside),
                            double(factory->rocksFed()),
                            double(fragmentsDischarged),
                            double(model->counters().bonds_broken),
                            mantleWork,
                            e.kinetic(),
                            e.stored(),
                            e.dissipated(),
                            e.fracture,
                            e.exchanged,
                            e.gravity_work,
                            e.balance() - model->initialBalance(),
                            spin.rate(),
                            spin.kineticEnergy(),
                            spin.bearingDissipated(),
                            mantleWork + spin.torqueWork()};
    sumForce = sumTorque = Vec3{};
    sumPower = 0.0;
    sampleSteps = 0;
    return row;
}

void CrusherRun::writeVtk(long step)
{
    if (cellsInside == 0) return;
    backend->download();
    const DemModel* whole = decomposer ? decomposer->gather(*model) : model.get();
    if (writes()) writeDemVtk(app.casePath(), static_cast<int>(step), *whole, shapes, restarted || step > 0);
}

// The state of the whole model and of the run into <time>/ (demState, crusherState), then
// the frames, then the time directory is published: a run killed before the commit restarts
// from the previous time, which writes these frames again. The initial state (step 0, the
// empty machine or the first feed) is a fresh start: no state, only its frame.
void CrusherRun::writeTime(long step)
{
    if (step == 0) {
        writeVtk(step);
        return;
    }
    backend->download();
    const DemModel* whole = decomposer ? decomposer->gather(*model) : model.get();
    if (!writes()) return;
    const fs::path staging = runTime.prepareStagingDir(whole->time());
    writeDemState(staging / "demState", *whole, step, 0.0, false);
    writeCrusherState(staging / "crusherState", state(step, *whole));
    if (cellsInside > 0)
        writeDemVtk(app.casePath(), static_cast<int>(step), *whole, shapes, restarted || step > 0);
    runTime.commitTimeDir(whole->time());
}

CrusherState CrusherRun::state(long step, const DemModel& whole) const
{
    CrusherState c;
    c.step = step;
    c.time = whole.time();
    c.fed = fed;
    c.mass_fed = factory->massFed();
    c.rocks_fed = factory->rocksFed();
    c.rocks_fed_by_class = factory->rocksFedByClass();
    c.attempts_spent = factory->attemptsSpent();
    c.mass_discharged = massDischarged;
    c.fragments_discharged = fragmentsDischarged;
    for (int k = 0; k < whole.nWalls(); ++k) c.wall_work.push_back(whole.wallWork(k));
    c.spin_angle = spin.angle();
    c.spin_rate = spin.rate();
    c.spin_torque_work = spin.torqueWork();
    c.spin_bearing_dissipated = spin.bearingDissipated();
    c.choke_lowered = chokeLowered;
    c.sum_force = sumForce;
    c.sum_torque = sumTorque;
    c.sum_power = sumPower;
    c.last_power = lastPower;
    c.sample_steps = sampleSteps;
    const DemCounters& counters = whole.counters();
    c.split_steps = counters.split_steps;
    c.substeps = counters.substeps;
    c.most_substeps = counters.most_substeps;
    c.neighbour_rebuilds = counters.neighbour_rebuilds;
    return c;
}

// startFrom latestTime: the model built again from the rocks fed (crusherState), its state
// read into it (demState), then the run's books. The walls' work first: readDemState keeps it,
// and marks the restored forces valid last (so that the next step continues from them).
void CrusherRun::restoreState()
{
    const fs::path dir = app.path(runTime.startTimeName());
    const fs::path file = dir / "crusherState";
    const CrusherState c = readCrusherState(file);
    rebuildCrusherModel(c.fed, *factory, *model, shapes, file);
    if (static_cast<int>(c.wall_work.size()) != model->nWalls())
        throw UserError(file.string() + ": walls.work has " + std::to_string(c.wall_work.size()) +
                        " walls, the case " + std::to_string(model->nWalls()) +
                        " (the choke plane on or off?); the state does not belong to this case");
    for (int k = 0; k < model->nWalls(); ++k) {
        WallState w = model->wall(k);
        w.work = c.wall_work[k];
        model->setWallState(k, w);
    }
    const DemRestart r = readDemState(dir / "demState", *model);
    if (r.step != c.step)
        throw UserError(file.string() + ": step " + std::to_string(c.step) + ", but demState's is " +
                        std::to_string(r.step) + "; the two files are of different writes");
    DemCounters counters = model->counters();
    counters.split_steps = c.split_steps;
    counters.substeps = c.substeps;
    counters.most_substeps = c.most_substeps;
    counters.neighbour_rebuilds = c.neighbour_rebuilds;
    model->setCounters(counters);
    fed = c.fed;
    factory->restoreCounters(c.mass_fed, c.rocks_fed, c.rocks_fed_by_class, c.attempts_spent, file.string());
    massDischarged = c.mass_discharged;
    fragmentsDischarged = c.fragments_discharged;
    mantleWork = model->wallWork(mantle);
    spin.restore(c.spin_angle, c.spin_rate, c.spin_torque_work, c.spin_bearing_dissipated);
    chokeLowered = c.choke_lowered;
    sumForce = c.sum_force;
    sumTorque = c.sum_torque;
    sumPower = c.sum_power;
    lastPower = c.last_power;
    sampleSteps = c.sample_steps;
    countInside(*model);
    restartStep = r.step;
    restarted = true;
}

// ---- the loop's hooks (core/timeLoop.hpp) ----------------------------------------

long CrusherRun::start(bool)
{
    if (decomposer) {
        decomposer->decompose(*model);
        std::printf("%s\n", decomposer->describe().c_str());
    }
    backend = std::make_unique<DemBackend>(*model, useCuda);
    if (useCuda) {
        std::printf("Backend: %s, %s (cells are fed and discharged on the host)\n",
                    cudaBackendSummary().c_str(), cudaBackendInfo().status.c_str());
    } else {
        std::printf("Backend: cpu (OpenMP)\n");
    }
    wallStart = std::chrono::steady_clock::now();
    const long first = restarted ? restartStep : 0;
    if (!writes()) return first;
    // A restart continues the series from its time. machine.dat's rows are window means: a
    // restart within a window drops the row the stopped run wrote for its unfinished rest.
    const double t = model->time();
    const double machineFrom = !restarted                    ? -1.0
                               : first % sampleInterval == 0 ? t
                                                             : t - 0.5 * runTime.deltaT();
    machineSeries =
        std::make_unique<TimeSeriesWriter>(app.casePath(), "machine", machineColumns(), machineFrom);
    dischargeSeries = std::make_unique<TimeSeriesWriter>(app.casePath(), "discharge",
                                                         std::vector<Column>{{"Time", "s"},
                                                                             {"cells", "-"},
                                                                             {"mass", "kg"},
                                                                             {"volume", "m^3"},
                                                                             {"equivalentDiameter", "m"},
                                                                             {"sieveSize", "m"}},
                                                         restarted ? t : -1.0);
    return first;
}

// Machine state before a step: mantle pose, choke plane, feed; at step 0 also the forces
// of the initial state for its machine.dat row.
void CrusherRun::beforeStep(long step)
{
    const double t = model->time();
    pose = mantlePose(loading.machine.kinematics, t, spin.angle(), spin.rate());
    model->setWallMotion(mantle, wallMotion(pose));
    if (choke >= 0 && !chokeLowered && t >= loading.choke.duration) {
        WallState w = model->wall(choke);
        w.origin.z = loading.destructor.below - 1e3;  // lowered far below everything
        model->setWallState(choke, w);
        chokeLowered = true;
    }
    const long feedEvery = std::max(1L, std::lround(loading.feed.interval / runTime.deltaT()));
    if (step % feedEvery == 0 && factory->feeds(t)) {
        // Cells are inserted on the host (DemModel::insertCells, the same code for both
        // backends): the device state comes down before and goes up after. A decomposed run
        // inserts them into the whole model on every rank alike and cuts it anew.
        backend->download();  // the factory looks for free space among the current cells
        DemModel& whole = decomposer ? decomposer->gatherEverywhere(*model) : *model;
        const std::vector<InsertedRock> rocks = factory->feed(whole, t);
        for (const InsertedRock& rock : rocks) {
            appendShapes(shapes, rock, whole);
            fed.add(rock);
        }
        if (!rocks.empty()) {
            countInside(whole);
            if (decomposer) decomposer->redistribute(*model);
            backend->upload();
        }
    }
    if (step == 0) backend->evaluateForces(runTime.deltaT());
}

StepResult CrusherRun::advance(double deltaT)
{
    const long stepsBefore = model->counters().steps;
    const double cellsBefore = cellsInside;
    backend->step(deltaT);
    cellSteps += cellsBefore * double(model->counters().steps - stepsBefore);  // substeps too
    const DemStatus& status = model->status();
    if (status.ok()) return {};
    return {false, status.message()};
}

void CrusherRun::afterStep(long step)
{
    // The model books the mantle's work half a step at a time with the forces of each
    // half kick (the mantle moves every step, so the forces are re-evaluated before it).
    mantleWork = model->wallWork(mantle);
    const Vec3 force = model->wallReaction(mantle);
    const Vec3 origin = model->wall(mantle).origin;
    const Vec3 torque =
        model->wallReactionTorque(mantle) + cross(origin - loading.machine.kinematics.pivot, force);
    // The drive delivers the gyration's power: what the wall gives the rocks plus what
    // the rocks' torque takes from the spin (mantleSpin.hpp); with spin fixed the rate is 0.
    const double axialTorque = dot(pose.rotation * Vec3{0.0, 0.0, 1.0}, torque);
    const double power = model->wallPower(mantle) + spin.rate() * axialTorque;
    lastPower = power;
    spin.advance(axialTorque, runTime.deltaT());
    sumForce += force;
    sumTorque += torque;
    sumPower += power;
    ++sampleSteps;
    if (step % loading.destructor.interval == 0) discharge();
    if (decomposer) redistributeWhenDue(*decomposer, *model, step);
}

// The destructor: fragments with a cell below its level leave. A decomposed run gathers the
// whole model only when one of its ranks has such a cell.
void CrusherRun::discharge()
{
    backend->download();  // cells are removed on the host, as they are fed
    if (decomposer) {
        bool below = false;
        const CellArrays& cells = model->cells();
        for (int c = 0; c < cells.size() && !below; ++c)
            below = model->ownsCell(c) && cells.position[c].z < loading.destructor.below;
        if (!decomposer->anyRank(below)) return;
    }
    DemModel& whole = decomposer ? decomposer->gatherEverywhere(*model) : *model;
    const DestructorResult r = destroyBelow(whole, loading.destructor.below);
    if (r.fragments.empty()) return;
    countInside(whole);
    if (decomposer) decomposer->redistribute(*model);
    backend->upload();
    compactShapes(shapes, r.new_index);
    fed.compact(r.new_index);
    massDischarged += r.mass;
    fragmentsDischarged += static_cast<int>(r.fragments.size());
    for (const DischargedFragment& f : r.fragments)
        if (writes())
            dischargeSeries->append(
                {f.time, double(f.n_cells), f.mass, f.volume, f.equivalent_diameter, f.sieve_size});
}

std::string CrusherRun::writeFailure(long step)
{
    if (cellsInside == 0) return {};
    writeVtk(step);
    return "VTK/cells_" + std::to_string(step) + ".vtu";
}

std::string CrusherRun::progress() const
{
    char buffer[200];
    // cut: contacts whose cores intersect in this step (pressed deeper than the shells,
    // docs/theory-dem.md §6), cell–cell pairs + cells on the liners; more than a few means
    // the rocks are jammed.
    const DemCounters& counters = model->counters();
    std::snprintf(buffer, sizeof(buffer),
                  "cells %d  fed %.4g kg  out %.4g kg  P %.4g kW  broken %d  cut %d+%d  split %ld",
                  cellsInside, factory->massFed(), massDischarged, 1e-3 * lastPower, counters.bonds_broken,
                  counters.pair_core_intersections,
                  counters.core_intersections - counters.pair_core_intersections, counters.split_steps);
    return buffer;
}

std::string spinText(const MantleSpinSpec& s)
{
    if (!s.free) return "spin fixed";
    char buffer[160];
    std::snprintf(buffer, sizeof(buffer),
                  "spin free (inertia %.4g kg m^2 about the axis, bearing drag %.4g N m s)", s.inertia,
                  s.bearing_damping);
    return buffer;
}

// One size class: its sizes, template rock, and the band of its cells' sizes it gives (the
// volume-equivalent diameter of the template's mean cell, scaled to the class's smallest and
// largest rock), also as a fraction of the CSS.
std::string CrusherRun::feedClassLine(int i) const
{
    const FeedRockTemplate& rock = factory->rock(i);
    const FeedClass& c = loading.feed.classes[i];
    const auto [lo, hi] = feedClassSizes(loading.feed, i);
    const double cell = std::cbrt(6.0 / 3.14159265358979323846 * rock.volume / rock.mesh.nCells());
    const double small = cell * lo / rock.sieve_size, large = cell * hi / rock.sieve_size;
    const double css = loading.machine.closed_side_setting;
    char buffer[600];
    std::snprintf(buffer, sizeof(buffer),
                  "Feed class %s: sizes %.4g-%.4g mm, rock %s: %d cells, %d bonds, sieve size %.4g mm, "
                  "volume-equivalent diameter %.4g mm; cells %.4g-%.4g mm (volume-equivalent), %.3g-%.3g CSS",
                  c.name.c_str(), 1e3 * lo, 1e3 * hi, c.rock_case.string().c_str(), rock.mesh.nCells(),
                  rock.mesh.nBonds(), 1e3 * rock.sieve_size, 1e3 * rock.equivalent_diameter, 1e3 * small,
                  1e3 * large, small / css, large / css);
    return buffer;
}

void CrusherRun::printSetup() const
{
    const FeedSpec& f = loading.feed;
    const MachineSpec& m = loading.machine;
    std::printf(
        "Machine: mantle gyrating about (%g %g %g) m, eccentric angle %.4f deg, %.4g rpm, %s; "
        "CSS %.1f mm, discharge at z = %.4g m\n",
        m.kinematics.pivot.x, m.kinematics.pivot.y, m.kinematics.pivot.z,
        180.0 / 3.14159265358979323846 * m.kinematics.eccentric_angle,
        m.kinematics.eccentric_speed * 60.0 / (2 * 3.14159265358979323846), spinText(loading.spin).c_str(),
        1e3 * m.closed_side_setting, m.discharge_level);
    std::printf("Feed: sizes %.4g-%.4g mm at %.4g kg/s (at most %.4g kg) in %d size class%s\n",
                1e3 * f.size_min, 1e3 * f.size_max, f.mass_rate, f.total_mass, factory->classes(),
                factory->classes() == 1 ? "" : "es");
    for (int i = 0; i < factory->classes(); ++i) std::printf("%s\n", feedClassLine(i).c_str());
    if (loading.choke.enabled)
        std::printf("Choke plane at z = %.4g m until t = %.4g s\n", loading.choke.level,
                    loading.choke.duration);
    std::printf("Destructor below z = %.4g m, checked every %ld steps\n", loading.destructor.below,
                loading.destructor.interval);
    std::printf(
        "Time step %.4g s = %.3g x stable step %.4g s of the smallest rock%s (Rayleigh %.4g s); end time "
        "%.4g s (%ld steps)\n",
        runTime.deltaT(), runTime.deltaT() / critical.value, critical.value,
        factory->classes() == 1 ? "" : (" of class " + f.classes[stepClass].name).c_str(), rayleighStep,
        runTime.endTime(), runTime.endStep());
    if (restarted)
        std::printf("Restart from time %s (step %ld): %zu rocks fed, %d cells inside\n",
                    runTime.startTimeName().c_str(), restartStep, fed.rocks.size(), cellsInside);
}

void CrusherRun::report(bool)
{
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    const double inside = massInside, massFed = factory->massFed();
    std::printf(
        "Mass: fed %.9g kg = inside %.9g kg + discharged %.9g kg (imbalance %.3g kg); %d rocks fed, %d "
        "fragments discharged\n",
        massFed, inside, massDischarged, massFed - inside - massDischarged, factory->rocksFed(),
        fragmentsDischarged);
    std::string byClass;
    for (int i = 0; i < factory->classes(); ++i)
        byClass +=
            (i ? ", " : "") + loading.feed.classes[i].name + " " + std::to_string(factory->rocksFed(i));
    std::printf("Rocks fed by size class: %s\n", byClass.c_str());
    const DemEnergies& e = model->energies();
    std::printf(
        "Energy: mantle work %.5g J, gravity work %.5g J = kinetic %.5g + stored %.5g + dissipated %.5g "
        "(fracture %.5g) + carried out %.5g J; balance error %.3g J\n",
        mantleWork, e.gravity_work, e.kinetic(), e.stored(), e.dissipated(), e.fracture, e.exchanged,
        e.balance() - model->initialBalance());
    std::printf("%s\n", stepCheckSummary(model->counters()).c_str());
    std::printf("Throughput of the solver: %.4g cell-steps/s (%.4g cell-steps in %.4g s wall)\n",
                cellSteps / std::max(seconds, 1e-9), cellSteps, seconds);
    if (decomposer) std::printf("%s (feed, discharge, moves, balance)\n", describeCuts(*decomposer).c_str());
}

}  // namespace

std::unique_ptr<TimedRun> newCrusherRun(const Application& app, TimeLoop& loop, DemDecomposer* decomposer)
{
    return std::make_unique<CrusherRun>(app, loop, decomposer);
}

}  // namespace rockfrac
