#pragma once
// The inputs of explainGap (system/explainGapDict) and of the twin-data generator
// (system/twinDataDict), read and checked before anything runs (docs/explainGap.md).
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "calibration/calibrationStudy.hpp"
#include "explain/responseFeatures.hpp"
#include "stats/measurements.hpp"

namespace rockfrac::explain {

// A baseline parameter: calibrated as usual, re-fitted with every candidate effect.
struct BaselineParameter {
    calibration::CalibratedParameter where;  // file, entry, unit, range
    double relativeStep = 0.1;               // trial step for its sensitivity
};

// One test condition: a model case and the specimens measured under the same conditions
// (a loading rate, a specimen shape). A study fits all its conditions together: an effect
// that acts differently in them (the rate effect at two plate speeds) is then told apart
// from a baseline parameter that acts alike in all.
struct TestCondition {
    std::string name;  // "" for the single condition of a study without 'conditions'
    std::filesystem::path targetCase;
    std::filesystem::path measurementsFile;
    stats::MeasurementSet measurements;
};

struct ExplainStudy {
    std::filesystem::path directory, dictionary;
    std::vector<TestCondition> conditions;  // at least one
    // Where the simulations are kept (<simulations>/runs, or <simulations>/<condition>/runs
    // with several conditions); studies of the same model case may share it, so that the
    // baseline and its sensitivities are run once.
    std::filesystem::path simulations;
    std::string prepareCommand, command;
    int jobs = 1;
    SchedulerSettings scheduler;  // where the runs go: local or Slurm
    calibration::SeedList seeds;  // the model's own scatter: every evaluation runs every seed
    std::vector<BaselineParameter> baseline;
    std::vector<calibration::TiedEntry> tied;
    std::vector<std::string> effects;                                       // names from the library
    std::map<std::string, std::map<std::string, std::string>> effectFixed;  // effect -> entry -> value
    std::vector<int> requestedFeatures;                                     // empty: every available one
    Statistics statistics = Statistics::mean;  // how a set of specimens is summarised
    std::filesystem::path responseFile = "postProcessing/plateForce/0/plateForce.dat";
    std::string forceColumn = "force", displacementColumn = "gapChange";
    double heldOutFraction = 0.5;
    double minimumGapReduction = 0.3;
    double significance = 0.01;
    // Pairs of the top-ranked effects refitted when no single effect passes the absolute test
    // (explainGapDict `pairs`: a count 0-3, or off = 0)
    int maxPairs = 3;
    double indistinguishableAic = 2.0;  // kept effects within this AIC of the best are not told apart

    // A calibration study over baseline + effect parameters, for the runCases helpers:
    // the runs of one condition.
    calibration::CalibrationStudy runStudy(std::size_t condition) const;
};

ExplainStudy readExplainStudy(const std::filesystem::path& studyDirectory);
// The top-level entries of system/explainGapDict that readExplainStudy reads.
const std::vector<std::string>& explainGapDictEntries();

// The twin-data generator: the model case, its hidden effects, the specimens'
// seeds and the noise; the label goes to <study>/hiddenLabel only.
struct TwinStudy {
    std::filesystem::path directory, dictionary, targetCase;
    std::string prepareCommand, command;
    int jobs = 1;
    SchedulerSettings scheduler;    // where the runs go: local or Slurm
    calibration::SeedList seeds;    // one specimen per seed
    std::string hiddenEffectsText;  // the body of constant/modelEffects ("" = none)
    std::vector<std::string> hiddenEffects;
    double forceNoise = 0.0;         // relative standard deviation of each force sample [-]
    double displacementNoise = 0.0;  // standard deviation of each displacement sample [m]
    std::uint64_t noiseSeed = 1;
    std::filesystem::path output;  // the measurements directory, relative to the study
    std::filesystem::path responseFile = "postProcessing/plateForce/0/plateForce.dat";
    std::string material = "granite";

    calibration::CalibrationStudy runStudy() const;
};

TwinStudy readTwinStudy(const std::filesystem::path& studyDirectory);
// The top-level entries of system/twinDataDict that readTwinStudy reads.
const std::vector<std::string>& twinDataDictEntries();

}  // namespace rockfrac::explain
