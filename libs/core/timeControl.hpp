#pragma once
// controlDict time and write control, time directories, and clean interruption.
//
// controlDict entries (conventions.md §1): startFrom firstTime|startTime|latestTime,
// startTime, stopAt endTime|writeNow, endTime, deltaT, writeControl
// timeStep|runTime|clockTime, writeInterval, purgeWrite, writePrecision.
//
// Time directories are written atomically: the solver fills "<case>/.tmp.<time>"
// and TimeControl renames it to "<case>/<time>" when complete, so a run killed
// at any moment leaves every time directory either complete or absent.
//
// The solvers' time loop (write rules, signals, progress) is TimeLoop (timeLoop.hpp).
#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace rockfrac {

class Dictionary;

class TimeControl {
public:
    enum class WriteControl { timeStep, runTime, clockTime };

    TimeControl(const Dictionary& controlDict, const std::filesystem::path& caseDir);

    double startTime() const { return startTime_; }  // where this run starts (after latestTime lookup)
    double endTime() const { return endTime_; }
    double deltaT() const { return deltaT_; }
    bool deltaTGiven() const { return deltaTGiven_; }
    bool restarting() const { return startTime_ > 0 || restartDirExists_; }
    std::string startTimeName() const { return timeName(startTime_); }
    int writePrecision() const { return writePrecision_; }

    // Steps are counted from time 0 so that write times of a restarted run fall
    // on the same steps as the uninterrupted one: t_n = n * deltaT exactly.
    long stepOf(double time) const;
    double timeOf(long step) const { return static_cast<double>(step) * deltaT_; }
    long endStep() const { return stepOf(endTime_); }
    void setDeltaT(double dt) { deltaT_ = dt; }  // solvers that compute their step

    // Should state be written after `step`? (timeStep: every writeInterval steps;
    // runTime: when a multiple of writeInterval is crossed; clockTime: wall seconds.)
    bool writeDue(long step);

    std::string timeName(double time) const;
    std::filesystem::path stagingDir(double time) const;  // "<case>/.tmp.<time>"
    // An empty staging dir for `time`; UserError naming it when it cannot be
    // made (read-only case, disk full): the previous time directories are kept.
    std::filesystem::path prepareStagingDir(double time) const;
    // Publish a filled staging dir as "<case>/<time>" (replacing an old one) and
    // purge old time directories when purgeWrite > 0. The solvers write the state into the
    // staging dir and their VTK frames before publishing: a time directory has its frames.
    void commitTimeDir(double time);
    // prepareStagingDir, `fill` (writes the files into the staging dir it is given), commit.
    void writeTimeDir(double time, const std::function<void(const std::filesystem::path&)>& fill);
    // Name of the newest complete time directory of the case, "none" without one.
    std::string latestTimeName() const;

    // Numeric time directories of a case, ascending (".tmp.*" and "0" excluded when empty).
    static std::vector<double> timeDirectories(const std::filesystem::path& caseDir);

private:
    std::filesystem::path case_;
    double startTime_ = 0, endTime_ = 0, deltaT_ = 0, writeInterval_ = 0;
    bool deltaTGiven_ = false, restartDirExists_ = false;
    WriteControl writeControl_ = WriteControl::timeStep;
    int purgeWrite_ = 0, writePrecision_ = 8;
    std::chrono::steady_clock::time_point lastClockWrite_;
    std::vector<double> written_;
};

}  // namespace rockfrac
