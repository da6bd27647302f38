#pragma once
// Running the members of a study, `jobs` at a time.
//
// Members already done are skipped (their values must still match the
// design); every other member is made afresh from the template and run. A
// failed member is recorded and the batch goes on. SIGINT or SIGTERM stops
// launching, terminates the running members (SIGTERM to their process groups,
// SIGKILL after a grace period), records them as pending and returns: running
// runCases again continues where it stopped.
#include "studyDefinition.hpp"

namespace rockfrac::runcases {

struct BatchSummary {
    int alreadyDone = 0;
    int done = 0;
    int failed = 0;
    int interrupted = 0;  // members stopped by a signal, pending again
    int signal = 0;       // the signal that stopped the batch, 0 when none
};

BatchSummary runBatch(const Study& study, int jobs);

// Print one line per member (id, state, values) without running anything.
void listMembers(const Study& study);

}  // namespace rockfrac::runcases
