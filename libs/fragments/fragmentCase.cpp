#include "fragments/fragmentCase.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <sstream>

#include "core/atomicFile.hpp"
#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "dem/bondLaw.hpp"
#include "io/stateFile.hpp"
#include "io/vtkOutput.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

namespace {

bool parseNumber(const std::string& text, double& value)
{
    if (text.empty()) return false;
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(value);
}

std::string listOf(const std::vector<TimeDirectory>& times)
{
    std::string s;
    for (const auto& t : times) s += (s.empty() ? "" : " ") + t.name;
    return s;
}

}  // namespace

std::vector<TimeDirectory> demStateTimes(const fs::path& case_dir)
{
    std::vector<TimeDirectory> times;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(case_dir, ec)) {
        TimeDirectory t;
        t.name = entry.path().filename().string();
        if (entry.is_directory() && parseNumber(t.name, t.value) &&
            fs::is_regular_file(entry.path() / "demState"))
            times.push_back(t);
    }
    if (ec) throw UserError(case_dir.string() + ": cannot list the case directory (" + ec.message() + ")");
    std::sort(times.begin(), times.end(),
              [](const TimeDirectory& a, const TimeDirectory& b) { return a.value < b.value; });
    return times;
}

TimeDirectory selectTime(const fs::path& case_dir, const std::optional<std::string>& requested)
{
    const std::vector<TimeDirectory> times = demStateTimes(case_dir);
    if (times.empty())
        throw UserError(case_dir.string() + ": no time directory with a demState; run bondedDemFoam first");
    if (!requested) return times.back();
    if (*requested == "latestTime") return times.back();
    double value = 0.0;
    if (!parseNumber(*requested, value))
        throw UserError("-time '" + *requested + "' is not a number; available times: " + listOf(times));
    for (const auto& t : times)
        if (t.name == *requested || std::abs(t.value - value) <= 1e-9 * std::max(std::abs(value), 1e-300))
            return t;
    throw UserError("-time " + *requested +
                    ": no such time directory with a demState; available times: " + listOf(times));
}

double readRockDensity(const fs::path& case_dir)
{
    static const Dimensions density = Dimensions::fromUnits("kg/m^3");
    const Dictionary d = Dictionary::readFile(case_dir / "constant/rockProperties");
    return d.subDict("rock").getScalar("density", Bounds::positive(), &density);
}

DemSnapshot readDemSnapshot(const fs::path& state_file, int n_cells, int n_bonds)
{
    const StateFile s = StateFile::read(state_file);
    DemSnapshot snap;
    snap.time = s.scalar("time");
    snap.poses.position = s.vectors("cell.position", n_cells);
    const auto& q = s.doubles("cell.orientation", 4L * n_cells);
    snap.poses.orientation.resize(n_cells);
    for (long c = 0; c < n_cells; ++c)
        snap.poses.orientation[c] = {q[4 * c], q[4 * c + 1], q[4 * c + 2], q[4 * c + 3]};
    snap.bond_stage = s.bytes("bond.stage", n_bonds);
    for (std::size_t b = 0; b < snap.bond_stage.size(); ++b)
        if (snap.bond_stage[b] > bondBroken)
            throw UserError(state_file.string() + ": bond.stage[" + std::to_string(b) +
                            "] = " + std::to_string(snap.bond_stage[b]) +
                            " is not a bond stage (0 elastic, 1 softening, 2 broken)");
    return snap;
}

FragmentSizeReport reportSizes(const FragmentAnalysis& analysis)
{
    FragmentSizeReport r;
    std::vector<double> mass, equivalent, sieve;
    double largest = 0.0;
    for (const Fragment& f : analysis.fragments) {
        mass.push_back(f.mass);
        equivalent.push_back(f.equivalent_diameter);
        sieve.push_back(f.sieve_size);
        largest = std::max(largest, f.mass);
    }
    r.original_size = volumeEquivalentDiameter(analysis.total_volume);
    r.largest_mass_fraction = largest / analysis.total_mass;
    r.by_equivalent_diameter = cumulativePassing(equivalent, mass);
    r.by_sieve_size = cumulativePassing(sieve, mass);
    r.equivalent_diameter = summarisePsd(r.by_equivalent_diameter, r.original_size);
    r.sieve_size = summarisePsd(r.by_sieve_size, r.original_size);
    return r;
}

void writeFragmentTable(const fs::path& file, const FragmentAnalysis& analysis)
{
    writeFileAtomically(file, [&](std::ostream& out) {
        out << "# fragment [-]\tfirstCell [-]\tcells [-]\tmass [kg]\tvolume [m^3]\tequivalentDiameter [m]\t"
               "sieveSize [m]\textent1 [m]\textent2 [m]\textent3 [m]\tcentroidX [m]\tcentroidY [m]\t"
               "centroidZ [m]\n";
        out << std::setprecision(10);
        for (std::size_t k = 0; k < analysis.fragments.size(); ++k) {
            const Fragment& f = analysis.fragments[k];
            out << k << '\t' << f.first_cell << '\t' << f.n_cells << '\t' << f.mass << '\t' << f.volume
                << '\t' << f.equivalent_diameter << '\t' << f.sieve_size << '\t' << f.principal_extents.x
                << '\t' << f.principal_extents.y << '\t' << f.principal_extents.z << '\t' << f.centroid.x
                << '\t' << f.centroid.y << '\t' << f.centroid.z << '\n';
        }
    });
}

void writePsdTable(const fs::path& file, const FragmentSizeReport& report)
{
    writePassingTable(file, {"passingEquivalentDiameter", "passingSieveSize"},
                      {&report.by_equivalent_diameter, &report.by_sieve_size});
}

void writePassingTable(const fs::path& file, const std::vector<std::string>& names,
                       const std::vector<const PsdCurve*>& curves)
{
    std::vector<double> sizes;
    for (const PsdCurve* c : curves) sizes.insert(sizes.end(), c->size.begin(), c->size.end());
    std::sort(sizes.begin(), sizes.end());
    sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
    writeFileAtomically(file, [&](std::ostream& out) {
        out << "# size [m]";
        for (const std::string& name : names) out << '\t' << name << " [-]";
        out << '\n' << std::setprecision(10);
        for (double x : sizes) {
            out << x;
            for (const PsdCurve* c : curves) out << '\t' << passingAt(*c, x);
            out << '\n';
        }
    });
}

void writeSummary(const fs::path& file, double time, const FragmentAnalysis& analysis,
                  const FragmentSizeReport& r)
{
    writeFileAtomically(file, [&](std::ostream& out) {
        out << "# Time [s]\tfragments [-]\tcells [-]\tmass [kg]\toriginalSize [m]\tlargestMassFraction [-]\t"
               "P50equivalent [m]\tP80equivalent [m]\tt10equivalent [-]\tP50sieve [m]\tP80sieve [m]\t"
               "t10sieve [-]\n"
            << std::setprecision(10) << time << '\t' << analysis.labels.n_fragments << '\t'
            << analysis.labels.fragment_of_cell.size() << '\t' << analysis.total_mass << '\t'
            << r.original_size << '\t' << r.largest_mass_fraction << '\t' << r.equivalent_diameter.p50 << '\t'
            << r.equivalent_diameter.p80 << '\t' << r.equivalent_diameter.t10 << '\t' << r.sieve_size.p50
            << '\t' << r.sieve_size.p80 << '\t' << r.sieve_size.t10 << '\n';
    });
}

void writeFragmentVtu(const fs::path& file, const VoronoiMesh& mesh, const FragmentAnalysis& analysis,
                      double time)
{
    // Every cell lists its own vertices, as bondedDemFoam draws them.
    PolyhedronSet cells;
    cells.points = analysis.vertices;
    cells.cellFaceOffset = mesh.cellFaceOffset;
    cells.faceVertexOffset = mesh.faceVertexOffset;
    cells.faceVertices = mesh.globalFaceVertices();
    const int n = mesh.nCells();
    std::vector<int> ids(n), fragment_cells(n);
    std::vector<double> fragment_mass(n);
    for (int c = 0; c < n; ++c) {
        ids[c] = c;
        const Fragment& f = analysis.fragments[analysis.labels.fragment_of_cell[c]];
        fragment_cells[c] = f.n_cells;
        fragment_mass[c] = f.mass;
    }
    writePolyhedraVtu(
        file, cells,
        {Field::integer("fragmentId", analysis.labels.fragment_of_cell), Field::integer("cellId", ids),
         Field::integer("fragmentCells", fragment_cells), Field::scalar("fragmentMass", fragment_mass)},
        time);
}

std::string plotPsd(const fs::path& directory, const FragmentSizeReport& r, const fs::path& gnuplot)
{
    if (::access(gnuplot.c_str(), X_OK) != 0) return "no plot: " + gnuplot.string() + " is not installed";
    // Sizes in mm on a log axis; the P80 of each measure as a dashed drop line.
    std::ostringstream script;
    script
        << std::setprecision(8) << "set terminal pngcairo size 900,600 noenhanced\n"
        << "set output 'psd.png'\nset logscale x\nset grid\n"
        << "set xlabel 'size [mm]'\nset ylabel 'cumulative mass passing [%]'\nset yrange [0:100]\n"
        << "set key left top\nset datafile separator '\\t'\n"
        << "set arrow from " << 1e3 * r.equivalent_diameter.p80 << ",0 to " << 1e3 * r.equivalent_diameter.p80
        << ",80 nohead dt 2 lc 1\n"
        << "set arrow from " << 1e3 * r.sieve_size.p80 << ",0 to " << 1e3 * r.sieve_size.p80
        << ",80 nohead dt 2 lc 2\n"
        << "plot 'psd.dat' using ($1*1e3):($2*100) with linespoints pt 7 ps 0.5 lc 1 title "
           "'volume-equivalent diameter (P80 "
        << 1e3 * r.equivalent_diameter.p80 << " mm)', \\\n"
        << "     'psd.dat' using ($1*1e3):($3*100) with linespoints pt 7 ps 0.5 lc 2 title 'sieve size (P80 "
        << 1e3 * r.sieve_size.p80 << " mm)'\n";
    writeFileAtomically(directory / "psd.gp", [&](std::ostream& out) { out << script.str(); });
    const std::string command =
        "cd '" + directory.string() + "' && '" + gnuplot.string() + "' psd.gp > psd.gnuplot.log 2>&1";
    if (std::system(command.c_str()) != 0)
        return "no plot: gnuplot failed on " + (directory / "psd.gp").string() + ", see " +
               (directory / "psd.gnuplot.log").string();
    fs::remove(directory / "psd.gnuplot.log");
    return {};
}

}  // namespace rockfrac
