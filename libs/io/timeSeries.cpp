#include "io/timeSeries.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/atomicFile.hpp"
#include "core/error.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

namespace {

std::string headerLine(const std::vector<Column>& columns)
{
    std::string line = "#";
    for (std::size_t i = 0; i < columns.size(); ++i) {
        line += (i == 0 ? " " : "\t");
        line += columns[i].name + " [" + columns[i].unit + "]";
    }
    return line;
}

// Split "name [unit]" into its two parts.
void splitNameUnit(const std::string& text, std::string& name, std::string& unit)
{
    const auto open = text.find('[');
    const auto close = text.find(']');
    if (open != std::string::npos && close != std::string::npos && close > open) {
        name = text.substr(0, open);
        unit = text.substr(open + 1, close - open - 1);
    } else {
        name = text;
        unit = "";
    }
    while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.pop_back();
    while (!name.empty() && (name.front() == ' ' || name.front() == '\t')) name.erase(name.begin());
}

}  // namespace

TimeSeriesWriter::TimeSeriesWriter(const fs::path& caseDir, const std::string& name,
                                   const std::vector<Column>& columns, double restartTime,
                                   const std::string& startTimeName)
    : path_(caseDir / "postProcessing" / name / startTimeName / (name + ".dat")), nColumns_(columns.size())
{
    const std::string header = headerLine(columns);
    std::vector<std::string> kept;
    if (restartTime >= 0 && fs::exists(path_)) {
        // Keep the rows up to and including the restart time.
        std::ifstream in(path_);
        std::string line;
        while (std::getline(in, line)) {
            if (line.empty() || line[0] == '#') continue;
            std::istringstream fields(line);
            double t = 0;
            if (!(fields >> t)) continue;
            // A run killed while appending can leave a torn last row, whose cut time
            // may read as an earlier one: only whole rows are kept.
            const auto nFields = static_cast<std::size_t>(std::count(line.begin(), line.end(), '\t')) + 1;
            if (nFields != nColumns_) continue;
            if (t <= restartTime * (1 + 1e-12) + 1e-300) kept.push_back(line);
        }
    }
    writeFileAtomically(path_, [&](std::ostream& out) {
        out << header << "\n";
        for (const auto& line : kept) out << line << "\n";
    });
    out_.open(path_, std::ios::app);
    if (!out_) throw UserError("cannot append to '" + path_.string() + "'; check permissions and free space");
}

void TimeSeriesWriter::append(const std::vector<double>& row)
{
    if (row.size() != nColumns_)
        throw std::logic_error("time series row has " + std::to_string(row.size()) + " values, expected " +
                               std::to_string(nColumns_));
    out_ << std::setprecision(precision_);
    for (std::size_t i = 0; i < row.size(); ++i) out_ << (i ? "\t" : "") << row[i];
    out_ << "\n" << std::flush;
    if (!out_) throw UserError("cannot write to '" + path_.string() + "' (disk full or I/O error)");
}

int TimeSeries::column(const std::string& name) const
{
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<int>(i);
    return -1;
}

std::vector<double> TimeSeries::values(const std::string& name) const
{
    const int c = column(name);
    if (c < 0) throw UserError("time series has no column '" + name + "'");
    std::vector<double> v;
    v.reserve(rows.size());
    for (const auto& r : rows) v.push_back(r[c]);
    return v;
}

TimeSeries readTimeSeries(const fs::path& file)
{
    std::ifstream in(file);
    if (!in) throw UserError("cannot read '" + file.string() + "': no such file or not readable");
    TimeSeries series;
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (line.empty()) continue;
        if (line[0] == '#') {
            if (!series.names.empty()) continue;  // only the first header names columns
            std::string body = line.substr(1);
            std::istringstream cols(body);
            std::string col;
            while (std::getline(cols, col, '\t')) {
                std::string name, unit;
                splitNameUnit(col, name, unit);
                if (name.empty()) continue;
                series.names.push_back(name);
                series.units.push_back(unit);
            }
            continue;
        }
        std::istringstream fields(line);
        std::vector<double> row;
        std::string token;
        while (fields >> token) {
            char* end = nullptr;
            const double v = std::strtod(token.c_str(), &end);
            if (end == token.c_str() || *end != '\0')
                throw UserError(file.string() + ":" + std::to_string(lineNo) + ": '" + token +
                                "' is not a number; expected tab-separated numbers");
            row.push_back(v);
        }
        if (!series.names.empty() && row.size() != series.names.size())
            throw UserError(file.string() + ":" + std::to_string(lineNo) + ": " + std::to_string(row.size()) +
                            " values, but the header names " + std::to_string(series.names.size()) +
                            " columns");
        series.rows.push_back(std::move(row));
    }
    if (series.names.empty())
        throw UserError(file.string() +
                        ": no '#' header line naming the columns; expected e.g. "
                        "'# Time [s]<TAB>force [N]'");
    return series;
}

}  // namespace rockfrac
