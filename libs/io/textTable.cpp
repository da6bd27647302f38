#include "io/textTable.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/atomicFile.hpp"
#include "core/error.hpp"

namespace rockfrac {

namespace {

std::string trimmed(const std::string& text)
{
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> splitTabs(const std::string& line)
{
    std::vector<std::string> cells;
    std::istringstream in(line);
    std::string cell;
    while (std::getline(in, cell, '\t')) cells.push_back(trimmed(cell));
    return cells;
}

void readHeader(const std::string& line, TextTable& table)
{
    for (const std::string& cell : splitTabs(line.substr(1))) {
        if (cell.empty()) continue;
        const auto open = cell.find('['), close = cell.rfind(']');
        const bool hasUnit = open != std::string::npos && close != std::string::npos && close > open;
        table.names.push_back(trimmed(hasUnit ? cell.substr(0, open) : cell));
        table.units.push_back(hasUnit ? trimmed(cell.substr(open + 1, close - open - 1)) : "");
    }
}

}  // namespace

int TextTable::column(const std::string& name) const
{
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<int>(i);
    return -1;
}

std::string TextTable::header() const
{
    std::string line = "#";
    for (std::size_t i = 0; i < names.size(); ++i)
        line += (i ? "\t" : " ") + names[i] + " [" + (units[i].empty() ? "-" : units[i]) + "]";
    return line;
}

TextTable readTextTable(const std::filesystem::path& file)
{
    std::ifstream in(file);
    if (!in) throw UserError("cannot read '" + file.string() + "': no such file or not readable");
    TextTable table;
    std::string line;
    for (int lineNo = 1; std::getline(in, line); ++lineNo) {
        if (trimmed(line).empty()) continue;
        if (line[0] == '#') {
            if (table.names.empty()) readHeader(line, table);
            continue;
        }
        if (table.names.empty())
            throw UserError(file.string() + ":" + std::to_string(lineNo) +
                            ": data before the '#' header line that names the columns");
        table.rows.push_back(splitTabs(line));
        if (table.rows.back().size() != table.names.size())
            throw UserError(file.string() + ":" + std::to_string(lineNo) + ": " +
                            std::to_string(table.rows.back().size()) +
                            " tab-separated cells, but the header names " +
                            std::to_string(table.names.size()) + " columns");
    }
    if (table.names.empty())
        throw UserError(file.string() + ": empty, or no '#' header line naming the columns");
    return table;
}

void writeTextTable(const std::filesystem::path& file, const TextTable& table)
{
    writeFileAtomically(file, [&](std::ostream& out) {
        out << table.header() << "\n";
        for (const auto& row : table.rows) {
            for (std::size_t i = 0; i < row.size(); ++i) out << (i ? "\t" : "") << row[i];
            out << "\n";
        }
    });
}

std::optional<double> parseNumber(const std::string& cell)
{
    if (cell.empty()) return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(cell.c_str(), &end);
    if (end == cell.c_str() || *end != '\0') return std::nullopt;
    return value;
}

}  // namespace rockfrac
