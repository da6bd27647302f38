#pragma once
// The application shell every rockfrac executable stands on.
//
// A main() is thin: it declares what the application is (AppInfo), then hands
// its body to runApplication(), which parses the common options (-case, -help,
// -dry-run, -noFunctionObjects, -strict), prints the banner, and turns errors into the
// documented exit codes: 0 success, 1 user error (one clear line), 2 internal.
//
//   int main(int argc, char** argv)
//   {
//       return rockfrac::runApplication(info, argc, argv, [](rockfrac::Application& app) {
//           ... read app.casePath() / "system/xDict", work, write ...
//           return 0;
//       });
//   }
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace rockfrac {

struct AppOption {
    std::string name;     // e.g. "-entry"
    std::string argName;  // e.g. "name"; empty for a flag without argument
    std::string help;
};

struct AppInfo {
    std::string name;                     // executable name, e.g. "meshRock"
    std::string description;              // one paragraph: what it does
    std::string usage;                    // e.g. "[options]" or "[options] <file>"
    std::vector<std::string> sampleRuns;  // "Sample runs" shown by -help (MFEM style)
    std::vector<AppOption> options;       // application-specific options
    int minArgs = 0;                      // positional arguments accepted
    int maxArgs = 0;
    bool banner = true;  // print the banner (utilities that print data say false)
};

class Application {
public:
    Application(const AppInfo& info, int argc, char** argv);

    const AppInfo& info() const { return info_; }
    const std::filesystem::path& casePath() const { return case_; }
    std::filesystem::path path(const std::filesystem::path& relative) const { return case_ / relative; }
    std::string caseName() const;  // last component of the absolute case path

    bool dryRun() const { return dryRun_; }
    bool functionObjects() const { return functionObjects_; }
    bool helpRequested() const { return help_; }

    bool has(const std::string& option) const { return options_.count(option) > 0; }
    std::string option(const std::string& option) const;  // UserError if absent
    std::optional<std::string> optionIf(const std::string& option) const;
    const std::vector<std::string>& args() const { return args_; }

    void printHelp() const;
    void printBanner() const;

private:
    AppInfo info_;
    std::filesystem::path case_ = ".";
    bool dryRun_ = false;
    bool functionObjects_ = true;
    bool help_ = false;
    std::map<std::string, std::string> options_;
    std::vector<std::string> args_;
};

// Parse arguments, print the banner, run body, map exceptions to exit codes.
int runApplication(const AppInfo& info, int argc, char** argv, const std::function<int(Application&)>& body);

// Build identification shown in banners: version, git commit, build type.
std::string buildString();

}  // namespace rockfrac
