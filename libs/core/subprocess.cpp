#include "core/subprocess.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "core/error.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

namespace {

// Only async-signal-safe calls between fork and exec.
[[noreturn]] void becomeChild(char* const* argv, char* const* environment, const char* directory,
                              const char* logFile)
{
    setpgid(0, 0);
    const int log = open(logFile, O_WRONLY | O_CREAT | O_APPEND, 0644);
    const int nothing = open("/dev/null", O_RDONLY);
    if (log >= 0) dup2(log, STDOUT_FILENO), dup2(log, STDERR_FILENO), close(log);
    if (nothing >= 0) dup2(nothing, STDIN_FILENO), close(nothing);
    if (chdir(directory) != 0) {
        const char message[] = "cannot enter the working directory\n";
        [[maybe_unused]] auto written = write(STDERR_FILENO, message, sizeof(message) - 1);
        _exit(127);
    }
    execvpe(argv[0], argv, environment);
    const char message[] = "cannot execute the command (not found or not executable)\n";
    [[maybe_unused]] auto written = write(STDERR_FILENO, message, sizeof(message) - 1);
    _exit(127);
}

// A null-terminated array of pointers into `words` (which must outlive it).
std::vector<char*> cStrings(const std::vector<std::string>& words)
{
    std::vector<char*> pointers;
    for (const std::string& word : words) pointers.push_back(const_cast<char*>(word.c_str()));
    pointers.push_back(nullptr);
    return pointers;
}

}  // namespace

pid_t startProcess(const std::vector<std::string>& argv, const fs::path& workingDirectory,
                   const fs::path& logFile, const std::vector<std::string>& environment)
{
    std::vector<std::string> fullEnvironment;
    for (char** entry = environ; *entry; ++entry) fullEnvironment.emplace_back(*entry);
    fullEnvironment.insert(fullEnvironment.end(), environment.begin(), environment.end());
    // Everything the child needs is prepared before fork: it may only make async-signal-safe calls.
    const std::vector<char*> argvPointers = cStrings(argv), environmentPointers = cStrings(fullEnvironment);
    const std::string directory = workingDirectory.string(), log = fs::absolute(logFile).string();
    const pid_t pid = fork();
    if (pid < 0) throw UserError("cannot start '" + argv.front() + "': " + std::strerror(errno));
    if (pid == 0)
        becomeChild(argvPointers.data(), environmentPointers.data(), directory.c_str(), log.c_str());
    setpgid(pid, pid);  // also in the parent, so the group exists before anyone signals it
    return pid;
}

int shellExitStatus(int waitStatus)
{
    if (WIFEXITED(waitStatus)) return WEXITSTATUS(waitStatus);
    if (WIFSIGNALED(waitStatus)) return 128 + WTERMSIG(waitStatus);
    return 255;
}

int runProcess(const std::vector<std::string>& argv, const fs::path& workingDirectory,
               const fs::path& logFile)
{
    const pid_t pid = startProcess(argv, workingDirectory, logFile);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
    return shellExitStatus(status);
}

std::optional<fs::path> findExecutable(const std::string& name)
{
    auto executable = [](const fs::path& p) { return access(p.c_str(), X_OK) == 0 && !fs::is_directory(p); };
    if (name.find('/') != std::string::npos)
        return executable(name) ? std::optional<fs::path>(name) : std::nullopt;
    const char* path = std::getenv("PATH");
    std::istringstream directories(path ? path : "/usr/bin:/bin");
    std::string directory;
    while (std::getline(directories, directory, ':'))
        if (!directory.empty() && executable(fs::path(directory) / name)) return fs::path(directory) / name;
    return std::nullopt;
}

}  // namespace rockfrac
