#pragma once
// fragmentPSD's case I/O: which time directory to read, the DEM state at that
// time, and the outputs (docs/user-guide.md):
//   postProcessing/fragmentPSD/<time>/fragments.dat   one row per fragment
//   postProcessing/fragmentPSD/<time>/psd.dat         cumulative mass passing
//   postProcessing/fragmentPSD/<time>/summary.dat     counts, P50, P80, t10
//   postProcessing/fragmentPSD/<time>/psd.png         when gnuplot is installed
//   VTK/fragments_<time>.vtu                          cells coloured by fragmentId
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fragments/fragments.hpp"
#include "fragments/psd.hpp"

namespace rockfrac {

struct TimeDirectory {
    std::string name;  // as on disk, e.g. "0.0012"
    double value = 0.0;
};

// Numeric directories of the case that hold a demState, ascending in time.
std::vector<TimeDirectory> demStateTimes(const std::filesystem::path& case_dir);

// The latest one, or the one whose name or value matches `requested`
// (relative tolerance 1e-9). UserError listing the available times otherwise.
TimeDirectory selectTime(const std::filesystem::path& case_dir, const std::optional<std::string>& requested);

// rock/density of constant/rockProperties [kg/m^3].
double readRockDensity(const std::filesystem::path& case_dir);

// The part of a demState fragmentPSD needs; UserError when the arrays do not
// match the mesh (a state of another case) or a bond stage is not a BondStage.
struct DemSnapshot {
    double time = 0.0;
    CellPoses poses;
    std::vector<std::uint8_t> bond_stage;
};
DemSnapshot readDemSnapshot(const std::filesystem::path& state_file, int n_cells, int n_bonds);

// Both size measures of one analysis, and their curves and summaries.
struct FragmentSizeReport {
    double original_size = 0.0;  // volume-equivalent diameter of the whole specimen [m]
    double largest_mass_fraction = 0.0;
    PsdCurve by_equivalent_diameter, by_sieve_size;
    PsdSummary equivalent_diameter, sieve_size;
};
FragmentSizeReport reportSizes(const FragmentAnalysis& analysis);

// Text outputs (tab separated, '#' header with units), written atomically.
void writeFragmentTable(const std::filesystem::path& file, const FragmentAnalysis& analysis);
void writePsdTable(const std::filesystem::path& file, const FragmentSizeReport& report);
// Mass passing of several curves side by side: one row per size of any of them (ascending, each
// once), each curve's passingAt there (0 for an empty curve); columns "# size [m]" then
// "<name> [-]" per curve.
void writePassingTable(const std::filesystem::path& file, const std::vector<std::string>& names,
                       const std::vector<const PsdCurve*>& curves);
void writeSummary(const std::filesystem::path& file, double time, const FragmentAnalysis& analysis,
                  const FragmentSizeReport& report);

// Cells at their current poses as VTK polyhedra with fragmentId, cellId,
// fragmentCells and fragmentMass.
void writeFragmentVtu(const std::filesystem::path& file, const VoronoiMesh& mesh,
                      const FragmentAnalysis& analysis, double time);

// psd.png from psd.dat through gnuplot (a tiny script psd.gp written beside it).
// Returns an empty string when the plot was made, else why not (no gnuplot at that
// path: nothing written; gnuplot failed: its messages are in psd.gnuplot.log). A
// missing plot is a note, not an error: the numbers are in the .dat files.
std::string plotPsd(const std::filesystem::path& directory, const FragmentSizeReport& report,
                    const std::filesystem::path& gnuplot = "/usr/bin/gnuplot");

}  // namespace rockfrac
