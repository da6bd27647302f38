#include "stats/sampleSource.hpp"

#include <fstream>

#include "core/error.hpp"
#include "io/textTable.hpp"
#include "stats/measurements.hpp"

namespace rockfrac::stats {

namespace fs = std::filesystem;

bool isTextTable(const fs::path& file)
{
    std::ifstream in(file);
    if (!in) throw UserError("cannot read '" + file.string() + "': no such file or not readable");
    for (std::string line; std::getline(in, line);) {
        const auto first = line.find_first_not_of(" \t\r");
        if (first != std::string::npos) return line[first] == '#';
    }
    throw UserError(file.string() +
                    ": the file is empty; expected a measurements dictionary or a results table");
}

namespace {

LabelledSample readTableColumn(const fs::path& file, const std::string& column)
{
    const TextTable table = readTextTable(file);
    if (column.empty())
        throw UserError(file.string() + ": a table; say which column holds the values (-column name)");
    const int c = table.column(column);
    if (c < 0)
        throw UserError(file.string() + ": no column '" + column + "'; its columns are " + table.header());
    const int status = table.column("status");
    LabelledSample sample{file.parent_path().filename().string() + " " + column, table.units[c], {}};
    for (const auto& row : table.rows) {
        if (status >= 0 && row[status] != "done") continue;
        if (auto value = parseNumber(row[c])) sample.values.push_back(*value);
    }
    if (sample.values.empty()) throw UserError(file.string() + ": no values in column '" + column + "'");
    return sample;
}

}  // namespace

LabelledSample readSample(const fs::path& file, const std::string& column)
{
    if (isTextTable(file)) return readTableColumn(file, column);
    const MeasurementSet set = readMeasurements(file);
    return {set.label(), "N", set.failureLoads()};
}

}  // namespace rockfrac::stats
