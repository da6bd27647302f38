#include "core/timeLoop.hpp"

#include <atomic>
#include <csignal>
#include <cstdio>

#include "core/application.hpp"
#include "core/error.hpp"
#include "core/knownEntries.hpp"
#include "core/progress.hpp"

namespace rockfrac {

namespace {
Dictionary checkedControlDict(const Application& app, const ControlDictEntries& entries)
{
    Dictionary controlDict = Dictionary::readFile(app.path("system/controlDict"));
    checkControlDict(controlDict, entries.run, entries.functions);
    return controlDict;
}
}  // namespace

TimeLoop::TimeLoop(const Application& app, const ControlDictEntries& entries)
    : TimeLoop(checkedControlDict(app, entries), app.casePath(), app.dryRun())
{
}

TimeLoop::TimeLoop(Dictionary controlDict, const std::filesystem::path& caseDir, bool dryRun)
    : controlDict_(std::move(controlDict)), time_(controlDict_, caseDir), dryRun_(dryRun)
{
}

TimedRun::TimedRun(TimeLoop& loop) : controlDict(loop.controlDict()), runTime(loop.time()) {}

int TimeLoop::run(TimedRun& run)
{
    const bool restarted = time_.restarting();
    if (restarted && !run.canRestart())
        throw UserError(controlDict_.fileName() + ": the run starts at " + time_.startTimeName() +
                        " s, but this run cannot restart (it writes no state to continue from); set "
                        "startFrom startTime; startTime 0; and remove the time directories");
    if (dryRun_) {
        std::printf("Dry run: every input is valid; nothing run, nothing written.\n");
        return exitSuccess;
    }
    installInterruptHandlers();
    step_ = run.start(restarted);
    const Sampling sampling = run.sampling();
    const long firstStep = step_, endStep = time_.endStep();
    ProgressReporter progress(time_.startTime(), time_.endTime());
    std::string reason = "end time reached";
    int exitCode = exitSuccess;
    while (step_ < endStep) {
        run.beforeStep(step_);
        if (!restarted && step_ == firstStep) {  // the initial state: its row and time directory
            run.sample();
            run.writeTime(step_);
        }
        const StepResult result = run.advance(time_.deltaT());
        ++step_;
        if (!result.ok) fail(run, result);
        run.afterStep(step_);
        const bool sampleDue = step_ % sampling.interval == 0;
        if (sampleDue) run.sample();
        const std::string stop = run.stopReason();
        if (run.interruptedEverywhere(interrupted())) {
            reason = run.canRestart()
                         ? "interrupted by a signal: state written, continue with startFrom latestTime"
                         : "interrupted by a signal: output written (this run cannot restart)";
            exitCode = interruptExitCode();
        }
        if (!stop.empty()) reason = stop;
        // A write time adds a row to the series only when the uninterrupted run has it
        // too: not at the step a signal arrived, or the continued series would differ.
        const bool regularWrite = time_.writeDue(step_) || !stop.empty() || step_ == endStep;
        if (regularWrite || exitCode != exitSuccess) {
            if (regularWrite && !sampleDue && sampling.rows == Sampling::Rows::instantaneous) run.sample();
            run.writeTime(step_);
        }
        if (!stop.empty() || exitCode != exitSuccess) break;
        progress.update(step_, run.time(), [&] { return run.progress(); });
    }
    if (sampling.rows == Sampling::Rows::windowMeans && step_ % sampling.interval != 0) run.sample();
    progress.finish(step_, run.time(), reason);
    run.report(exitCode != exitSuccess);
    return exitCode;
}

void TimeLoop::fail(TimedRun& run, const StepResult& result)
{
    const std::string dumped = run.writeFailure(step_);
    char when[96];
    std::snprintf(when, sizeof(when), "step %ld (t = %.6g s): ", step_, run.time());
    std::string text = when + result.message;
    if (run.canRestart()) text += ". Last complete time directory: " + time_.latestTimeName();
    if (!dumped.empty()) text += (run.canRestart() ? "; " : ". ") + ("the failing state is in " + dumped);
    throw UserError(text);
}

const std::vector<std::string>& timeControlEntries()
{
    static const std::vector<std::string> entries = {
        "application",   "startFrom",  "startTime",      "endTime", "deltaT",   "writeControl",
        "writeInterval", "purgeWrite", "writePrecision", "stopAt",  "functions"};
    return entries;
}

void checkControlDict(const Dictionary& controlDict, const std::vector<std::string>& runEntries,
                      const std::vector<std::string>& functions)
{
    checkKnownEntries(controlDict, withEntries(timeControlEntries(), runEntries));
    checkKnownSubEntries(controlDict, "functions", functions);
}

long readSampleInterval(const Dictionary& controlDict, const std::string& function, long defaultSteps)
{
    if (!controlDict.found("functions") || !controlDict.subDict("functions").found(function))
        return defaultSteps;
    const Dictionary& dict = controlDict.subDict("functions").subDict(function);
    checkKnownEntries(dict, {"writeInterval"});
    const long interval = dict.getOrDefault<long>("writeInterval", defaultSteps);
    if (interval < 1)
        throw UserError(dict.location("writeInterval").str() + ": functions/" + function +
                        "/writeInterval must be >= 1 step");
    return interval;
}

// ---- interruption -------------------------------------------------------------

namespace {
std::atomic<int> receivedSignal{0};
extern "C" void onSignal(int signal)
{
    receivedSignal.store(signal);
}
}  // namespace

void installInterruptHandlers()
{
    receivedSignal.store(0);
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
}

bool interrupted()
{
    return receivedSignal.load() != 0;
}

int interruptExitCode()
{
    const int signal = receivedSignal.load();
    return 128 + (signal != 0 ? signal : SIGTERM);
}

}  // namespace rockfrac
