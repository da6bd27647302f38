#include "stats/measurements.hpp"

#include <algorithm>
#include <cmath>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "io/timeSeries.hpp"

namespace rockfrac::stats {

namespace fs = std::filesystem;

Sample MeasurementSet::failureLoads() const
{
    Sample loads;
    for (const Specimen& specimen : specimens) loads.push_back(specimen.failureLoad);
    return loads;
}

std::string MeasurementSet::label() const
{
    std::string text = "measured";
    for (const std::string& word : {material, test})
        if (!word.empty()) text += " " + word;
    return text;
}

namespace {

const std::vector<std::string> specimenKeywords = {
    "failureLoad", "tensileStrength",    "diameter", "thickness",
    "volume",      "equivalentDiameter", "cells",    "curve"};

// A physical quantity: positive, and its dimension set is required and checked.
std::optional<double> quantity(const Dictionary& dict, const std::string& key, const char* units)
{
    const Entry* entry = dict.findEntry(key);
    if (!entry) return std::nullopt;
    if (!entry->dimensions)
        throw UserError(entry->keywordLocation.str() + ": " + key +
                        " has no dimension set; measured values state " + "their unit, e.g. '" + key + " [" +
                        units + "] <value>;' in SI units");
    const Dimensions expected = Dimensions::fromUnits(units);
    return dict.getScalar(key, Bounds::positive(), &expected);
}

void checkCurveColumn(const fs::path& file, const TimeSeries& series, const std::string& name,
                      const std::string& unit)
{
    const int c = series.column(name);
    if (c < 0)
        throw UserError(file.string() + ": no column '" + name + "'; the header must name '" + name + " [" +
                        unit + "]' (e.g. '# displacement [m]<TAB>force [N]')");
    if (series.units[c] != unit)
        throw UserError(file.string() + ": column '" + name + "' is in [" + series.units[c] +
                        "]; write it in [" + unit + "] (SI units, convert the values)");
}

// `id` is the specimen's keyword (the sub-dictionary's name() is its whole path).
Specimen readSpecimen(const std::string& id, const Dictionary& specimenDict,
                      const Dictionary* defaultGeometry, const fs::path& directory)
{
    Specimen specimen;
    specimen.id = id;
    for (const std::string& key : specimenDict.keys())
        if (std::find(specimenKeywords.begin(), specimenKeywords.end(), key) == specimenKeywords.end())
            throw UserError(specimenDict.entry(key).keywordLocation.str() + ": unknown specimen entry '" +
                            key +
                            "'; expected failureLoad, tensileStrength, diameter, thickness, volume, "
                            "equivalentDiameter, cells or curve");
    auto geometry = [&](const std::string& key, const char* units) {
        auto value = quantity(specimenDict, key, units);
        return value || !defaultGeometry ? value : quantity(*defaultGeometry, key, units);
    };
    specimen.geometry = {geometry("diameter", "m"), geometry("thickness", "m"), geometry("volume", "m^3"),
                         geometry("equivalentDiameter", "m")};
    specimen.tensileStrength = quantity(specimenDict, "tensileStrength", "Pa");
    if (specimenDict.found("cells")) specimen.cells = specimenDict.get<int>("cells");
    if (specimenDict.found("curve"))
        specimen.curve = readForceDisplacementCurve(directory / specimenDict.get<std::string>("curve"));
    const std::optional<double> load = quantity(specimenDict, "failureLoad", "N");
    if (load)
        specimen.failureLoad = *load;
    else if (specimen.curve) {  // the peak of the curve
        specimen.failureLoad = *std::max_element(specimen.curve->force.begin(), specimen.curve->force.end());
        if (!(specimen.failureLoad > 0.0))  // found by fuzzing: a zero load broke the statistics
            throw UserError(specimen.curve->file.string() +
                            ": the force never rises above 0 N, so specimen '" + specimen.id +
                            "' has no failure load; check the curve or give 'failureLoad [N] <value>;'");
    } else
        throw UserError(specimenDict.endLocation().str() + ": specimen '" + specimen.id +
                        "' has no failureLoad; give 'failureLoad [N] <value>;' or a 'curve \"file.dat\";'");
    return specimen;
}

}  // namespace

ForceDisplacementCurve readForceDisplacementCurve(const fs::path& path)
{
    const TimeSeries series = readTimeSeries(path);
    checkCurveColumn(path, series, "displacement", "m");
    checkCurveColumn(path, series, "force", "N");
    if (series.rows.empty())
        throw UserError(path.string() +
                        ": no data rows under the header; expected one row per measured point");
    ForceDisplacementCurve curve{path, series.values("displacement"), series.values("force")};
    for (std::size_t i = 0; i < curve.force.size(); ++i) {
        if (!std::isfinite(curve.force[i]) || !std::isfinite(curve.displacement[i]))
            throw UserError(path.string() + ": a value in data row " + std::to_string(i + 1) +
                            " is not a finite number; correct the row");
        if (curve.force[i] < 0.0)
            throw UserError(path.string() + ": negative force " + formatNumber(curve.force[i]) +
                            " N in data row " + std::to_string(i + 1) +
                            "; compressive loads are positive (remove the load cell offset)");
    }
    return curve;
}

MeasurementSet readMeasurements(const fs::path& path)
{
    return readMeasurements(Dictionary::readFile(path), path);
}

MeasurementSet readMeasurements(const Dictionary& dict, const fs::path& path)
{
    MeasurementSet set;
    set.file = path;
    set.test = dict.getOrDefault<std::string>("test", "");
    set.material = dict.getOrDefault<std::string>("material", "");
    set.reference = dict.getOrDefault<std::string>("reference", "");
    const Dictionary* defaultGeometry = dict.isDict("geometry") ? &dict.subDict("geometry") : nullptr;
    const Dictionary& specimens = dict.subDict("specimens");
    for (const Entry& entry : specimens.entries()) {
        if (!entry.isDict())
            throw UserError(entry.keywordLocation.str() + ": '" + entry.keyword +
                            "' is not a specimen; expected '" + entry.keyword +
                            " { failureLoad [N] <value>; }'");
        set.specimens.push_back(
            readSpecimen(entry.keyword, *entry.dict, defaultGeometry, path.parent_path()));
    }
    if (set.specimens.empty())
        throw UserError(specimens.endLocation().str() +
                        ": no specimens; list at least one, e.g. 'S1 { failureLoad [N] 10900; }'");
    return set;
}

}  // namespace rockfrac::stats
