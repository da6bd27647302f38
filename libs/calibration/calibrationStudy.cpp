#include "calibration/calibrationStudy.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/dictionary.hpp"
#include "core/dictionaryEditor.hpp"
#include "core/error.hpp"
#include "core/knownEntries.hpp"
#include "core/textFile.hpp"

namespace rockfrac::calibration {

namespace fs = std::filesystem;

namespace {

const fs::path defaultFile = "constant/rockProperties";

// The entry must exist in the case: a calibration changes entries, it never adds one.
void checkEntryExists(const Dictionary& dict, const std::string& owner, const fs::path& caseDir,
                      const fs::path& file, const std::string& entry)
{
    const fs::path path = caseDir / file;
    if (!fs::is_regular_file(path))
        throw UserError(dict.endLocation().str() + ": " + owner + ": the case has no '" + file.string() +
                        "' ('" + path.string() + "')");
    if (!hasTextEntry(readFileText(path), entry, path.string()))
        throw UserError(dict.endLocation().str() + ": " + owner + ": '" + path.string() + "' has no entry '" +
                        entry + "'; the calibration changes existing entries only");
}

CalibratedParameter readParameter(const Entry& e, const fs::path& caseDir)
{
    if (!e.isDict())
        throw UserError(e.keywordLocation.str() + ": parameter '" + e.keyword +
                        "' must be a dictionary, e.g. '" + e.keyword +
                        " { entry bond/voronoiQNSC/E; range (20e9 80e9); }'");
    const Dictionary& d = *e.dict;
    checkKnownEntries(d, {"file", "entry", "unit", "range"});
    CalibratedParameter p;
    p.name = e.keyword;
    p.file = d.getOrDefault<std::string>("file", defaultFile.string());
    p.entry = d.get<std::string>("entry");
    p.unit = d.getOrDefault<std::string>("unit", "-");
    const auto range = d.get<std::vector<double>>("range");
    if (range.size() != 2 || !(range[0] < range[1]))
        throw UserError(d.location("range").str() + ": parameter '" + e.keyword +
                        "': range must be two numbers (low high) with low < high");
    p.low = range[0];
    p.high = range[1];
    checkEntryExists(d, "parameter '" + e.keyword + "'", caseDir, p.file, p.entry);
    return p;
}

TiedEntry readTied(const Entry& e, const CalibrationStudy& study)
{
    if (!e.isDict())
        throw UserError(e.keywordLocation.str() + ": tied entry '" + e.keyword +
                        "' must be a dictionary, e.g. '" + e.keyword +
                        " { entry bond/voronoiQNSC/cohesion; factor 1.5; of tensileStrength; }'");
    const Dictionary& d = *e.dict;
    checkKnownEntries(d, {"entry", "factor", "of", "file"});
    TiedEntry t;
    t.name = e.keyword;
    t.entry = d.get<std::string>("entry");
    t.factor = d.getScalar("factor", Bounds::positive());
    const std::string of = d.get<std::string>("of");
    const auto names = study.parameterNames();
    std::size_t i = 0;
    while (i < names.size() && names[i] != of) ++i;
    if (i == names.size())
        throw UserError(d.location("of").str() + ": tied entry '" + e.keyword + "': '" + of +
                        "' is not one of the parameters");
    t.parameter = i;
    t.file = d.getOrDefault<std::string>("file", study.parameters[i].file.string());
    checkEntryExists(d, "tied entry '" + e.keyword + "'", study.targetCase, t.file, t.entry);
    return t;
}

void readMethodSettings(const Dictionary& dict, CalibrationStudy& s)
{
    if (dict.found("responseSurface")) {
        const Dictionary& r = dict.subDict("responseSurface");
        s.design =
            r.found("design") ? r.getWord("design", {"fullFactorial", "latinHypercube"}) : "fullFactorial";
        if (s.design == "fullFactorial") {
            s.levels = static_cast<int>(r.getScalarOrDefault("levels", 3, Bounds::nonNegative()));
            if (s.levels == 0)
                throw UserError(r.location("levels").str() +
                                ": levels 0: the design has no runs; give 3 or more");
            if (s.levels < 3)
                throw UserError(r.location("levels").str() + ": levels " + std::to_string(s.levels) +
                                ": a quadratic needs at least 3 levels per parameter");
        } else {
            s.samples = static_cast<std::size_t>(r.getScalar("samples", Bounds::nonNegative()));
            if (s.samples == 0)
                throw UserError(
                    r.location("samples").str() +
                    ": samples 0: the design has no runs; give at least the number of coefficients");
            s.designSeed = r.getOrDefault<std::uint64_t>("seed", 1);
        }
        s.surfaceStarts = static_cast<int>(r.getScalarOrDefault("starts", 5, Bounds::closed(1, 20)));
    }
    if (dict.found("bobyqa")) {
        const Dictionary& b = dict.subDict("bobyqa");
        s.maxEvaluations = static_cast<int>(b.getScalarOrDefault("maxEvaluations", 30, Bounds::atLeast(1)));
        s.initialStep = b.getScalarOrDefault("initialStep", 0.5, Bounds::open(0, 2));
        s.tolerance = b.getScalarOrDefault("tolerance", 1e-3, Bounds::positive());
    }
}

void readTarget(const Dictionary& dict, CalibrationStudy& s)
{
    const Dictionary& t = dict.subDict("target");
    checkKnownEntries(t, s.model == "fem" ? std::vector<std::string>{"response", "failureLoad", "distance"}
                                          : std::vector<std::string>{
                                                "response", "force", "displacement", "displacementAtPeak",
                                                "displacementSource", "forceWeight", "displacementWeight",
                                                "regularisation", "reference"});
    s.responseFile = t.get<std::string>("response");
    for (const auto& p : s.parameters) s.reference.push_back(0.5 * (p.low + p.high));  // BOBYQA starts here
    if (s.model == "fem") {
        s.forceColumn = t.getOrDefault<std::string>("failureLoad", "failureLoad");
        s.distance = t.found("distance") ? t.getWord("distance", {"wasserstein1", "kolmogorovSmirnov"})
                                         : "wasserstein1";
        return;
    }
    static const Dimensions metre = Dimensions::fromUnits("m");
    s.forceColumn = t.getOrDefault<std::string>("force", "force");
    s.displacementColumn = t.getOrDefault<std::string>("displacement", "gapChange");
    if (t.found("displacementAtPeak")) {
        s.displacementTarget = t.getScalar("displacementAtPeak", Bounds::positive(), &metre);
        if (!t.found("displacementSource"))
            throw UserError(t.location("displacementAtPeak").str() +
                            ": say where the measured displacement comes from: displacementSource \"...\";");
        s.displacementSource = t.get<std::string>("displacementSource");
    }
    s.forceWeight = t.getScalarOrDefault("forceWeight", 0.5, Bounds::nonNegative());
    s.displacementWeight = t.getScalarOrDefault("displacementWeight", 0.5, Bounds::nonNegative());
    if (!s.displacementTarget) {  // only the force is measured: it alone is the objective
        s.forceWeight = 1.0;
        s.displacementWeight = 0.0;
    }
    if (s.forceWeight + s.displacementWeight <= 0)
        throw UserError(t.endLocation().str() + ": forceWeight and displacementWeight are both 0");
    s.regularisation = t.getScalarOrDefault("regularisation", 1e-3, Bounds::nonNegative());
    if (t.found("reference")) {
        const auto& ref = t.subDict("reference");
        checkKnownEntries(ref, s.parameterNames());
        for (std::size_t i = 0; i < s.parameters.size(); ++i)
            if (ref.found(s.parameters[i].name))
                s.reference[i] = ref.getScalar(s.parameters[i].name,
                                               Bounds::closed(s.parameters[i].low, s.parameters[i].high));
    }
}

}  // namespace

std::vector<std::string> CalibrationStudy::parameterNames() const
{
    std::vector<std::string> names;
    for (const auto& p : parameters) names.push_back(p.name);
    return names;
}

std::string valueText(double value)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", value);
    return formatNumber(std::stod(text));
}

std::string describeValues(const CalibrationStudy& study, const std::vector<double>& values)
{
    std::string text;
    for (std::size_t i = 0; i < study.parameters.size() && i < values.size(); ++i) {
        if (i) text += ", ";
        text += study.parameters[i].name + "=" + valueText(values[i]);
        if (study.parameters[i].unit != "-") text += " " + study.parameters[i].unit;
    }
    return text;
}

const std::vector<std::string>& calibrationDictEntries()
{
    static const std::vector<std::string> entries = {
        "model", "method",     "case", "measurements", "prepare",         "command", "jobs",  "scheduler",
        "slurm", "parameters", "tied", "seeds",        "responseSurface", "bobyqa",  "target"};
    return entries;
}

CalibrationStudy readCalibrationStudy(const fs::path& studyDirectory)
{
    CalibrationStudy s;
    s.directory = studyDirectory;
    s.dictionary = studyDirectory / "system/calibrationDict";
    if (!fs::is_regular_file(s.dictionary))
        throw UserError("no '" + s.dictionary.string() +
                        "'; a calibration study holds system/calibrationDict (see calibrateModel -help)");
    const Dictionary dict = Dictionary::readFile(s.dictionary);
    checkKnownEntries(dict, calibrationDictEntries());
    checkKnownSubEntries(dict, "responseSurface", {"design", "levels", "samples", "seed", "starts"});
    checkKnownSubEntries(dict, "bobyqa", {"maxEvaluations", "initialStep", "tolerance"});
    s.model = dict.getWord("model", {"dem", "fem"});
    s.method = dict.found("method") ? dict.getWord("method", {"responseSurface", "bobyqa"})
                                    : (s.model == "dem" ? "responseSurface" : "bobyqa");
    if (s.model == "fem" && s.method != "bobyqa")
        throw UserError(dict.location("method").str() +
                        ": the FEM calibration matches a distribution over seeds directly: method bobyqa");
    s.targetCase = (studyDirectory / dict.get<std::string>("case")).lexically_normal();
    if (!fs::is_directory(s.targetCase))
        throw UserError(dict.location("case").str() + ": case '" + s.targetCase.string() +
                        "' does not exist; give the case to calibrate, relative to the study");
    s.measurementsFile = (studyDirectory / dict.get<std::string>("measurements")).lexically_normal();
    if (!fs::is_regular_file(s.measurementsFile))
        throw UserError(dict.location("measurements").str() + ": no measurements file '" +
                        s.measurementsFile.string() + "'");
    s.measurements = stats::readMeasurements(s.measurementsFile);
    s.prepareCommand = dict.getOrDefault<std::string>("prepare", "");
    s.command = dict.get<std::string>("command");
    s.jobs = static_cast<int>(dict.getScalarOrDefault("jobs", 1, Bounds::atLeast(1)));
    s.scheduler = readScheduler(dict);
    for (const Entry& e : dict.subDict("parameters").entries())
        s.parameters.push_back(readParameter(e, s.targetCase));
    if (s.parameters.empty())
        throw UserError(dict.location("parameters").str() + ": no parameters to calibrate");
    if (dict.found("tied"))
        for (const Entry& e : dict.subDict("tied").entries()) s.tied.push_back(readTied(e, s));
    if (dict.found("seeds")) {
        const Dictionary& d = dict.subDict("seeds");
        checkKnownEntries(d, {"file", "entry", "values"});
        SeedList seeds{
            d.getOrDefault<std::string>("file", defaultFile.string()), d.get<std::string>("entry"), {}};
        for (double v : d.get<std::vector<double>>("values")) seeds.values.push_back(formatNumber(v));
        if (seeds.values.empty())
            throw UserError(d.location("values").str() + ": no seeds: the design has no runs");
        checkEntryExists(d, "seeds", s.targetCase, seeds.file, seeds.entry);
        s.seeds = seeds;
    }
    if (s.model == "fem" && (!s.seeds || s.seeds->values.size() < 2))
        throw UserError(
            dict.endLocation().str() +
            ": the FEM calibration compares distributions: give seeds { entry kstDfh/dfh/seed; values "
            "(1 ... 10); }");
    readMethodSettings(dict, s);
    readTarget(dict, s);
    return s;
}

}  // namespace rockfrac::calibration
