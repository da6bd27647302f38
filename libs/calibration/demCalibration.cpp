// The DEM calibration on the Brazilian disc (calibrationRun.hpp).
#include <cmath>
#include <ctime>
#include <iostream>
#include <map>

#include "calibration/boxMinimiser.hpp"
#include "calibration/calibrationDetail.hpp"
#include "calibration/responseSurface.hpp"
#include "core/error.hpp"
#include "stats/descriptive.hpp"

namespace rockfrac::calibration::detail {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

std::string today()
{
    const std::time_t now = std::time(nullptr);
    char text[16];
    std::strftime(text, sizeof(text), "%Y-%m-%d", std::gmtime(&now));
    return text;
}

std::string kN(double force)
{
    return format(force / 1e3, 4) + " kN";
}

std::string mm(double length)
{
    return format(length * 1e3, 4) + " mm";
}

std::string quotedText(const std::string& text)
{
    return "\"" + text + "\"";
}

// Mean response per design point (over seeds when there are several); the
// members that failed are left out and counted.
struct DesignResponses {
    std::vector<std::vector<double>> values;  // physical
    std::vector<PeakResponse> responses;
    std::size_t failed = 0;
    std::string firstFailure;
};

DesignResponses collect(const CalibrationStudy& study, const std::vector<MemberRun>& members)
{
    std::map<std::vector<double>, std::vector<PeakResponse>> byPoint;
    DesignResponses d;
    for (const MemberRun& m : members) {
        if (m.done) {
            try {
                byPoint[m.values].push_back(readPeakResponse(m.directory / study.responseFile,
                                                             study.forceColumn, study.displacementColumn));
                continue;
            } catch (const UserError&) {
            }
        }
        ++d.failed;
        if (d.firstFailure.empty()) d.firstFailure = (m.directory / "log.runCases").string();
    }
    for (const auto& [values, responses] : byPoint) {
        PeakResponse mean;
        for (const auto& r : responses) {
            mean.force += r.force / responses.size();
            mean.displacement += r.displacement / responses.size();
        }
        d.values.push_back(values);
        d.responses.push_back(mean);
    }
    return d;
}

// The mean response of the members of one point; UserError when none ran.
PeakResponse runPoint(const CalibrationStudy& study, const fs::path& directory,
                      const std::vector<double>& values, int jobs)
{
    const auto members = runSet(study, pointRunSet(directory, values), jobs);
    const DesignResponses d = collect(study, members);
    if (d.responses.empty())
        throw UserError("the objective cannot be evaluated at " + describeValues(study, values) + ": all " +
                        std::to_string(members.size()) + " runs failed (see " + d.firstFailure + ")");
    return d.responses.front();
}

std::string targetDescription(const CalibrationStudy& study)
{
    const auto loads = study.measurements.failureLoads();
    std::string text = "F* " + kN(stats::mean(loads)) + " (mean of " + std::to_string(loads.size()) + " in " +
                       study.measurementsFile.string() + ")";
    if (study.displacementTarget)
        text += ", d* " + mm(*study.displacementTarget) + " (" + study.displacementSource + ")";
    else
        text += ", no measured displacement: force only";
    return text;
}

void printTarget(const CalibrationStudy& study)
{
    std::cout << "calibrateModel: target " << targetDescription(study) << "; weights force "
              << format(study.forceWeight) << ", displacement " << format(study.displacementWeight);
    if (!study.displacementTarget)
        std::cout << "; among the parameter sets that meet the force, the one nearest "
                  << describeValues(study, study.reference) << " (regularisation "
                  << format(study.regularisation) << ")";
    std::cout << std::endl;
}

void addResultLines(CalibrationOutcome& o, const CalibrationStudy& study, const std::string& prefix,
                    const PeakResponse& r, const PeakErrors& e)
{
    o.report.push_back(
        {prefix + "PeakForce", format(r.force, 6), "[N], error " + format(100 * e.force, 3) + " %"});
    o.report.push_back(
        {prefix + "DisplacementAtPeak", format(r.displacement, 6),
         "[m]" + std::string(study.displacementTarget ? ", error " + format(100 * e.displacement, 3) + " %"
                                                      : ", not a target")});
}

void addTargetLines(CalibrationOutcome& o, const CalibrationStudy& study)
{
    o.report.push_back({"date", quotedText(today()), ""});
    o.report.push_back({"study", quotedText(studyName(study)), ""});
    o.report.push_back({"method", o.method, ""});
    o.report.push_back({"target", quotedText(targetDescription(study)), ""});
    o.report.push_back(
        {"measuredMeanForce", format(stats::mean(study.measurements.failureLoads()), 6), "[N]"});
    if (study.displacementTarget)
        o.report.push_back({"measuredDisplacementAtPeak", format(*study.displacementTarget, 6), "[m]"});
}

}  // namespace

CalibrationOutcome calibrateDemResponseSurface(const CalibrationStudy& study, int jobs)
{
    const auto start = Clock::now();
    printTarget(study);
    RunSet design;
    design.directory = study.runsDirectory() / "responseSurface/design";
    for (const auto& p : study.parameters) {
        std::vector<std::string> levels;
        if (study.design == "fullFactorial")
            for (int k = 0; k < study.levels; ++k)
                levels.push_back(valueText(fromUnit(-1.0 + 2.0 * k / (study.levels - 1), p.low, p.high)));
        design.values.push_back(levels);
    }
    if (study.design == "latinHypercube") {
        design.latinSamples = study.samples;
        design.latinSeed = study.designSeed;
    }
    std::cout << "calibrateModel: design of experiments in " << design.directory.string() << std::endl;
    const auto members = runSet(study, design, jobs);
    const DesignResponses d = collect(study, members);
    if (d.responses.empty())
        throw UserError("the objective cannot be evaluated: all " + std::to_string(members.size()) +
                        " members of the design failed (see " + d.firstFailure + ")");
    if (d.failed > 0)
        std::cout << "calibrateModel: warning: " << d.failed << " of " << members.size()
                  << " members failed and are left out (first: " << d.firstFailure << ")" << std::endl;

    std::vector<Point> points;
    std::vector<double> forces, displacements;
    for (std::size_t i = 0; i < d.values.size(); ++i) {
        points.push_back(unitValues(study, d.values[i]));
        forces.push_back(d.responses[i].force);
        displacements.push_back(d.responses[i].displacement);
    }
    const QuadraticSurface forceSurface = QuadraticSurface::fit(points, forces);
    const QuadraticSurface displacementSurface = QuadraticSurface::fit(points, displacements);
    std::cout << "calibrateModel: response surfaces from " << points.size() << " points: peak force R2 "
              << format(forceSurface.rSquared()) << " (leave-one-out "
              << format(forceSurface.leaveOneOutRSquared()) << "), displacement at peak R2 "
              << format(displacementSurface.rSquared()) << " (leave-one-out "
              << format(displacementSurface.leaveOneOutRSquared()) << ")" << std::endl;

    const Objective surfaceObjective = [&](const std::vector<double>& x) {
        return peakErrors(study, x, {forceSurface(x), displacementSurface(x)}).objective;
    };
    MinimiserSettings settings;
    settings.maxEvaluations = 400;
    settings.relativeTolerance = 1e-8;
    const Minimum best =
        minimiseMultiStart(surfaceObjective, study.parameters.size(), study.surfaceStarts, settings);
    const std::vector<double> values = physicalValues(study, best.x);
    const std::vector<double> x = unitValues(study, values);
    const PeakResponse predicted{forceSurface(x), displacementSurface(x)};
    const PeakErrors predictedErrors = peakErrors(study, x, predicted);
    std::cout << "calibrateModel: surface minimum at " << describeValues(study, values)
              << ": predicted peak force " << kN(predicted.force) << ", displacement "
              << mm(predicted.displacement) << std::endl;

    std::cout << "calibrateModel: confirmation run" << std::endl;
    const PeakResponse simulated =
        runPoint(study, study.runsDirectory() / "responseSurface/confirmation", values, jobs);
    const PeakErrors simulatedErrors = peakErrors(study, x, simulated);
    std::cout << "calibrateModel: simulated peak force " << kN(simulated.force) << " (error "
              << format(100 * simulatedErrors.force, 3) << " %), displacement " << mm(simulated.displacement);
    if (study.displacementTarget)
        std::cout << " (error " << format(100 * simulatedErrors.displacement, 3) << " %)";
    std::cout << std::endl;

    CalibrationOutcome o;
    o.method = "responseSurface";
    o.values = values;
    o.objective = simulatedErrors.objective;
    o.simulations = members.size() + (study.seeds ? study.seeds->values.size() : 1);
    o.wallSeconds = secondsSince(start);
    addTargetLines(o, study);
    o.report.push_back({"designRuns", std::to_string(members.size()), std::to_string(d.failed) + " failed"});
    o.report.push_back({"rSquaredForce", format(forceSurface.rSquared()), ""});
    o.report.push_back(
        {"looRSquaredForce", format(forceSurface.leaveOneOutRSquared()), "leave-one-out (PRESS)"});
    o.report.push_back({"rSquaredDisplacement", format(displacementSurface.rSquared()), ""});
    o.report.push_back({"looRSquaredDisplacement", format(displacementSurface.leaveOneOutRSquared()), ""});
    addResultLines(o, study, "predicted", predicted, predictedErrors);
    addResultLines(o, study, "simulated", simulated, simulatedErrors);
    o.report.push_back({"simulations", std::to_string(o.simulations), ""});
    o.report.push_back({"wallTime", format(o.wallSeconds, 4), "[s] of this calibrateModel run"});
    o.comment = "calibrateModel " + today() + ", study " + studyName(study) + ", response surface of " +
                std::to_string(members.size()) + " runs (R2 F " + format(forceSurface.rSquared(), 3) +
                ", d " + format(displacementSurface.rSquared(), 3) + "), target " + targetDescription(study) +
                "; predicted " + kN(predicted.force) + ", simulated " + kN(simulated.force);
    return o;
}

CalibrationOutcome calibrateDemBobyqa(const CalibrationStudy& study, int jobs)
{
    const auto start = Clock::now();
    printTarget(study);
    int evaluation = 0;
    std::size_t runs = 0;
    std::vector<double> bestValues;
    PeakResponse bestResponse;
    PeakErrors bestErrors;
    bestErrors.objective = HUGE_VAL;
    const Objective simulatedObjective = [&](const std::vector<double>& xRaw) {
        const std::vector<double> values = physicalValues(study, xRaw);
        const std::vector<double> x = unitValues(study, values);
        char name[32];
        std::snprintf(name, sizeof(name), "eval-%04d", evaluation++);
        const PeakResponse r = runPoint(study, study.runsDirectory() / "bobyqa" / name, values, jobs);
        runs += study.seeds ? study.seeds->values.size() : 1;
        const PeakErrors e = peakErrors(study, x, r);
        std::cout << "calibrateModel: " << name << "  " << describeValues(study, values) << "  peak "
                  << kN(r.force) << " at " << mm(r.displacement) << "  objective " << format(e.objective, 4)
                  << std::endl;
        if (e.objective < bestErrors.objective) {
            bestErrors = e;
            bestResponse = r;
            bestValues = values;
        }
        return e.objective;
    };
    MinimiserSettings settings;
    settings.maxEvaluations = study.maxEvaluations;
    settings.initialStep = study.initialStep;
    settings.relativeTolerance = study.tolerance;
    const Minimum m = minimiseBobyqa(reusingRepeatedSets(study, simulatedObjective),
                                     unitValues(study, study.reference), settings);
    std::cout << "calibrateModel: BOBYQA stopped after " << m.evaluations << " evaluations (" << m.status
              << ")" << std::endl;

    CalibrationOutcome o;
    o.method = "bobyqa";
    o.values = bestValues;
    o.objective = bestErrors.objective;
    o.simulations = runs;
    o.wallSeconds = secondsSince(start);
    addTargetLines(o, study);
    o.report.push_back({"evaluations", std::to_string(m.evaluations), quotedText(m.status)});
    addResultLines(o, study, "simulated", bestResponse, bestErrors);
    o.report.push_back({"simulations", std::to_string(runs), ""});
    o.report.push_back({"wallTime", format(o.wallSeconds, 4), "[s] of this calibrateModel run"});
    o.comment = "calibrateModel " + today() + ", study " + studyName(study) + ", BOBYQA on the simulation (" +
                std::to_string(m.evaluations) + " evaluations), target " + targetDescription(study) +
                "; simulated " + kN(bestResponse.force);
    return o;
}

}  // namespace rockfrac::calibration::detail
