#include "core/timeControl.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/faultPoint.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

namespace {

bool parseTimeName(const std::string& name, double& time)
{
    if (name.empty() || !(std::isdigit(static_cast<unsigned char>(name[0])) || name[0] == '.')) return false;
    char* end = nullptr;
    time = std::strtod(name.c_str(), &end);
    return end && *end == '\0' && std::isfinite(time) && time >= 0;
}

}  // namespace

std::vector<double> TimeControl::timeDirectories(const fs::path& caseDir)
{
    std::vector<double> times;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(caseDir, ec)) {
        double t = 0;
        if (entry.is_directory() && parseTimeName(entry.path().filename().string(), t)) times.push_back(t);
    }
    std::sort(times.begin(), times.end());
    return times;
}

TimeControl::TimeControl(const Dictionary& d, const fs::path& caseDir) : case_(caseDir)
{
    const std::string startFrom = d.getWord("startFrom", {"firstTime", "startTime", "latestTime"});
    const double givenStart = d.getScalarOrDefault("startTime", 0.0, Bounds::nonNegative());
    endTime_ = d.getScalar("endTime", Bounds::positive());
    deltaTGiven_ = d.found("deltaT");
    if (deltaTGiven_) deltaT_ = d.getScalar("deltaT", Bounds::positive());
    writeControl_ = [&] {
        const std::string w = d.getWord("writeControl", {"timeStep", "runTime", "clockTime"});
        return w == "timeStep"  ? WriteControl::timeStep
               : w == "runTime" ? WriteControl::runTime
                                : WriteControl::clockTime;
    }();
    writeInterval_ = d.getScalar("writeInterval", Bounds::positive());
    purgeWrite_ = d.getOrDefault<int>("purgeWrite", 0);
    if (purgeWrite_ < 0) throw UserError(d.fileName() + ": purgeWrite must be >= 0 (0 keeps every write)");
    writePrecision_ = d.getOrDefault<int>("writePrecision", 8);
    // A double has 17 significant digits; longer names only cut time directories short.
    if (writePrecision_ < 1 || writePrecision_ > 17)
        throw UserError(d.location("writePrecision").str() + ": writePrecision " +
                        std::to_string(writePrecision_) +
                        " is outside [1, 17] (a time has at most 17 significant digits); use 8 to 17");
    if (d.found("stopAt")) d.getWord("stopAt", {"endTime", "writeNow"});

    const std::vector<double> existing = timeDirectories(caseDir);
    if (startFrom == "startTime") {
        startTime_ = givenStart;
    } else if (startFrom == "latestTime") {
        startTime_ = existing.empty() ? 0.0 : existing.back();
    } else {
        startTime_ = existing.empty() ? 0.0 : existing.front();
    }
    restartDirExists_ = startTime_ > 0 && fs::is_directory(caseDir / timeName(startTime_));
    if (startTime_ > 0 && !restartDirExists_)
        throw UserError(
            d.fileName() + ": startTime " + timeName(startTime_) +
            " has no time directory in the case; choose an existing time or startFrom latestTime");
    if (startTime_ >= endTime_)
        throw UserError(d.fileName() + ": the run starts at " + timeName(startTime_) +
                        " s, at or after endTime " + timeName(endTime_) +
                        " s; raise endTime to continue the run");
    written_ = existing;
    lastClockWrite_ = std::chrono::steady_clock::now();
}

long TimeControl::stepOf(double time) const
{
    // Steps are counted in a long and t_n = n * deltaT must stay exact in a double: 10^15
    // steps at most (about 3 years of wall time at 10^7 steps/s).
    constexpr double maxSteps = 1e15;
    const double steps = time / deltaT_;
    if (!(steps <= maxSteps))
        throw UserError((case_ / "system/controlDict").string() + ": time " + timeName(time) + " s is " +
                        formatNumber(steps) + " steps of " + formatNumber(deltaT_) +
                        " s, more than the 1e15 a run can count; lower endTime or raise deltaT");
    return static_cast<long>(std::llround(steps));
}

bool TimeControl::writeDue(long step)
{
    switch (writeControl_) {
        case WriteControl::timeStep: {
            const long every = std::max(1L, std::lround(writeInterval_));
            return step % every == 0;
        }
        case WriteControl::runTime: {
            // A multiple of writeInterval lies in (t_{n-1}, t_n].
            const double t1 = timeOf(step), t0 = timeOf(step - 1);
            return std::floor(t1 / writeInterval_ * (1 + 1e-12)) >
                   std::floor(t0 / writeInterval_ * (1 + 1e-12));
        }
        case WriteControl::clockTime: {
            const auto now = std::chrono::steady_clock::now();
            if (std::chrono::duration<double>(now - lastClockWrite_).count() < writeInterval_) return false;
            lastClockWrite_ = now;
            return true;
        }
    }
    return false;
}

std::string TimeControl::timeName(double time) const
{
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.*g", writePrecision_, time);
    return buffer;
}

fs::path TimeControl::stagingDir(double time) const
{
    return case_ / (".tmp." + timeName(time));
}

fs::path TimeControl::prepareStagingDir(double time) const
{
    const fs::path staging = stagingDir(time);
    std::error_code ec;
    fs::remove_all(staging, ec);
    if (!ec) fs::create_directories(staging, ec);
    if (ec)
        throw UserError("cannot write time directory " + (case_ / timeName(time)).string() + " (" +
                        ec.message() +
                        "); check the free space and permissions of the case; the last complete time is " +
                        latestTimeName());
    faultPoint("staged");
    return staging;
}

std::string TimeControl::latestTimeName() const
{
    const auto times = timeDirectories(case_);
    return times.empty() ? std::string("none") : timeName(times.back());
}

void TimeControl::writeTimeDir(double time, const std::function<void(const fs::path&)>& fill)
{
    fill(prepareStagingDir(time));
    commitTimeDir(time);
}

void TimeControl::commitTimeDir(double time)
{
    faultPoint("beforeCommit");
    const fs::path staging = stagingDir(time), final = case_ / timeName(time);
    std::error_code ec;
    if (fs::exists(final)) {
        // Move the old one aside first so the final name is never half-replaced.
        const fs::path old = case_ / (".old." + timeName(time));
        fs::remove_all(old, ec);
        fs::rename(final, old, ec);
        fs::rename(staging, final, ec);
        if (ec)
            throw UserError("cannot publish time directory " + final.string() + ": " + ec.message() +
                            "; check the free space and permissions of the case");
        fs::remove_all(old, ec);
    } else {
        fs::rename(staging, final, ec);
        if (ec)
            throw UserError("cannot publish time directory " + final.string() + ": " + ec.message() +
                            "; check the free space and permissions of the case");
    }
    written_.push_back(time);
    std::sort(written_.begin(), written_.end());
    written_.erase(std::unique(written_.begin(), written_.end()), written_.end());
    if (purgeWrite_ > 0) {
        while (static_cast<int>(written_.size()) > purgeWrite_) {
            if (written_.front() > 0) fs::remove_all(case_ / timeName(written_.front()), ec);
            written_.erase(written_.begin());
        }
    }
}

}  // namespace rockfrac
