#include "explain/pointRuns.hpp"

#include <cstdio>
#include <functional>
#include <iostream>

#include "calibration/studyRunner.hpp"
#include "core/atomicFile.hpp"
#include "core/error.hpp"
#include "io/timeSeries.hpp"

namespace rockfrac::explain {

namespace fs = std::filesystem;

void writeTemplateEffects(const calibration::CalibrationStudy& study, const std::string& body)
{
    const fs::path file = study.templateDirectory() / "constant/modelEffects";
    if (body.empty()) {
        fs::remove(file);
        return;
    }
    writeFileAtomically(file, [&](std::ostream& out) {
        out << "FoamFile { format ascii; class dictionary; object modelEffects; }\n\n"
            << "// Written by " << study.dictionary.filename().string()
            << "'s application: the model effects every run may switch on (docs/explainGap.md).\n"
            << body;
    });
}

PointRuns runPoint(const calibration::CalibrationStudy& study, const std::vector<double>& values,
                   const std::string& label, const std::string& displacementColumn,
                   const std::string& forceColumn)
{
    std::string key;
    for (double v : values) key += calibration::valueText(v) + " ";
    char hash[20];
    std::snprintf(hash, sizeof(hash), "%08zx", std::hash<std::string>{}(key)&0xffffffffu);
    calibration::RunSet set;
    set.directory = study.runsDirectory() / (values.empty() ? label : label + "-" + hash);
    for (double v : values) set.values.push_back({calibration::valueText(v)});
    const auto members = calibration::runSet(study, set, study.jobs);
    PointRuns runs;
    runs.values = values;
    runs.directory = set.directory;
    for (const auto& m : members) {
        if (!m.done) {
            ++runs.failed;
            continue;
        }
        const TimeSeries series = readTimeSeries(m.directory / study.responseFile);
        const int dc = series.column(displacementColumn), fc = series.column(forceColumn);
        if (dc < 0 || fc < 0)
            throw UserError((m.directory / study.responseFile).string() + ": no column '" +
                            (dc < 0 ? displacementColumn : forceColumn) + "'");
        std::vector<double> d, f;
        for (const auto& row : series.rows) {
            d.push_back(row[static_cast<std::size_t>(dc)]);
            f.push_back(row[static_cast<std::size_t>(fc)]);
        }
        const auto features = curveFeatures(d, f);
        if (!features) {
            ++runs.failed;
            continue;
        }
        runs.seeds.push_back(m.seed);
        runs.displacement.push_back(std::move(d));
        runs.force.push_back(std::move(f));
        runs.features.push_back(*features);
    }
    if (runs.features.size() < 2)
        throw UserError("only " + std::to_string(runs.features.size()) + " of " +
                        std::to_string(members.size()) + " runs in '" + set.directory.string() +
                        "' gave a curve with a peak and a load drop; see their log files (a run that stops "
                        "before the drop needs a later endTime or a stop criterion in constant/loading)");
    return runs;
}

}  // namespace rockfrac::explain
