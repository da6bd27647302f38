#include "batch.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include "core/error.hpp"
#include "core/subprocess.hpp"
#include "members.hpp"
#include "slurmBatch.hpp"

namespace rockfrac::runcases {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

volatile sig_atomic_t stopSignal = 0;
extern "C" void requestStop(int signal)
{
    stopSignal = signal;
}

// SIGINT/SIGTERM set a flag (and interrupt waitpid: no SA_RESTART); the old
// handlers come back when the batch ends.
class StopSignals {
public:
    StopSignals()
    {
        stopSignal = 0;
        struct sigaction action {};
        action.sa_handler = requestStop;
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, &oldInt_);
        sigaction(SIGTERM, &action, &oldTerm_);
    }
    ~StopSignals()
    {
        sigaction(SIGINT, &oldInt_, nullptr);
        sigaction(SIGTERM, &oldTerm_, nullptr);
    }
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

private:
    struct sigaction oldInt_ {
    }, oldTerm_{};
};

// One runCases per study at a time: two would run the same members twice.
class StudyLock {
public:
    explicit StudyLock(const Study& study)
    {
        fs::create_directories(study.membersDirectory());
        const fs::path file = study.membersDirectory() / ".runCases.lock";
        fd_ = open(file.c_str(), O_RDWR | O_CREAT, 0644);
        if (fd_ < 0 || flock(fd_, LOCK_EX | LOCK_NB) != 0)
            throw UserError("another runCases is working on '" + study.directory.string() + "' (lock " +
                            file.string() + "); wait for it to finish");
    }
    ~StudyLock() { close(fd_); }
    StudyLock(const StudyLock&) = delete;
    StudyLock& operator=(const StudyLock&) = delete;

private:
    int fd_ = -1;
};

struct RunningMember {
    const MemberDesign* member;
    Clock::time_point start;
};

std::string seconds(Clock::duration elapsed)
{
    std::ostringstream text;
    text << std::fixed << std::setprecision(1) << std::chrono::duration<double>(elapsed).count() << " s";
    return text.str();
}

class Batch {
public:
    Batch(const Study& study, int jobs) : study_(study), jobs_(jobs), table_(study) {}

    BatchSummary run()
    {
        planMembers();
        writeTable();
        while (true) {
            while (!stopSignal && running_.size() < static_cast<std::size_t>(jobs_) && !queue_.empty())
                launchNext();
            if (running_.empty()) break;
            if (stopSignal) {
                terminateRunning();
                break;
            }
            waitForOne();
        }
        summary_.signal = stopSignal;
        writeTable();
        return summary_;
    }

private:
    // Done members stay; everything else is made afresh, so that nothing a
    // failed or interrupted run left behind leaks into the new run.
    void planMembers()
    {
        for (const MemberDesign& member : study_.members) {
            const auto status = readStatus(study_, member);
            if (status && status->state == "done") {
                checkStatusMatchesDesign(study_, member, *status);
                ++summary_.alreadyDone;
                continue;
            }
            if (status && status->state == "submitted")
                std::cout << "warning: member " << member.id << " was submitted to Slurm as "
                          << status->slurmJob
                          << " by a runCases that did not finish; it runs here now (scancel "
                          << status->slurmJob << " if squeue still lists it)" << std::endl;
            queue_.push_back(&member);
        }
        for (const MemberDesign* member : queue_) prepareMember(study_, *member);
        std::cout << "runCases: " << study_.members.size() << " members, " << summary_.alreadyDone
                  << " already done, " << queue_.size() << " to run, " << jobs_ << " at a time" << std::endl;
        // Members that each start as many OpenMP threads as there are cores, several at a
        // time, oversubscribe the machine: a 60-cell disc ran about eight times slower with two
        // members of two threads each on two cores. Unless the user chose (OMP_NUM_THREADS set),
        // every member gets its share of the cores. The solvers give the same answer on any
        // number of threads, so this changes the time, never the results.
        if (!std::getenv("OMP_NUM_THREADS")) {
            const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
            memberThreads_ = std::to_string(std::max(1u, cores / static_cast<unsigned>(std::max(1, jobs_))));
            std::cout << "runCases: each member runs with OMP_NUM_THREADS=" << memberThreads_ << " (" << cores
                      << " cores, " << jobs_ << " at a time; set OMP_NUM_THREADS to choose)" << std::endl;
        }
    }

    void launchNext()
    {
        const MemberDesign& member = *queue_.front();
        queue_.pop_front();
        const fs::path directory = study_.memberDirectory(member.id);
        writeStatus(study_, member, "running");
        table_.forget(member.id);
        std::vector<std::string> environment = {"RUNCASES_MEMBER=" + member.id,
                                                "RUNCASES_STUDY=" + fs::absolute(study_.directory).string()};
        if (!memberThreads_.empty()) environment.push_back("OMP_NUM_THREADS=" + memberThreads_);
        const pid_t pid = startProcess({"/bin/sh", "-c", study_.command}, directory,
                                       directory / "log.runCases", environment);
        running_[pid] = {&member, Clock::now()};
        std::cout << "started " << member.id << "  " << describeValues(study_, member) << std::endl;
    }

    void waitForOne()
    {
        int status = 0;
        const pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) {
            if (errno == EINTR) return;  // a stop signal: the loop decides
            throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
        }
        finish(pid, shellExitStatus(status), false);
    }

    void finish(pid_t pid, int exitCode, bool stopping)
    {
        const auto it = running_.find(pid);
        if (it == running_.end()) return;
        const MemberDesign& member = *it->second.member;
        const std::string elapsed = seconds(Clock::now() - it->second.start);
        running_.erase(it);
        if (stopping && exitCode != 0) {
            writeStatus(study_, member, "pending", exitCode, "interrupted; runCases runs it again");
            ++summary_.interrupted;
            std::cout << "interrupted " << member.id << "  exit " << exitCode << "  " << elapsed << std::endl;
            return;
        }
        std::string message = exitCode == 0 ? "" : "the command exited with " + std::to_string(exitCode);
        if (exitCode == 0) {
            try {
                std::vector<std::string> units;
                collectResults(study_, member, units);
            } catch (const UserError& e) {
                message = e.what();
            }
        }
        const bool ok = message.empty();
        writeStatus(study_, member, ok ? "done" : "failed", exitCode, message);
        ++(ok ? summary_.done : summary_.failed);
        std::cout << (ok ? "done " : "failed ") << member.id << "  exit " << exitCode << "  " << elapsed
                  << (ok ? ""
                         : "  (" + message + "; see " +
                               (study_.memberDirectory(member.id) / "log.runCases").string() + ")")
                  << std::endl;
        writeTable();
    }

    // SIGTERM to every member's process group, SIGKILL to what is left after the grace period.
    void terminateRunning()
    {
        std::cout << "runCases: signal " << stopSignal << ": stopping " << running_.size()
                  << " running member(s)" << std::endl;
        for (const auto& [pid, member] : running_) kill(-pid, SIGTERM);
        const auto deadline = Clock::now() + std::chrono::seconds(10);
        while (!running_.empty()) {
            int status = 0;
            const pid_t pid = waitpid(-1, &status, WNOHANG);
            if (pid > 0) {
                finish(pid, shellExitStatus(status), true);
                continue;
            }
            if (pid < 0 && errno != EINTR) break;
            if (Clock::now() > deadline)
                for (const auto& [group, member] : running_) kill(-group, SIGKILL);
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
    }

    void writeTable()
    {
        std::vector<std::string> warnings;
        table_.write(warnings);
        for (const std::string& w : warnings) std::cout << "warning: " << w << std::endl;
    }

    const Study& study_;
    int jobs_;
    std::string memberThreads_;  // OMP_NUM_THREADS for the members; empty: inherited
    ResultsTable table_;
    std::deque<const MemberDesign*> queue_;
    std::map<pid_t, RunningMember> running_;
    BatchSummary summary_;
};

}  // namespace

BatchSummary runBatch(const Study& study, int jobs)
{
    if (study.scheduler.isSlurm()) requireSlurmCommands();  // before the lock file is made
    StudyLock lock(study);
    StopSignals signals;
    if (study.scheduler.isSlurm()) return runSlurmBatch(study, stopSignal);
    return Batch(study, jobs).run();
}

void listMembers(const Study& study)
{
    for (const MemberDesign& member : study.members) {
        const auto status = readStatus(study, member);
        std::cout << member.id << "  " << (status ? status->state : "new") << "  "
                  << describeValues(study, member) << "\n";
    }
}

}  // namespace rockfrac::runcases
