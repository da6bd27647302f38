// explainGap: find where simulation and measurement disagree, name the missing
// physical effect, add it to the model and show the gap shrink.
//
// A study directory holds system/explainGapDict: the model case, the measured
// data, the baseline parameters (calibrated as usual) and the candidate effects
// of the library (libs/effects). explainGap runs the model over several Voronoi
// seeds through runCases (resumable), measures the gap on a few response
// features, decides whether it exceeds the model's own scatter, screens every
// effect by a score test, confirms the best by a joint refit judged on held-out
// specimens, and writes the augmented case, tables, plots and one sentence.
//
// Sample runs:
//   explainGap -case tutorials/explainGap/study
//   explainGap -case tutorials/explainGap/study -jobs 2
//   explainGap -case tutorials/explainGap/study -dry-run     # check the inputs, run nothing
#include "explain/explainGap.hpp"

#include <iostream>

#include "core/application.hpp"
#include "core/error.hpp"
#include "effects/modelEffect.hpp"

using namespace rockfrac;
using namespace rockfrac::explain;

namespace {

const AppInfo info = {
    "explainGap",
    "Find where a model and measured data disagree and which model effect explains it, as "
    "system/explainGapDict of the study directory (-case) describes. Writes explainGap.report, "
    "explainGap.result, gapTable.dat, gapMetrics.dat, screening.dat, residuals.png, curves.png and, when one "
    "effect explains the gap, augmentedCase/ (the case with that effect switched on at its fitted size). "
    "Simulations run through runCases under <study>/runs and are not run again. See docs/explainGap.md.",
    "[options]",
    {"explainGap -case tutorials/explainGap/study", "explainGap -case tutorials/explainGap/study -dry-run",
     "explainGap -listEffects"},
    {
        {"-jobs", "N", "simulations at the same time (overrides 'jobs')"},
        {"-listEffects", "", "print the library of model effects and exit"},
    },
    0,
    0,
    true,
};

int run(Application& app)
{
    if (app.has("-listEffects")) {
        for (const auto& e : effectLibrary())
            std::cout << e.name << "  (" << e.parameter << " [" << e.unit << "], neutral " << e.neutral
                      << ")\n    " << e.physics << "\n    signature: " << e.signature << "\n";
        return exitSuccess;
    }
    ExplainStudy study = readExplainStudy(app.casePath());
    int jobs = study.jobs;
    if (const auto text = app.optionIf("-jobs")) {
        try {
            jobs = std::stoi(*text);
        } catch (const std::exception&) {
            jobs = 0;
        }
        if (jobs < 1) throw UserError("-jobs " + *text + ": expected a whole number of at least 1");
    }
    for (const auto& c : study.conditions)
        std::cout << "explainGap: " << (c.name.empty() ? "" : "condition " + c.name + ": ") << "case "
                  << c.targetCase.string() << ", measurements " << c.measurementsFile.string() << " ("
                  << c.measurements.specimens.size() << " specimens)\n";
    std::cout << "explainGap: effects:";
    for (const auto& e : study.effects) std::cout << " " << e;
    std::cout << std::endl;
    if (app.dryRun()) return exitSuccess;
    const ExplainOutcome outcome = explainGap(std::move(study), jobs);
    std::cout << outcome.sentence << "\n(" << outcome.simulations << " simulations; tables and plots in "
              << app.casePath().string() << ")" << std::endl;
    return exitSuccess;
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, run);
}
