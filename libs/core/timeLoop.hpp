#pragma once
// One time loop for the solvers: bondedDemFoam (plates, crusher) and feFractureSolver.
//
// As in OpenFOAM's foamRun, where Time owns the clock and the write control and the
// solver module only its physics: a solver is a TimedRun (its step, its samples, its
// time-directory writes) and TimeLoop owns the rest, the same for every solver:
// controlDict's time and write control (TimeControl), the step counter, -dry-run,
// SIGINT/SIGTERM, the progress lines, the sampling cadence and the write rules.
//
//   TimeLoop loop(app, {runEntries, functions});       // system/controlDict, checked
//   std::unique_ptr<TimedRun> run = newXRun(app, loop);  // reads and checks every input
//   run->printSetup();
//   return loop.run(*run);                             // the exit code
//
// loop.run(run): a run that cannot restart refuses a restart; -dry-run stops here;
// then start(restarted) gives the step to continue from, and for each step n -> n + 1:
//
//   beforeStep(n)                   the stage of the step (plates, mantle, feed)
//   [fresh run, first step]         sample(), writeTime(n): the state at the start time
//   advance(deltaT) -> ok?          n += 1; failed: writeFailure(n), then one UserError
//                                   naming the step, the cause, the last complete time
//                                   directory and the dumped state
//   afterStep(n)                    running maxima, detectors, discharge
//   sample() every `interval` steps
//   stopReason()                    non-empty: the run is over
//   write on writeDue(n), at a stop or at the last step: a row first when this step has
//   none (instantaneous rows: every time directory has its row); at SIGINT/SIGTERM write
//   the state but add no row (the uninterrupted run has none there, so the continued
//   series is identical), then exit 130/143
//   progress line
//
// then the rest of the last window (window-mean rows), the "End:" line and report().
// Steps are counted from t = 0 (t_n = n deltaT), so a restarted run writes and samples
// at the same steps as the uninterrupted one.
#include <filesystem>
#include <string>
#include <vector>

#include "core/dictionary.hpp"
#include "core/timeControl.hpp"

namespace rockfrac {

class Application;

// What advance() reports: ok, or why the state cannot go on.
struct StepResult {
    bool ok = true;
    std::string message;  // the cause and what to do (the loop adds where and when)
};

// How a run's time series are sampled (its functions/<name>/writeInterval).
struct Sampling {
    enum class Rows {
        instantaneous,  // a row is the state at its step: also one at every regular write
        windowMeans     // a row is the mean since the last one: rows only every interval
                        // steps, and one for the rest of the last window at the end
    };
    long interval = 1;  // steps between rows
    Rows rows = Rows::instantaneous;
};

class TimeLoop;

// A solver as TimeLoop drives it. The hooks describe the loop, not the physics.
class TimedRun {
public:
    virtual ~TimedRun() = default;
    TimedRun(const TimedRun&) = delete;
    TimedRun& operator=(const TimedRun&) = delete;

    virtual void printSetup() const = 0;
    // A run that writes no restartable state is refused a restart, and its
    // interruption and failure messages name no time directory.
    virtual bool canRestart() const { return true; }

    // After the dry-run check, before any step: the backend and the series files (continued
    // on a restart). Returns the step to continue from: 0, or on a restart the step the
    // state file records.
    virtual long start(bool restarted) = 0;
    virtual Sampling sampling() const = 0;
    // Before the step from t_step: its stage (and at step 0 the forces of the initial state).
    virtual void beforeStep(long step) = 0;
    virtual StepResult advance(double deltaT) = 0;
    // After a successful step, `step` now counting it.
    virtual void afterStep(long step) { (void)step; }
    virtual void sample() = 0;
    // Non-empty when the run is over before endTime: the reason, for the "End:" line.
    virtual std::string stopReason() const { return {}; }
    virtual void writeTime(long step) = 0;
    // The failing state for inspection; returns where it went (empty: nothing written).
    virtual std::string writeFailure(long step) = 0;
    // Whether to stop for a signal: `here`, whether one reached this process. A run over
    // several processes (MPI) answers for all of them, so that they stop at the same step.
    virtual bool interruptedEverywhere(bool here) { return here; }
    // Simulated time [s] and the run's part of a progress line.
    virtual double time() const = 0;
    virtual std::string progress() const { return {}; }
    // The summary after the "End:" line.
    virtual void report(bool interrupted) = 0;

protected:
    // A run holds its loop's controlDict and clock, as OpenFOAM's solver modules hold runTime.
    explicit TimedRun(TimeLoop& loop);
    const Dictionary& controlDict;  // system/controlDict, as the loop read it
    TimeControl& runTime;           // deltaT (a solver may set it), endTime, time directories
};

// The entries of controlDict a run reads beyond the loop's (timeControlEntries), and the
// names of its functions: the loop checks controlDict against them before it reads it.
struct ControlDictEntries {
    std::vector<std::string> run;
    std::vector<std::string> functions;
};

class TimeLoop {
public:
    // Reads <case>/system/controlDict, after checking it for unknown entries.
    TimeLoop(const Application& app, const ControlDictEntries& entries);
    TimeLoop(Dictionary controlDict, const std::filesystem::path& caseDir, bool dryRun = false);

    const Dictionary& controlDict() const { return controlDict_; }
    TimeControl& time() { return time_; }
    const TimeControl& time() const { return time_; }
    long step() const { return step_; }

    // The loop above; returns the exit code (0, or 130/143 after SIGINT/SIGTERM).
    int run(TimedRun& run);

private:
    [[noreturn]] void fail(TimedRun& run, const StepResult& result);

    Dictionary controlDict_;
    TimeControl time_;
    bool dryRun_ = false;
    long step_ = 0;
};

// The entries of system/controlDict that TimeControl reads, plus `functions` and
// `application` (which only names the solver, as in OpenFOAM).
const std::vector<std::string>& timeControlEntries();
// Unknown entries of controlDict (core/knownEntries.hpp): the top level against
// timeControlEntries() and the run's own `runEntries`, functions against `functions`.
void checkControlDict(const Dictionary& controlDict, const std::vector<std::string>& runEntries,
                      const std::vector<std::string>& functions);

// functions/<function>/writeInterval of controlDict [steps], >= 1; defaultSteps without it.
long readSampleInterval(const Dictionary& controlDict, const std::string& function, long defaultSteps);

// SIGINT / SIGTERM: installInterruptHandlers() (which forgets an earlier signal) at the
// start of a loop; the loop checks interrupted() every step, writes the state at the
// current step and exits with interruptExitCode() (130 / 143; 143 in a process that stops
// because another one of its run was signalled).
void installInterruptHandlers();
bool interrupted();
int interruptExitCode();

}  // namespace rockfrac
