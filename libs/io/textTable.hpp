#pragma once
// Tab-separated tables with a '#' header of "name [unit]" columns, like the
// postProcessing time series (io/timeSeries.hpp), but whose cells may be words:
// the results table of a parameter study holds member ids and states beside
// the numbers. "-" marks a value that does not exist (a failed member).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rockfrac {

struct TextTable {
    std::vector<std::string> names;  // column names without units
    std::vector<std::string> units;  // "" when the header gives none
    std::vector<std::vector<std::string>> rows;

    int column(const std::string& name) const;  // -1 when absent
    std::string header() const;                 // "# id [-]\tE [Pa]..."
};

// UserError naming the file (and line) on a missing header or a ragged row.
TextTable readTextTable(const std::filesystem::path& file);
// Atomic: readers (and an interrupted writer) never see half a table.
void writeTextTable(const std::filesystem::path& file, const TextTable& table);

// A cell as a number, when it is one.
std::optional<double> parseNumber(const std::string& cell);

}  // namespace rockfrac
