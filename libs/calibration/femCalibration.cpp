// The FEM (KST-DFH) calibration on the failure-load distribution (calibrationRun.hpp).
#include <cmath>
#include <ctime>
#include <iostream>

#include "calibration/boxMinimiser.hpp"
#include "calibration/calibrationDetail.hpp"
#include "core/error.hpp"
#include "io/timeSeries.hpp"
#include "stats/distances.hpp"
#include "stats/weibull.hpp"

namespace rockfrac::calibration::detail {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

// The failure load of a member: the last row of its response column.
std::optional<double> failureLoad(const CalibrationStudy& study, const MemberRun& m)
{
    if (!m.done) return std::nullopt;
    try {
        const TimeSeries s = readTimeSeries(m.directory / study.responseFile);
        const int c = s.column(study.forceColumn);
        if (c < 0 || s.rows.empty()) return std::nullopt;
        const double load = s.rows.back()[static_cast<std::size_t>(c)];
        if (load > 0 && std::isfinite(load)) return load;  // 0: the run never failed
    } catch (const UserError&) {
    }
    return std::nullopt;
}

double distance(const CalibrationStudy& study, const stats::Sample& simulated, const stats::Sample& measured)
{
    if (study.distance == "kolmogorovSmirnov") return stats::kolmogorovSmirnov(simulated, measured);
    return stats::wasserstein1(simulated, measured) / stats::mean(measured);
}

}  // namespace

CalibrationOutcome calibrateFemBobyqa(const CalibrationStudy& study, int jobs)
{
    const auto start = Clock::now();
    const stats::Sample measured = study.measurements.failureLoads();
    std::cout << "calibrateModel: target the failure-load distribution of " << study.measurements.label()
              << " (" << measured.size() << " specimens, mean " << format(stats::mean(measured) / 1e3)
              << " kN), " << study.seeds->values.size() << " seeds per parameter set, distance "
              << study.distance << std::endl;
    int evaluation = 0;
    std::size_t runs = 0;
    double bestObjective = HUGE_VAL;
    std::vector<double> bestValues;
    stats::Sample bestSample;
    const Objective objective = [&](const std::vector<double>& xRaw) {
        const std::vector<double> values = physicalValues(study, xRaw);
        char name[32];
        std::snprintf(name, sizeof(name), "eval-%04d", evaluation++);
        const auto members =
            runSet(study, pointRunSet(study.runsDirectory() / "bobyqa" / name, values), jobs);
        runs += members.size();
        stats::Sample simulated;
        for (const auto& m : members)
            if (auto load = failureLoad(study, m)) simulated.push_back(*load);
        if (simulated.empty())
            throw UserError("the objective cannot be evaluated at " + describeValues(study, values) +
                            ": all " + std::to_string(members.size()) + " seeds failed (see " +
                            (members.front().directory / "log.runCases").string() + ")");
        if (simulated.size() < members.size())
            std::cout << "calibrateModel: warning: " << members.size() - simulated.size() << " of "
                      << members.size() << " seeds gave no failure load in " << name
                      << "; compared without them" << std::endl;
        const double d = distance(study, simulated, measured);
        std::cout << "calibrateModel: " << name << "  " << describeValues(study, values) << "  median "
                  << format(stats::median(simulated) / 1e3) << " kN  " << study.distance << " " << format(d)
                  << std::endl;
        if (d < bestObjective) {
            bestObjective = d;
            bestValues = values;
            bestSample = simulated;
        }
        return d;
    };
    MinimiserSettings settings;
    settings.maxEvaluations = study.maxEvaluations;
    settings.initialStep = study.initialStep;
    settings.relativeTolerance = study.tolerance;
    const Minimum m =
        minimiseBobyqa(reusingRepeatedSets(study, objective), unitValues(study, study.reference), settings);
    std::cout << "calibrateModel: BOBYQA stopped after " << m.evaluations << " evaluations (" << m.status
              << ")" << std::endl;

    CalibrationOutcome o;
    o.method = "bobyqa";
    o.values = bestValues;
    o.objective = bestObjective;
    o.simulations = runs;
    o.wallSeconds = secondsSince(start);
    const std::time_t now = std::time(nullptr);
    char today[16];
    std::strftime(today, sizeof(today), "%Y-%m-%d", std::gmtime(&now));
    const std::string name = studyName(study);
    o.report.push_back({"date", "\"" + std::string(today) + "\"", ""});
    o.report.push_back({"study", "\"" + name + "\"", ""});
    o.report.push_back({"distance", study.distance, ""});
    o.report.push_back(
        {"objective", format(bestObjective), study.distance == "wasserstein1" ? "W1 / measured mean" : "KS"});
    o.report.push_back({"kolmogorovSmirnov", format(stats::kolmogorovSmirnov(bestSample, measured)), ""});
    o.report.push_back({"wasserstein1", format(stats::wasserstein1(bestSample, measured), 6), "[N]"});
    o.report.push_back({"seeds", std::to_string(study.seeds->values.size()), ""});
    o.report.push_back({"simulatedMean", format(stats::mean(bestSample), 6), "[N]"});
    o.report.push_back({"measuredMean", format(stats::mean(measured), 6), "[N]"});
    o.report.push_back({"evaluations", std::to_string(m.evaluations), "\"" + m.status + "\""});
    o.report.push_back({"simulations", std::to_string(runs), ""});
    o.report.push_back({"wallTime", format(o.wallSeconds, 4), "[s]"});
    o.comment = "calibrateModel " + std::string(today) + ", study " + name + ", BOBYQA, " +
                std::to_string(study.seeds->values.size()) + " seeds per set against " +
                std::to_string(measured.size()) + " failure loads of " + study.measurements.label() + ": " +
                study.distance + " " + format(bestObjective, 3) + ", KS " +
                format(stats::kolmogorovSmirnov(bestSample, measured), 3);
    return o;
}

}  // namespace rockfrac::calibration::detail
