#include "slurmBatch.hpp"

#include <pwd.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <thread>

#include "core/atomicFile.hpp"
#include "core/error.hpp"
#include "core/subprocess.hpp"
#include "core/textFile.hpp"
#include "members.hpp"

namespace rockfrac::runcases {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

struct Captured {
    int status = 0;
    std::string output;  // stdout and stderr
};

// Run a Slurm command and keep what it printed (through a file of the study: the
// subprocess helpers write to files).
Captured capture(const std::vector<std::string>& argv, const fs::path& scratch)
{
    std::error_code ec;
    fs::remove(scratch, ec);
    Captured result;
    result.status = runProcess(argv, scratch.parent_path(), scratch);
    if (fs::exists(scratch)) result.output = readFileText(scratch);
    fs::remove(scratch, ec);
    while (!result.output.empty() && (result.output.back() == '\n' || result.output.back() == ' '))
        result.output.pop_back();
    return result;
}

std::string shellQuoted(const std::string& text)
{
    std::string q = "'";
    for (char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string userName()
{
    const passwd* pw = getpwuid(getuid());
    return pw ? pw->pw_name : std::to_string(getuid());
}

// "0-3,5,7-9": the indices of the array, in ranges.
std::string arrayList(const std::vector<unsigned long>& indices)
{
    std::ostringstream out;
    for (std::size_t i = 0; i < indices.size();) {
        std::size_t j = i;
        while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
        out << (i ? "," : "") << indices[i];
        if (j > i) out << "-" << indices[j];
        i = j + 1;
    }
    return out.str();
}

std::string slurmElapsed(Clock::duration elapsed)
{
    std::ostringstream text;
    text << std::fixed << std::setprecision(1) << std::chrono::duration<double>(elapsed).count() << " s";
    return text.str();
}

std::string arrayOf(const std::string& task)
{
    return task.substr(0, task.find('_'));
}

// The exit code the array task wrote, when it got that far.
std::optional<int> readExitFile(const fs::path& file)
{
    if (!fs::is_regular_file(file)) return std::nullopt;
    try {
        std::size_t used = 0;
        const std::string text = readFileText(file);
        const int code = std::stoi(text, &used);
        if (used > 0) return code;
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

class SlurmBatch {
public:
    SlurmBatch(const Study& study, const volatile sig_atomic_t& stop)
        : study_(study),
          stop_(stop),
          table_(study),
          members_(fs::weakly_canonical(fs::absolute(study.membersDirectory()))),
          scratch_(members_ / ".runCases.slurm.out")
    {
    }

    BatchSummary run()
    {
        std::vector<const MemberDesign*> toSubmit = planMembers();
        writeTable();
        if (!toSubmit.empty() && !stop_) submit(toSubmit);
        waitForMembers();
        summary_.signal = stop_;
        writeTable();
        return summary_;
    }

private:
    struct Waiting {
        const MemberDesign* member;
        std::string task;  // "<array>_<index>"
        Clock::time_point since;
        int misses = 0;  // polls that found the task gone without its exit code
    };

    fs::path exitFile(const MemberDesign& member) const { return members_ / member.id / "runCases.exit"; }

    // The array tasks of this user that squeue lists (pending, running, completing).
    std::optional<std::set<std::string>> queuedTasks()
    {
        const Captured c = capture({"squeue", "-h", "-r", "-u", userName(), "-o", "%i"}, scratch_);
        if (c.status != 0) {
            std::cout << "warning: squeue failed (exit " << c.status << "): " << c.output
                      << "; asking again later" << std::endl;
            return std::nullopt;
        }
        std::set<std::string> tasks;
        std::istringstream in(c.output);
        for (std::string task; in >> task;) tasks.insert(task);
        return tasks;
    }

    // Done members stay; members whose task is still queued, or ended while no runCases
    // was watching, are waited for; everything else is made afresh and submitted.
    std::vector<const MemberDesign*> planMembers()
    {
        std::optional<std::set<std::string>> queued;
        std::vector<const MemberDesign*> toSubmit;
        for (const MemberDesign& member : study_.members) {
            const auto status = readStatus(study_, member);
            if (status && status->state == "done") {
                checkStatusMatchesDesign(study_, member, *status);
                ++summary_.alreadyDone;
                continue;
            }
            if (status && status->state == "submitted" && !status->slurmJob.empty()) {
                checkStatusMatchesDesign(study_, member, *status);
                if (!queued) queued = queuedTasks();
                if (!queued)
                    throw UserError("squeue failed; runCases cannot tell which members of '" +
                                    study_.directory.string() + "' are still in Slurm: run it again later");
                if (queued->count(status->slurmJob) || readExitFile(exitFile(member))) {
                    waiting_.push_back({&member, status->slurmJob, Clock::now()});
                    continue;
                }
            }
            toSubmit.push_back(&member);
        }
        for (const MemberDesign* member : toSubmit) prepareMember(study_, *member);
        std::cout << "runCases: " << study_.members.size() << " members, " << summary_.alreadyDone
                  << " already done, " << waiting_.size() << " already submitted to Slurm, "
                  << toSubmit.size() << " to submit (scheduler slurm: Slurm decides how many run at once)"
                  << std::endl;
        return toSubmit;
    }

    // Array task N runs member N; it writes the command's exit code once the command ends.
    fs::path writeJobScript()
    {
        const fs::path script = members_ / "runCases.sbatch";
        const std::size_t width = study_.members.front().id.size();
        const fs::path study = fs::weakly_canonical(fs::absolute(study_.directory));
        writeFileAtomically(script, [&](std::ostream& out) {
            out << "#!/bin/sh\n"
                << "# Written by runCases for the study " << study.string()
                << " (rewritten at each submission):\n"
                << "# array task N runs member N in its directory, as runCases runs it locally.\n"
                << "id=$(printf '%0" << width << "d' \"$SLURM_ARRAY_TASK_ID\")\n"
                << "cd " << shellQuoted(members_.string()) << "/\"$id\" || exit 1\n"
                << "rm -f runCases.exit\n"
                << "export RUNCASES_MEMBER=\"$id\" RUNCASES_STUDY=" << shellQuoted(study.string()) << "\n";
            if (!std::getenv("OMP_NUM_THREADS"))
                out << "export OMP_NUM_THREADS=" << study_.scheduler.slurm.cpusPerTask << "\n";
            out << "/bin/sh -c " << shellQuoted(study_.command) << " > log.runCases 2>&1 < /dev/null\n"
                << "code=$?\n"
                << "echo \"$code\" > runCases.exit.part && mv runCases.exit.part runCases.exit\n"
                << "exit \"$code\"\n";
        });
        return script;
    }

    std::vector<std::string> sbatchCommand(const std::vector<const MemberDesign*>& members)
    {
        const SlurmSettings& s = study_.scheduler.slurm;
        std::vector<unsigned long> indices;
        for (const MemberDesign* member : members) indices.push_back(std::stoul(member->id));
        std::string array = arrayList(indices);
        if (s.maxRunning > 0) array += "%" + std::to_string(s.maxRunning);
        const std::size_t width = study_.members.front().id.size();
        std::vector<std::string> argv = {
            "sbatch",
            "--parsable",
            "--job-name=runCases-" + study_.directory.filename().string(),
            "--array=" + array,
            "--cpus-per-task=" + std::to_string(s.cpusPerTask),
            "--chdir=" + members_.string(),
            "--output=" + (members_ / ("%" + std::to_string(width) + "a/log.slurm")).string()};
        if (!s.partition.empty()) argv.push_back("--partition=" + s.partition);
        if (!s.time.empty()) argv.push_back("--time=" + s.time);
        if (!s.account.empty()) argv.push_back("--account=" + s.account);
        argv.insert(argv.end(), s.extraOptions.begin(), s.extraOptions.end());
        argv.push_back(writeJobScript().string());
        return argv;
    }

    void submit(const std::vector<const MemberDesign*>& members)
    {
        const std::vector<std::string> argv = sbatchCommand(members);
        const Captured c = capture(argv, scratch_);
        const std::string array = c.output.substr(0, c.output.find_first_of(";\n"));
        if (c.status != 0 || array.empty() || array.find_first_not_of("0123456789") != std::string::npos) {
            std::string command;
            for (const std::string& a : argv) command += (command.empty() ? "" : " ") + a;
            std::string said = c.output;
            std::replace(said.begin(), said.end(), '\n', ' ');
            throw UserError(
                "sbatch failed (exit " + std::to_string(c.status) + "): " + said + " (command: " + command +
                "); the members stay pending: check the slurm { } entries of " + study_.dictionary.string());
        }
        const auto now = Clock::now();
        for (const MemberDesign* member : members) {
            const std::string task = array + "_" + std::to_string(std::stoul(member->id));
            writeStatus(study_, *member, "submitted", -1, "", task);
            table_.forget(member->id);
            waiting_.push_back({member, task, now});
        }
        std::cout << "runCases: submitted " << members.size() << " member(s) as Slurm job array " << array
                  << " (" << argv[3] << ")" << std::endl;
        for (const MemberDesign* member : members)
            std::cout << "submitted " << member->id << "  " << describeValues(study_, *member) << std::endl;
    }

    void sleepUnlessStopped(Clock::duration duration) const
    {
        const auto end = Clock::now() + duration;
        while (!stop_ && Clock::now() < end)
            std::this_thread::sleep_for(
                std::min<Clock::duration>(std::chrono::milliseconds(100), end - Clock::now()));
    }

    // Poll squeue: 1 s, doubling to 30 s while nothing ends, back to 1 s when a member ends.
    void waitForMembers()
    {
        Clock::duration interval = std::chrono::seconds(1);
        const Clock::duration longest = std::chrono::seconds(30);
        while (!waiting_.empty()) {
            if (stop_) {
                cancelArrays();
                return;
            }
            sleepUnlessStopped(interval);
            if (stop_) continue;
            const auto queued = queuedTasks();
            const bool ended = queued && collectEnded(*queued, false);
            interval = ended ? std::chrono::seconds(1) : std::min(interval * 2, longest);
        }
    }

    // Finish the members whose task squeue no longer lists; true when any left squeue
    // (the next poll comes soon).
    bool collectEnded(const std::set<std::string>& queued, bool stopping)
    {
        bool left = false;
        for (auto it = waiting_.begin(); it != waiting_.end();) {
            if (queued.count(it->task)) {
                ++it;
                continue;
            }
            left = true;
            const std::optional<int> code = readExitFile(exitFile(*it->member));
            // On a shared file system the exit file may show up a little after the
            // task has left squeue: one more poll before the member counts as lost.
            if (!code && !stopping && ++it->misses < 2) {
                ++it;
                continue;
            }
            finish(*it, code, stopping);
            it = waiting_.erase(it);
        }
        return left;
    }

    // The state Slurm gives the task: scontrol (recent jobs), else sacct (accounting).
    std::string slurmState(const std::string& task)
    {
        const Captured c = capture({"scontrol", "-o", "show", "job", task}, scratch_);
        const std::size_t at = c.output.find("JobState=");
        if (c.status == 0 && at != std::string::npos)
            return c.output.substr(at + 9, c.output.find_first_of(" \n", at) - at - 9);
        if (findExecutable("sacct")) {
            const Captured a = capture({"sacct", "-n", "-X", "-P", "-j", task, "-o", "State"}, scratch_);
            if (a.status == 0 && !a.output.empty()) return a.output.substr(0, a.output.find('\n'));
        }
        return "unknown (Slurm no longer lists the job)";
    }

    std::string logs(const MemberDesign& member) const
    {
        return (members_ / member.id / "log.runCases").string() + ", " +
               (members_ / member.id / "log.slurm").string();
    }

    void finish(const Waiting& w, std::optional<int> code, bool stopping)
    {
        const MemberDesign& member = *w.member;
        const std::string elapsed = slurmElapsed(Clock::now() - w.since);
        if (stopping && code.value_or(-1) != 0) {
            writeStatus(study_, member, "pending", code.value_or(-1),
                        "interrupted (Slurm job " + w.task + " cancelled); runCases submits it again");
            ++summary_.interrupted;
            std::cout << "interrupted " << member.id << "  Slurm job " << w.task << " cancelled" << std::endl;
            return;
        }
        std::string message;
        if (!code)
            message = "Slurm job " + w.task + " ended before the command did";
        else if (*code != 0)
            message = "the command exited with " + std::to_string(*code);
        else
            try {
                std::vector<std::string> units;
                collectResults(study_, member, units);
            } catch (const UserError& e) {
                message = e.what();
            }
        if (!message.empty()) message += " (Slurm state " + slurmState(w.task) + ")";
        const bool ok = message.empty();
        writeStatus(study_, member, ok ? "done" : "failed", code.value_or(-1), message, w.task);
        ++(ok ? summary_.done : summary_.failed);
        std::cout << (ok ? "done " : "failed ") << member.id << "  exit "
                  << (code ? std::to_string(*code) : std::string("-")) << "  " << elapsed
                  << (ok ? "" : "  (" + message + "; see " + logs(member) + ")") << std::endl;
        writeTable();
    }

    // scancel the arrays, wait until squeue no longer lists their tasks, leave the
    // members that did not finish pending.
    void cancelArrays()
    {
        std::set<std::string> arrays;
        for (const Waiting& w : waiting_) arrays.insert(arrayOf(w.task));
        std::vector<std::string> argv = {"scancel"};
        argv.insert(argv.end(), arrays.begin(), arrays.end());
        std::cout << "runCases: signal " << stop_ << ": cancelling Slurm job array(s)";
        for (const std::string& a : arrays) std::cout << " " << a;
        std::cout << " (" << waiting_.size() << " member(s) not finished)" << std::endl;
        const Captured c = capture(argv, scratch_);
        if (c.status != 0)
            std::cout << "warning: scancel failed (exit " << c.status << "): " << c.output << std::endl;
        const auto deadline = Clock::now() + std::chrono::seconds(60);
        std::optional<std::set<std::string>> queued;
        while (Clock::now() < deadline) {
            queued = queuedTasks();
            const bool anyLeft =
                !queued || std::any_of(waiting_.begin(), waiting_.end(),
                                       [&](const Waiting& w) { return queued->count(w.task) > 0; });
            if (!anyLeft) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(500));
        }
        if (queued) collectEnded(*queued, true);
        for (const Waiting& w : waiting_)
            std::cout << "warning: member " << w.member->id << ": Slurm still lists " << w.task
                      << " after scancel; the next runCases waits for it" << std::endl;
    }

    void writeTable()
    {
        std::vector<std::string> warnings;
        table_.write(warnings);
        for (const std::string& w : warnings) std::cout << "warning: " << w << std::endl;
    }

    const Study& study_;
    const volatile sig_atomic_t& stop_;
    ResultsTable table_;
    fs::path members_;
    fs::path scratch_;
    std::vector<Waiting> waiting_;
    BatchSummary summary_;
};

}  // namespace

BatchSummary runSlurmBatch(const Study& study, const volatile sig_atomic_t& stopSignal)
{
    return SlurmBatch(study, stopSignal).run();
}

}  // namespace rockfrac::runcases
