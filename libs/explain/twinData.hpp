#pragma once
// Twin experiments for explainGap: "measured" data made by the model itself with
// a known effect hidden in it (or none, or two), on other Voronoi seeds than the
// model under test uses, with noise on every force and displacement sample. The
// data go to a measurements dictionary and curve files; what was hidden goes only
// to <study>/hiddenLabel, so that explainGap runs blind.
#include "explain/explainStudy.hpp"

namespace rockfrac::explain {

struct TwinOutcome {
    std::filesystem::path measurements;  // the measurements dictionary written
    std::filesystem::path label;         // hiddenLabel
    int specimens = 0;
};

TwinOutcome makeTwinData(const TwinStudy& study);

}  // namespace rockfrac::explain
