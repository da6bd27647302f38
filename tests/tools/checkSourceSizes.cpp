// checkSourceSizes <source dir> <allow-list>
//
// The size rule of the code (files under 800 lines, functions under 150): lists every source file (.cpp .hpp
// .h .cu .cuh) under libs/ and applications/ of more than 800 lines and every function of more than 150
// (measured by sourceSizes.hpp's brace matcher, from the first line of its declaration to its closing brace).
// An allow-list line `path[:function] reason` lets one through; an entry without a reason, or one that no
// longer matches anything over a limit, is an error too, so the list stays short and true. Exit 0 when
// nothing is over a limit that the list does not allow, else 1.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "sourceSizes.hpp"

namespace fs = std::filesystem;
using namespace rockfrac::sourceSizes;

namespace {

constexpr int maxFileLines = 800;
constexpr int maxFunctionLines = 150;

struct AllowEntry {
    int line = 0;  // in the allow-list
    std::string reason;
    bool used = false;
};

std::string readFile(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// path or path:function -> entry. Malformed lines are reported and counted in `errors`.
std::map<std::string, AllowEntry> readAllowList(const fs::path& file, int& errors)
{
    std::map<std::string, AllowEntry> entries;
    std::ifstream in(file);
    if (!in) {
        std::cout << file.string() << ": cannot be read (give the allow-list file)\n";
        ++errors;
        return entries;
    }
    std::string text;
    for (int lineNo = 1; std::getline(in, text); ++lineNo) {
        std::istringstream ls(text);
        std::string key, reason;
        ls >> key;
        if (key.empty() || key[0] == '#') {
            continue;
        }
        std::getline(ls, reason);
        reason.erase(0, reason.find_first_not_of(" \t"));
        if (reason.empty()) {
            std::cout << file.string() << ":" << lineNo << ": '" << key
                      << "' has no reason: write why a split would hurt after it\n";
            ++errors;
        } else if (!entries.emplace(key, AllowEntry{lineNo, reason, false}).second) {
            std::cout << file.string() << ":" << lineNo << ": '" << key << "' is listed twice\n";
            ++errors;
        }
    }
    return entries;
}

std::vector<fs::path> sourceFiles(const fs::path& root)
{
    std::vector<fs::path> files;
    for (const char* top : {"libs", "applications"}) {
        if (!fs::is_directory(root / top)) {
            continue;
        }
        for (const auto& e : fs::recursive_directory_iterator(root / top)) {
            const std::string ext = e.path().extension().string();
            if (e.is_regular_file() &&
                (ext == ".cpp" || ext == ".hpp" || ext == ".h" || ext == ".cu" || ext == ".cuh")) {
                files.push_back(fs::relative(e.path(), root));
            }
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::cerr << "usage: checkSourceSizes <source dir> <allow-list>\n";
        return 1;
    }
    const fs::path root = argv[1];
    const fs::path allowFile = argv[2];
    int errors = 0, allowed = 0;
    auto entries = readAllowList(allowFile, errors);
    // An offence: allowed when listed (the entry is marked used), else reported.
    auto judge = [&](const std::string& key, const std::string& what) {
        const auto it = entries.find(key);
        if (it != entries.end()) {
            it->second.used = true;
            ++allowed;
            return;
        }
        std::cout << what << "\n";
        ++errors;
    };
    const auto files = sourceFiles(root);
    for (const fs::path& rel : files) {
        const std::string path = rel.generic_string();
        const std::string text = readFile(root / rel);
        const int lines = countLines(text);
        if (lines > maxFileLines) {
            judge(path, path + ": " + std::to_string(lines) + " lines (limit " +
                            std::to_string(maxFileLines) + "): split it along its seams");
        }
        std::string error;
        for (const FunctionSpan& f : findFunctions(text, error)) {
            if (f.lines() > maxFunctionLines) {
                judge(path + ":" + f.name, path + ":" + std::to_string(f.firstLine) + ": " + f.name + ": " +
                                               std::to_string(f.lines()) + " lines (limit " +
                                               std::to_string(maxFunctionLines) + "): split it into steps");
            }
        }
        if (!error.empty()) {
            std::cout << path << ": its functions cannot be measured (" << error
                      << "): balance the braces outside preprocessor branches\n";
            ++errors;
        }
    }
    for (const auto& [key, entry] : entries) {
        if (!entry.used) {
            std::cout << allowFile.string() << ":" << entry.line << ": '" << key
                      << "' is within the limits (or gone): remove the entry\n";
            ++errors;
        }
    }
    std::cout << "checkSourceSizes: " << files.size() << " files, " << allowed << " allowed by "
              << allowFile.filename().string() << ", " << errors << " problem(s)\n";
    return errors == 0 ? 0 : 1;
}
