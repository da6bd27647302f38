#include "core/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace rockfrac {

ProgressReporter::ProgressReporter(double startTime, double endTime, double intervalSeconds)
    : startTime_(startTime),
      endTime_(endTime),
      interval_(intervalSeconds),
      terminal_(::isatty(STDOUT_FILENO) != 0),
      wallStart_(std::chrono::steady_clock::now()),
      lastPrint_(wallStart_)
{
}

std::string ProgressReporter::formatDuration(double seconds)
{
    if (!std::isfinite(seconds) || seconds < 0) return "--:--:--";
    const long s = static_cast<long>(seconds + 0.5);
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%02ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
    return buffer;
}

void ProgressReporter::update(long step, double time, const std::function<std::string()>& extras)
{
    // Look at the clock only every 64 calls: update() sits in the time loop.
    if ((++calls_ & 63) != 0) return;
    const auto now = std::chrono::steady_clock::now();
    const double sinceLast = std::chrono::duration<double>(now - lastPrint_).count();
    const double wanted = terminal_ ? 0.25 : interval_;
    if (sinceLast < wanted) return;
    lastPrint_ = now;

    const double elapsed = std::chrono::duration<double>(now - wallStart_).count();
    const double span = endTime_ - startTime_;
    const double fraction = span > 0 ? std::clamp((time - startTime_) / span, 0.0, 1.0) : 1.0;
    const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : NAN;

    std::ostringstream line;
    line.precision(4);
    line << "step " << step << "  t = " << time << " s  " << std::fixed;
    line.precision(1);
    line << 100.0 * fraction << " %  ETA " << formatDuration(eta);
    const std::string more = extras ? extras() : std::string();
    if (!more.empty()) line << "  " << more;

    if (terminal_) {
        const int width = 24;
        const int filled = static_cast<int>(fraction * width);
        std::cout << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] "
                  << line.str() << "\033[K" << std::flush;
    } else {
        std::cout << line.str() << "\n" << std::flush;
    }
}

void ProgressReporter::finish(long step, double time, const std::string& summary)
{
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
    if (terminal_) std::cout << "\r\033[K";
    std::cout << "End: step " << step << "  t = " << time << " s  wall " << formatDuration(elapsed)
              << (summary.empty() ? "" : "  " + summary) << "\n"
              << std::flush;
}

}  // namespace rockfrac
