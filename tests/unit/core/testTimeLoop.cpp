// TimeLoop (libs/core/timeLoop.hpp) with a fake run: the write times, the rows, a stop,
// a signal write and the continuation from it, the failure path, a run that cannot
// restart, and -dry-run.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/timeLoop.hpp"

namespace fs = std::filesystem;
using namespace rockfrac;

namespace {

// endTime 1 s, deltaT 0.1 s: 10 steps; a write every 3 steps.
std::string controlDictText(const std::string& startFrom = "latestTime")
{
    return "FoamFile { format ascii; class dictionary; object controlDict; }\n"
           "application fake;\nstartFrom " +
           startFrom + ";\nstartTime 0;\nendTime 1;\ndeltaT 0.1;\nwriteControl timeStep;\nwriteInterval 3;\n";
}

// The cases of this process, removed when it ends.
struct ScratchRoot {
    const fs::path path =
        fs::temp_directory_path() / ("rockfrac-test-timeLoop-" + std::to_string(::getpid()));
    ~ScratchRoot()
    {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
} scratch;

fs::path freshCase(const std::string& name)
{
    const fs::path dir = scratch.path / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TimeLoop makeLoop(const fs::path& caseDir, bool dryRun = false)
{
    return TimeLoop(Dictionary::parse(controlDictText(), (caseDir / "system/controlDict").string()), caseDir,
                    dryRun);
}

// A run that only counts: its state is its step n (t = n deltaT), written to <time>/state.
class FakeRun final : public TimedRun {
public:
    FakeRun(const fs::path& caseDir, TimeLoop& loop, Sampling sampling, bool restartable = true)
        : TimedRun(loop), caseDir_(caseDir), sampling_(sampling), restartable_(restartable)
    {
    }

    long signalAt = -1, stopAt = -1, failAt = -1;  // the step at which each happens
    std::vector<long> rows, writes, before;        // steps of each sample, write, beforeStep
    long failureDump = -1, startedAt = -1;
    bool reported = false, reportedInterrupted = false;

    void printSetup() const override {}
    bool canRestart() const override { return restartable_; }
    Sampling sampling() const override { return sampling_; }
    long start(bool restarted) override
    {
        if (restarted) std::ifstream(caseDir_ / runTime.startTimeName() / "state") >> n_;
        startedAt = n_;
        return n_;
    }
    void beforeStep(long step) override
    {
        CHECK(step == n_);
        before.push_back(step);
    }
    StepResult advance(double deltaT) override
    {
        CHECK(deltaT == Approx(0.1));
        ++n_;
        if (n_ == signalAt) std::raise(SIGTERM);
        if (n_ == failAt) return {false, "the fake state blew up"};
        return {};
    }
    void sample() override { rows.push_back(n_); }
    std::string stopReason() const override { return n_ == stopAt ? "the fake is done" : ""; }
    void writeTime(long step) override
    {
        CHECK(step == n_);
        writes.push_back(step);
        if (!restartable_) return;
        runTime.writeTimeDir(time(), [&](const fs::path& dir) { std::ofstream(dir / "state") << step; });
    }
    std::string writeFailure(long step) override
    {
        failureDump = step;
        return "VTK/fake_" + std::to_string(step) + ".vtu";
    }
    double time() const override { return runTime.timeOf(n_); }
    void report(bool interrupted) override
    {
        reported = true;
        reportedInterrupted = interrupted;
    }

private:
    fs::path caseDir_;
    Sampling sampling_;
    bool restartable_;
    long n_ = 0;
};

const Sampling everyOther{2, Sampling::Rows::instantaneous};

}  // namespace

TEST_CASE("TimeLoop writes at writeDue and the last step; every write has its row", "[timeLoop]")
{
    const fs::path dir = freshCase("uninterrupted");
    TimeLoop loop = makeLoop(dir);
    FakeRun run(dir, loop, everyOther);
    REQUIRE(loop.run(run) == exitSuccess);
    CHECK(run.writes == std::vector<long>{0, 3, 6, 9, 10});
    // Every second step, and the write steps that are not sample steps.
    CHECK(run.rows == std::vector<long>{0, 2, 3, 4, 6, 8, 9, 10});
    CHECK(run.before == std::vector<long>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
    CHECK(loop.step() == 10);
    CHECK(run.reported);
    CHECK_FALSE(run.reportedInterrupted);
    // The time directories are named by t_n = n deltaT.
    CHECK(TimeControl::timeDirectories(dir) == std::vector<double>{0, 0.3, 0.6, 0.9, 1.0});
    CHECK(fs::is_directory(dir / "0.3"));
    CHECK(fs::is_directory(dir / "1"));
}

TEST_CASE("TimeLoop stops at the run's stop reason with a write and its row", "[timeLoop]")
{
    const fs::path dir = freshCase("stop");
    TimeLoop loop = makeLoop(dir);
    FakeRun run(dir, loop, everyOther);
    run.stopAt = 5;
    REQUIRE(loop.run(run) == exitSuccess);
    CHECK(run.writes == std::vector<long>{0, 3, 5});
    CHECK(run.rows == std::vector<long>{0, 2, 3, 4, 5});
    CHECK(loop.step() == 5);
    CHECK_FALSE(run.reportedInterrupted);
}

TEST_CASE("TimeLoop: a signal writes the state without a row; the continuation is the uninterrupted run",
          "[timeLoop]")
{
    const fs::path reference = freshCase("reference");
    TimeLoop referenceLoop = makeLoop(reference);
    FakeRun uninterrupted(reference, referenceLoop, everyOther);
    REQUIRE(referenceLoop.run(uninterrupted) == exitSuccess);

    const fs::path dir = freshCase("signal");
    std::vector<long> rows, writes;
    {
        TimeLoop loop = makeLoop(dir);
        FakeRun run(dir, loop, everyOther);
        run.signalAt = 5;
        CHECK(loop.run(run) == 128 + SIGTERM);
        CHECK(run.writes == std::vector<long>{0, 3, 5});   // the state at the signal's step ...
        CHECK(run.rows == std::vector<long>{0, 2, 3, 4});  // ... but no row there
        CHECK(run.reportedInterrupted);
        CHECK(fs::is_directory(dir / "0.5"));
        rows = run.rows;
        writes = run.writes;
    }
    {
        TimeLoop loop = makeLoop(dir);  // startFrom latestTime: 0.5, step 5
        REQUIRE(loop.time().restarting());
        FakeRun run(dir, loop, everyOther);
        REQUIRE(loop.run(run) == exitSuccess);
        CHECK(run.startedAt == 5);
        CHECK(run.before.front() == 5);
        CHECK(run.writes == std::vector<long>{6, 9, 10});  // the uninterrupted run's write steps
        rows.insert(rows.end(), run.rows.begin(), run.rows.end());
    }
    CHECK(rows == uninterrupted.rows);
    CHECK(TimeControl::timeDirectories(dir) == std::vector<double>{0, 0.3, 0.5, 0.6, 0.9, 1.0});
}

TEST_CASE("TimeLoop: a failed step dumps the state and names the last complete time directory", "[timeLoop]")
{
    const fs::path dir = freshCase("failure");
    TimeLoop loop = makeLoop(dir);
    FakeRun run(dir, loop, everyOther);
    run.failAt = 7;
    try {
        loop.run(run);
        FAIL("no UserError");
    } catch (const UserError& e) {
        const std::string text = e.what();
        CHECK_THAT(text, Catch::Contains("step 7 (t = 0.7 s): the fake state blew up"));
        CHECK_THAT(text, Catch::Contains("Last complete time directory: 0.6"));
        CHECK_THAT(text, Catch::Contains("the failing state is in VTK/fake_7.vtu"));
    }
    CHECK(run.failureDump == 7);
    CHECK(run.writes == std::vector<long>{0, 3, 6});
    CHECK_FALSE(run.reported);
}

TEST_CASE("TimeLoop: window-mean rows, and a run that cannot restart", "[timeLoop]")
{
    const Sampling windows{4, Sampling::Rows::windowMeans};
    const fs::path dir = freshCase("windows");
    {
        TimeLoop loop = makeLoop(dir);
        FakeRun run(dir, loop, windows, false);
        REQUIRE(loop.run(run) == exitSuccess);
        CHECK(run.writes == std::vector<long>{0, 3, 6, 9, 10});
        // Rows only every 4 steps, and the rest of the last window at the end.
        CHECK(run.rows == std::vector<long>{0, 4, 8, 10});
        CHECK(TimeControl::timeDirectories(dir).empty());
    }
    {
        TimeLoop loop = makeLoop(dir);
        FakeRun run(dir, loop, windows, false);
        run.signalAt = 5;
        CHECK(loop.run(run) == 128 + SIGTERM);
        CHECK(run.writes == std::vector<long>{0, 3, 5});
        CHECK(run.rows == std::vector<long>{0, 4, 5});  // window means: the last window's row
    }
    // A time directory to start from is refused before anything runs.
    fs::create_directories(dir / "0.5");
    TimeLoop loop = makeLoop(dir);
    FakeRun run(dir, loop, windows, false);
    CHECK_THROWS_WITH(loop.run(run), Catch::Contains("cannot restart"));
    CHECK(run.startedAt == -1);
}

TEST_CASE("TimeLoop: -dry-run runs and writes nothing", "[timeLoop]")
{
    const fs::path dir = freshCase("dryRun");
    TimeLoop loop = makeLoop(dir, true);
    FakeRun run(dir, loop, everyOther);
    CHECK(loop.run(run) == exitSuccess);
    CHECK(run.startedAt == -1);
    CHECK(run.writes.empty());
    CHECK(run.rows.empty());
    CHECK(TimeControl::timeDirectories(dir).empty());
}

TEST_CASE("readSampleInterval reads functions/<name>/writeInterval", "[timeLoop]")
{
    const auto dict = [](const std::string& functions) {
        return Dictionary::parse(controlDictText() + functions, "system/controlDict");
    };
    CHECK(readSampleInterval(dict(""), "plateForce", 10) == 10);
    CHECK(readSampleInterval(dict("functions { plateForce { writeInterval 4; } }\n"), "plateForce", 10) == 4);
    CHECK(readSampleInterval(dict("functions { machine { writeInterval 4; } }\n"), "plateForce", 10) == 10);
    CHECK_THROWS_WITH(
        readSampleInterval(dict("functions { plateForce { writeInterval 0; } }\n"), "plateForce", 10),
        Catch::Contains("system/controlDict:") && Catch::Contains("writeInterval must be >= 1"));
}
