#pragma once
// PNG plots through gnuplot, run as a subprocess on a generated script.
//
// The script is kept beside the picture (<name>.png.gp) so that a user can
// restyle a plot by hand and re-run `gnuplot <name>.png.gp`. The PNG is drawn
// to a temporary name and renamed: a failed plot never leaves a torn file.
#include <filesystem>
#include <string>
#include <vector>

namespace rockfrac::plot {

// The gnuplot to run: $ROCKFRAC_GNUPLOT when set, else `gnuplot` on PATH.
// UserError saying how to install it when there is none.
std::filesystem::path findGnuplot();

// A gnuplot string literal ("..." with \ and " escaped).
std::string gnuplotString(const std::string& text);

// An inline data block `$name << EOD`, one row per line, blank-line separated
// blocks when `rows` holds an empty row (gnuplot's "index").
std::string gnuplotDataBlock(const std::string& name, const std::vector<std::vector<double>>& rows);

// How values are shown on an axis: SI values times `factor`, in `unit`
// with a prefix chosen from the largest magnitude (12.3e3 N -> 12.3 kN).
struct DisplayScale {
    double factor = 1.0;
    std::string unit;  // e.g. "kN", "mm", "-"
};
DisplayScale chooseDisplayScale(double largestMagnitude, const std::string& siUnit);
// "12.3 kN": a value with 3 significant digits in its display scale.
std::string formatQuantity(double value, const std::string& siUnit);

// Legend in a box below the plot, where it never hides a curve; the bottom
// margin is sized for `entries` lines so that the box clears the x label.
std::string legendBelowPlot(int entries);

// `lc rgb "#0072B2"`: the i-th colour of the Okabe–Ito palette, readable by
// colour-blind readers and distinct from the black and grey of measured data.
std::string seriesColour(std::size_t i);

// A comma-separated option value ("granite,limestone") as its parts.
std::vector<std::string> splitCommaList(const std::string& text);

// Draw `commands` (everything after terminal and output) into `png`, a
// width × height picture with the pngcairo terminal, or png when gnuplot was
// built without cairo. UserError with gnuplot's own message when it fails.
void renderPng(const std::string& commands, const std::filesystem::path& png, int width = 1000,
               int height = 700);

}  // namespace rockfrac::plot
