#include "explain/twinData.hpp"

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

#include "calibration/studyRunner.hpp"
#include "core/atomicFile.hpp"
#include "core/counterRandom.hpp"
#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "explain/pointRuns.hpp"

namespace rockfrac::explain {

namespace fs = std::filesystem;

namespace {

// A standard normal variate from the counter-based stream (Box–Muller).
double gaussian(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter)
{
    const double u1 = uniform01(seed, stream, 2 * counter);
    const double u2 = uniform01(seed, stream, 2 * counter + 1);
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

// The specimens' dimensions as a lab reports them, from the prepared model case's
// geometryProperties: a disc's diameter and thickness, another shape's volume and equivalent
// diameter (the measurements' 'geometry' defaults); "" when the file is missing.
std::string geometryEntries(const fs::path& properties)
{
    if (!fs::exists(properties)) return "";
    const Dictionary d = Dictionary::readFile(properties);
    std::ostringstream o;
    o << std::setprecision(10) << "geometry\n{\n";
    if (d.isDict("disc") && d.found("type") && d.get<std::string>("type") == "disc") {
        const Dictionary& disc = d.subDict("disc");
        o << "    diameter    [m] " << disc.getScalar("diameter", Bounds::positive()) << ";\n"
          << "    thickness   [m] " << disc.getScalar("thickness", Bounds::positive()) << ";\n";
    } else {
        o << "    volume      [m^3] " << d.getScalar("volume", Bounds::positive()) << ";\n"
          << "    equivalentDiameter [m] " << d.getScalar("equivalentDiameter", Bounds::positive()) << ";\n";
    }
    o << "}\n\n";
    return o.str();
}

}  // namespace

TwinOutcome makeTwinData(const TwinStudy& s)
{
    const calibration::CalibrationStudy study = s.runStudy();
    calibration::prepareTemplate(study);
    writeTemplateEffects(study, s.hiddenEffectsText);
    const PointRuns runs = runPoint(study, {}, "specimens", "gapChange", "force");

    const fs::path out = (s.directory / s.output).lexically_normal();
    fs::create_directories(out / "curves");
    std::ostringstream specimens;
    for (std::size_t k = 0; k < runs.features.size(); ++k) {
        char id[32];
        std::snprintf(id, sizeof(id), "TW-%02zu", k + 1);
        const auto& d = runs.displacement[k];
        const auto& f = runs.force[k];
        const fs::path curve = out / "curves" / (std::string(id) + ".dat");
        writeFileAtomically(curve, [&](std::ostream& o) {
            o << "# displacement [m]\tforce [N]\n" << std::setprecision(10);
            for (std::size_t i = 0; i < d.size(); ++i) {
                const double noisyF = f[i] * (1.0 + s.forceNoise * gaussian(s.noiseSeed, 2 * k, i));
                const double noisyD = d[i] + s.displacementNoise * gaussian(s.noiseSeed, 2 * k + 1, i);
                o << noisyD << "\t" << std::max(0.0, noisyF) << "\n";
            }
        });
        specimens << "    " << id << " { curve \"curves/" << id << ".dat\"; }   // Voronoi seed "
                  << runs.seeds[k] << "\n";
    }
    const fs::path measurements = out / "measurements";
    writeFileAtomically(measurements, [&](std::ostream& o) {
        o << "FoamFile { format ascii; class dictionary; object measurements; }\n\n"
          << "// Twin data written by makeTwinData from the study " << s.directory.filename().string()
          << ": the model case\n// run on " << runs.features.size()
          << " Voronoi seeds with noise on every sample. What was hidden in it is in\n"
          << "// the study's hiddenLabel, not here: the analysis is blind.\n\n"
          << "test        BDT;\nmaterial    " << s.material
          << ";\nreference   \"twin data (makeTwinData)\";\n\n"
          << geometryEntries(study.templateDirectory() / "constant/geometryProperties") << "specimens\n{\n"
          << specimens.str() << "}\n";
    });
    const fs::path label = s.directory / "hiddenLabel";
    writeFileAtomically(label, [&](std::ostream& o) {
        o << "FoamFile { format ascii; class dictionary; object hiddenLabel; }\n\n"
          << "// What makeTwinData hid in " << measurements.string() << ".\n"
          << "hiddenEffects (";
        for (std::size_t i = 0; i < s.hiddenEffects.size(); ++i) o << (i ? " " : "") << s.hiddenEffects[i];
        o << ");\neffects\n{\n"
          << s.hiddenEffectsText << "}\nforceNoise " << s.forceNoise << ";\ndisplacementNoise "
          << s.displacementNoise << ";\nspecimens " << runs.features.size() << ";\nfailedRuns " << runs.failed
          << ";\n";
    });
    return {measurements, label, static_cast<int>(runs.features.size())};
}

}  // namespace rockfrac::explain
