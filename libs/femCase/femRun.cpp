#include "femCase/femRun.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/knownEntries.hpp"
#include "core/memoryLimit.hpp"
#include "fem/addedMass.hpp"
#include "fem/measurements.hpp"
#include "femCase/femCase.hpp"
#include "io/timeSeries.hpp"

namespace rockfrac {

namespace fs = std::filesystem;
using namespace fem;

namespace {

// Quasi-static criterion of physics.md §2: kinetic energy below 1 % of the external work.
constexpr double quasiStaticLimit = 0.01;
// Drop fractions of the failure-load detectors: the case's X and the sensitivity pair.
constexpr double sensitivityLow = 0.1, sensitivityHigh = 0.3;

struct Bounds3 {
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    Vec3 centre() const { return 0.5 * (lo + hi); }
};

Bounds3 meshBounds(const TetMesh& mesh)
{
    Bounds3 b;
    for (const Vec3& p : mesh.nodes)
        for (int k = 0; k < 3; ++k) b.lo[k] = std::min(b.lo[k], p[k]), b.hi[k] = std::max(b.hi[k], p[k]);
    return b;
}

// The FEM run: reads and checks every input in its constructor (UserError before any
// step); TimeLoop drives it through the hooks below.
class FeFractureRun final : public TimedRun {
public:
    FeFractureRun(const Application& a, TimeLoop& loop);
    // The log's set-up and summary.
    void printSetup() const override;
    void report(bool interrupted) override;

    // ---- the loop's hooks (core/timeLoop.hpp), in the loop's order

    long start(bool) override
    {
        // The .dat files print 10 digits, so the row of the restart time may read back a little
        // above it; the next row is a whole step later (dt / t >> 1e-9).
        const double restartTime = restarted ? model->time() * (1 + 1e-9) : -1.0;
        plateForceSeries = std::make_unique<TimeSeriesWriter>(app.casePath(), "plateForce",
                                                              plateForceColumns(), restartTime);
        extensometerSeries = std::make_unique<TimeSeriesWriter>(app.casePath(), "extensometer",
                                                                extensometerColumns(), restartTime);
        if (!probeElements.empty())
            centreStressSeries = std::make_unique<TimeSeriesWriter>(app.casePath(), "centreStress",
                                                                    centreStressColumns(), restartTime);
        return restarted ? run.step : 0;
    }

    Sampling sampling() const override { return {sampleInterval, Sampling::Rows::instantaneous}; }

    void beforeStep(long) override { applyStage(model->time(), runTime.deltaT()); }

    StepResult advance(double deltaT) override
    {
        const StepStatus status = model->step(deltaT);
        return {status.ok, status.message};
    }

    // The running maxima and detectors every step; the arc load's failure at the sample steps.
    void afterStep(long step) override
    {
        track();
        if (step % sampleInterval == 0) trackArcFailure();
    }

    void sample() override
    {
        plateForceSeries->append(plateForceRow());
        extensometerSeries->append(extensometerRow());
        if (centreStressSeries) centreStressSeries->append(centreStressRow());
        checkQuasiStatic();
    }

    std::string stopReason() const override
    {
        if (!loadingStarted(model->time())) return {};
        if (loading.kind == FemLoading::Kind::arcLoad) {
            if (!detectors[1].failed()) return {};
            return "failure under the arc load (kinetic energy above 1 % of the external work)";
        }
        if (!(loading.stopForceFraction > 0)) return {};
        if (!(run.peakForce > loading.minPeakForce && run.peakForce > 0 &&
              plateForce() < loading.stopForceFraction * run.peakForce))
            return {};
        return "stop criterion met (force below the set fraction of its peak)";
    }

    void writeTime(long step) override
    {
        run.step = step;
        // State, then frames, then the time directory is published (see demRun.cpp).
        const fs::path staging = runTime.prepareStagingDir(model->time());
        writeFemState(staging / "femState", *model, run);
        writeFemVtk(app.casePath(), step, *model, restarted || step > 0);
        runTime.commitTimeDir(model->time());
    }

    std::string writeFailure(long step) override
    {
        writeFemVtk(app.casePath(), step, *model, true);
        return "VTK/fem_" + std::to_string(step) + ".vtu";
    }

    double time() const override { return model->time(); }

    std::string progress() const override
    {
        char buffer[200];
        std::snprintf(buffer, sizeof(buffer), "F %.4g kN (peak %.4g)  cracked %ld/%zu  KE/W %.2g %%",
                      1e-3 * plateForce(), 1e-3 * run.peakForce, crackedElements(), mesh.numTets(),
                      100 * kineticRatio());
        return buffer;
    }

private:
    // Refuse a mesh whose model cannot fit, before the model's arrays exist
    // (core/memoryLimit.hpp). Bytes per node (positions, displacements,
    // velocities, forces, masses and their parallel partial sums) and per
    // tetrahedron (geometry, gradients, stresses, KST-DFH state with three
    // Weibull thresholds, per-thread partial forces), generously; plus the code
    // and libraries (gmsh, VTK). docs/reliability.md compares it with the peak.
    void checkFemMemory(const fs::path& msh) const
    {
        constexpr std::uint64_t perNode = 1000, perTet = 2000, libraries = 80000000;
        const std::uint64_t estimate = libraries + perNode * mesh.numNodes() + perTet * mesh.numTets();
        checkMemoryFits(
            estimate,
            msh.string() + ": " + std::to_string(mesh.numNodes()) + " nodes and " +
                std::to_string(mesh.numTets()) + " tetrahedra",
            "use a coarser mesh (elementSize of system/feMeshDict) or a machine with more memory");
        if (app.dryRun())
            std::printf("%s\n", estimateLine(estimate, std::to_string(mesh.numNodes()) + " nodes, " +
                                                           std::to_string(mesh.numTets()) + " tetrahedra")
                                    .c_str());
    }

    void readSolverControls()
    {
        static const Dimensions seconds = Dimensions::fromUnits("s");
        static const Dimensions perSecond = Dimensions::fromUnits("1/s");
        parameters.timeStepSafety = controlDict.getScalarOrDefault(
            "timeStepSafety", parameters.timeStepSafety, Bounds::closed(1e-6, 1));
        parameters.massScalingTimeStep =
            controlDict.getScalarOrDefault("massScalingTimeStep", 0.0, Bounds::nonNegative(), &seconds);
        parameters.massDamping =
            controlDict.getScalarOrDefault("massDamping", 0.0, Bounds::nonNegative(), &perSecond);
        parameters.gravity = loading.gravity;
        parameters.contactPenaltyScale = loading.contactPenaltyScale;
        parameters.contactCrushingPressure = loading.contactCrushingPressure;
        parameters.tangentialPenaltyRatio = loading.tangentialPenaltyRatio;
    }

    void placeLoads(const Dictionary& loadingDict)
    {
        const Vec3 centre = loading.extensometerCentre.value_or(bounds.centre());
        try {
            extensometer = std::make_unique<VirtualExtensometer>(mesh, centre, Vec3{0, 0, 1},
                                                                 loading.extensometerLength);
        } catch (const UserError& e) {
            throw UserError(loadingDict.fileName() + ": extensometer: " + e.what() +
                            "; shorten extensometer/length or move extensometer/centre into the specimen");
        }
        if (loading.kind == FemLoading::Kind::plates) {
            RigidPlate lower, upper;
            lower.name = "lower", upper.name = "upper";
            lower.point = {0, 0, bounds.lo.z};
            upper.point = {0, 0, bounds.hi.z + loading.startGap};
            lower.normal = {0, 0, 1}, upper.normal = {0, 0, -1};
            lower.friction = loading.lower.friction, upper.friction = loading.upper.friction;
            lowerPlate = model->addPlate(lower);
            upperPlate = model->addPlate(upper);
            return;
        }
        // Arc load on a disc with its axis along y (meshRock's placement).
        const Vec3 c = bounds.centre();
        const double width = bounds.hi.x - bounds.lo.x, height = bounds.hi.z - bounds.lo.z;
        if (std::abs(width - height) > 0.02 * height)
            throw UserError(
                loadingDict.fileName() +
                ": arcLoad needs a disc with its axis along y (x and z extents equal); the mesh spans " +
                std::to_string(width) + " m in x and " + std::to_string(height) + " m in z");
        arcUnitForces = arcLoadUnitForces(mesh, c, loading.arc.halfAngle, arcTopForcePerPascal);
        if (!(arcTopForcePerPascal > 0))
            throw UserError(loadingDict.fileName() +
                            ": arcLoad: no boundary face lies on the arcs; widen halfAngle");
        const double inset = 0.02 * height;  // inside the faceted surface
        topPole = locateMaterialPoint(mesh, {c.x, c.y, bounds.hi.z - inset});
        bottomPole = locateMaterialPoint(mesh, {c.x, c.y, bounds.lo.z + inset});
    }

    void chooseTimeStep()
    {
        stableStep = model->stableTimeStep();
        if (!runTime.deltaTGiven()) {
            runTime.setDeltaT(stableStep);
            return;
        }
        const double limit = stableStep / parameters.timeStepSafety;
        if (runTime.deltaT() > limit)
            throw UserError(controlDict.fileName() + ": deltaT " + formatNumber(runTime.deltaT()) +
                            " s exceeds the stable step " + formatNumber(limit) +
                            " s of this mesh; remove deltaT to use timeStepSafety x the stable step");
    }

    // A plate that cannot reach the specimen before endTime would make a run of nothing.
    void checkPlateReachesSpecimen(const Dictionary& loadingDict) const
    {
        if (loading.kind != FemLoading::Kind::plates) return;
        const double loadingTime = std::max(0.0, runTime.endTime() - loading.settlingTime);
        const double travel = loading.approachSpeed() * loadingTime;
        if (travel <= loading.startGap)
            throw UserError(
                loadingDict.fileName() + ": the upper plate travels " + formatNumber(travel) +
                " m by endTime " + formatNumber(runTime.endTime()) + " s, less than plates/startGap " +
                formatNumber(loading.startGap) +
                " m: it never touches the specimen; reduce startGap or raise endTime or the speed");
    }

    void readFunctions()
    {
        sampleInterval = readSampleInterval(controlDict, "plateForce", sampleInterval);
        if (!controlDict.found("functions")) return;
        const Dictionary& functions = controlDict.subDict("functions");
        if (functions.found("centreStress")) {
            static const Dimensions metre = Dimensions::fromUnits("m");
            checkKnownEntries(functions.subDict("centreStress"), {"radius"});
            probeRadius = functions.subDict("centreStress").getScalar("radius", Bounds::positive(), &metre);
            const Vec3 c = bounds.centre();
            for (std::size_t e = 0; e < mesh.numTets(); ++e) {
                Vec3 centroid;
                for (int a = 0; a < 4; ++a) centroid += 0.25 * mesh.nodes[mesh.tets[e][a]];
                if (std::hypot(centroid.x - c.x, centroid.z - c.z) < probeRadius)
                    probeElements.push_back(static_cast<int>(e));
            }
            if (probeElements.empty())
                throw UserError(controlDict.fileName() + ": functions/centreStress/radius " +
                                formatNumber(probeRadius) + " m holds no element centroid; enlarge it");
        }
    }

    // Volume average of the stress over the probe elements (xx yy zz xy yz zx).
    std::vector<double> centreStressRow() const
    {
        double sum[6] = {0, 0, 0, 0, 0, 0}, volume = 0;
        const auto& stresses = model->state().elementStresses;
        for (int e : probeElements) {
            const double v = model->geometry().volumes[e];
            for (int k = 0; k < 6; ++k) sum[k] += v * stresses[6 * e + k];
            volume += v;
        }
        std::vector<double> row{model->time(), plateForce()};
        for (double s : sum) row.push_back(s / volume);
        return row;
    }

    static std::vector<Column> centreStressColumns()
    {
        return {{"Time", "s"},      {"force", "N"},     {"sigma_xx", "Pa"}, {"sigma_yy", "Pa"},
                {"sigma_zz", "Pa"}, {"sigma_xy", "Pa"}, {"sigma_yz", "Pa"}, {"sigma_zx", "Pa"}};
    }

    std::vector<double> dropFractions() const
    {
        return {sensitivityLow, loading.failureDropFraction, sensitivityHigh};
    }

    void initialiseDetectors()
    {
        detectors.clear();
        for (double x : dropFractions()) detectors.emplace_back(x);
        run.detectorMaximum.assign(detectors.size(), 0.0);
        run.detectorFailed.assign(detectors.size(), 0.0);
        run.detectorTime.assign(detectors.size(), 0.0);
    }

    void restoreState()
    {
        const fs::path file = app.path(runTime.startTimeName()) / "femState";
        run = readFemState(file, *model);
        if (run.detectorMaximum.size() != detectors.size())
            throw UserError(file.string() + ": the failure-load detectors do not match this solver");
        // A detector is its running maximum and whether it has fired: replay both.
        for (std::size_t k = 0; k < detectors.size(); ++k) {
            detectors[k].update(run.detectorMaximum[k]);
            if (run.detectorFailed[k] != 0) detectors[k].update(-1.0);
        }
        restarted = true;
    }

    bool loadingStarted(double t) const { return t >= loading.settlingTime * (1 - 1e-12); }

    // Plate velocities (or the arc load at the end of the step) for the step from t to t + dt.
    void applyStage(double t, double dt)
    {
        if (loading.kind == FemLoading::Kind::plates) {
            const bool on = loadingStarted(t);
            model->plate(lowerPlate).velocity = on ? loading.lower.velocity : Vec3{};
            model->plate(upperPlate).velocity = on ? loading.upper.velocity : Vec3{};
            return;
        }
        const double p = arcPressure(t + dt);
        std::vector<double> f(arcUnitForces.size());
        for (std::size_t k = 0; k < f.size(); ++k) f[k] = p * arcUnitForces[k];
        model->setAppliedForces(f);
    }

    double arcPressure(double t) const
    {
        return loading.arc.pressureRate * std::max(0.0, t - loading.settlingTime);
    }

    double plateForce() const
    {
        if (loading.kind == FemLoading::Kind::arcLoad)
            return arcPressure(model->time()) * arcTopForcePerPascal;
        return model->plate(upperPlate).force.z;
    }
    double lowerPlateForce() const
    {
        if (loading.kind == FemLoading::Kind::arcLoad) return plateForce();
        return -model->plate(lowerPlate).force.z;
    }
    double gapChange() const
    {
        if (loading.kind == FemLoading::Kind::arcLoad) {
            const auto& u = model->state().displacements;
            return interpolateDisplacement(mesh, u, bottomPole).z -
                   interpolateDisplacement(mesh, u, topPole).z;
        }
        return model->plate(lowerPlate).displacement.z - model->plate(upperPlate).displacement.z;
    }
    double elongation() const { return extensometer->elongation(*model); }

    long crackedElements() const
    {
        long n = 0;
        for (std::size_t e = 0; e < mesh.numTets(); ++e) n += model->material().damage(e, 0) > 0.5;
        return n;
    }

    double kineticRatio() const
    {
        const double w = model->energy().externalWork;
        return w > 0 ? model->kineticEnergy() / w : 0.0;
    }

    std::vector<double> plateForceRow() const
    {
        return {model->time(),
                gapChange(),
                plateForce(),
                lowerPlateForce(),
                elongation(),
                model->kineticEnergy(),
                model->strainEnergy(),
                model->energy().externalWork,
                static_cast<double>(crackedElements())};
    }

    static std::vector<Column> plateForceColumns()
    {
        return {{"Time", "s"},         {"gapChange", "m"},    {"force", "N"},
                {"forceLower", "N"},   {"elongation", "m"},   {"kinetic", "J"},
                {"strainEnergy", "J"}, {"externalWork", "J"}, {"crackedElements", "-"}};
    }

    std::vector<double> extensometerRow() const
    {
        const double e = elongation();
        return {model->time(), e, e / extensometer->length(), plateForce()};
    }

    static std::vector<Column> extensometerColumns()
    {
        return {{"Time", "s"}, {"elongation", "m"}, {"strain", "-"}, {"force", "N"}};
    }

    // Peak, failure detectors and the running quasi-static check, after every step.
    void track()
    {
        if (!loadingStarted(model->time())) return;
        const double f = plateForce();
        run.peakForce = std::max(run.peakForce, f);
        if (loading.kind == FemLoading::Kind::arcLoad) return;  // trackArcFailure instead
        // The detectors start once the force has reached stop/minPeakForce, so the force
        // oscillation of the first contact is not taken for a failure.
        if (run.peakForce < loading.minPeakForce) return;
        for (std::size_t k = 0; k < detectors.size(); ++k) {
            if (detectors[k].failed()) continue;
            if (f > run.detectorMaximum[k]) {
                run.detectorMaximum[k] = f, run.detectorTime[k] = model->time();
                if (k == 1) {
                    run.peakTime = model->time(), run.peakGap = gapChange(),
                    run.peakElongation = elongation();
                    run.kineticRatioAtPeak = kineticRatio();
                }
            }
            if (detectors[k].update(f)) run.detectorFailed[k] = 1.0;
        }
    }

    // Arc load (load control), at sample steps: the force never drops, so the failure
    // load is the applied resultant at which the disc stops carrying it statically, i.e.
    // the first time KE / W_ext exceeds the quasi-static limit after stop/minPeakForce
    // (the crack runs unstably and the halves accelerate apart). This is the explicit
    // counterpart of the FreeFEM reference's criterion (damage cascading at a fixed load).
    // All detectors fire at once, so the failure load does not depend on the drop fraction.
    // Armed only when stop/minPeakForce > 0 (the ramp's start is not quasi-static either).
    void trackArcFailure()
    {
        if (loading.kind != FemLoading::Kind::arcLoad || detectors[1].failed() || !(loading.minPeakForce > 0))
            return;
        const double f = plateForce();
        if (!(f > loading.minPeakForce) || !(kineticRatio() > quasiStaticLimit)) return;
        for (std::size_t k = 0; k < detectors.size(); ++k) {
            detectors[k].update(f);
            detectors[k].update(-1.0);
            run.detectorMaximum[k] = f, run.detectorTime[k] = model->time(), run.detectorFailed[k] = 1.0;
        }
        run.peakTime = model->time(), run.peakGap = gapChange(), run.peakElongation = elongation();
        run.kineticRatioAtPeak = kineticRatio();
    }

    // At sample steps, while loading up to failure: warn once when KE / W_ext exceeds the
    // limit (after the force has passed stop/minPeakForce, so the contact transient is skipped).
    void checkQuasiStatic()
    {
        if (!loadingStarted(model->time()) || detectors[1].failed() || !(plateForce() > loading.minPeakForce))
            return;
        const double ratio = kineticRatio();
        if (ratio > quasiStaticLimit && !quasiStaticWarned) {
            std::printf(
                "Warning: t = %.6g s: kinetic energy / external work = %.3g %% > %.3g %%: not "
                "quasi-static; lower the plate speed or raise massDamping\n",
                model->time(), 100 * ratio, 100 * quasiStaticLimit);
            quasiStaticWarned = true;
        }
    }

    // The quasi-static check of the whole loading branch, from plateForce.dat (so that it
    // covers restarted runs): the largest KE / W_ext on the rising branch between 50 % and
    // 95 % of the peak force.
    void reportQuasiStatic(const fs::path& plateForceFile) const
    {
        const TimeSeries series = readTimeSeries(plateForceFile);
        const auto force = series.values("force"), kinetic = series.values("kinetic"),
                   work = series.values("externalWork");
        std::size_t peak = 0;
        for (std::size_t k = 0; k < force.size(); ++k)
            if (force[k] > force[peak]) peak = k;
        double worst = 0;
        for (std::size_t k = 0; k < peak; ++k)
            if (force[k] >= 0.5 * force[peak] && force[k] <= 0.95 * force[peak] && work[k] > 0)
                worst = std::max(worst, kinetic[k] / work[k]);
        std::printf(
            "Quasi-static check: KE / W_ext at most %.3g %% on the rising branch (50-95 %% of the peak "
            "force), %.3g %% at the peak (limit %.0f %%): %s\n",
            100 * worst, 100 * run.kineticRatioAtPeak, 100 * quasiStaticLimit,
            worst < quasiStaticLimit ? "quasi-static" : "NOT quasi-static");
    }

    // Where the cracks are: the cracked volume (D1 = 1) and its share within H/8 of the
    // vertical mid-plane x = x_c (H the specimen height along the load): a Brazilian disc
    // that splits along its loaded diameter has most of it there.
    void reportCrackLocation() const
    {
        const double height = bounds.hi.z - bounds.lo.z, xc = bounds.centre().x;
        double cracked = 0, nearPlane = 0;
        for (std::size_t e = 0; e < mesh.numTets(); ++e) {
            if (!(model->material().damage(e, 0) > 0.5)) continue;
            double x = 0;
            for (int a = 0; a < 4; ++a) x += 0.25 * mesh.nodes[mesh.tets[e][a]].x;
            const double v = model->geometry().volumes[e];
            cracked += v;
            if (std::abs(x - xc) < height / 8) nearPlane += v;
        }
        std::printf(
            "Cracked volume %.4g mm^3 (%.3g %% of the specimen); %.3g %% of it within |x - x_c| < H/8 = "
            "%.4g mm of the loaded mid-plane\n",
            1e9 * cracked, 100 * cracked / totalVolume(), cracked > 0 ? 100 * nearPlane / cracked : 0.0,
            1e3 * height / 8);
    }

    // Contact crushing: per plate, the nodes crushed, the largest crushed depth and the
    // crushed area (the nodes' projected contact areas), i.e. how far the contacts have
    // flattened. Also when crushing is off now but a restart brought crushed depths.
    void reportContactCrushing() const
    {
        bool anyCrushed = false;
        for (int k = 0; k < model->numPlates(); ++k)
            for (double c : model->plate(k).crushedDepth) anyCrushed = anyCrushed || c > 0;
        if (!(loading.contactCrushingPressure > 0) && !anyCrushed) return;
        for (int k = 0; k < model->numPlates(); ++k) {
            const RigidPlate& p = model->plate(k);
            int nodes = 0;
            double deepest = 0, area = 0;
            for (std::size_t j = 0; j < p.crushedDepth.size(); ++j)
                if (p.crushedDepth[j] > 0) {
                    ++nodes;
                    deepest = std::max(deepest, p.crushedDepth[j]);
                    area += model->contactAreas(k)[j];
                }
            std::printf("Contact crushing under plate %s: %d nodes, %.4g mm^2, deepest %.4g mm\n",
                        p.name.c_str(), nodes, 1e6 * area, 1e3 * deepest);
        }
    }

    double totalVolume() const
    {
        double v = 0;
        for (double ve : model->geometry().volumes) v += ve;
        return v;
    }

    // postProcessing/failureLoad/0/failureLoad.dat: one row for the first-drop criterion.
    void writeFailureLoad() const
    {
        const std::vector<double> fractions = dropFractions();
        if (!detectors[1].failed()) {
            std::printf("Failure load: no drop of more than %.0f %% below the running maximum (%.6g N) yet\n",
                        100 * fractions[1], run.detectorMaximum[1]);
            return;
        }
        TimeSeriesWriter out(app.casePath(), "failureLoad",
                             {{"Time", "s"},
                              {"failureLoad", "N"},
                              {"dropFraction", "-"},
                              {"gapChange", "m"},
                              {"elongation", "m"},
                              {"kineticRatio", "-"},
                              {"failureLoad10", "N"},
                              {"failureLoad30", "N"}});
        auto load = [&](int k) { return detectors[k].failed() ? detectors[k].failureLoad() : 0.0; };
        out.append({run.peakTime, load(1), fractions[1], run.peakGap, run.peakElongation,
                    run.kineticRatioAtPeak, load(0), load(2)});
        if (loading.kind == FemLoading::Kind::arcLoad) {
            std::printf(
                "Failure load %.6g N (arc load: kinetic energy above %.0f %% of the external work) at "
                "t = %.6g s\n",
                load(1), 100 * quasiStaticLimit, run.peakTime);
        } else {
            std::printf(
                "Failure load %.6g N (first drop of more than %.0f %% below the running maximum) at t = %.6g "
                "s, "
                "gap change %.4g mm, extensometer %.4g um; sensitivity: %.6g N (10 %%), %.6g N (30 %%, 0 = "
                "no such drop)\n",
                load(1), 100 * fractions[1], run.peakTime, 1e3 * run.peakGap, 1e6 * run.peakElongation,
                load(0), load(2));
        }
        const double width = bounds.hi.x - bounds.lo.x, height = bounds.hi.z - bounds.lo.z;
        if (std::abs(width - height) < 0.02 * height)
            std::printf("  as a Brazilian disc (D %.4g mm, t %.4g mm): UTS = 2F/(pi D t) = %.4g MPa\n",
                        1e3 * height, 1e3 * (bounds.hi.y - bounds.lo.y),
                        1e-6 * 2 * load(1) / (M_PI * height * (bounds.hi.y - bounds.lo.y)));
    }

    const Application& app;
    FemParameters parameters;
    FemLoading loading;
    TetMesh mesh;
    Bounds3 bounds;
    std::unique_ptr<FemModel> model;
    std::unique_ptr<VirtualExtensometer> extensometer;
    int lowerPlate = -1, upperPlate = -1;
    std::vector<double> arcUnitForces;  // per Pa
    double arcTopForcePerPascal = 0.0;
    MaterialPoint topPole, bottomPole;  // arc load: the approach of the two poles
    long sampleInterval = 10;           // steps between rows (functions/plateForce/writeInterval)
    std::unique_ptr<TimeSeriesWriter> plateForceSeries, extensometerSeries, centreStressSeries;
    // centreStress function: elements whose centroid lies within `radius` of the line
    // through the specimen centre along y (the disc axis); empty = off.
    std::vector<int> probeElements;
    double probeRadius = 0.0;
    double stableStep = 0.0;
    FemRunState run;
    std::vector<FailureLoadDetector> detectors;
    bool restarted = false;
    bool quasiStaticWarned = false;
};

FeFractureRun::FeFractureRun(const Application& a, TimeLoop& loop) : TimedRun(loop), app(a)
{
    parameters = readFemParameters(Dictionary::readFile(a.path("constant/rockProperties")));
    const Dictionary loadingDict = Dictionary::readFile(a.path("constant/loading"));
    loading = readFemLoading(loadingDict);
    readSolverControls();
    const fs::path msh = a.path("constant/feMesh/specimen.msh");
    if (!fs::exists(msh))
        throw UserError("missing " + msh.string() +
                        "; run meshRock with a system/feMeshDict first to make the tetrahedral mesh");
    mesh = readGmshMesh(msh.string());  // rejects inverted or degenerate elements
    checkFemMemory(msh);
    bounds = meshBounds(mesh);
    model = std::make_unique<FemModel>(mesh, parameters);
    placeLoads(loadingDict);
    chooseTimeStep();
    checkPlateReachesSpecimen(loadingDict);
    readFunctions();
    initialiseDetectors();
    if (runTime.restarting()) restoreState();
}

void FeFractureRun::printSetup() const
{
    double mass = 0;
    for (double m : model->nodalMasses()) mass += m;
    const ElasticParameters& m = parameters.rock;
    std::printf("Mesh: %zu tets, %zu nodes, %zu boundary nodes; extent %.4g x %.4g x %.4g mm\n",
                mesh.numTets(), mesh.numNodes(), model->contactNodes().size(),
                1e3 * (bounds.hi.x - bounds.lo.x), 1e3 * (bounds.hi.y - bounds.lo.y),
                1e3 * (bounds.hi.z - bounds.lo.z));
    std::printf("Material %s: E %.4g GPa, nu %.3g, density %.5g kg/m^3%s\n",
                parameters.material->type().c_str(), 1e-9 * m.youngsModulus, m.poissonRatio, m.density,
                parameters.material->describe().c_str());
    std::printf(
        "Time step %.4g s (stable step x safety %.4g s); end time %.4g s (%ld steps); mass %.5g kg, "
        "added mass %.3g %%; mass damping %.4g 1/s\n",
        runTime.deltaT(), stableStep, runTime.endTime(), runTime.endStep(), mass,
        100 * model->addedMassFraction(), parameters.massDamping);
    const std::string addedMass = fem::addedMassWarning(
        fem::summariseAddedMass(*model, parameters.rock.density), parameters.massScalingTimeStep);
    if (!addedMass.empty()) std::printf("%s\n", addedMass.c_str());
    if (loading.kind == FemLoading::Kind::plates)
        std::printf(
            "Plates: upper velocity (%g %g %g) m/s, lower (%g %g %g) m/s, friction %.3g/%.3g, start gap "
            "%.4g mm, settling %.4g s, gravity (%g %g %g)\n",
            loading.upper.velocity.x, loading.upper.velocity.y, loading.upper.velocity.z,
            loading.lower.velocity.x, loading.lower.velocity.y, loading.lower.velocity.z,
            loading.upper.friction, loading.lower.friction, 1e3 * loading.startGap, loading.settlingTime,
            loading.gravity.x, loading.gravity.y, loading.gravity.z);
    if (loading.kind == FemLoading::Kind::plates && loading.contactCrushingPressure > 0)
        std::printf(
            "Contact crushing: plate pressure on a contact node at most %.4g MPa (plates/crushingPressure)\n",
            1e-6 * loading.contactCrushingPressure);
    if (loading.kind == FemLoading::Kind::arcLoad)
        std::printf(
            "Arc load: 2 x %.4g deg arcs, pressure rate %.4g Pa/s, resultant %.5g N per Pa of pressure\n",
            2 * loading.arc.halfAngle * 180 / M_PI, loading.arc.pressureRate, arcTopForcePerPascal);
    std::printf(
        "Extensometer: l = %.4g mm along z; failure load: first drop of more than %.0f %% below the running "
        "maximum; quasi-static check: KE / W_ext < %.0f %%\n",
        1e3 * loading.extensometerLength, 100 * loading.failureDropFraction, 100 * quasiStaticLimit);
    if (!probeElements.empty())
        std::printf("centreStress: mean stress of %zu elements within %.4g mm of the disc axis\n",
                    probeElements.size(), 1e3 * probeRadius);
    if (restarted)
        std::printf("Restart from time %s (step %ld)\n", runTime.startTimeName().c_str(), run.step);
}

void FeFractureRun::report(bool interrupted)
{
    const EnergyBalance& e = model->energy();
    std::printf("Peak force %.6g N; %ld of %zu elements cracked (D1 = 1)\n", run.peakForce, crackedElements(),
                mesh.numTets());
    std::printf(
        "Energy: external work %.4g J, internal work %.4g J, damping %.4g J, kinetic %.4g J, strain %.4g J\n",
        e.externalWork, e.internalWork, e.dampingWork, model->kineticEnergy(), model->strainEnergy());
    reportQuasiStatic(plateForceSeries->path());
    reportCrackLocation();
    reportContactCrushing();
    if (!interrupted) writeFailureLoad();
}

}  // namespace

std::unique_ptr<TimedRun> newFeFractureRun(const Application& app, TimeLoop& loop)
{
    return std::make_unique<FeFractureRun>(app, loop);
}

}  // namespace rockfrac
