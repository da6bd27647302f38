#pragma once
// Progress reporting for long runs: a bar on a terminal, steady lines in a log.
//
// Solvers call update() every step (cheap: it only looks at the clock every
// few calls); a line is printed at most every `interval` wall seconds, with the
// step, simulated time, % done, ETA and whatever the solver adds (broken bonds,
// energy balance ...).
#include <chrono>
#include <functional>
#include <string>

namespace rockfrac {

class ProgressReporter {
public:
    ProgressReporter(double startTime, double endTime, double intervalSeconds = 5.0);

    // Report if due; `extras` is only called when a line is printed.
    void update(long step, double time, const std::function<std::string()>& extras);
    // Final line (always printed).
    void finish(long step, double time, const std::string& summary);

    static std::string formatDuration(double seconds);
    bool terminal() const { return terminal_; }

private:
    double startTime_, endTime_, interval_;
    bool terminal_;
    std::chrono::steady_clock::time_point wallStart_, lastPrint_;
    long calls_ = 0;
};

}  // namespace rockfrac
