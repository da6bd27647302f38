#pragma once
// A parameter study as system/runCasesDict describes it: the template case,
// the command, the parameters and their design, the seeds, and the results to
// collect (docs/user-guide.md, "runCases"). Everything is checked here, before a
// member is made, so a typo stops the study at once with one clear line.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/batchScheduler.hpp"

namespace rockfrac::runcases {

// One entry of a template file that the study varies.
struct EntryTarget {
    std::filesystem::path file;  // relative to the case, e.g. constant/rockProperties
    std::string entry;           // slash path, e.g. bond/voronoiQNSC/E
};

struct Parameter {
    std::string name;
    EntryTarget target;
    std::string unit;                 // for the results table, "-" when not given
    std::vector<std::string> values;  // full-factorial levels, as written in the dictionary
    bool isRange = false;             // Latin hypercube over [low, high)
    double low = 0.0, high = 0.0;
};

struct Result {
    std::string name;
    std::filesystem::path file;   // relative to the member case
    std::string column;           // a .dat column, or
    std::string entry;            // a dictionary entry
    std::string select = "last";  // for a column: last, first, max or min row
    std::string unit;             // from the dictionary; "" lets the .dat header say
};

// One member of the study: its values of every parameter, and its seed.
struct MemberDesign {
    std::string id;                   // "0000", "0001", ...
    std::vector<std::string> values;  // one per parameter, in the order of Study::parameters
    std::optional<std::string> seed;
};

struct Study {
    std::filesystem::path directory;  // the study (the -case directory)
    std::filesystem::path dictionary;
    std::filesystem::path templateCase;
    std::string command;
    int jobs = 1;
    SchedulerSettings scheduler;  // local, or the members as a Slurm job array
    std::vector<Parameter> parameters;
    std::string design;  // fullFactorial or latinHypercube
    std::size_t samples = 0;
    std::uint64_t designSeed = 1;
    std::optional<EntryTarget> seedTarget;
    std::vector<std::string> seeds;
    std::vector<Result> results;
    std::vector<MemberDesign> members;

    std::filesystem::path membersDirectory() const { return directory / "members"; }
    std::filesystem::path memberDirectory(const std::string& id) const { return membersDirectory() / id; }
    std::filesystem::path resultsTable() const { return directory / "results.dat"; }
};

// Read and check system/runCasesDict of `studyDirectory` and expand its design.
Study readStudy(const std::filesystem::path& studyDirectory);

}  // namespace rockfrac::runcases
