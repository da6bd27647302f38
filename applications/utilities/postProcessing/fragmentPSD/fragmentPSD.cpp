// fragmentPSD: the fragments of a bondedDemFoam state and their size distribution.
//
// Reads  constant/voronoiMesh/, constant/rockProperties (rock/density),
//        <time>/demState (the latest time, or -time <t>)
// Writes postProcessing/fragmentPSD/<time>/fragments.dat   one row per fragment
//        postProcessing/fragmentPSD/<time>/psd.dat         cumulative mass passing vs size
//        postProcessing/fragmentPSD/<time>/summary.dat     fragments, P50, P80, t10
//        postProcessing/fragmentPSD/<time>/psd.png         (when gnuplot is installed)
//        VTK/fragments_<time>.vtu                          cells coloured by fragmentId
//
// A fragment is a set of cells connected through intact bonds (docs/theory-fragments.md);
// its size is measured two ways, the volume-equivalent diameter and the sieve size
// (the intermediate principal extent), and the PSD of each gives P50, P80 and t10.
#include <chrono>
#include <cstdio>

#include "core/application.hpp"
#include "core/memoryLimit.hpp"
#include "fragments/fragmentCase.hpp"
#include "voronoi/voronoiMeshIO.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

namespace {

const AppInfo info{
    "fragmentPSD",
    "Finds the fragments of a bondedDemFoam state (cells joined by at least one intact bond,\n"
    "by union-find), measures each (mass, volume, volume-equivalent diameter, sieve size =\n"
    "intermediate principal extent) and writes the cumulative mass-passing PSD with P50, P80\n"
    "and t10, a table of fragments, a PSD plot and the cells coloured by fragment for ParaView.",
    "[options]",
    {"fragmentPSD -case tutorials/BDT/granite", "fragmentPSD -case tutorials/BDT/granite -time 0.0005",
     "fragmentPSD -case tutorials/BDT/granite -dry-run"},
    {{"-time", "t", "time directory to analyse (default: the latest holding a demState)"},
     {"-noVTK", "", "do not write VTK/fragments_<time>.vtu"},
     {"-noPlot", "", "do not run gnuplot"}},
};

double seconds(std::chrono::steady_clock::time_point since)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

void printSummary(const FragmentAnalysis& a, const FragmentSizeReport& r)
{
    std::printf("Fragments: %d of %zu cells, total mass %.6g kg, original size %.4g mm\n",
                a.labels.n_fragments, a.labels.fragment_of_cell.size(), a.total_mass, 1e3 * r.original_size);
    std::printf("Largest fragment: %.4g %% of the mass\n", 100 * r.largest_mass_fraction);
    std::printf("%-28s %10s %10s %10s\n", "size measure", "P50 [mm]", "P80 [mm]", "t10 [%]");
    for (const auto& [name, s] :
         {std::pair<const char*, PsdSummary>{"volume-equivalent diameter", r.equivalent_diameter},
          {"sieve size", r.sieve_size}})
        std::printf("%-28s %10.4g %10.4g %10.4g\n", name, 1e3 * s.p50, 1e3 * s.p80, 100 * s.t10);
}

// Refuse a mesh whose analysis cannot fit, before reading it (core/memoryLimit.hpp): the
// VoronoiMesh as read, the state's poses and bond stages, the fragments' labels and
// per-cell geometry; plus the code and libraries. An upper estimate, compared with the
// measured peak in docs/reliability.md. Returns the -dry-run line.
std::string checkFragmentMemory(const fs::path& caseDir)
{
    const VoronoiMeshSizes s = readVoronoiMeshSizes(caseDir);
    constexpr std::uint64_t perCell = 1500, perVertex = 100, perFace = 80, perFaceVertex = 8,
                            perBond = sizeof(VoronoiBond) + 100, libraries = 30000000;
    const std::uint64_t bytes = libraries + perCell * s.nCells + perVertex * s.nVertices +
                                perFace * s.nFaces + perFaceVertex * s.nFaceVertices + perBond * s.nBonds;
    const std::string counts = std::to_string(s.nCells) + " cells, " + std::to_string(s.nBonds) + " bonds";
    checkMemoryFits(bytes,
                    (caseDir / voronoiMeshDirectory / "meshInfo").lexically_normal().string() + ": " + counts,
                    "analyse a smaller mesh or use a machine with more memory");
    return estimateLine(bytes, counts);
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, [](Application& app) {
        const auto start = std::chrono::steady_clock::now();
        const TimeDirectory time = selectTime(app.casePath(), app.optionIf("-time"));
        const double density = readRockDensity(app.casePath());
        const std::string estimate = checkFragmentMemory(app.casePath());
        const VoronoiMesh mesh = readVoronoiMesh(app.casePath());
        const DemSnapshot state =
            readDemSnapshot(app.path(time.name) / "demState", mesh.nCells(), mesh.nBonds());
        std::printf("Time %s: %d cells, %d bonds, density %g kg/m^3 (read in %.3g s)\n", time.name.c_str(),
                    mesh.nCells(), mesh.nBonds(), density, seconds(start));

        const auto analysis_start = std::chrono::steady_clock::now();
        const FragmentAnalysis analysis =
            analyseFragments(mesh, demBondCells(mesh), state.bond_stage, state.poses,
                             initialCellOrientations(mesh, density), density);
        const FragmentSizeReport report = reportSizes(analysis);
        const double analysis_time = seconds(analysis_start);
        printSummary(analysis, report);
        std::printf("Analysis: %.3g s\n", analysis_time);
        if (app.dryRun()) {
            std::printf("%s\nDry run: nothing written.\n", estimate.c_str());
            return 0;
        }

        const fs::path out = app.path("postProcessing/fragmentPSD") / time.name;
        writeFragmentTable(out / "fragments.dat", analysis);
        writePsdTable(out / "psd.dat", report);
        writeSummary(out / "summary.dat", state.time, analysis, report);
        std::string written = "postProcessing/fragmentPSD/" + time.name + "/{fragments,psd,summary}.dat";
        if (!app.has("-noPlot")) {
            const std::string problem = plotPsd(out, report);
            if (problem.empty())
                written += ", psd.png";
            else
                std::printf("Note: %s\n", problem.c_str());
        }
        if (!app.has("-noVTK")) {
            const std::string vtu = "VTK/fragments_" + time.name + ".vtu";
            writeFragmentVtu(app.path(vtu), mesh, analysis, state.time);
            written += ", " + vtu;
        }
        std::printf("End: %d fragments, P80 %.4g mm (sieve) / %.4g mm (equivalent); written %s (%.3g s)\n",
                    analysis.labels.n_fragments, 1e3 * report.sieve_size.p80,
                    1e3 * report.equivalent_diameter.p80, written.c_str(), seconds(start));
        return 0;
    });
}
