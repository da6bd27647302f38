#pragma once
// Running other programs: the members of a parameter study (runCases) and
// gnuplot (the plot utilities). fork/exec rather than system(), so that the
// caller knows each child's pid, can wait for any of them and can stop them.
#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rockfrac {

// Start argv (argv[0] searched on PATH) in `workingDirectory`, stdin from
// /dev/null, stdout and stderr appended to `logFile`. The child leads its own
// process group, so a terminal's Ctrl-C reaches only the parent, which decides
// what happens to its children (and can signal the child's whole group).
// UserError when the process cannot be created; a program that cannot be
// executed exits with 127 and says why in the log, like a shell.
// `environment` holds extra NAME=value entries added to the parent's environment.
pid_t startProcess(const std::vector<std::string>& argv, const std::filesystem::path& workingDirectory,
                   const std::filesystem::path& logFile, const std::vector<std::string>& environment = {});

// Exit status as a shell reports it: the exit code, or 128 + the signal number.
int shellExitStatus(int waitStatus);

// Start and wait (retrying when a signal interrupts the wait).
int runProcess(const std::vector<std::string>& argv, const std::filesystem::path& workingDirectory,
               const std::filesystem::path& logFile);

// An executable of that name on PATH (or the name itself when it holds a '/').
std::optional<std::filesystem::path> findExecutable(const std::string& name);

}  // namespace rockfrac
