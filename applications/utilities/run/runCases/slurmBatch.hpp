#pragma once
// Running the members of a study as one Slurm job array (scheduler slurm;).
//
// The pending members are made from the template and submitted together with
// `sbatch --array=<their indices>`; array task N runs member N in its directory
// and writes the command's exit code to runCases.exit there. Each member's
// runCases.status records "submitted" and its task ("<array>_<N>"), so a
// runCases started again after its driver died waits for the tasks still in
// squeue, collects those that ended, and submits only the rest. runCases
// polls squeue with a back-off (1 s doubling to 30 s, back to 1 s when a
// member ends). SIGINT/SIGTERM cancel the arrays (scancel), wait until squeue
// no longer lists them and leave the unfinished members pending. A member that
// ends without an exit code (time limit, cancelled, node failure) or with a
// non-zero one is failed, with its Slurm state (scontrol, else sacct) and logs.
#include <csignal>

#include "batch.hpp"
#include "studyDefinition.hpp"

namespace rockfrac::runcases {

BatchSummary runSlurmBatch(const Study& study, const volatile sig_atomic_t& stopSignal);

}  // namespace rockfrac::runcases
