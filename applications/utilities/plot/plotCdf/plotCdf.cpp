// plotCdf: failure-load CDFs by median ranks, simulated against measured, as
// in the paper's Figs. 6, 10 and 14. Each sample is drawn at its Benard median
// ranks F_i = (i − 0.3)/(n + 0.4); the legend gives each simulated sample's
// Kolmogorov–Smirnov and Wasserstein-1 distance to the measured one
// (docs/statistics.md), and -weibull adds the maximum-likelihood Weibull CDF
// of the measured loads.
//
// Sample runs:
//   plotCdf -measured cases/experiments/BDT/granite/measurements
//   plotCdf -measured cases/experiments/BDT/granite/measurements -column peakForce study/results.dat
//   plotCdf -measured cases/experiments/SPB/granite/measurements -weibull -output spb.png a/results.dat
//   b/results.dat
#include <iostream>

#include "core/application.hpp"
#include "core/error.hpp"
#include "plot/gnuplot.hpp"
#include "stats/distances.hpp"
#include "stats/empiricalCdf.hpp"
#include "stats/sampleSource.hpp"
#include "stats/weibull.hpp"

using namespace rockfrac;
using namespace rockfrac::stats;
using namespace rockfrac::plot;

namespace {

const AppInfo info = {
    "plotCdf",
    "Plot failure-load CDFs by median ranks into a PNG (gnuplot): the measured sample (-measured, a "
    "measurements "
    "dictionary) and any number of simulated samples (results tables of runCases with -column, or other "
    "measurements dictionaries). The legend gives each sample's size and its Kolmogorov-Smirnov and "
    "Wasserstein-1 distances to the measured sample. Relative paths are relative to the case.",
    "[options] [sample file]...",
    {"plotCdf -measured cases/experiments/BDT/granite/measurements",
     "plotCdf -measured cases/experiments/BDT/granite/measurements -column peakForce study/results.dat",
     "plotCdf -measured cases/experiments/SPB/granite/measurements -weibull -labels DEM,FEM a/results.dat "
     "b/results.dat"},
    {
        {"-measured", "file", "measurements dictionary of the reference sample"},
        {"-column", "name", "column of the results tables that holds the failure loads"},
        {"-labels", "a,b,...", "legend labels of the sample files, comma separated"},
        {"-title", "text", "plot title (default: failure-load CDF)"},
        {"-weibull", "", "add the Weibull maximum-likelihood CDF of the measured sample"},
        {"-output", "file.png", "picture to write (default: plots/failureLoadCdf.png in the case)"},
    },
    0,
    1000,
    true,
};

struct PlottedSample {
    LabelledSample sample;
    std::string legend;
};

std::string distancesLegend(const LabelledSample& sample, const LabelledSample* measured)
{
    std::string legend = sample.label + " (n = " + std::to_string(sample.values.size()) + ")";
    if (!measured) return legend;
    char ks[32];
    std::snprintf(ks, sizeof(ks), "%.2f", kolmogorovSmirnov(sample.values, measured->values));
    return legend + ": KS " + ks + ", W1 " +
           formatQuantity(wasserstein1(sample.values, measured->values), sample.unit);
}

std::vector<PlottedSample> readSamples(const Application& app, const std::optional<LabelledSample>& measured)
{
    const std::vector<std::string> labels = splitCommaList(app.optionIf("-labels").value_or(""));
    if (app.has("-labels") && labels.size() != app.args().size())
        throw UserError("-labels gives " + std::to_string(labels.size()) + " labels for " +
                        std::to_string(app.args().size()) + " sample files; give one per file");
    std::vector<PlottedSample> samples;
    const std::string column = app.optionIf("-column").value_or("");
    for (std::size_t i = 0; i < app.args().size(); ++i) {
        LabelledSample sample = readSample(app.path(app.args()[i]), column);
        if (!labels.empty()) sample.label = labels[i];
        if (measured && sample.unit != measured->unit)
            throw UserError(app.args()[i] + ": the values are in [" + sample.unit +
                            "], the measured loads in [" + measured->unit + "]; plot a column in [N]");
        samples.push_back({sample, distancesLegend(sample, measured ? &*measured : nullptr)});
    }
    return samples;
}

std::vector<std::vector<double>> medianRankRows(const Sample& values, double factor)
{
    std::vector<std::vector<double>> rows;
    for (const CdfPoint& p : medianRankCdf(values)) rows.push_back({p.value * factor, p.probability});
    return rows;
}

struct Curve {
    std::string dataBlock;
    std::string legend;
};

Curve weibullCurve(const Sample& measured, double factor, double xMin, double xMax)
{
    const WeibullFit fit = fitWeibull(measured, 0.90);
    std::vector<std::vector<double>> rows;
    for (int k = 0; k <= 200; ++k) {
        const double x = xMin + (xMax - xMin) * k / 200.0;
        rows.push_back({x * factor, fit.cdf(x)});
    }
    char legend[160];
    std::snprintf(legend, sizeof(legend), "Weibull fit of measured: m = %.1f, σ_w = %s", fit.modulus,
                  formatQuantity(fit.mean, "N").c_str());
    return {gnuplotDataBlock("weibull", rows), legend};
}

std::string script(const Application& app, const std::optional<LabelledSample>& measured,
                   const std::vector<PlottedSample>& samples)
{
    double largest = measured ? maximum(measured->values) : 0.0;
    double smallest = measured ? minimum(measured->values) : samples.front().sample.values.front();
    for (const auto& s : samples) {
        largest = std::max(largest, maximum(s.sample.values));
        smallest = std::min(smallest, minimum(s.sample.values));
    }
    const std::string unit = measured ? measured->unit : samples.front().sample.unit;
    const DisplayScale scale = chooseDisplayScale(largest, unit);
    std::string data, plots;
    const int legendEntries =
        static_cast<int>(samples.size()) + (measured ? 1 : 0) + (measured && app.has("-weibull") ? 1 : 0);
    if (measured) {
        data += gnuplotDataBlock("measured", medianRankRows(measured->values, scale.factor));
        plots += "$measured using 1:2 with linespoints lw 2 pt 7 ps 1.5 lc rgb \"black\" title " +
                 gnuplotString(measured->label + " (n = " + std::to_string(measured->values.size()) + ")");
        if (app.has("-weibull")) {
            const Curve weibull = weibullCurve(measured->values, scale.factor, 0.9 * smallest, 1.1 * largest);
            data += weibull.dataBlock;
            plots += ", \\\n     $weibull using 1:2 with lines dt 2 lw 2 lc rgb \"gray40\" title " +
                     gnuplotString(weibull.legend);
        }
    }
    const int pointTypes[] = {5, 9, 13, 11};  // squares, triangles, diamonds: the measured sample has circles
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const std::string name = "sample" + std::to_string(i);
        data += gnuplotDataBlock(name, medianRankRows(samples[i].sample.values, scale.factor));
        plots += std::string(plots.empty() ? "" : ", \\\n     ") + "$" + name +
                 " using 1:2 with linespoints lw 2 " + seriesColour(i) + " pt " +
                 std::to_string(pointTypes[i % 4]) + " ps 1.3 title " + gnuplotString(samples[i].legend);
    }
    return data + "set title " +
           gnuplotString(app.optionIf("-title").value_or("Failure-load CDF (median ranks)")) +
           "\nset xlabel " + gnuplotString("failure load [" + scale.unit + "]") + "\nset ylabel " +
           gnuplotString("cumulative probability F = (i - 0.3)/(n + 0.4) [-]") +
           "\nset yrange [0:1]\nset offsets graph 0.05, graph 0.05, 0, 0\nset grid\n" +
           legendBelowPlot(legendEntries) + "plot " + plots + "\n";
}

int run(Application& app)
{
    std::optional<LabelledSample> measured;
    if (app.has("-measured")) measured = readSample(app.path(app.option("-measured")), "");
    const std::vector<PlottedSample> samples = readSamples(app, measured);
    if (!measured && samples.empty())
        throw UserError(
            "nothing to plot: give -measured <measurements> and/or sample files (see plotCdf -help)");
    if (app.has("-weibull") && !measured)
        throw UserError("-weibull fits the measured sample: give -measured");
    const std::filesystem::path output =
        app.path(app.optionIf("-output").value_or("plots/failureLoadCdf.png"));
    const std::string commands = script(app, measured, samples);
    for (const auto& s : samples) std::cout << "plotCdf: " << s.legend << "\n";
    if (app.dryRun()) return exitSuccess;
    renderPng(commands, output);
    std::cout << "plotCdf: wrote " << output.string() << "\n";
    return exitSuccess;
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, run);
}
