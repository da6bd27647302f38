#pragma once
// Where the members of a study run (docs/user-guide.md, "Running a study on a Slurm cluster"):
//
//     scheduler   slurm;          // or local (the default): members run on this machine
//     slurm                       // only with 'scheduler slurm;'; every entry optional
//     {
//         partition   short;
//         time        00:30:00;   // per member: minutes, MM:SS, HH:MM:SS or D-HH:MM:SS
//         cpusPerTask 2;          // cores per member (OMP_NUM_THREADS); default 1
//         account     rockfrac;
//         maxRunning  20;         // members running at once (the array's %N); default: no limit
//         extra       "--qos=normal --mem-per-cpu=2G";   // more sbatch options
//     }
//
// runCasesDict reads these entries; calibrationDict, explainGapDict and makeTwinDataDict take
// the same two and pass them on to the runCases studies they write.
#include <string>
#include <vector>

#include "core/dictionary.hpp"

namespace rockfrac {

struct SlurmSettings {
    std::string partition;  // "" : the cluster's default
    std::string time;       // "" : the partition's default limit
    int cpusPerTask = 1;
    std::string account;
    int maxRunning = 0;                     // 0: no limit
    std::string extra;                      // as written
    std::vector<std::string> extraOptions;  // `extra` split at blanks
};

struct SchedulerSettings {
    std::string type = "local";  // local | slurm
    SlurmSettings slurm;
    bool isSlurm() const { return type == "slurm"; }
};

// The top-level entries the scheduler adds to a study dictionary.
const std::vector<std::string>& schedulerEntries();

// Read 'scheduler' and 'slurm' of `dict`; UserError with file:line for a bad entry.
SchedulerSettings readScheduler(const Dictionary& dict);

// The entries as a study dictionary holds them ("" for the default, local), for the
// runCases studies that calibrateModel, explainGap and makeTwinData write.
std::string schedulerText(const SchedulerSettings& settings);

// UserError unless sbatch, squeue and scancel are on PATH (checked before anything is written).
void requireSlurmCommands();

}  // namespace rockfrac
