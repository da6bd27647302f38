#pragma once
// Running the simulations of a calibration through runCases: every set of
// runs (the design, one BOBYQA evaluation, the confirmation run) is a runCases
// study under <study>/runs/, so members run `jobs` at a time, a study that was
// interrupted continues where it stopped, and a finished one is not run again.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "calibration/calibrationStudy.hpp"

namespace rockfrac::calibration {

// The template of every run: the case's system/ and constant/ copied to
// runs/template, the tied entries written as #eval of their parameter, and the
// `prepare` command run once (meshing). Kept while runs/template/.prepared is newer
// than the case's inputs.
void prepareTemplate(const CalibrationStudy& study);

// One set of runs: value lists per parameter (full factorial) or a Latin hypercube.
struct RunSet {
    std::filesystem::path directory;               // a runCases study, under runs/
    std::vector<std::vector<std::string>> values;  // per parameter; empty for a range
    std::size_t latinSamples = 0;                  // > 0: ranges of the parameters
    std::uint64_t latinSeed = 1;
};

// A member that ran: its parameter values and seed, and where it is.
struct MemberRun {
    std::string id;
    std::vector<double> values;
    std::string seed;
    bool done = false;
    std::filesystem::path directory;
};

// Write the runCases study (unless it is there with the same dictionary) and run it.
// UserError when runCases stops on an input error or is interrupted.
std::vector<MemberRun> runSet(const CalibrationStudy& study, const RunSet& set, int jobs);

// The runCases executable: beside this program, else on PATH.
std::filesystem::path runCasesExecutable();

// The number of members of every runCases study under runs/ (simulations run so far).
std::size_t countSimulations(const CalibrationStudy& study);

}  // namespace rockfrac::calibration
