#include "demCase/demRun.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/memoryLimit.hpp"
#include "demCase/demBackend.hpp"
#include "demCase/demCase.hpp"
#include "demCuda/cudaDemModel.hpp"
#include "effects/modelEffect.hpp"
#include "io/timeSeries.hpp"
#include "voronoi/voronoiMeshIO.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

// Bytes the run holds per mesh item: the VoronoiMesh as read (with its file
// buffers), the DemModel's cell, interface and bond arrays (DemModel::memoryBytes
// itemises them), and a generous share of neighbour and contact lists per cell;
// plus the code and libraries. An upper estimate: docs/reliability.md compares
// it with the measured peak.
std::uint64_t estimateDemMemoryBytes(const VoronoiMeshSizes& s)
{
    constexpr std::uint64_t perCell = 2000, perVertex = 100, perFace = 80, perFaceVertex = 8,
                            perBondedFace = 200, perBond = sizeof(VoronoiBond) + 150, libraries = 50000000;
    return libraries + perCell * s.nCells + perVertex * s.nVertices + perFace * s.nFaces +
           perFaceVertex * s.nFaceVertices + perBondedFace * s.nBondedFaces + perBond * s.nBonds;
}

namespace {

// Refuse a mesh that cannot fit before reading it (core/memoryLimit.hpp); under -dry-run,
// print the estimate.
void checkDemMemory(const fs::path& caseDir, bool dryRun)
{
    const VoronoiMeshSizes sizes = readVoronoiMeshSizes(caseDir);
    const std::string counts =
        std::to_string(sizes.nCells) + " cells, " + std::to_string(sizes.nBonds) + " bonds";
    checkMemoryFits(estimateDemMemoryBytes(sizes),
                    (caseDir / voronoiMeshDirectory / "meshInfo").lexically_normal().string() + ": " +
                        std::to_string(sizes.nCells) + " cells and " + std::to_string(sizes.nBonds) +
                        " bonds",
                    "use fewer cells (nCells of system/voronoiMeshDict) or a machine with more memory");
    if (dryRun) std::printf("%s\n", estimateLine(estimateDemMemoryBytes(sizes), counts).c_str());
}

}  // namespace

// controlDict `backend cpu|cuda;` (default cpu). Asking for cuda where this build or
// machine has none is one error naming the entry (demCuda/cudaDemModel.hpp).
const std::vector<std::string>& demControlEntries()
{
    static const std::vector<std::string> entries = {"backend", "rayleighFraction", "criticalFraction"};
    return entries;
}

bool readCudaBackend(const Dictionary& controlDict)
{
    if (!controlDict.found("backend")) return false;
    if (controlDict.getWord("backend", {"cpu", "cuda"}) == "cpu") return false;
    const CudaBackendInfo info = cudaBackendInfo();
    if (!info.compiled || info.devices == 0)
        throw UserError(controlDict.location("backend").str() + ": backend cuda is not available: " +
                        info.status + "; set 'backend cpu;' in " + controlDict.fileName());
    return true;
}

namespace {

// The plates' run: reads and checks every input in its constructor (UserError before any
// step); TimeLoop drives it through the hooks below.
class BondedDemRun final : public TimedRun {
public:
    BondedDemRun(const Application& a, TimeLoop& loop, DemDecomposer* decomposer);
    // The log's set-up and summary.
    void printSetup() const override;
    void report(bool interrupted) override;

    // ---- the loop's hooks (core/timeLoop.hpp), in the loop's order

    long start(bool) override
    {
        if (decomposer) {
            decomposer->decompose(*model);
            std::printf("%s\n", decomposer->describe().c_str());
        }
        backend = std::make_unique<DemBackend>(*model, useCuda);
        if (const CudaDemModel* device = backend->device())
            std::printf("CUDA backend: %.3g MB of device memory (%.0f bytes per cell)\n",
                        1e-6 * static_cast<double>(device->deviceBytes()),
                        static_cast<double>(device->deviceBytes()) / model->cells().size());
        if (writes())
            plateForceSeries = std::make_unique<TimeSeriesWriter>(app.casePath(), "plateForce", columns(),
                                                                  restarted ? model->time() : -1.0);
        return restarted ? restartStep : 0;
    }

    Sampling sampling() const override { return {sampleInterval, Sampling::Rows::instantaneous}; }

    void beforeStep(long step) override
    {
        applyStage();
        // The reactions of the initial state for its row and time directory (a restart
        // reads the forces from its state file).
        if (step == 0) backend->evaluateForces(runTime.deltaT());
    }

    StepResult advance(double deltaT) override
    {
        backend->step(deltaT);
        const DemStatus& status = model->status();
        if (status.ok()) return {};
        return {false, status.message() +
                           "; likely cause: the time step is too large for the stiffest bond or contact; "
                           "reduce deltaT"};
    }

    void afterStep(long step) override
    {
        if (loadingStarted) peakForce = std::max(peakForce, plateForce());
        if (decomposer) redistributeWhenDue(*decomposer, *model, step);
    }

    void sample() override
    {
        if (writes()) plateForceSeries->append(sampleRow());
    }

    std::string stopReason() const override
    {
        if (!loadingStarted) return {};
        const bool approached = loading.stopDisplacement > 0 && plateApproach() >= loading.stopDisplacement;
        const bool dropped = loading.stopForceFraction > 0 && peakForce > loading.minPeakForce &&
                             peakForce > 0 && plateForce() < loading.stopForceFraction * peakForce;
        if (!approached && !dropped) return {};
        return "stop criterion met (force below the set fraction of its peak, or maximum approach)";
    }

    void writeTime(long step) override
    {
        backend->download();  // the cell arrays from the device
        const DemModel* whole = wholeState();
        if (!writes()) return;
        // State, then frames, then the time directory is published: a run killed before the
        // commit restarts from the previous time, which writes these frames again.
        const fs::path staging = runTime.prepareStagingDir(whole->time());
        writeDemState(staging / "demState", *whole, step, peakForce, loadingStarted);
        writeDemVtk(app.casePath(), static_cast<int>(step), *whole, shapes, restarted || step > 0);
        runTime.commitTimeDir(whole->time());
    }

    std::string writeFailure(long step) override
    {
        backend->download();
        const DemModel* whole = wholeState();
        if (!writes()) return {};
        writeDemVtk(app.casePath(), static_cast<int>(step), *whole, shapes, true);
        return "VTK/cells_" + std::to_string(step) + ".vtu";
    }

    // The ranks of a decomposed run stop together, at the first step a signal reached one.
    bool interruptedEverywhere(bool here) override { return decomposer ? decomposer->anyRank(here) : here; }

    double time() const override { return model->time(); }

    std::string progress() const override
    {
        const DemEnergies& e = model->energies();
        const double scale = std::max({e.externalWork(), e.kinetic() + e.stored(), 1e-30});
        char buffer[160];
        std::snprintf(buffer, sizeof(buffer), "F %.4g kN (peak %.4g)  broken %d/%d  balance %+.2g %%",
                      1e-3 * plateForce(), 1e-3 * peakForce, model->counters().bonds_broken,
                      model->counters().bonds, 100 * (e.balance() - model->initialBalance()) / scale);
        return buffer;
    }

private:
    bool writes() const { return !decomposer || decomposer->writes(); }
    // The whole model's state to write (gathered on the writing rank of a decomposed run).
    const DemModel* wholeState() { return decomposer ? decomposer->gather(*model) : model.get(); }

    void placePlates()
    {
        double zMin = 1e300, zMax = -1e300;
        for (const auto& v : mesh.vertices) {
            zMin = std::min(zMin, v.z);
            zMax = std::max(zMax, v.z);
        }
        lowerPlate = model->addPlate({0, 0, zMin - loading.startGap}, loading.lower.normal);
        upperPlate = model->addPlate({0, 0, zMax + loading.startGap}, loading.upper.normal);
    }

    void restoreState()
    {
        const fs::path file = app.path(runTime.startTimeName()) / "demState";
        const DemRestart r = readDemState(file, *model);
        restartStep = r.step;
        peakForce = r.peakForce;
        loadingStarted = r.loadingStarted;
        restarted = true;
        applyStage();
    }

    // Plates at rest during settling, then at their loading velocities.
    void applyStage()
    {
        const bool loadingNow = model->time() >= loading.settlingTime * (1 - 1e-12);
        if (loadingNow) loadingStarted = true;
        model->setWallVelocity(lowerPlate, loadingStarted ? loading.lower.velocity : Vec3{});
        model->setWallVelocity(upperPlate, loadingStarted ? loading.upper.velocity : Vec3{});
    }

    double plateForce() const { return model->wallReaction(upperPlate).z; }
    double lowerPlateForce() const { return -model->wallReaction(lowerPlate).z; }
    // How far the plates have approached each other.
    double plateApproach() const
    {
        return model->wallDisplacement(lowerPlate).z - model->wallDisplacement(upperPlate).z;
    }
    // What the machine records: the plate approach plus whatever model effects put
    // in series with the specimen (compliance, seating); equal without them.
    double gapChange() const { return effects.recordedDisplacement(plateApproach(), plateForce()); }

    std::vector<double> sampleRow() const
    {
        const DemEnergies& e = model->energies();
        return {model->time(),
                gapChange(),
                plateForce(),
                lowerPlateForce(),
                static_cast<double>(model->counters().bonds_broken),
                e.kinetic(),
                e.stored(),
                e.dissipated(),
                e.fracture,
                e.externalWork(),
                e.balance() - model->initialBalance(),
                plateApproach()};
    }

    static std::vector<Column> columns()
    {
        return {{"Time", "s"},        {"gapChange", "m"},    {"force", "N"},        {"forceLower", "N"},
                {"brokenBonds", "-"}, {"kinetic", "J"},      {"strain", "J"},       {"dissipated", "J"},
                {"fracture", "J"},    {"externalWork", "J"}, {"balanceError", "J"}, {"plateApproach", "m"}};
    }

    const Application& app;
    DemDecomposer* decomposer = nullptr;  // -parallel
    DemParameters parameters;
    Loading loading;
    ModelEffects effects;  // constant/modelEffects (optional): off = the baseline model
    VoronoiMesh mesh;
    std::unique_ptr<DemModel> model;
    bool useCuda = false;
    std::unique_ptr<DemBackend> backend;  // made by start()
    std::unique_ptr<TimeSeriesWriter> plateForceSeries;
    CellShapes shapes;
    int lowerPlate = -1, upperPlate = -1;
    long sampleInterval = 10;  // steps between plateForce rows (functions/plateForce/writeInterval)
    double rayleighStep = 0.0;
    CriticalTimeStep critical;

    // Run state (restart).
    long restartStep = 0;  // the step the state file of a restart records
    double peakForce = 0.0;
    bool loadingStarted = false;
    bool restarted = false;
};

BondedDemRun::BondedDemRun(const Application& a, TimeLoop& loop, DemDecomposer* d)
    : TimedRun(loop), app(a), decomposer(d)
{
    useCuda = readCudaBackend(controlDict);
    if (decomposer && useCuda)
        throw UserError(controlDict.location("backend").str() +
                        ": backend cuda under -parallel is not built yet; set 'backend cpu;' in " +
                        controlDict.fileName());
    parameters = readDemParameters(Dictionary::readFile(a.path("constant/rockProperties")));
    loading = readLoading(Dictionary::readFile(a.path("constant/loading")));
    parameters.gravity = loading.gravity;
    if (fs::exists(a.path("constant/modelEffects"))) {
        effects = ModelEffects::read(Dictionary::readFile(a.path("constant/modelEffects")));
        effects.applyToParameters(parameters);
        parameters.validate();
    }
    if (!fs::exists(a.path("constant/voronoiMesh/meshInfo")))
        throw UserError("missing " + a.path("constant/voronoiMesh").string() +
                        "; run voronoiMesh first to make the bonded cells");
    checkDemMemory(a.casePath(), a.dryRun());
    mesh = readVoronoiMesh(a.casePath());
    model = std::make_unique<DemModel>(mesh, parameters);
    shapes = captureCellShapes(mesh, *model);
    placePlates();
    effects.applyToModel(*model, {model->wall(lowerPlate).origin.z, model->wall(upperPlate).origin.z});
    rayleighStep = model->rayleighTimeStep();
    critical = model->criticalTimeStep();
    chooseDemTimeStep(controlDict, runTime, rayleighStep, critical, "this mesh and these parameters");
    // Steps too long for a cell pressed into many contact points are split (DemModel::step).
    model->setStepLimit(runTime.deltaT() / critical.value, critical.bond_frequency,
                        critical.bond_damping_ratio);
    sampleInterval = readSampleInterval(controlDict, "plateForce", sampleInterval);
    if (runTime.restarting()) restoreState();
}

// The interfaces' areas and, when the bond size effect is on, its factors and the
// reference area that would leave this mesh's mean factor at 1 (the value to give for
// the mesh the bonds were calibrated on).
void printBondSizeEffect(const InterfaceArrays& faces, const DemParameters& p)
{
    if (faces.size() == 0) return;
    const double m = p.bond_size_effect_modulus > 0.0 ? p.bond_size_effect_modulus : 7.0;
    double areaSum = 0.0, powerSum = 0.0, factorSum = 0.0, factorMin = 1e300, factorMax = 0.0;
    for (int k = 0; k < faces.size(); ++k) {
        const double area = faces.bond_area[k] * (faces.bond_offset[k + 1] - faces.bond_offset[k]);
        areaSum += area;
        powerSum += std::pow(area, -1.0 / m);
        const double factor = p.bondSizeFactor(area);
        factorSum += factor;
        factorMin = std::min(factorMin, factor);
        factorMax = std::max(factorMax, factor);
    }
    const double n = faces.size();
    const double neutral = std::pow(powerSum / n, -m);
    if (!(p.bond_size_effect_modulus > 0.0)) {
        std::printf(
            "Interfaces: %d, mean area %.4g mm^2 (bond size effect off; with m = 7 the reference area "
            "%.4g mm^2 would leave this mesh's mean strength factor at 1)\n",
            faces.size(), 1e6 * areaSum / n, 1e6 * neutral);
        return;
    }
    std::printf(
        "Interfaces: %d, mean area %.4g mm^2; bond size effect (A_ref/A)^(1/m), m %.3g, A_ref %.4g mm^2: "
        "strength factors %.3f-%.3f, mean %.4f (mean 1 at A_ref %.4g mm^2)\n",
        faces.size(), 1e6 * areaSum / n, m, 1e6 * p.bond_size_effect_reference_area, factorMin, factorMax,
        factorSum / n, 1e6 * neutral);
}

void BondedDemRun::printSetup() const
{
    const CellArrays& cells = model->cells();
    double mass = 0;
    for (int c = 0; c < cells.size(); ++c) mass += cells.mass[c];
    std::printf("Mesh: %d cells, %d bonds, dilation radius %.4g mm, mass %.5g kg\n", mesh.nCells(),
                mesh.nBonds(), 1e3 * mesh.dilationRadius, mass);
    if (model->counters().own_radius_cells > 0)
        std::printf(
            "Dilation: %d cells too thin for the dilation radius (a centroid-face distance below 1.1 "
            "radii) have their own, half that distance (their dilated cores stay inside them)\n",
            model->counters().own_radius_cells);
    std::printf("Bonds: %s, damping %s %.3g\n", parameters.bond_law->describe().c_str(),
                dampingReadingName(parameters.damping_reading), parameters.bond_damping);
    printBondSizeEffect(model->interfaces(), parameters);
    std::printf("Time step %.4g s = %.4g x Rayleigh step %.4g s; end time %.4g s (%ld steps)\n",
                runTime.deltaT(), runTime.deltaT() / rayleighStep, rayleighStep, runTime.endTime(),
                runTime.endStep());
    std::printf(
        "Stable step %.4g s (bonds %.4g s: highest frequency %.4g rad/s, damping ratio %.3g, Gershgorin "
        "translation %.4g s, rotation %.4g s; contacts %.4g s); the step is %.3g of it\n",
        critical.value, critical.bond, critical.bond_frequency, critical.bond_damping_ratio,
        critical.bond_translation_bound, critical.bond_rotation_bound, critical.contact,
        runTime.deltaT() / critical.value);
    std::printf(
        "Plates: upper velocity (%g %g %g) m/s, lower (%g %g %g) m/s, settling %.4g s; memory %.3g MB\n",
        loading.upper.velocity.x, loading.upper.velocity.y, loading.upper.velocity.z,
        loading.lower.velocity.x, loading.lower.velocity.y, loading.lower.velocity.z, loading.settlingTime,
        1e-6 * static_cast<double>(model->memoryBytes()));
    for (const std::string& line : effects.descriptions()) std::printf("Model effect: %s\n", line.c_str());
    if (useCuda)
        std::printf("Backend: %s, %s\n", cudaBackendSummary().c_str(), cudaBackendInfo().status.c_str());
    else
        std::printf("Backend: cpu (OpenMP)\n");
    if (restarted)
        std::printf("Restart from time %s (step %ld)\n", runTime.startTimeName().c_str(), restartStep);
    if (decomposer)
        std::printf(
            "Parallel: rank 0 gathers the state at write times and writes the time directories and VTK "
            "frames a serial run writes (a restart may use another number of ranks)\n");
}

void BondedDemRun::report(bool)
{
    const DemEnergies& e = model->energies();
    std::printf("Peak force %.6g N at the upper plate; %d of %d bonds broken; %ld neighbour-list rebuilds\n",
                peakForce, model->counters().bonds_broken, model->counters().bonds,
                model->counters().neighbour_rebuilds);
    std::printf(
        "Energy: external work %.4g J, kinetic %.4g J, stored %.4g J, dissipated %.4g J "
        "(fracture %.4g J), balance error %.3g J\n",
        e.externalWork(), e.kinetic(), e.stored(), e.dissipated(), e.fracture,
        e.balance() - model->initialBalance());
    std::printf("%s\n", stepCheckSummary(model->counters()).c_str());
    if (decomposer) std::printf("%s\n", describeCuts(*decomposer).c_str());
}

}  // namespace

std::string describeCuts(const DemDecomposer& d)
{
    char line[300];
    std::snprintf(line, sizeof(line),
                  "Parallel: the cells were cut anew %ld times; %ld gathers of the whole state on every rank "
                  "(%.4g MB received by rank 0), %.3g s with the cuts on rank 0",
                  d.redistributions(), d.wholeGathers(), 1e-6 * d.redistributionBytes(),
                  d.redistributionSeconds());
    return line;
}

void redistributeWhenDue(DemDecomposer& decomposer, DemModel& local, long step)
{
    const std::string why = decomposer.redistributionDue();
    if (why.empty()) return;
    decomposer.gatherEverywhere(local);
    decomposer.redistribute(local);
    std::printf("Step %ld: cells cut anew (%s). %s\n", step, why.c_str(), decomposer.describe().c_str());
}

std::unique_ptr<TimedRun> newBondedDemRun(const Application& app, TimeLoop& loop, DemDecomposer* decomposer)
{
    return std::make_unique<BondedDemRun>(app, loop, decomposer);
}

}  // namespace rockfrac
