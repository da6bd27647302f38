#include "demCase/demRun.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/memoryLimit.hpp"
#include "core/progress.hpp"
#include "core/timeControl.hpp"
#include "demCase/demCase.hpp"
#include "demCuda/cudaDemModel.hpp"
#include "effects/modelEffect.hpp"
#include "io/timeSeries.hpp"
#include "voronoi/voronoiMeshIO.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

namespace {

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

// Refuse a mesh that cannot fit before reading it (core/memoryLimit.hpp).
void checkDemMemory(const fs::path& caseDir)
{
    const VoronoiMeshSizes sizes = readVoronoiMeshSizes(caseDir);
    checkMemoryFits(estimateDemMemoryBytes(sizes),
                    (caseDir / voronoiMeshDirectory / "meshInfo").lexically_normal().string() + ": " +
                        std::to_string(sizes.nCells) + " cells and " + std::to_string(sizes.nBonds) +
                        " bonds",
                    "use fewer cells (nCells of system/voronoiMeshDict) or a machine with more memory");
}

}  // namespace

// controlDict `backend cpu|cuda;` (default cpu). Asking for cuda where this build or
// machine has none is one error naming the entry (demCuda/cudaDemModel.hpp).
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

struct BondedDemRun::Impl {
    const Application& app;
    Dictionary controlDict;
    TimeControl time;
    DemParameters parameters;
    Loading loading;
    ModelEffects effects;  // constant/modelEffects (optional): off = the baseline model
    VoronoiMesh mesh;
    std::unique_ptr<DemModel> model;
    bool useCuda = false;
    std::unique_ptr<CudaDemModel> device;  // made by execute() when useCuda
    CellShapes shapes;
    int lowerPlate = -1, upperPlate = -1;
    long sampleInterval = 10;  // steps between plateForce rows
    double rayleighStep = 0.0;
    CriticalTimeStep critical;

    // Run state (restart).
    long step = 0;
    double peakForce = 0.0;
    bool loadingStarted = false;
    bool restarted = false;

    explicit Impl(const Application& a)
        : app(a),
          controlDict(Dictionary::readFile(a.path("system/controlDict"))),
          time(controlDict, a.casePath())
    {
        useCuda = readCudaBackend(controlDict);
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
        checkDemMemory(a.casePath());
        mesh = readVoronoiMesh(a.casePath());
        model = std::make_unique<DemModel>(mesh, parameters);
        shapes = captureCellShapes(mesh, *model);
        placePlates();
        effects.applyToModel(*model, {model->wall(lowerPlate).origin.z, model->wall(upperPlate).origin.z});
        chooseTimeStep();
        // Steps too long for a cell pressed into many contact points are split (DemModel::step).
        model->setStepLimit(time.deltaT() / critical.value, critical.bond_frequency,
                            critical.bond_damping_ratio);
        readFunctions();
        if (time.restarting()) restoreState();
    }

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

    void chooseTimeStep()
    {
        rayleighStep = model->rayleighTimeStep();
        critical = model->criticalTimeStep();
        const int given = int(time.deltaTGiven()) + int(controlDict.found("rayleighFraction")) +
                          int(controlDict.found("criticalFraction"));
        if (given != 1)
            throw UserError(
                controlDict.fileName() +
                ": give exactly one of 'deltaT' [s], 'rayleighFraction' (the step as a fraction of "
                "the Rayleigh step, e.g. 0.02) or 'criticalFraction' (the step as a fraction of the "
                "largest stable step of the bonds and contacts, e.g. 0.8)");
        if (controlDict.found("rayleighFraction"))
            time.setDeltaT(controlDict.getScalar("rayleighFraction", Bounds::open(0, 1)) * rayleighStep);
        if (controlDict.found("criticalFraction"))
            time.setDeltaT(controlDict.getScalar("criticalFraction", Bounds::closed(1e-9, 1)) *
                           critical.value);
        if (time.deltaT() > critical.value) {
            char buffer[400];
            std::snprintf(
                buffer, sizeof(buffer),
                ": the time step %.4g s is above the largest stable step %.4g s of this mesh and these "
                "parameters (bonds: highest frequency %.4g rad/s, damping ratio %.3g; contacts %.4g s); "
                "set deltaT <= %.4g or use criticalFraction (e.g. 0.8)",
                time.deltaT(), critical.value, critical.bond_frequency, critical.bond_damping_ratio,
                critical.contact, critical.value);
            throw UserError(controlDict.fileName() + buffer);
        }
    }

    void readFunctions()
    {
        if (!controlDict.found("functions")) return;
        const Dictionary& functions = controlDict.subDict("functions");
        if (functions.found("plateForce"))
            sampleInterval =
                functions.subDict("plateForce").getOrDefault<long>("writeInterval", sampleInterval);
        if (sampleInterval < 1)
            throw UserError(controlDict.fileName() +
                            ": functions/plateForce/writeInterval must be >= 1 step");
    }

    void restoreState()
    {
        const fs::path file = app.path(time.startTimeName()) / "demState";
        const DemRestart r = readDemState(file, *model);
        step = r.step;
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

    // One step on the chosen backend; the model's time, energies, counters, status
    // and plate reactions are current afterwards on either.
    void advance()
    {
        if (device)
            device->step(time.deltaT());
        else
            model->step(time.deltaT());
    }

    // The device state into the model before anything reads its cell arrays.
    void synchroniseForOutput()
    {
        if (device) device->downloadState();
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

    void writeTime()
    {
        synchroniseForOutput();
        const double t = model->time();
        const fs::path staging = time.prepareStagingDir(t);
        writeDemState(staging / "demState", *model, step, peakForce, loadingStarted);
        time.commitTimeDir(t);
        writeDemVtk(app.casePath(), static_cast<int>(step), *model, shapes, restarted || step > 0);
    }

    bool stopCriterionMet() const
    {
        if (!loadingStarted) return false;
        const double f = plateForce();
        if (loading.stopDisplacement > 0 && plateApproach() >= loading.stopDisplacement) return true;
        return loading.stopForceFraction > 0 && peakForce > loading.minPeakForce && peakForce > 0 &&
               f < loading.stopForceFraction * peakForce;
    }

    std::string progressExtras() const
    {
        const DemEnergies& e = model->energies();
        const double scale = std::max({e.externalWork(), e.kinetic() + e.stored(), 1e-30});
        char buffer[160];
        std::snprintf(buffer, sizeof(buffer), "F %.4g kN (peak %.4g)  broken %d/%d  balance %+.2g %%",
                      1e-3 * plateForce(), 1e-3 * peakForce, model->counters().bonds_broken,
                      model->counters().bonds, 100 * (e.balance() - model->initialBalance()) / scale);
        return buffer;
    }
};

BondedDemRun::BondedDemRun(const Application& app) : impl_(std::make_unique<Impl>(app)) {}
BondedDemRun::~BondedDemRun() = default;

// The interfaces' areas and, when the bond size effect is on, its factors and the
// reference area that would leave this mesh's mean factor at 1 (the value to give for
// the mesh the bonds were calibrated on).
static void printBondSizeEffect(const InterfaceArrays& faces, const DemParameters& p)
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
    const Impl& r = *impl_;
    const CellArrays& cells = r.model->cells();
    double mass = 0;
    for (int c = 0; c < cells.size(); ++c) mass += cells.mass[c];
    std::printf("Mesh: %d cells, %d bonds, dilation radius %.4g mm, mass %.5g kg\n", r.mesh.nCells(),
                r.mesh.nBonds(), 1e3 * r.mesh.dilationRadius, mass);
    std::printf("Bonds: %s, damping %s %.3g\n", r.parameters.bond_law->describe().c_str(),
                dampingReadingName(r.parameters.damping_reading), r.parameters.bond_damping);
    printBondSizeEffect(r.model->interfaces(), r.parameters);
    std::printf("Time step %.4g s = %.4g x Rayleigh step %.4g s; end time %.4g s (%ld steps)\n",
                r.time.deltaT(), r.time.deltaT() / r.rayleighStep, r.rayleighStep, r.time.endTime(),
                r.time.endStep());
    std::printf(
        "Stable step %.4g s (bonds %.4g s: highest frequency %.4g rad/s, damping ratio %.3g, Gershgorin "
        "translation %.4g s, rotation %.4g s; contacts %.4g s); the step is %.3g of it\n",
        r.critical.value, r.critical.bond, r.critical.bond_frequency, r.critical.bond_damping_ratio,
        r.critical.bond_translation_bound, r.critical.bond_rotation_bound, r.critical.contact,
        r.time.deltaT() / r.critical.value);
    std::printf(
        "Plates: upper velocity (%g %g %g) m/s, lower (%g %g %g) m/s, settling %.4g s; memory %.3g MB\n",
        r.loading.upper.velocity.x, r.loading.upper.velocity.y, r.loading.upper.velocity.z,
        r.loading.lower.velocity.x, r.loading.lower.velocity.y, r.loading.lower.velocity.z,
        r.loading.settlingTime, 1e-6 * static_cast<double>(r.model->memoryBytes()));
    for (const std::string& line : r.effects.descriptions()) std::printf("Model effect: %s\n", line.c_str());
    if (r.useCuda)
        std::printf("Backend: %s, %s\n", cudaBackendSummary().c_str(), cudaBackendInfo().status.c_str());
    else
        std::printf("Backend: cpu (OpenMP)\n");
    if (r.restarted) std::printf("Restart from time %s (step %ld)\n", r.time.startTimeName().c_str(), r.step);
}

int BondedDemRun::execute()
{
    Impl& r = *impl_;
    if (r.app.dryRun()) {
        std::printf("Dry run: every input is valid; nothing run, nothing written.\n");
        return exitSuccess;
    }
    installInterruptHandlers();
    if (r.useCuda) {
        r.device = std::make_unique<CudaDemModel>(*r.model);
        std::printf("CUDA backend: %.3g MB of device memory (%.0f bytes per cell)\n",
                    1e-6 * static_cast<double>(r.device->deviceBytes()),
                    static_cast<double>(r.device->deviceBytes()) / r.model->cells().size());
    }
    TimeSeriesWriter plateForce(r.app.casePath(), "plateForce", Impl::columns(),
                                r.restarted ? r.model->time() : -1.0);
    if (!r.restarted) {
        r.applyStage();
        if (r.device)
            r.device->evaluateForces(r.time.deltaT());
        else
            r.model->evaluateForces(r.time.deltaT());
        plateForce.append(r.sampleRow());
        r.writeTime();
    }
    ProgressReporter progress(r.time.startTime(), r.time.endTime());
    const long endStep = r.time.endStep();
    std::string reason = "end time reached";
    int exitCode = exitSuccess;
    while (r.step < endStep) {
        r.applyStage();
        r.advance();
        ++r.step;
        const DemStatus& status = r.model->status();
        if (!status.ok()) {
            r.synchroniseForOutput();
            writeDemVtk(r.app.casePath(), static_cast<int>(r.step), *r.model, r.shapes, true);
            const auto times = TimeControl::timeDirectories(r.app.casePath());
            throw UserError("step " + std::to_string(r.step) + " (t = " + std::to_string(r.model->time()) +
                            " s): " + status.message() +
                            "; likely cause: the time step is too large for the stiffest bond or contact; "
                            "reduce deltaT. Last complete time directory: " +
                            (times.empty() ? std::string("none") : r.time.timeName(times.back())) +
                            "; the failing state is in VTK/cells_" + std::to_string(r.step) + ".vtu");
        }
        if (r.loadingStarted) r.peakForce = std::max(r.peakForce, r.plateForce());
        if (r.step % r.sampleInterval == 0) plateForce.append(r.sampleRow());
        const bool stop = r.stopCriterionMet();
        if (interrupted()) {
            reason = "interrupted by a signal: state written, continue with startFrom latestTime";
            exitCode = interruptExitCode();
        }
        if (stop)
            reason = "stop criterion met (force below the set fraction of its peak, or maximum approach)";
        // A write time adds a row to the series only when the uninterrupted run has it
        // too: not at the step a signal arrived, or the continued series would differ.
        const bool regularWrite = r.time.writeDue(r.step) || stop || r.step == endStep;
        if (regularWrite || exitCode != exitSuccess) {
            if (r.step % r.sampleInterval != 0 && regularWrite) plateForce.append(r.sampleRow());
            r.writeTime();
        }
        if (stop || exitCode != exitSuccess) break;
        progress.update(r.step, r.model->time(), [&] { return r.progressExtras(); });
    }
    progress.finish(r.step, r.model->time(), reason);
    std::printf("Peak force %.6g N at the upper plate; %d of %d bonds broken; %ld neighbour-list rebuilds\n",
                r.peakForce, r.model->counters().bonds_broken, r.model->counters().bonds,
                r.model->counters().neighbour_rebuilds);
    std::printf(
        "Energy: external work %.4g J, kinetic %.4g J, stored %.4g J, dissipated %.4g J "
        "(fracture %.4g J), balance error %.3g J\n",
        r.model->energies().externalWork(), r.model->energies().kinetic(), r.model->energies().stored(),
        r.model->energies().dissipated(), r.model->energies().fracture,
        r.model->energies().balance() - r.model->initialBalance());
    std::printf("%s\n", stepCheckSummary(r.model->counters()).c_str());
    return exitCode;
}

}  // namespace rockfrac
