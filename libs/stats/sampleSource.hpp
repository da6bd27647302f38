#pragma once
// Where a sample of failure loads comes from, for the plot utilities: a
// measurements dictionary (its failure loads) or a results table of runCases
// (one column, of the members that are done).
#include <filesystem>
#include <string>

#include "stats/descriptive.hpp"

namespace rockfrac::stats {

struct LabelledSample {
    std::string label;  // for legends: "measured granite BDT", "results.dat peakForce"
    std::string unit;   // "N", or the table column's unit
    Sample values;
};

// `column` selects the column of a table; a measurements dictionary always
// gives its failure loads. UserError when the file has no such column or no values.
LabelledSample readSample(const std::filesystem::path& file, const std::string& column);

// Whether the file is a '#'-headed table rather than a dictionary.
bool isTextTable(const std::filesystem::path& file);

}  // namespace rockfrac::stats
