// crusherPost: the crusher's performance from bondedDemFoam's machine time series.
//
// Reads  postProcessing/machine/0/machine.dat, postProcessing/discharge/0/discharge.dat,
//        system/crusherPostDict (steadyStart [s], pistonArea [m^2]),
//        constant/crusherKinematics (closedSideSetting, for P80 vs CSS),
//        constant/loading (feed/sizeRange, for the feed's F80; feed/rock or feed/classes and
//        the latest <time>/crusherState, for the cells' PSD), the feed rocks' meshes,
//        constant/rockProperties (rock/density)
// Writes postProcessing/crusherPost/summary.dat, psd.dat (discharge and cells' PSD), power.png,
//        pressure.png, throughput.png, psd.png
//
// Definitions (docs/theory-crusher.md): power draw = sum of contact force . mantle
// surface velocity; hydraulic pressure = vertical force on the mantle / piston area;
// throughput = discharged mass per second; means and spreads over t >= steadyStart.
// Per tonne (libs/crusher/crusherFigures.hpp): specific energy = mean power / mean
// throughput [kWh/t], P80/CSS, the feed's F80 and the reduction ratio F80/P80. The cells'
// PSD (libs/crusher/feedCells.hpp): every Voronoi cell of every rock fed as a particle, the
// finest product the feed's meshes can make.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/application.hpp"
#include "core/atomicFile.hpp"
#include "core/dictionary.hpp"
#include "core/knownEntries.hpp"
#include "crusher/crusherFigures.hpp"
#include "crusher/feedCells.hpp"
#include "crusher/machineLoading.hpp"
#include "fragments/fragmentCase.hpp"
#include "fragments/psd.hpp"
#include "io/timeSeries.hpp"
#include "plot/gnuplot.hpp"
#include "voronoi/voronoiMeshIO.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

namespace {

const AppInfo info{
    "crusherPost",
    "Power draw, hydraulic pressure, throughput (steady-state means and spreads after the start-up),\n"
    "the discharge PSD (P50, P80 against the CSS), the specific energy (kWh/t), the feed's F80 and\n"
    "the reduction ratio of a bondedDemFoam crusher run, and the PSD of the Voronoi cells of every\n"
    "rock fed (the finest product its meshes can make), with PNG plots and a one-screen summary.",
    "[options]",
    {"crusherPost -case tutorials/CH660/tiny"},
    {},
};

struct Stat {
    double mean = 0.0, spread = 0.0;  // mean and standard deviation
    int n = 0;
};

Stat statistics(const std::vector<double>& v)
{
    Stat s;
    s.n = static_cast<int>(v.size());
    if (v.empty()) return s;
    for (double x : v) s.mean += x;
    s.mean /= s.n;
    for (double x : v) s.spread += (x - s.mean) * (x - s.mean);
    s.spread = s.n > 1 ? std::sqrt(s.spread / (s.n - 1)) : 0.0;
    return s;
}

void plotSeries(const fs::path& png, const std::string& title, const std::string& ylabel,
                const std::vector<double>& t, const std::vector<double>& y, double scale, double steadyStart)
{
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < t.size(); ++i) rows.push_back({t[i], scale * y[i]});
    std::string g = plot::gnuplotDataBlock("data", rows);
    g += "set title " + plot::gnuplotString(title) + "\nset xlabel 'time [s]'\nset ylabel " +
         plot::gnuplotString(ylabel) + "\nset grid\n";
    g += "set arrow from " + std::to_string(steadyStart) + ", graph 0 to " + std::to_string(steadyStart) +
         ", graph 1 nohead dt 2\n";
    g += "plot $data using 1:2 with lines " + plot::seriesColour(0) + " title ''\n";
    plot::renderPng(g, png);
}

// The feed's F80 from constant/loading's feed/sizeRange (the distribution the factory draws
// from, not the few rocks a short run fed); not available without it.
CrusherFigure feedF80(const fs::path& loadingFile)
{
    CrusherFigure f;
    f.why = "no feed/sizeRange in " + loadingFile.string();
    if (!fs::exists(loadingFile)) return f;
    const Dictionary loading = Dictionary::readFile(loadingFile);
    if (!loading.isDict("feed") || !loading.subDict("feed").found("sizeRange")) return f;
    const auto range = loading.subDict("feed").get<std::vector<double>>("sizeRange");
    if (range.size() != 2 || !(range[0] > 0.0) || !(range[1] >= range[0])) {
        f.why = loadingFile.string() + ": feed/sizeRange is not (min max) with 0 < min <= max";
        return f;
    }
    return {true, uniformFeedPassingSize(range[0], range[1], 0.8), 0.0, ""};
}

// The figures per tonne: specific energy, F80, P80/CSS, F80/P80.
struct PerTonne {
    CrusherFigure energy, f80, p80Css, reduction;
};

PerTonne perTonne(const Stat& power, const Stat& throughput, int nFragments, double p80, double css,
                  const fs::path& loadingFile)
{
    PerTonne r;
    r.energy = specificEnergy(power.mean, power.spread, throughput.mean, throughput.spread);
    if (power.n == 0) r.energy = {false, 0.0, 0.0, "no rows in the steady window"};
    r.f80 = feedF80(loadingFile);
    const std::string noPsd = "nothing discharged yet (no P80)";
    r.p80Css = sizeRatio(nFragments > 0 ? p80 : 0.0, css, noPsd);
    r.reduction = sizeRatio(r.f80.available ? r.f80.value : 0.0, nFragments > 0 ? p80 : 0.0,
                            r.f80.available ? noPsd : r.f80.why);
    return r;
}

// One figure as text: its value (or spread) with 6 digits, or "not available: <why>".
std::string figureText(const CrusherFigure& f, bool spread = false)
{
    if (!f.available) return "not available: " + f.why;
    char b[64];
    std::snprintf(b, sizeof(b), "%.6g", spread ? f.spread : f.value);
    return b;
}

std::string perTonneKeys(const PerTonne& r)
{
    return "specificEnergy_kWh_t\t" + figureText(r.energy) + "\nspecificEnergySpread_kWh_t\t" +
           figureText(r.energy, true) + "\nP80_CSS\t" + figureText(r.p80Css) + "\nF80_m\t" +
           figureText(r.f80) + "\nreductionRatio_F80_P80\t" + figureText(r.reduction) + "\n";
}

void printPerTonne(const PerTonne& r)
{
    if (r.energy.available)
        std::printf("Specific energy   %10.4g kWh/t (spread %.3g kWh/t; mean power / mean throughput)\n",
                    r.energy.value, r.energy.spread);
    else
        std::printf("Specific energy   %s\n", figureText(r.energy).c_str());
    std::printf("P80 / CSS         %s\n", figureText(r.p80Css).c_str());
    if (r.f80.available)
        std::printf("Feed F80          %10.4g mm   (feed/sizeRange, uniform in number, mass ~ size^3)\n",
                    1e3 * r.f80.value);
    else
        std::printf("Feed F80          %s\n", figureText(r.f80).c_str());
    std::printf("Reduction ratio   %s%s\n", figureText(r.reduction).c_str(),
                r.reduction.available ? " (F80 / P80)" : "");
}

// The discharge PSD from the destructor's record (sieve size, mass per fragment); empty before
// the first discharge.
PsdCurve dischargePsd(const fs::path& dischargeFile, int& nFragments)
{
    nFragments = 0;
    if (!fs::exists(dischargeFile)) return {};
    const TimeSeries d = readTimeSeries(dischargeFile);
    const std::vector<double> sizes = d.values("sieveSize"), masses = d.values("mass");
    nFragments = static_cast<int>(sizes.size());
    return sizes.empty() ? PsdCurve{} : cumulativePassing(sizes, masses);
}

// The cells' PSD: every cell of every rock fed by the latest time directory (its crusherState),
// its class's template cell scaled to the rock's size. Empty, with `why`, before the run has
// written a state.
struct CellsPsd {
    PsdCurve curve;
    PsdSummary summary;
    int cells = 0, rocks = 0;
    double mass = 0.0;
    std::string time, why;
};

CellsPsd cellsPsd(const Application& app, double css)
{
    CellsPsd r;
    const std::vector<TimeDirectory> times = demStateTimes(app.casePath());
    if (times.empty() || !fs::exists(app.path(times.back().name) / "crusherState")) {
        r.why = "no time directory with a crusherState yet";
        return r;
    }
    r.time = times.back().name;
    const fs::path loadingFile = app.path("constant/loading");
    const FeedSpec feed = readFeedSpec(Dictionary::readFile(loadingFile).subDict("feed"), app.casePath());
    const double density = readRockDensity(app.casePath());
    std::vector<FeedRockTemplate> templates;
    std::vector<CellSizes> perClass;
    for (const FeedClass& c : feed.classes) {
        templates.push_back(makeFeedRockTemplate(readVoronoiMesh(c.rock_case), density));
        perClass.push_back(templateCellSizes(templates.back(), density));
    }
    const fs::path stateFile = app.path(r.time) / "crusherState";
    const CrusherState state = readCrusherState(stateFile);
    CellSizes cells;
    try {
        cells = fedCellSizes(state.fed.rocks, templates, perClass);
    } catch (const std::invalid_argument& e) {
        throw UserError(stateFile.string() + ": its rocks do not fit " + loadingFile.string() + "'s feed (" +
                        e.what() + "); run crusherPost on the case that wrote it");
    }
    r.rocks = static_cast<int>(state.fed.rocks.size());
    r.cells = static_cast<int>(cells.mass.size());
    for (double m : cells.mass) r.mass += m;
    if (r.cells == 0) {
        r.why = "no rock fed by t = " + r.time + " s";
        return r;
    }
    r.curve = cumulativePassing(cells.sieve_size, cells.mass);
    r.summary = summarisePsd(r.curve, css);
    return r;
}

// psd.png: the discharge PSD and the cells' PSD, the CSS marked.
void plotPsd(const fs::path& png, const PsdCurve& discharge, const PsdCurve& cells, double css)
{
    std::string g;
    std::string plots;
    const PsdCurve* curves[2] = {&discharge, &cells};
    const char* names[2] = {"discharge", "cells"};
    const char* titles[2] = {"discharge", "Voronoi cells of the rocks fed"};
    const char* styles[2] = {" with linespoints ", " with lines "};
    for (int k = 0; k < 2; ++k) {
        if (curves[k]->empty()) continue;
        std::vector<std::vector<double>> rows;
        for (std::size_t i = 0; i < curves[k]->size.size(); ++i)
            rows.push_back({1e3 * curves[k]->size[i], 100 * curves[k]->passing[i]});
        g += plot::gnuplotDataBlock(names[k], rows);
        plots += std::string(plots.empty() ? "plot " : ", ") + "$" + names[k] + " using 1:2" + styles[k] +
                 plot::seriesColour(k) + " title " + plot::gnuplotString(titles[k]);
    }
    if (plots.empty()) return;
    g += "set title 'Discharge PSD and the PSD of the cells fed'\nset xlabel 'sieve size [mm]'\nset ylabel "
         "'passing [%]'\n"
         "set logscale x\nset grid\nset key top left\nset arrow from " +
         std::to_string(1e3 * css) + ", graph 0 to " + std::to_string(1e3 * css) + ", graph 1 nohead dt 2\n" +
         plots + "\n";
    plot::renderPng(g, png);
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, [](Application& app) {
        const Dictionary dict = Dictionary::readFile(app.path("system/crusherPostDict"));
        checkKnownEntries(dict, crusherPostDictEntries());
        const double steadyStart = dict.getScalar("steadyStart", Bounds::nonNegative());
        const double pistonArea = dict.getScalar("pistonArea", Bounds::positive());
        const double css = Dictionary::readFile(app.path("constant/crusherKinematics"))
                               .getScalar("closedSideSetting", Bounds::positive());
        const TimeSeries machine = readTimeSeries(app.path("postProcessing/machine/0/machine.dat"));
        const auto t = machine.values("Time");
        const auto power = machine.values("power");
        const auto fz = machine.values("forceZ");
        const auto out = machine.values("massDischarged");
        const auto fed = machine.values("massFed");
        const auto inside = machine.values("massInside");
        if (t.size() < 2) throw UserError("machine.dat has fewer than two rows; run bondedDemFoam longer");
        std::vector<double> pressure(t.size()), throughput(t.size(), 0.0), steadyP, steadyPressure, steadyQ;
        for (std::size_t i = 0; i < t.size(); ++i) {
            // forceZ is the force the rocks exert on the mantle: down (negative) when they
            // press on it; the piston under the main shaft carries it, p = -F_z / A.
            pressure[i] = -fz[i] / pistonArea;
            if (i > 0 && t[i] > t[i - 1]) throughput[i] = (out[i] - out[i - 1]) / (t[i] - t[i - 1]);
            if (t[i] >= steadyStart && i > 0) {
                steadyP.push_back(power[i]);
                steadyPressure.push_back(pressure[i]);
                steadyQ.push_back(throughput[i]);
            }
        }
        const Stat P = statistics(steadyP), p = statistics(steadyPressure), Q = statistics(steadyQ);
        const double imbalance = fed.back() - inside.back() - out.back();

        int nFragments = 0;
        const PsdCurve curve = dischargePsd(app.path("postProcessing/discharge/0/discharge.dat"), nFragments);
        const PsdSummary psd = curve.empty() ? PsdSummary{} : summarisePsd(curve, css);
        const CellsPsd cells = cellsPsd(app, css);
        const fs::path dir = app.path("postProcessing/crusherPost");
        const PerTonne figures = perTonne(P, Q, nFragments, psd.p80, css, app.path("constant/loading"));
        char text[2000];
        std::snprintf(
            text, sizeof(text),
            "# crusherPost summary (steady window t >= %g s, %d rows)\n"
            "powerMean_W\t%.6g\npowerSpread_W\t%.6g\n"
            "pressureMean_Pa\t%.6g\npressureSpread_Pa\t%.6g\n"
            "throughputMean_kg_s\t%.6g\nthroughputSpread_kg_s\t%.6g\nthroughputMean_t_h\t%.6g\n"
            "massFed_kg\t%.9g\nmassInside_kg\t%.9g\nmassDischarged_kg\t%.9g\nmassImbalance_kg\t%.3g\n"
            "fragmentsDischarged\t%d\nP50_m\t%.6g\nP80_m\t%.6g\nCSS_m\t%.6g\n",
            steadyStart, P.n, P.mean, P.spread, p.mean, p.spread, Q.mean, Q.spread, 3.6 * Q.mean, fed.back(),
            inside.back(), out.back(), imbalance, nFragments, psd.p50, psd.p80, css);
        char cellKeys[200];
        std::snprintf(cellKeys, sizeof(cellKeys),
                      "cellsFed\t%d\ncellsMass_kg\t%.9g\ncellsP50_m\t%.6g\ncellsP80_m\t%.6g\n", cells.cells,
                      cells.mass, cells.summary.p50, cells.summary.p80);
        if (!app.dryRun()) {  // a dry run writes nothing
            fs::create_directories(dir);
            writeFileAtomically(dir / "summary.dat",
                                [&](std::ostream& o) { o << text << perTonneKeys(figures) << cellKeys; });
            writePassingTable(dir / "psd.dat", {"passingDischarge", "passingCells"}, {&curve, &cells.curve});
        }
        std::printf("Steady window t >= %g s (%d rows of %zu)\n", steadyStart, P.n, t.size());
        std::printf("Power draw        %10.4g kW   (spread %.3g kW)\n", 1e-3 * P.mean, 1e-3 * P.spread);
        std::printf("Hydraulic press.  %10.4g MPa  (spread %.3g MPa; piston area %g m^2)\n", 1e-6 * p.mean,
                    1e-6 * p.spread, pistonArea);
        std::printf("Throughput        %10.4g t/h  (spread %.3g t/h)\n", 3.6 * Q.mean, 3.6 * Q.spread);
        std::printf("Mass: fed %.9g kg = inside %.9g kg + discharged %.9g kg (imbalance %.3g kg)\n",
                    fed.back(), inside.back(), out.back(), imbalance);
        if (nFragments > 0)
            std::printf(
                "Discharge PSD: %d fragments, P50 %.4g mm, P80 %.4g mm (CSS %.4g mm, P80 - CSS %+.3g mm)\n",
                nFragments, 1e3 * psd.p50, 1e3 * psd.p80, 1e3 * css, 1e3 * (psd.p80 - css));
        else
            std::printf("Discharge PSD: nothing discharged yet\n");
        if (cells.cells > 0)
            std::printf(
                "Cells' PSD: %d Voronoi cells of %d rocks fed by t = %s s, %.9g kg, P50 %.4g mm, P80 %.4g mm "
                "(the finest product these feed meshes can make)\n",
                cells.cells, cells.rocks, cells.time.c_str(), cells.mass, 1e3 * cells.summary.p50,
                1e3 * cells.summary.p80);
        else
            std::printf("Cells' PSD: %s\n", cells.why.c_str());
        printPerTonne(figures);
        if (!app.dryRun()) {
            try {
                plotSeries(dir / "power.png", "Power draw", "power [kW]", t, power, 1e-3, steadyStart);
                plotSeries(dir / "pressure.png", "Hydraulic pressure", "pressure [MPa]", t, pressure, 1e-6,
                           steadyStart);
                plotSeries(dir / "throughput.png", "Throughput", "throughput [t/h]", t, throughput, 3.6,
                           steadyStart);
                plotPsd(dir / "psd.png", curve, cells.curve, css);
            } catch (const UserError& e) {
                std::printf("Plots skipped: %s\n", e.what());
            }
        } else {
            std::printf("Dry run: nothing written.\n");
        }
        return 0;
    });
}
