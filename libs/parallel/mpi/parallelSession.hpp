#pragma once
// An application's -parallel run: MPI started and ended, one log, one error message.
//
// Rank 0 prints the log; the other ranks' stdout goes to /dev/null and their stderr is held
// back in a temporary file. At the end every rank reports its exit code to the others
// (non-blocking, for at most `wait` seconds):
//  - every rank arrived: the run ends cleanly with the largest code; an error that rank 0
//    also found (bad input is read alike by every rank) is printed once, by rank 0; an
//    error rank 0 did not have is printed by the rank that had it;
//  - a rank did not arrive (it waits in a collective call for a rank that stopped): the
//    held-back errors are printed and MPI_Abort ends every rank, so a run never hangs.
//
//     int main(int argc, char** argv) {
//         mpi::ParallelSession session(argc, argv);   // only when -parallel was given
//         const int code = runApplication(...);
//         return session.finish(code);
//     }

namespace rockfrac::mpi {

class ParallelSession {
public:
    ParallelSession(int& argc, char**& argv);
    ParallelSession(const ParallelSession&) = delete;
    ParallelSession& operator=(const ParallelSession&) = delete;
    // The process's exit code; MPI is finalised (or the run aborted) on return.
    int finish(int code, double wait = 10.0);

private:
    int rank_ = 0;
    int held_stderr_ = -1;  // the original stderr of a rank > 0 (its own is the temporary file)
    void printHeldErrors();
};

}  // namespace rockfrac::mpi
