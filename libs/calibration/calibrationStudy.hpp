#pragma once
// A calibration study as system/calibrationDict describes it (docs/calibration.md):
// the case to calibrate, the measured data, the parameters and their bounds,
// the entries tied to them, how each run is made, and what is compared.
// Everything is checked here, before anything runs or is written.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/batchScheduler.hpp"
#include "stats/measurements.hpp"

namespace rockfrac::calibration {

struct CalibratedParameter {
    std::string name;
    std::filesystem::path file;  // relative to the case, default constant/rockProperties
    std::string entry;           // slash path, e.g. bond/voronoiQNSC/E
    std::string unit;            // "-" when not given
    double low = 0.0, high = 0.0;
};

// An entry set together with a parameter: value = factor × parameter (cohesion = 1.5 σ̄).
struct TiedEntry {
    std::string name;
    std::filesystem::path file;
    std::string entry;
    double factor = 1.0;
    std::size_t parameter = 0;  // index into CalibrationStudy::parameters
};

struct SeedList {
    std::filesystem::path file;
    std::string entry;
    std::vector<std::string> values;
};

struct CalibrationStudy {
    std::filesystem::path directory;   // the study (-case)
    std::filesystem::path dictionary;  // system/calibrationDict
    std::string model;                 // dem | fem
    std::string method;                // responseSurface | bobyqa
    std::filesystem::path targetCase;  // gets the calibrated values
    std::filesystem::path measurementsFile;
    stats::MeasurementSet measurements;
    std::string prepareCommand;  // run once in the template ("" for none)
    std::string command;         // run in every member
    int jobs = 1;
    SchedulerSettings scheduler;  // passed on to the runCases studies
    std::vector<CalibratedParameter> parameters;
    std::vector<TiedEntry> tied;
    std::optional<SeedList> seeds;

    // Response surface design: a full factorial with `levels` per parameter, or a Latin hypercube.
    std::string design = "fullFactorial";
    int levels = 3;
    std::size_t samples = 0;
    std::uint64_t designSeed = 1;
    int surfaceStarts = 5;  // multi-start grid per dimension for the surface minimum

    // BOBYQA on the simulated objective.
    int maxEvaluations = 30;
    double initialStep = 0.5;
    double tolerance = 1e-3;  // on the normalised parameters

    // What each run gives and what it is compared with.
    std::filesystem::path responseFile;  // relative to a member
    std::string forceColumn = "force";   // dem: the peak is its maximum; fem: the failure load (last row)
    std::string displacementColumn = "gapChange";  // dem: at the peak
    double forceWeight = 0.5, displacementWeight = 0.5;
    std::optional<double> displacementTarget;  // [m]
    std::string displacementSource;
    double regularisation = 1e-3;           // force-only DEM: pull towards `reference` (normalised)
    std::vector<double> reference;          // physical values, default the centre of the bounds
    std::string distance = "wasserstein1";  // fem: or kolmogorovSmirnov

    std::filesystem::path runsDirectory() const { return directory / "runs"; }
    std::filesystem::path templateDirectory() const { return runsDirectory() / "template"; }
    std::filesystem::path rockPropertiesOfTarget() const { return targetCase / "constant/rockProperties"; }
    std::vector<std::string> parameterNames() const;
};

// Read and check system/calibrationDict of `studyDirectory` and the measurements it names.
CalibrationStudy readCalibrationStudy(const std::filesystem::path& studyDirectory);
// The top-level entries of system/calibrationDict that readCalibrationStudy reads.
const std::vector<std::string>& calibrationDictEntries();

// The top-level entries of system/runCasesDict (runCases reads them; calibrateModel and
// explainGap write such dictionaries).
inline const std::vector<std::string>& runCasesDictEntries()
{
    static const std::vector<std::string> entries = {"template", "command",    "jobs",  "scheduler",
                                                     "slurm",    "parameters", "seeds", "results",
                                                     "design",   "samples",    "seed"};
    return entries;
}

// "E=4.6e10 Pa, tensileStrength=2.8e7 Pa, ...".
std::string describeValues(const CalibrationStudy& study, const std::vector<double>& values);

// A value as members get it: 6 significant digits, written as the dictionary prints numbers.
std::string valueText(double value);

}  // namespace rockfrac::calibration
