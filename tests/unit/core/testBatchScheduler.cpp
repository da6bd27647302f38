// The scheduler entries of a study dictionary: local by default, slurm with its sbatch
// settings, every bad entry refused at its line, and the text calibrateModel writes into
// its runCases studies read back to the same settings.
#include <catch2/catch.hpp>

#include "core/batchScheduler.hpp"
#include "core/dictionary.hpp"
#include "core/error.hpp"

using namespace rockfrac;

namespace {

SchedulerSettings readText(const std::string& text)
{
    return readScheduler(Dictionary::parse(text, "runCasesDict"));
}

}  // namespace

TEST_CASE("scheduler: local by default and when named, nothing written for it", "[scheduler]")
{
    CHECK(readText("jobs 2;\n").type == "local");
    CHECK_FALSE(readText("scheduler local;\n").isSlurm());
    CHECK(schedulerText(readText("scheduler local;\n")).empty());
}

TEST_CASE("scheduler slurm: the settings, defaults and the text round trip", "[scheduler]")
{
    const SchedulerSettings bare = readText("scheduler slurm;\n");
    CHECK(bare.isSlurm());
    CHECK(bare.slurm.partition.empty());
    CHECK(bare.slurm.time.empty());
    CHECK(bare.slurm.cpusPerTask == 1);
    CHECK(bare.slurm.maxRunning == 0);

    const SchedulerSettings s = readText(
        "scheduler slurm;\nslurm { partition short; time 1-02:30:00; cpusPerTask 4; account rf;\n"
        "maxRunning 10; extra \"--qos=normal  --mem-per-cpu=2G\"; }\n");
    CHECK(s.slurm.partition == "short");
    CHECK(s.slurm.time == "1-02:30:00");
    CHECK(s.slurm.cpusPerTask == 4);
    CHECK(s.slurm.account == "rf");
    CHECK(s.slurm.maxRunning == 10);
    CHECK(s.slurm.extraOptions == std::vector<std::string>{"--qos=normal", "--mem-per-cpu=2G"});

    const SchedulerSettings again = readText(schedulerText(s));
    CHECK(again.slurm.partition == s.slurm.partition);
    CHECK(again.slurm.time == s.slurm.time);
    CHECK(again.slurm.cpusPerTask == s.slurm.cpusPerTask);
    CHECK(again.slurm.account == s.slurm.account);
    CHECK(again.slurm.maxRunning == s.slurm.maxRunning);
    CHECK(again.slurm.extra == s.slurm.extra);
}

TEST_CASE("scheduler slurm: Slurm's time formats", "[scheduler]")
{
    for (const char* ok : {"30", "30:00", "02:30:00", "1-0", "1-02:30", "1-02:30:00"})
        CHECK(readText(std::string("scheduler slurm; slurm { time ") + ok + "; }\n").slurm.time == ok);
    for (const char* bad : {"1:2:3:4", "-1", "1--2", "1h", "2:", ":30", "a-1"})
        CHECK_THROWS_WITH(readText(std::string("scheduler slurm; slurm { time \"") + bad + "\"; }\n"),
                          Catch::Contains("runCasesDict:1") && Catch::Contains("not a Slurm time limit"));
}

TEST_CASE("scheduler: bad entries are refused at their line", "[scheduler]")
{
    CHECK_THROWS_WITH(readText("jobs 1;\nscheduler pbs;\n"), Catch::Contains("runCasesDict:2"));
    CHECK_THROWS_WITH(readText("slurm { partition short; }\n"),
                      Catch::Contains("runCasesDict:1") && Catch::Contains("the scheduler is local"));
    CHECK_THROWS_WITH(readText("scheduler slurm;\nslurm short;\n"),
                      Catch::Contains("runCasesDict:2") && Catch::Contains("must be a dictionary"));
    CHECK_THROWS_WITH(readText("scheduler slurm; slurm { cpusPerTask 0; }\n"),
                      Catch::Contains("cpusPerTask"));
    CHECK_THROWS_WITH(readText("scheduler slurm; slurm { cpusPerTask 2.5; }\n"),
                      Catch::Contains("whole number"));
    CHECK_THROWS_WITH(readText("scheduler slurm; slurm { partition (a b); }\n"),
                      Catch::Contains("one value"));
    for (const char* own : {"--array=1-3", "-a", "--output=x", "--parsable", "--wrap=ls"})
        CHECK_THROWS_WITH(
            readText(std::string("scheduler slurm; slurm { extra \"--qos=x ") + own + "\"; }\n"),
            Catch::Contains("runCases sets itself"));
}
