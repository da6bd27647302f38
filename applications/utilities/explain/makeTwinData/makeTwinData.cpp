// makeTwinData: "measured" data with a known effect hidden in them, to prove
// that explainGap names the right cause (twin experiments).
//
// A study directory holds system/twinDataDict: the model case, the effects to
// hide (none, one or two, at chosen sizes), the Voronoi seeds of the synthetic
// specimens (others than the model under test uses) and the noise on every
// force and displacement sample. Writes <output>/measurements with one curve per
// specimen; what was hidden goes only to <study>/hiddenLabel.
//
// Sample runs:
//   makeTwinData -case tutorials/explainGap/twin
//   makeTwinData -case tutorials/explainGap/twin -dry-run
#include <iostream>

#include "core/application.hpp"
#include "explain/twinData.hpp"

using namespace rockfrac;
using namespace rockfrac::explain;

namespace {

const AppInfo info = {
    "makeTwinData",
    "Make synthetic measured data with hidden model effects, as system/twinDataDict of the study directory "
    "(-case) describes: runs the model case once per seed through runCases, adds noise, and writes a "
    "measurements dictionary with force-displacement curves; the hidden effects go to <study>/hiddenLabel "
    "only. See docs/explainGap.md.",
    "[options]",
    {"makeTwinData -case tutorials/explainGap/twin"},
    {},
    0,
    0,
    true,
};

int run(Application& app)
{
    const TwinStudy study = readTwinStudy(app.casePath());
    std::cout << "makeTwinData: case " << study.targetCase.string() << ", " << study.seeds.values.size()
              << " specimens, " << study.hiddenEffects.size()
              << " hidden effect(s) (not shown: see hiddenLabel)" << std::endl;
    if (app.dryRun()) return exitSuccess;
    const TwinOutcome outcome = makeTwinData(study);
    std::cout << "makeTwinData: wrote " << outcome.measurements.string() << " (" << outcome.specimens
              << " specimens with curves); the label is in " << outcome.label.string() << std::endl;
    return exitSuccess;
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, run);
}
