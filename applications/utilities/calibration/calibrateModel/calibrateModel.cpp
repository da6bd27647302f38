// calibrateModel: fit model parameters of a case to laboratory measurements.
//
// DEM (the paper's section 5.2): bond Young's modulus, tensile strength (with
// the cohesion tied to it) and friction coefficient so that the simulated
// Brazilian disc gives the measured mean peak force (and its displacement, when
// measured): a design of experiments run by runCases, quadratic response
// surfaces and their minimum, checked by one confirmation run
// (method responseSurface); or BOBYQA directly on the simulations (bobyqa).
// FEM: the Weibull modulus and stress of DFH so that one run per seed
// reproduces the measured failure-load distribution (BOBYQA on W1 or KS).
// The calibrated values go into the case's constant/rockProperties with a
// comment saying when and from what; nothing is written when anything fails.
//
// Sample runs:
//   calibrateModel -case cases/calibration/granite                      # the study's method
//   calibrateModel -case cases/calibration/granite -method bobyqa -jobs 2
//   calibrateModel -case cases/calibration/granite -dry-run             # check the inputs, run nothing
//   calibrateModel -case cases/calibration/granite -noWrite             # calibrate, leave the case as it is
#include <iostream>

#include "calibration/calibrationRun.hpp"
#include "calibration/calibrationStudy.hpp"
#include "calibration/responseSurface.hpp"
#include "core/application.hpp"
#include "core/dictionary.hpp"
#include "core/error.hpp"

using namespace rockfrac;
using namespace rockfrac::calibration;

namespace {

const AppInfo info = {
    "calibrateModel",
    "Calibrate the parameters of a case on measurements, as system/calibrationDict of the study directory "
    "(-case) describes: runs the simulations through runCases under <study>/runs (resumable: runs that are "
    "done are not run again), compares them with the measured data, writes the calibrated values into the "
    "case's files with a comment saying when and from what, and a report into "
    "<study>/calibratedValues.<method>. "
    "See docs/calibration.md.",
    "[options]",
    {"calibrateModel -case cases/calibration/granite",
     "calibrateModel -case cases/calibration/granite -method bobyqa",
     "calibrateModel -case cases/calibration/granite -dry-run"},
    {
        {"-jobs", "N", "simulations at the same time (overrides 'jobs')"},
        {"-method", "name", "responseSurface or bobyqa (overrides 'method')"},
        {"-noWrite", "", "leave the case unchanged; only the report calibratedValues.<method> is written"},
    },
    0,
    0,
    true,
};

int wholeNumberOption(const Application& app, const std::string& name, int fallback)
{
    const auto text = app.optionIf(name);
    if (!text) return fallback;
    try {
        std::size_t used = 0;
        const int n = std::stoi(*text, &used);
        if (used == text->size() && n >= 1) return n;
    } catch (const std::exception&) {
    }
    throw UserError(name + " " + *text + ": expected a whole number of at least 1");
}

void printPlan(const CalibrationStudy& study)
{
    std::cout << "calibrateModel: " << study.model << " model, method " << study.method << ", case "
              << study.targetCase.string() << ", measurements " << study.measurementsFile.string() << " ("
              << study.measurements.specimens.size() << " specimens)\n";
    for (const auto& p : study.parameters)
        std::cout << "  " << p.name << "  " << p.file.string() << " " << p.entry << "  in ["
                  << valueText(p.low) << ", " << valueText(p.high) << "] " << p.unit << "\n";
    for (const auto& t : study.tied)
        std::cout << "  " << t.name << "  " << t.entry << " = " << formatNumber(t.factor) << " x "
                  << study.parameters[t.parameter].name << "\n";
    std::cout << std::flush;
}

int run(Application& app)
{
    CalibrationStudy study = readCalibrationStudy(app.casePath());
    if (const auto method = app.optionIf("-method")) {
        if (*method != "responseSurface" && *method != "bobyqa")
            throw UserError("-method " + *method + ": expected responseSurface or bobyqa");
        if (study.model == "fem" && *method != "bobyqa")
            throw UserError("-method " + *method + ": the FEM calibration uses bobyqa");
        study.method = *method;
    }
    const int jobs = wholeNumberOption(app, "-jobs", study.jobs);
    printPlan(study);
    if (app.dryRun()) return exitSuccess;
    const CalibrationOutcome outcome = calibrate(study, jobs);
    std::cout << "calibrateModel: calibrated " << describeValues(study, outcome.values) << " ("
              << outcome.method << ", " << outcome.simulations << " simulations, " << outcome.wallSeconds
              << " s)\n";
    for (const auto& line : outcome.report)
        std::cout << "  " << line[0] << " " << line[1]
                  << (line.size() > 2 && !line[2].empty() ? "  " + line[2] : "") << "\n";
    const bool intoCase = !app.has("-noWrite");
    writeCalibratedValues(study, outcome, intoCase);
    std::cout << "calibrateModel: wrote "
              << (study.directory / ("calibratedValues." + outcome.method)).string();
    if (intoCase)
        std::cout << " and the values into " << study.targetCase.string() << std::endl;
    else
        std::cout << "; -noWrite: the case is unchanged" << std::endl;
    return exitSuccess;
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, run);
}
