#pragma once
// PNG plots through gnuplot, run as a subprocess on a generated script.
//
// The script is kept beside the picture (<name>.png.gp) so that a user can
// restyle a plot by hand and re-run `gnuplot <name>.png.gp`. The PNG is drawn
// to a temporary name and renamed: a failed plot never leaves a torn file.
#include <filesystem>
#include <string>
#include <vector>

namespace rockfrac::stats {

// The gnuplot to run: $ROCKFRAC_GNUPLOT when set, else `gnuplot` on PATH.
// UserError saying how to install it when there is none.
std::filesystem::path findGnuplot();

// A gnuplot string literal ("..." with \ and " escaped).
std::string gnuplotString(const std::string& text);

// An inline data block `$name << EOD`, one row per line, blank-line separated
// blocks when `rows` holds an empty row (gnuplot's "index").
std::string gnuplotDataBlock(const std::string& name, const std::vector<std::vector<double>>& rows);

// Draw `commands` (everything after terminal and output) into `png`, a
// width × height picture with the pngcairo terminal, or png when gnuplot was
// built without cairo. UserError with gnuplot's own message when it fails.
void renderPng(const std::string& commands, const std::filesystem::path& png, int width = 1000,
               int height = 700);

}  // namespace rockfrac::stats
