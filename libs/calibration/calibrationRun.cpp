#include "calibration/calibrationRun.hpp"

#include <cmath>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "calibration/calibrationDetail.hpp"
#include "calibration/responseSurface.hpp"
#include "core/atomicFile.hpp"
#include "core/dictionary.hpp"
#include "core/dictionaryEditor.hpp"
#include "core/error.hpp"
#include "io/timeSeries.hpp"

namespace rockfrac::calibration {

namespace fs = std::filesystem;

namespace detail {

std::vector<double> physicalValues(const CalibrationStudy& study, const std::vector<double>& x)
{
    std::vector<double> values;
    for (std::size_t i = 0; i < study.parameters.size(); ++i)
        values.push_back(
            std::stod(valueText(fromUnit(x[i], study.parameters[i].low, study.parameters[i].high))));
    return values;
}

Objective reusingRepeatedSets(const CalibrationStudy& study, Objective objective)
{
    auto objectives = std::make_shared<std::map<std::vector<double>, double>>();
    return [&study, objective = std::move(objective), objectives](const std::vector<double>& x) {
        const std::vector<double> values = physicalValues(study, x);
        if (const auto seen = objectives->find(values); seen != objectives->end()) {
            std::cout << "calibrateModel: " << describeValues(study, values) << " again: objective "
                      << format(seen->second) << " of its earlier runs reused" << std::endl;
            return seen->second;
        }
        const double value = objective(x);
        objectives->emplace(values, value);
        return value;
    };
}

std::vector<double> unitValues(const CalibrationStudy& study, const std::vector<double>& values)
{
    std::vector<double> x;
    for (std::size_t i = 0; i < study.parameters.size(); ++i)
        x.push_back(toUnit(values[i], study.parameters[i].low, study.parameters[i].high));
    return x;
}

RunSet pointRunSet(const fs::path& directory, const std::vector<double>& values)
{
    RunSet set;
    set.directory = directory;
    for (double v : values) set.values.push_back({valueText(v)});
    return set;
}

std::string format(double value, int digits)
{
    std::ostringstream s;
    s.precision(digits);
    s << value;
    return s.str();
}

std::string studyName(const CalibrationStudy& study)
{
    fs::path dir = fs::absolute(study.directory).lexically_normal();
    if (dir.filename().empty()) dir = dir.parent_path();
    return dir.filename().string();
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace detail

PeakResponse readPeakResponse(const fs::path& file, const std::string& forceColumn,
                              const std::string& displacementColumn)
{
    if (!fs::is_regular_file(file)) throw UserError("no response file '" + file.string() + "'");
    const TimeSeries series = readTimeSeries(file);
    const int f = series.column(forceColumn), d = series.column(displacementColumn);
    if (f < 0 || d < 0)
        throw UserError("'" + file.string() + "' has no column '" +
                        (f < 0 ? forceColumn : displacementColumn) + "'");
    if (series.rows.empty()) throw UserError("'" + file.string() + "' has no rows");
    PeakResponse peak{-HUGE_VAL, 0.0};
    for (const auto& row : series.rows)
        if (row[static_cast<std::size_t>(f)] > peak.force) {
            peak.force = row[static_cast<std::size_t>(f)];
            peak.displacement = row[static_cast<std::size_t>(d)];
        }
    return peak;
}

PeakErrors peakErrors(const CalibrationStudy& study, const std::vector<double>& x, const PeakResponse& r)
{
    const double targetForce = stats::mean(study.measurements.failureLoads());
    PeakErrors e;
    e.force = (r.force - targetForce) / targetForce;
    e.objective = study.forceWeight * e.force * e.force;
    if (study.displacementTarget) {
        e.displacement = (r.displacement - *study.displacementTarget) / *study.displacementTarget;
        e.objective += study.displacementWeight * e.displacement * e.displacement;
    } else {  // force only: a curve of solutions; take the one nearest the reference
        const auto ref = detail::unitValues(study, study.reference);
        for (std::size_t i = 0; i < x.size(); ++i)
            e.objective += study.regularisation * std::pow(x[i] - ref[i], 2);
    }
    return e;
}

CalibrationOutcome calibrate(const CalibrationStudy& study, int jobs)
{
    prepareTemplate(study);
    if (study.model == "fem") return detail::calibrateFemBobyqa(study, jobs);
    if (study.method == "bobyqa") return detail::calibrateDemBobyqa(study, jobs);
    return detail::calibrateDemResponseSurface(study, jobs);
}

void writeCalibratedValues(const CalibrationStudy& study, const CalibrationOutcome& outcome, bool intoCase)
{
    // Check every edit first (checkOnly), then write: a failure leaves every file as it was.
    for (bool checkOnly : {true, false}) {
        if (!intoCase) break;
        for (std::size_t i = 0; i < study.parameters.size(); ++i) {
            const auto& p = study.parameters[i];
            editDictionaryFile(
                study.targetCase / p.file,
                [&](const std::string& text, const std::string& name) {
                    return replaceEntry(text, p.entry, valueText(outcome.values[i]), name, outcome.comment);
                },
                "set " + p.entry, checkOnly);
        }
        for (const TiedEntry& t : study.tied)
            editDictionaryFile(
                study.targetCase / t.file,
                [&](const std::string& text, const std::string& name) {
                    return replaceEntry(text, t.entry, valueText(t.factor * outcome.values[t.parameter]),
                                        name,
                                        formatNumber(t.factor) + " x " + study.parameters[t.parameter].name +
                                            "; " + outcome.comment);
                },
                "set " + t.entry, checkOnly);
    }
    const fs::path file = study.directory / ("calibratedValues." + outcome.method);
    writeFileAtomically(file, [&](std::ostream& out) {
        out << "FoamFile { format ascii; class dictionary; object calibratedValues; }\n\n// "
            << outcome.comment << "\n\nvalues\n{\n";
        for (std::size_t i = 0; i < study.parameters.size(); ++i)
            out << "    " << study.parameters[i].name << "    " << valueText(outcome.values[i]) << ";    // "
                << study.parameters[i].entry << " [" << study.parameters[i].unit << "]\n";
        for (const TiedEntry& t : study.tied)
            out << "    " << t.name << "    " << valueText(t.factor * outcome.values[t.parameter])
                << ";    // " << t.entry << " = " << formatNumber(t.factor) << " x "
                << study.parameters[t.parameter].name << "\n";
        out << "}\n\nreport\n{\n";
        for (const auto& line : outcome.report)
            out << "    " << line[0] << "    " << line[1] << ";"
                << (line.size() > 2 && !line[2].empty() ? "    // " + line[2] : "") << "\n";
        out << "}\n";
    });
}

}  // namespace rockfrac::calibration
