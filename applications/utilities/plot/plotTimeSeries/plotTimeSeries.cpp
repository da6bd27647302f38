// plotTimeSeries: one column against another from postProcessing .dat files,
// into a PNG (gnuplot): e.g. plate force against displacement for several
// cases, with the measured failure loads as a band (-measured) and the
// measured force–displacement curves when the measurements have them.
// Axis labels carry the units of the files' headers.
//
// Sample runs:
//   plotTimeSeries -x displacement -y force postProcessing/plateForce/0/plateForce.dat
//   plotTimeSeries -x displacement -y force -measured cases/experiments/BDT/granite/measurements
//                  -labels "300 cells,500 cells" a/plateForce.dat b/plateForce.dat
#include <cmath>
#include <iostream>

#include "core/application.hpp"
#include "core/error.hpp"
#include "io/timeSeries.hpp"
#include "plot/gnuplot.hpp"
#include "stats/measurements.hpp"

using namespace rockfrac;
using namespace rockfrac::stats;
using namespace rockfrac::plot;
namespace fs = std::filesystem;

namespace {

const AppInfo info = {
    "plotTimeSeries",
    "Plot column -y against column -x (default: the first column, Time) of one or more postProcessing .dat "
    "files into a PNG (gnuplot). -measured adds the measured failure loads of a measurements dictionary as a "
    "band (lowest to highest) with their mean, and the measured force-displacement curves when it has them. "
    "Relative paths are relative to the case.",
    "[options] <file.dat>...",
    {"plotTimeSeries -y force postProcessing/plateForce/0/plateForce.dat",
     "plotTimeSeries -x displacement -y force -measured cases/experiments/BDT/granite/measurements "
     "-labels DEM,FEM a/plateForce.dat b/plateForce.dat"},
    {
        {"-x", "column", "column on the x axis (default: the first column)"},
        {"-y", "column", "column on the y axis"},
        {"-measured", "file", "measurements dictionary: band of measured failure loads (y must be a force)"},
        {"-labels", "a,b,...", "legend labels of the files, comma separated (default: the case names)"},
        {"-title", "text", "plot title"},
        {"-output", "file.png", "picture to write (default: plots/<y>.png in the case)"},
    },
    1,
    1000,
    true,
};

struct Series {
    fs::path file;
    std::string label;
    int xColumn = 0, yColumn = 0;  // 0-based
    std::string xUnit, yUnit;
    double largestX = 0.0, largestY = 0.0;
};

// The case a postProcessing file belongs to: <case>/postProcessing/<name>/<time>/<name>.dat.
std::string caseLabel(const fs::path& file)
{
    const fs::path absolute = fs::absolute(file).lexically_normal();
    for (fs::path p = absolute.parent_path(); p.has_relative_path(); p = p.parent_path())
        if (p.filename() == "postProcessing") return p.parent_path().filename().string();
    return absolute.stem().string();
}

int requireColumn(const TimeSeries& series, const fs::path& file, const std::string& name)
{
    const int c = series.column(name);
    if (c < 0) {
        std::string names;
        for (const auto& n : series.names) names += (names.empty() ? "" : ", ") + n;
        throw UserError(file.string() + ": no column '" + name + "'; its columns are " + names);
    }
    return c;
}

Series readSeries(const fs::path& file, const std::string& xName, const std::string& yName)
{
    const TimeSeries series = readTimeSeries(file);
    if (series.rows.empty())
        throw UserError(file.string() + ": no data rows under the header; nothing to plot");
    Series s;
    s.file = fs::absolute(file);
    s.label = caseLabel(file);
    s.xColumn = xName.empty() ? 0 : requireColumn(series, file, xName);
    s.yColumn = requireColumn(series, file, yName);
    s.xUnit = series.units[s.xColumn];
    s.yUnit = series.units[s.yColumn];
    for (const auto& row : series.rows) {
        s.largestX = std::max(s.largestX, std::fabs(row[s.xColumn]));
        s.largestY = std::max(s.largestY, std::fabs(row[s.yColumn]));
    }
    return s;
}

std::vector<Series> readAllSeries(const Application& app)
{
    const std::string xName = app.optionIf("-x").value_or(""), yName = app.option("-y");
    const std::vector<std::string> labels = splitCommaList(app.optionIf("-labels").value_or(""));
    if (app.has("-labels") && labels.size() != app.args().size())
        throw UserError("-labels gives " + std::to_string(labels.size()) + " labels for " +
                        std::to_string(app.args().size()) + " files; give one per file");
    std::vector<Series> all;
    for (std::size_t i = 0; i < app.args().size(); ++i) {
        all.push_back(readSeries(app.path(app.args()[i]), xName, yName));
        if (!labels.empty()) all.back().label = labels[i];
        if (all.back().xUnit != all.front().xUnit || all.back().yUnit != all.front().yUnit)
            throw UserError(app.args()[i] + ": its columns are in [" + all.back().xUnit + "] and [" +
                            all.back().yUnit + "], the first file's in [" + all.front().xUnit + "] and [" +
                            all.front().yUnit + "]; plot files with the same units together");
    }
    return all;
}

// The measured failure loads as a band from the lowest to the highest, their
// mean as a dashed line, and the measured curves (when x and y are m and N).
std::string measuredPlots(const MeasurementSet& set, const Series& first, const DisplayScale& xScale,
                          const DisplayScale& yScale, std::string& data)
{
    if (first.yUnit != "N")
        throw UserError("-measured draws failure loads [N], but the y column is in [" + first.yUnit +
                        "]; plot a force with -y");
    const Sample loads = set.failureLoads();
    const double low = minimum(loads) * yScale.factor, high = maximum(loads) * yScale.factor;
    const std::string n = std::to_string(loads.size());
    std::string plots =
        "NaN with filledcurves fc rgb \"#d0d0d0\" title " +
        gnuplotString(set.label() + " failure loads (n = " + n + "): " + formatQuantity(minimum(loads), "N") +
                      " to " + formatQuantity(maximum(loads), "N")) +
        ", \\\n     " + std::to_string(mean(loads) * yScale.factor) +
        " with lines dt 2 lw 2 lc rgb \"black\" title " +
        gnuplotString("measured mean " + formatQuantity(mean(loads), "N"));
    data += "set object 1 rect from graph 0, first " + std::to_string(low) + " to graph 1, first " +
            std::to_string(high) + " fc rgb \"#d0d0d0\" fillstyle solid 1.0 noborder behind\n";
    bool firstCurve = true;
    for (const Specimen& specimen : set.specimens) {
        if (!specimen.curve || first.xUnit != "m") continue;
        std::vector<std::vector<double>> rows;
        for (std::size_t i = 0; i < specimen.curve->force.size(); ++i)
            rows.push_back(
                {specimen.curve->displacement[i] * xScale.factor, specimen.curve->force[i] * yScale.factor});
        const std::string name = "curve" + std::to_string(&specimen - set.specimens.data());
        data += gnuplotDataBlock(name, rows);
        plots += ", \\\n     $" + name + " using 1:2 with lines lw 1 lc rgb \"gray50\" title " +
                 (firstCurve ? gnuplotString("measured curves") : std::string("''"));
        firstCurve = false;
    }
    return plots;
}

std::string script(const Application& app, const std::vector<Series>& all,
                   const std::optional<MeasurementSet>& measured)
{
    double largestX = 0.0, largestY = measured ? maximum(measured->failureLoads()) : 0.0;
    for (const Series& s : all)
        largestX = std::max(largestX, s.largestX), largestY = std::max(largestY, s.largestY);
    const DisplayScale xScale = chooseDisplayScale(largestX, all.front().xUnit);
    const DisplayScale yScale = chooseDisplayScale(largestY, all.front().yUnit);
    const TimeSeries header = readTimeSeries(all.front().file);
    std::string data, plots;
    if (measured) plots = measuredPlots(*measured, all.front(), xScale, yScale, data) + ", \\\n     ";
    // The files, the band and mean of the measured loads, and "measured curves" when drawn.
    const int legendEntries = static_cast<int>(all.size()) + (measured ? 2 : 0) +
                              (plots.find("measured curves") != std::string::npos ? 1 : 0);
    for (std::size_t i = 0; i < all.size(); ++i) {
        const Series& s = all[i];
        plots += std::string(i ? ", \\\n     " : "") + gnuplotString(s.file.string()) + " using (column(" +
                 std::to_string(s.xColumn + 1) + ")*" + std::to_string(xScale.factor) + "):(column(" +
                 std::to_string(s.yColumn + 1) + ")*" + std::to_string(yScale.factor) + ") with lines lw 2 " +
                 seriesColour(i) + " title " + gnuplotString(s.label);
    }
    const std::string xLabel = header.names[all.front().xColumn] + " [" + xScale.unit + "]";
    const std::string yLabel = header.names[all.front().yColumn] + " [" + yScale.unit + "]";
    return data + "set title " +
           gnuplotString(app.optionIf("-title").value_or(yLabel + " against " + xLabel)) + "\nset xlabel " +
           gnuplotString(xLabel) + "\nset ylabel " + gnuplotString(yLabel) +
           "\nset grid\nset offsets 0, 0, graph 0.05, 0\n" + legendBelowPlot(legendEntries) +
           "set datafile separator \"\\t\"\nplot " + plots + "\n";
}

int run(Application& app)
{
    const std::vector<Series> all = readAllSeries(app);
    std::optional<MeasurementSet> measured;
    if (app.has("-measured")) measured = readMeasurements(app.path(app.option("-measured")));
    const fs::path output = app.path(app.optionIf("-output").value_or("plots/" + app.option("-y") + ".png"));
    const std::string commands = script(app, all, measured);
    if (app.dryRun()) return exitSuccess;
    renderPng(commands, output);
    std::cout << "plotTimeSeries: wrote " << output.string() << "\n";
    return exitSuccess;
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, run);
}
