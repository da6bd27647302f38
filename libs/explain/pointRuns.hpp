#pragma once
// One point of parameter space run over every seed of a study (a runCases study
// under <study>/runs/<label>-<hash>), and the force–displacement curves it gave.
// A point that was run before is not run again (runCases resumes).
#include <filesystem>
#include <string>
#include <vector>

#include "calibration/calibrationStudy.hpp"
#include "explain/responseFeatures.hpp"

namespace rockfrac::explain {

struct PointRuns {
    std::vector<double> values;
    std::vector<std::string> seeds;                 // of the members that gave a curve
    std::vector<std::vector<double>> displacement;  // per member
    std::vector<std::vector<double>> force;
    std::vector<CurveFeatures> features;  // per member with a complete curve
    int failed = 0;                       // members that failed or gave no load drop
    std::filesystem::path directory;
    FeatureSummary summary(Statistics statistics = Statistics::mean) const
    {
        return summarise(features, statistics);
    }
};

// Write the effect entries every run of the study may change into the template's
// constant/modelEffects (the effects at their neutral values plus the fixed entries).
void writeTemplateEffects(const calibration::CalibrationStudy& study, const std::string& body);

PointRuns runPoint(const calibration::CalibrationStudy& study, const std::vector<double>& values,
                   const std::string& label, const std::string& displacementColumn,
                   const std::string& forceColumn);

}  // namespace rockfrac::explain
