#pragma once
// postProcessing time series: postProcessing/<name>/<startTime>/<name>.dat
//
// Tab-separated, a '#' header naming every column with its unit, first column
// Time. Rows are flushed as they are written so a crashed run keeps what it
// had. On restart the rows after the restart time are dropped (the file is
// rewritten atomically) and new rows are appended: a restarted run continues
// the file, it never clobbers it.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rockfrac {

struct Column {
    std::string name;  // e.g. "force"
    std::string unit;  // e.g. "N"; "-" for dimensionless
};

class TimeSeriesWriter {
public:
    // restartTime < 0: a new file (an existing one is replaced).
    TimeSeriesWriter(const std::filesystem::path& caseDir, const std::string& name,
                     const std::vector<Column>& columns, double restartTime = -1.0,
                     const std::string& startTimeName = "0");
    void append(const std::vector<double>& row);
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
    std::size_t nColumns_;
    std::ofstream out_;
    int precision_ = 10;
};

// A whole .dat file read back: column names (with units stripped) and rows.
struct TimeSeries {
    std::vector<std::string> names;  // "Time", "force", ...
    std::vector<std::string> units;
    std::vector<std::vector<double>> rows;
    int column(const std::string& name) const;  // -1 when absent
    std::vector<double> values(const std::string& name) const;
};

// UserError naming the file and the line on malformed content.
TimeSeries readTimeSeries(const std::filesystem::path& file);

}  // namespace rockfrac
