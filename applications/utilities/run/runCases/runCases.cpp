// runCases: run a parameter study. Each member is a copy of a template case
// with some dictionary entries changed (a full factorial over value lists, a
// Latin hypercube over ranges, times a list of random seeds); a command runs in
// each member, several at a time, and one table collects their results.
//
// The study is resumable and scheduler-friendly: every member's state is in
// members/<id>/runCases.status, a re-run skips the members that are done,
// SIGINT/SIGTERM stop it cleanly, one line is printed per member started or
// finished, and the exit code is the number of failed members.
//
// Sample runs:
//   runCases -case studies/bondStrength                 # run (or continue) the study
//   runCases -case studies/bondStrength -jobs 4         # 4 members at a time
//   runCases -case studies/bondStrength -dry-run        # list the members and their states
//   runCases -case studies/bondStrength -collect        # only rebuild results.dat
#include <algorithm>
#include <iostream>
#include <string>

#include "batch.hpp"
#include "core/application.hpp"
#include "core/error.hpp"
#include "members.hpp"
#include "studyDefinition.hpp"

using namespace rockfrac;
using namespace rockfrac::runcases;

namespace {

const AppInfo info = {
    "runCases",
    "Run a parameter study described by system/runCasesDict of the study directory (-case): clone the "
    "template case once per member of the design into members/<id>, set its parameter values, run the "
    "command in it (several members at a time), and collect the results into results.dat. Members that are "
    "done are not run again; failed, interrupted and unfinished ones are. The exit code is the number of "
    "failed members (0: all done), or 130/143 when interrupted.",
    "[options]",
    {"runCases -case studies/bondStrength", "runCases -case studies/bondStrength -jobs 4",
     "runCases -case studies/bondStrength -dry-run", "runCases -case studies/bondStrength -collect"},
    {
        {"-jobs", "N", "members run at the same time (overrides 'jobs' of runCasesDict)"},
        {"-collect", "", "only rebuild results.dat from the members' states and result files"},
    },
    0,
    0,
    true,
};

int jobsOption(const Application& app, const Study& study)
{
    const auto text = app.optionIf("-jobs");
    if (!text) return study.jobs;
    try {
        std::size_t used = 0;
        const int jobs = std::stoi(*text, &used);
        if (used == text->size() && jobs >= 1) return jobs;
    } catch (const std::exception&) {
    }
    throw UserError("-jobs " + *text + ": expected a whole number of at least 1");
}

int collectOnly(const Study& study)
{
    std::vector<std::string> warnings;
    ResultsTable(study).write(warnings);
    for (const std::string& w : warnings) std::cout << "warning: " << w << "\n";
    std::cout << "runCases: wrote " << study.resultsTable().string() << "\n";
    return exitSuccess;
}

int run(Application& app)
{
    const Study study = readStudy(app.casePath());
    const int jobs = jobsOption(app, study);
    std::cout << "runCases: " << study.members.size() << " members (" << study.design << "), template "
              << study.templateCase.string() << ", command '" << study.command << "'" << std::endl;
    if (app.dryRun()) {
        listMembers(study);
        return exitSuccess;
    }
    if (app.has("-collect")) return collectOnly(study);
    const BatchSummary summary = runBatch(study, jobs);
    std::cout << "runCases: " << summary.alreadyDone + summary.done << " of " << study.members.size()
              << " members done (" << summary.done << " now), " << summary.failed << " failed, "
              << summary.interrupted << " interrupted; table " << study.resultsTable().string() << std::endl;
    if (summary.signal != 0) return 128 + summary.signal;
    return std::min(summary.failed, 125);
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, run);
}
