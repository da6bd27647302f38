#include "calibration/studyRunner.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/atomicFile.hpp"
#include "core/dictionary.hpp"
#include "core/dictionaryEditor.hpp"
#include "core/error.hpp"
#include "core/subprocess.hpp"
#include "core/textFile.hpp"
#include "io/textTable.hpp"

namespace rockfrac::calibration {

namespace fs = std::filesystem;

namespace {

std::string quoted(const std::string& text)
{
    std::string q = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') q += '\\';
        q += c;
    }
    return q + "\"";
}

std::string lastLine(const fs::path& file)
{
    std::istringstream in(readFileText(file));
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return last;
}

volatile sig_atomic_t forwardedSignal = 0;
extern "C" void rememberSignal(int signal)
{
    forwardedSignal = signal;
}

// Run argv in `directory` with its output in `log`; SIGINT/SIGTERM to this
// program are passed on to the child's process group (runCases then stops its
// members cleanly and records them as pending).
int runForwardingSignals(const std::vector<std::string>& argv, const fs::path& directory, const fs::path& log)
{
    forwardedSignal = 0;
    struct sigaction action {
    }, oldInt{}, oldTerm{};
    action.sa_handler = rememberSignal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &oldInt);
    sigaction(SIGTERM, &action, &oldTerm);
    const pid_t pid = startProcess(argv, directory, log);
    int status = 0;
    bool passedOn = false;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) break;
        if (forwardedSignal && !passedOn) {
            kill(-pid, forwardedSignal);
            passedOn = true;
        }
    }
    sigaction(SIGINT, &oldInt, nullptr);
    sigaction(SIGTERM, &oldTerm, nullptr);
    if (forwardedSignal)
        throw Interrupted("interrupted (signal " + std::to_string(int(forwardedSignal)) +
                          "); the runs done so far are kept: run the same command again to continue");
    return shellExitStatus(status);
}

// Newest modification time of the inputs of a case (system/, constant/ files, not meshes).
fs::file_time_type newestInput(const fs::path& caseDir)
{
    fs::file_time_type newest{};
    for (const char* sub : {"system", "constant"}) {
        if (!fs::is_directory(caseDir / sub)) continue;
        for (const auto& e : fs::directory_iterator(caseDir / sub))
            if (e.is_regular_file() && e.last_write_time() > newest) newest = e.last_write_time();
    }
    return newest;
}

void copyInputs(const fs::path& from, const fs::path& to)
{
    fs::create_directories(to);
    for (const char* sub : {"system", "constant"})
        if (fs::is_directory(from / sub))
            fs::copy(from / sub, to / sub,
                     fs::copy_options::recursive | fs::copy_options::overwrite_existing);
}

std::string runCasesDictText(const CalibrationStudy& study, const RunSet& set)
{
    std::ostringstream d;
    d << "FoamFile { format ascii; class dictionary; object runCasesDict; }\n\n"
      << "// Written by calibrateModel for the study " << study.directory.filename().string()
      << "; do not edit (it is rewritten).\n"
      << "template   " << quoted(fs::proximate(study.templateDirectory(), set.directory).string()) << ";\n"
      << "command    " << quoted(study.command) << ";\n"
      << "jobs       " << study.jobs << ";\n"
      << schedulerText(study.scheduler) << "\nparameters\n{\n";
    for (std::size_t i = 0; i < study.parameters.size(); ++i) {
        const auto& p = study.parameters[i];
        d << "    " << p.name << " { file " << quoted(p.file.string()) << "; entry " << p.entry << "; unit "
          << quoted(p.unit) << "; ";
        if (set.latinSamples > 0)
            d << "range (" << valueText(p.low) << " " << valueText(p.high) << "); }\n";
        else {
            d << "values (";
            for (std::size_t k = 0; k < set.values[i].size(); ++k) d << (k ? " " : "") << set.values[i][k];
            d << "); }\n";
        }
    }
    d << "}\n";
    if (set.latinSamples > 0)
        d << "design     latinHypercube;\nsamples    " << set.latinSamples << ";\nseed       "
          << set.latinSeed << ";\n";
    if (study.seeds) {
        d << "seeds      { file " << quoted(study.seeds->file.string()) << "; entry " << study.seeds->entry
          << "; values (";
        for (std::size_t k = 0; k < study.seeds->values.size(); ++k)
            d << (k ? " " : "") << study.seeds->values[k];
        d << "); }\n";
    }
    const std::string select = study.model == "dem" ? "max" : "last";
    d << "\nresults\n{\n    " << study.forceColumn << " { file " << quoted(study.responseFile.string())
      << "; column " << study.forceColumn << "; select " << select << "; }\n}\n";
    return d.str();
}

std::vector<MemberRun> readMembers(const CalibrationStudy& study, const fs::path& directory)
{
    const fs::path table = directory / "results.dat";
    if (!fs::is_regular_file(table))
        throw UserError("runCases wrote no '" + table.string() +
                        "': " + lastLine(directory / "log.runCases"));
    const TextTable t = readTextTable(table);
    const int idColumn = t.column("member"), statusColumn = t.column("status"), seedColumn = t.column("seed");
    std::vector<int> valueColumns;
    for (const auto& p : study.parameters) valueColumns.push_back(t.column(p.name));
    std::vector<MemberRun> members;
    for (const auto& row : t.rows) {
        MemberRun m;
        m.id = row.at(static_cast<std::size_t>(idColumn));
        m.done = row.at(static_cast<std::size_t>(statusColumn)) == "done";
        if (seedColumn >= 0) m.seed = row.at(static_cast<std::size_t>(seedColumn));
        for (int c : valueColumns)
            m.values.push_back(parseNumber(row.at(static_cast<std::size_t>(c))).value());
        m.directory = directory / "members" / m.id;
        members.push_back(m);
    }
    return members;
}

}  // namespace

fs::path runCasesExecutable()
{
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec && fs::exists(self.parent_path() / "runCases")) return self.parent_path() / "runCases";
    if (auto found = findExecutable("runCases")) return *found;
    throw UserError(
        "calibrateModel needs runCases, which is neither beside it nor on PATH; build rockfrac "
        "(ninja -C build) or add its bin/ to PATH");
}

void prepareTemplate(const CalibrationStudy& study)
{
    if (study.scheduler.isSlurm()) requireSlurmCommands();  // before anything is written
    const fs::path dir = study.templateDirectory(), stamp = dir / ".prepared";
    if (fs::exists(stamp) && fs::last_write_time(stamp) >= newestInput(study.targetCase)) return;
    fs::remove_all(dir);
    copyInputs(study.targetCase, dir);
    // A tied entry follows its parameter in every member: cohesion #eval "1.5 * $tensileStrength".
    for (const TiedEntry& t : study.tied) {
        const auto& p = study.parameters[t.parameter];
        const auto parent = [](const std::string& path) { return path.substr(0, path.rfind('/') + 1); };
        if (t.file != p.file || parent(t.entry) != parent(p.entry))
            throw UserError(study.dictionary.string() + ": tied entry '" + t.name +
                            "' must be in the same file and sub-dictionary as '" + p.name + "' (" + p.entry +
                            ")");
        setEntryInFile(
            dir / t.file, t.entry,
            "#eval \"" + formatNumber(t.factor) + " * $" + p.entry.substr(parent(p.entry).size()) + "\"");
    }
    if (!study.prepareCommand.empty()) {
        std::cout << "preparing the template of the runs (" << study.prepareCommand << ") in " << dir.string()
                  << std::endl;
        const int status =
            runForwardingSignals({"/bin/sh", "-c", study.prepareCommand}, dir, dir / "log.prepare");
        if (status != 0)
            throw UserError("prepare command '" + study.prepareCommand + "' failed with exit code " +
                            std::to_string(status) + " in '" + dir.string() +
                            "': " + lastLine(dir / "log.prepare"));
    }
    writeFileAtomically(stamp, [](std::ostream& out) { out << "prepared\n"; });
}

std::vector<MemberRun> runSet(const CalibrationStudy& study, const RunSet& set, int jobs)
{
    if (study.scheduler.isSlurm()) requireSlurmCommands();
    fs::create_directories(set.directory / "system");
    const fs::path dictFile = set.directory / "system/runCasesDict";
    const std::string text = runCasesDictText(study, set);
    if (!fs::exists(dictFile) || readFileText(dictFile) != text)
        writeFileAtomically(dictFile, [&](std::ostream& out) { out << text; });
    const fs::path log = set.directory / "log.runCases";
    const int status = runForwardingSignals(
        {runCasesExecutable().string(), "-case", ".", "-jobs", std::to_string(jobs)}, set.directory, log);
    const auto members = readMembers(study, set.directory);
    std::size_t done = 0;
    for (const auto& m : members) done += m.done ? 1 : 0;
    if (status != 0 && done == 0 && members.empty())
        throw UserError("runCases failed in '" + set.directory.string() + "': " + lastLine(log));
    return members;
}

std::size_t countSimulations(const CalibrationStudy& study)
{
    std::size_t n = 0;
    if (!fs::is_directory(study.runsDirectory())) return 0;
    for (const auto& e : fs::recursive_directory_iterator(study.runsDirectory()))
        if (e.is_regular_file() && e.path().filename() == "runCases.status") ++n;
    return n;
}

}  // namespace rockfrac::calibration
