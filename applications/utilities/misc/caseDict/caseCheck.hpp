#pragma once
// caseDict -check: a case's dictionaries against the entries their readers declare
// (core/knownEntries.hpp), without running the applications.
#include <filesystem>
#include <string>
#include <vector>

namespace rockfrac {

// One dictionary a case (or a study directory) may hold, and the top-level entries the
// applications reading it know: the union over its readers (constant/loading is read by the
// plate DEM, the crusher and the FEM).
struct DeclaredDictionary {
    std::string file;  // relative to the case: "system/controlDict"
    std::vector<std::string> entries;
};

// The table: one row per dictionary, built from the readers' own lists.
const std::vector<DeclaredDictionary>& declaredDictionaries();

// Each unknown top-level entry of the case's declared dictionaries: "file:line:column:
// unknown entry 'x' in dictionary 'd' (did you mean 'y'?)". A dictionary that does not parse
// gives one line, the parser's message.
std::vector<std::string> checkCaseDictionaries(const std::filesystem::path& caseDir);

}  // namespace rockfrac
