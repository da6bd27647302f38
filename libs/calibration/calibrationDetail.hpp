#pragma once
// Internal to libs/calibration: the procedures behind calibrate() and their helpers.
#include <chrono>
#include <string>
#include <vector>

#include "calibration/boxMinimiser.hpp"
#include "calibration/calibrationRun.hpp"
#include "calibration/studyRunner.hpp"

namespace rockfrac::calibration::detail {

CalibrationOutcome calibrateDemResponseSurface(const CalibrationStudy& study, int jobs);
CalibrationOutcome calibrateDemBobyqa(const CalibrationStudy& study, int jobs);
CalibrationOutcome calibrateFemBobyqa(const CalibrationStudy& study, int jobs);

// Physical values of a normalised point, rounded as members get them.
std::vector<double> physicalValues(const CalibrationStudy& study, const std::vector<double>& x);
std::vector<double> unitValues(const CalibrationStudy& study, const std::vector<double>& values);
// The objective of a simulation-driven search, asked twice for the same rounded parameter set
// (COBYLA does near its end), gives the first answer again instead of running the set anew:
// the runs would repeat it bit for bit (same values, same seeds). Says so in the log.
Objective reusingRepeatedSets(const CalibrationStudy& study, Objective objective);
// A one-point RunSet (one value per parameter).
RunSet pointRunSet(const std::filesystem::path& directory, const std::vector<double>& values);

std::string format(double value, int digits = 4);
// The study directory's name (of "." too).
std::string studyName(const CalibrationStudy& study);
double secondsSince(std::chrono::steady_clock::time_point start);

}  // namespace rockfrac::calibration::detail
