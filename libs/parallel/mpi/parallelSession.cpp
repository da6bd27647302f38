#include "parallel/mpi/parallelSession.hpp"

#include <mpi.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <thread>

namespace rockfrac::mpi {

ParallelSession::ParallelSession(int& argc, char**& argv)
{
    MPI_Init(&argc, &argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    if (rank_ == 0) return;
    if (!std::freopen("/dev/null", "w", stdout)) return;
    std::FILE* held = std::tmpfile();
    if (!held) return;
    std::fflush(stderr);
    held_stderr_ = dup(STDERR_FILENO);
    if (held_stderr_ < 0 || dup2(fileno(held), STDERR_FILENO) < 0) held_stderr_ = -1;
}

// A rank > 0: what it wrote to stderr, to the real stderr.
void ParallelSession::printHeldErrors()
{
    if (held_stderr_ < 0) return;
    std::fflush(stderr);
    const off_t end = lseek(STDERR_FILENO, 0, SEEK_CUR);
    char buffer[4096];
    for (off_t at = 0; at < end;) {
        const ssize_t got = pread(STDERR_FILENO, buffer, sizeof(buffer), at);
        if (got <= 0) break;
        if (write(held_stderr_, buffer, static_cast<std::size_t>(got)) != got) break;
        at += got;
    }
}

int ParallelSession::finish(int code, double wait)
{
    std::fflush(stdout);
    std::fflush(stderr);
    // {the largest code, rank 0's code}
    int mine[2] = {code, rank_ == 0 ? code : 0}, all[2] = {0, 0};
    MPI_Request request;
    MPI_Iallreduce(mine, all, 2, MPI_INT, MPI_MAX, MPI_COMM_WORLD, &request);
    const auto start = std::chrono::steady_clock::now();
    int arrived = 0;
    while (true) {
        MPI_Test(&request, &arrived, MPI_STATUS_IGNORE);
        if (arrived) break;
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > wait) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (!arrived) {
        printHeldErrors();
        MPI_Abort(MPI_COMM_WORLD, code != 0 ? code : 1);
    }
    if (code != 0 && all[1] == 0) printHeldErrors();
    MPI_Finalize();
    return all[0];
}

}  // namespace rockfrac::mpi
