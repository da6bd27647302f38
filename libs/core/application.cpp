// The application shell: option parsing, banner, help, and exit codes.
#include "core/application.hpp"

#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <iostream>

#include "core/knownEntries.hpp"

namespace rockfrac {

namespace {

// Options every application understands (conventions.md §2).
const std::vector<AppOption>& commonOptions()
{
    static const std::vector<AppOption> options = {
        {"-case", "dir", "case directory (default: the current directory)"},
        {"-dry-run", "", "read and check every input, run nothing, write nothing"},
        {"-noFunctionObjects", "", "do not execute the functions of controlDict"},
        {"-strict", "", "refuse unknown (misspelt) dictionary entries instead of warning"},
        {"-help", "", "print this help and exit"},
    };
    return options;
}

const AppOption* findOption(const std::vector<AppOption>& options, const std::string& name)
{
    for (const auto& o : options)
        if (o.name == name) return &o;
    return nullptr;
}

std::string hostName()
{
    char buffer[256] = {};
    if (gethostname(buffer, sizeof(buffer) - 1) != 0) return "unknown";
    return buffer;
}

std::string localTime()
{
    std::time_t now = std::time(nullptr);
    char buffer[64] = {};
    std::strftime(buffer, sizeof(buffer), "%Y-%m-%d %H:%M:%S", std::localtime(&now));
    return buffer;
}

}  // namespace

Application::Application(const AppInfo& info, int argc, char** argv) : info_(info)
{
    setStrictEntries(false, info_.name);
    for (int i = 1; i < argc; ++i) {
        const std::string word = argv[i];
        if (word == "-help" || word == "--help" || word == "-h") {
            help_ = true;
            continue;
        }
        if (word.size() > 1 && word[0] == '-' && !std::isdigit(static_cast<unsigned char>(word[1])) &&
            word[1] != '.') {
            const AppOption* option = findOption(commonOptions(), word);
            if (!option) option = findOption(info_.options, word);
            if (!option)
                throw UserError("unknown option '" + word + "'; run '" + info_.name +
                                " -help' for the options it accepts");
            std::string value;
            if (!option->argName.empty()) {
                if (i + 1 >= argc)
                    throw UserError("option '" + word + "' needs a value <" + option->argName + ">");
                value = argv[++i];
            }
            if (word == "-case")
                case_ = value;
            else if (word == "-dry-run")
                dryRun_ = true;
            else if (word == "-noFunctionObjects")
                functionObjects_ = false;
            else if (word == "-strict")
                setStrictEntries(true, info_.name);
            else
                options_[word] = value;
            continue;
        }
        args_.push_back(word);
    }
    if (help_) return;
    if (static_cast<int>(args_.size()) < info_.minArgs || static_cast<int>(args_.size()) > info_.maxArgs) {
        throw UserError("expected " +
                        (info_.minArgs == info_.maxArgs
                             ? std::to_string(info_.minArgs)
                             : std::to_string(info_.minArgs) + " to " + std::to_string(info_.maxArgs)) +
                        " argument(s), got " + std::to_string(args_.size()) + "; usage: " + info_.name + " " +
                        info_.usage);
    }
    std::error_code ec;
    if (!std::filesystem::is_directory(case_, ec))
        throw UserError("case directory '" + case_.string() +
                        (std::filesystem::exists(case_, ec) ? "' is not a directory" : "' does not exist") +
                        "; give an existing case with -case <dir>");
}

std::string Application::caseName() const
{
    std::error_code ec;
    auto absolute = std::filesystem::weakly_canonical(std::filesystem::absolute(case_), ec);
    if (ec) absolute = std::filesystem::absolute(case_);
    std::string name = absolute.filename().string();
    if (name.empty() || name == ".") name = absolute.parent_path().filename().string();
    return name;
}

std::string Application::option(const std::string& name) const
{
    auto it = options_.find(name);
    if (it == options_.end())
        throw UserError("option '" + name + "' is required; see " + info_.name + " -help");
    return it->second;
}

std::optional<std::string> Application::optionIf(const std::string& name) const
{
    auto it = options_.find(name);
    if (it == options_.end()) return std::nullopt;
    return it->second;
}

void Application::printHelp() const
{
    std::cout << "Usage: " << info_.name << " " << info_.usage << "\n\n"
              << info_.description << "\n\nOptions:\n";
    auto print = [](const AppOption& o) {
        std::string left = "  " + o.name + (o.argName.empty() ? "" : " <" + o.argName + ">");
        if (left.size() < 26) left.resize(26, ' ');
        std::cout << left << " " << o.help << "\n";
    };
    for (const auto& o : info_.options) print(o);
    for (const auto& o : commonOptions()) print(o);
    if (!info_.sampleRuns.empty()) {
        std::cout << "\nSample runs:\n";
        for (const auto& s : info_.sampleRuns) std::cout << "  " << s << "\n";
    }
    std::cout << "\n" << buildString() << "\n";
}

void Application::printBanner() const
{
    std::cout << "/*---------------------------------------------------------------------------*\\\n"
              << "  " << info_.name << "    " << buildString() << "\n"
              << "  case:  " << std::filesystem::absolute(case_).lexically_normal().string() << "\n"
              << "  host:  " << hostName() << "    date: " << localTime() << "\n"
              << (dryRun_ ? "  mode:  dry run (nothing is written)\n" : "")
              << "\\*---------------------------------------------------------------------------*/\n"
              << std::flush;
}

namespace {

int reportUserError(const AppInfo& info, const char* message)
{
    std::cout << std::flush;
    std::cerr << info.name << ": error: " << message << std::endl;
    return exitUserError;
}

}  // namespace

int runApplication(const AppInfo& info, int argc, char** argv, const std::function<int(Application&)>& body)
{
    try {
        Application app(info, argc, argv);
        if (app.helpRequested()) {
            app.printHelp();
            return exitSuccess;
        }
        if (info.banner) app.printBanner();
        return body(app);
    } catch (const UserError& e) {
        return reportUserError(info, e.what());
    } catch (const Interrupted& e) {  // stopped: the message says how to continue
        return reportUserError(info, e.what());
    } catch (const std::filesystem::filesystem_error& e) {
        // The case's file system refused (a symbolic link loop, a permission, a full disk):
        // the path is the case's, not a bug.
        const std::string message =
            std::string(e.what()) + "; check that path (links, permissions, free space) and run again";
        return reportUserError(info, message.c_str());
    } catch (const std::exception& e) {
        std::cout << std::flush;
        std::cerr << info.name << ": internal error: " << e.what()
                  << " (this is a bug in rockfrac: please report it with the case)" << std::endl;
        return exitInternalError;
    }
}

}  // namespace rockfrac
