#include "explain/explainStudy.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/dictionary.hpp"
#include "core/dictionaryEditor.hpp"
#include "core/error.hpp"
#include "core/knownEntries.hpp"
#include "core/textFile.hpp"
#include "effects/modelEffect.hpp"
#include "explain/effectPairs.hpp"
#include "explain/responseFeatures.hpp"

namespace rockfrac::explain {

namespace fs = std::filesystem;

namespace {

fs::path caseRelative(const Dictionary& dict, const fs::path& studyDir, const std::string& key)
{
    const fs::path p = dict.get<std::string>(key);
    const fs::path full = (p.is_absolute() ? p : studyDir / p).lexically_normal();
    return full;
}

fs::path existingCase(const Dictionary& dict, const fs::path& studyDir)
{
    const fs::path c = caseRelative(dict, studyDir, "case");
    if (!fs::is_directory(c / "system") || !fs::is_directory(c / "constant"))
        throw UserError(dict.location("case").str() + ": '" + c.string() +
                        "' is not a case (no system/ and constant/); give the model case to run");
    return c;
}

// Every case must hold `entry` in `file` (a study edits it in each of them).
void requireCaseEntry(const std::string& where, const std::vector<fs::path>& caseDirs, const fs::path& file,
                      const std::string& entry)
{
    for (const fs::path& caseDir : caseDirs) {
        const fs::path path = caseDir / file;
        if (!fs::is_regular_file(path) || !hasTextEntry(readFileText(path), entry, path.string()))
            throw UserError(where + ": the case has no entry '" + entry + "' in '" + path.string() + "'");
    }
}

calibration::SeedList readSeeds(const Dictionary& dict, const std::vector<fs::path>& caseDirs,
                                std::size_t minimum, const std::string& why)
{
    if (!dict.isDict("seeds"))
        throw UserError(dict.fileName() +
                        ": 'seeds { file system/voronoiMeshDict; entry seed; values (1 2 3 4); }' " +
                        "is required: " + why);
    const Dictionary& s = dict.subDict("seeds");
    checkKnownEntries(s, {"file", "entry", "values"});
    calibration::SeedList seeds;
    seeds.file = s.get<std::string>("file");
    seeds.entry = s.get<std::string>("entry");
    for (double v : s.get<std::vector<double>>("values")) seeds.values.push_back(formatNumber(v));
    if (seeds.values.size() < minimum)
        throw UserError(s.location("values").str() + ": " + std::to_string(seeds.values.size()) +
                        " seeds; at least " + std::to_string(minimum) + " are needed: " + why);
    requireCaseEntry(s.location("entry").str(), caseDirs, seeds.file, seeds.entry);
    return seeds;
}

void readCommands(const Dictionary& dict, std::string& prepare, std::string& command, int& jobs,
                  SchedulerSettings& scheduler)
{
    scheduler = readScheduler(dict);
    prepare = dict.getOrDefault<std::string>("prepare", "");
    command = dict.get<std::string>("command");
    jobs = static_cast<int>(dict.getScalarOrDefault("jobs", 1, Bounds::closed(1, 256)));
}

}  // namespace

namespace {

// What every runCases study of explainGap and makeTwinData shares: a DEM case, run
// once per seed by `command` after `prepare` in the template.
calibration::CalibrationStudy demRunStudy(const fs::path& directory, const fs::path& dictionary,
                                          const fs::path& targetCase, const std::string& prepare,
                                          const std::string& command, int jobs,
                                          const SchedulerSettings& scheduler,
                                          const calibration::SeedList& seeds, const fs::path& response)
{
    calibration::CalibrationStudy s;
    s.directory = directory;
    s.dictionary = dictionary;
    s.model = "dem";
    s.targetCase = targetCase;
    s.prepareCommand = prepare;
    s.command = command;
    s.jobs = jobs;
    s.scheduler = scheduler;
    s.seeds = seeds;
    s.responseFile = response;
    s.forceColumn = "force";
    return s;
}

}  // namespace

calibration::CalibrationStudy ExplainStudy::runStudy(std::size_t condition) const
{
    const TestCondition& c = conditions.at(condition);
    calibration::CalibrationStudy s =
        demRunStudy(c.name.empty() ? simulations : simulations / c.name, dictionary, c.targetCase,
                    prepareCommand, command, jobs, scheduler, seeds, responseFile);
    for (const auto& b : baseline) s.parameters.push_back(b.where);
    for (const std::string& name : effects) {
        const EffectDescriptor& d = findEffect(name, dictionary.string());
        calibration::CalibratedParameter p;
        p.name = name;
        p.file = "constant/modelEffects";
        p.entry = name + "/" + d.parameter;
        p.unit = d.unit;
        p.low = d.low;
        p.high = d.high;
        s.parameters.push_back(p);
    }
    s.tied = tied;
    s.forceColumn = forceColumn;
    return s;
}

const std::vector<std::string>& explainGapDictEntries()
{
    static const std::vector<std::string> entries = {"conditions",
                                                     "case",
                                                     "measurements",
                                                     "prepare",
                                                     "command",
                                                     "jobs",
                                                     "scheduler",
                                                     "slurm",
                                                     "simulations",
                                                     "seeds",
                                                     "baseline",
                                                     "tied",
                                                     "effects",
                                                     "effectSettings",
                                                     "features",
                                                     "statistics",
                                                     "response",
                                                     "heldOut",
                                                     "minimumGapReduction",
                                                     "significance",
                                                     "pairs"};
    return entries;
}

namespace {

// The `pairs` entry: a count 0 to maximumPairs, or the word off; absent: `current`.
int readPairs(const Dictionary& dict, int current)
{
    const Entry* pairs = dict.findEntry("pairs");
    if (!pairs) return current;
    const std::string what =
        "give the most pairs of effects to refit when no single effect passes the "
        "absolute test, 0 to " +
        std::to_string(maximumPairs) + " (each up to 9 evaluations of every seed), or off";
    if (pairs->values.size() == 1 && pairs->values[0].isNumber()) {
        const double n = dict.getScalarOrDefault("pairs", 3, Bounds::closed(0, maximumPairs));
        if (n != std::floor(n))
            throw UserError(dict.location("pairs").str() + ": pairs " + std::to_string(n) + " is no count; " +
                            what);
        return static_cast<int>(n);
    }
    if (pairs->values.size() == 1 && dict.get<std::string>("pairs") == "off") return 0;
    throw UserError(dict.location("pairs").str() + ": pairs is not a count nor off; " + what);
}

// The `tied` entries: each an entry set to a factor times a baseline parameter.
std::vector<calibration::TiedEntry> readTied(const Dictionary& dict,
                                             const std::vector<BaselineParameter>& baseline)
{
    std::vector<calibration::TiedEntry> tied;
    if (dict.isDict("tied"))
        for (const Entry& e : dict.subDict("tied").entries()) {
            if (!e.dict)
                throw UserError(
                    dict.subDict("tied").location(e.keyword).str() + ": tied entry '" + e.keyword +
                    "' must be a sub-dictionary { entry <file/entry>; factor <f>; of <baseline>; }");
            const Dictionary& d = *e.dict;
            checkKnownEntries(d, {"entry", "factor", "of"});
            calibration::TiedEntry t;
            t.name = e.keyword;
            t.entry = d.get<std::string>("entry");
            t.factor = d.getScalar("factor", Bounds::positive());
            const std::string of = d.get<std::string>("of");
            std::size_t i = 0;
            while (i < baseline.size() && baseline[i].where.name != of) ++i;
            if (i == baseline.size())
                throw UserError(d.location("of").str() + ": tied entry '" + e.keyword + "': '" + of +
                                "' is not a baseline parameter");
            t.parameter = i;
            t.file = baseline[i].where.file;
            tied.push_back(t);
        }

    return tied;
}

}  // namespace

ExplainStudy readExplainStudy(const fs::path& studyDirectory)
{
    ExplainStudy s;
    s.directory = studyDirectory;
    s.dictionary = studyDirectory / "system/explainGapDict";
    if (!fs::is_regular_file(s.dictionary))
        throw UserError(
            "missing '" + s.dictionary.string() +
            "': an explainGap study is a directory with system/explainGapDict (docs/explainGap.md)");
    const Dictionary dict = Dictionary::readFile(s.dictionary);
    checkKnownEntries(dict, explainGapDictEntries());
    auto condition = [&](const Dictionary& d, const std::string& name) {
        if (!name.empty()) checkKnownEntries(d, {"case", "measurements"});
        TestCondition c;
        c.name = name;
        c.targetCase = existingCase(d, studyDirectory);
        c.measurementsFile = caseRelative(d, studyDirectory, "measurements");
        if (!fs::is_regular_file(c.measurementsFile))
            throw UserError(d.location("measurements").str() + ": no measurements file '" +
                            c.measurementsFile.string() + "'");
        c.measurements = stats::readMeasurements(c.measurementsFile);
        return c;
    };
    if (dict.found("conditions")) {
        if (!dict.isDict("conditions"))
            throw UserError(dict.location("conditions").str() +
                            ": 'conditions' must be a dictionary: conditions { slow { case \"../bdt\"; "
                            "measurements \"...\"; } fast { ... } }");
        for (const char* key : {"case", "measurements"})
            if (dict.found(key))
                throw UserError(dict.location(key).str() + ": '" + key +
                                "' and 'conditions' together: with conditions, every condition names "
                                "its own case and measurements; remove the top-level '" +
                                key + "'");
        for (const Entry& e : dict.subDict("conditions").entries()) {
            if (!e.isDict())
                throw UserError(e.keywordLocation.str() + ": condition '" + e.keyword +
                                "' must be a dictionary { case \"...\"; measurements \"...\"; }");
            s.conditions.push_back(condition(*e.dict, e.keyword));
        }
        if (s.conditions.empty())
            throw UserError(dict.location("conditions").str() +
                            ": no conditions; give at least one { case ...; measurements ...; }");
    } else {
        s.conditions.push_back(condition(dict, ""));
    }
    readCommands(dict, s.prepareCommand, s.command, s.jobs, s.scheduler);
    s.simulations =
        dict.found("simulations") ? caseRelative(dict, studyDirectory, "simulations") : studyDirectory;
    std::vector<fs::path> cases;
    for (const TestCondition& c : s.conditions) cases.push_back(c.targetCase);
    s.seeds =
        readSeeds(dict, cases, 2,
                  "the model's own scatter is measured over several Voronoi seeds (4 or more recommended)");

    if (!dict.isDict("baseline"))
        throw UserError(dict.fileName() +
                        ": 'baseline { tensileStrength { entry bond/voronoiQNSC/tensileStrength; range (10e6 "
                        "60e6); } }' is "
                        "required: the parameters calibrated as usual, re-fitted with each candidate effect "
                        "('baseline { }' tests the case as it is calibrated)");
    for (const Entry& e : dict.subDict("baseline").entries()) {
        if (!e.isDict())
            throw UserError(e.keywordLocation.str() + ": baseline parameter '" + e.keyword +
                            "' must be a dictionary { entry ...; range (low high); }");
        const Dictionary& d = *e.dict;
        checkKnownEntries(d, {"file", "entry", "unit", "range", "relativeStep"});
        BaselineParameter b;
        b.where.name = e.keyword;
        b.where.file = d.getOrDefault<std::string>("file", "constant/rockProperties");
        b.where.entry = d.get<std::string>("entry");
        b.where.unit = d.getOrDefault<std::string>("unit", "-");
        const auto range = d.get<std::vector<double>>("range");
        if (range.size() != 2 || !(range[0] < range[1]))
            throw UserError(d.location("range").str() + ": range must be (low high) with low < high");
        b.where.low = range[0];
        b.where.high = range[1];
        b.relativeStep = d.getScalarOrDefault("relativeStep", 0.1, Bounds::open(0, 1));
        requireCaseEntry(d.location("entry").str(), cases, b.where.file, b.where.entry);
        s.baseline.push_back(b);
    }
    s.tied = readTied(dict, s.baseline);

    s.effects = dict.get<std::vector<std::string>>("effects");
    if (s.effects.empty())
        throw UserError(dict.location("effects").str() +
                        ": no candidate effects; name some of the library's");
    const Dictionary* settings = dict.isDict("effectSettings") ? &dict.subDict("effectSettings") : nullptr;
    for (const std::string& name : s.effects) {
        const EffectDescriptor& d = findEffect(name, dict.location("effects").str());
        for (const std::string& fixed : d.fixedEntries) {
            const std::string key = name + "/" + fixed;
            if (!settings || !settings->found(key))
                throw UserError(
                    dict.fileName() + ": effectSettings/" + key + " is missing: effect '" + name +
                    "' needs '" + fixed +
                    "' (docs/explainGap.md lists what each effect needs, e.g. "
                    "contactCrumbling depth: about one cell size in m; seatingOffset closureForce: "
                    "about 10 % of the failure load in N; bondStrengthScatter seed: a whole number)");
            s.effectFixed[name][fixed] = valueText(settings->entry(key));
        }
    }
    if (dict.found("features")) {
        for (const std::string& f : dict.get<std::vector<std::string>>("features")) {
            const int index = featureIndex(f);
            if (index < 0)
                throw UserError(
                    dict.location("features").str() + ": unknown feature '" + f +
                    "'; known: peakForce peakForceSpread peakDisplacement secantStiffness toeIndex "
                    "softening");
            s.requestedFeatures.push_back(index);
        }
    }
    if (dict.found("statistics")) {
        const std::string statistics = dict.get<std::string>("statistics");
        if (statistics == "median")
            s.statistics = Statistics::median;
        else if (statistics != "mean")
            throw UserError(dict.location("statistics").str() + ": statistics '" + statistics +
                            "' is not known; use mean (means and standard deviation) or median (medians "
                            "and the median absolute deviation, robust to an odd specimen)");
    }
    if (dict.found("response")) s.responseFile = dict.get<std::string>("response");
    s.heldOutFraction = dict.getScalarOrDefault("heldOut", 0.5, Bounds::open(0, 1));
    s.minimumGapReduction = dict.getScalarOrDefault("minimumGapReduction", 0.3, Bounds::open(0, 1));
    s.significance = dict.getScalarOrDefault("significance", 0.01, Bounds::open(0, 0.5));
    s.maxPairs = readPairs(dict, s.maxPairs);
    return s;
}

calibration::CalibrationStudy TwinStudy::runStudy() const
{
    return demRunStudy(directory, dictionary, targetCase, prepareCommand, command, jobs, scheduler, seeds,
                       responseFile);
}

const std::vector<std::string>& twinDataDictEntries()
{
    static const std::vector<std::string> entries = {"case",      "prepare", "command",  "jobs",
                                                     "scheduler", "slurm",   "seeds",    "effects",
                                                     "noise",     "output",  "material", "response"};
    return entries;
}

TwinStudy readTwinStudy(const fs::path& studyDirectory)
{
    TwinStudy s;
    s.directory = studyDirectory;
    s.dictionary = studyDirectory / "system/twinDataDict";
    if (!fs::is_regular_file(s.dictionary))
        throw UserError("missing '" + s.dictionary.string() +
                        "': a twin-data study is a directory with system/twinDataDict (docs/explainGap.md)");
    const Dictionary dict = Dictionary::readFile(s.dictionary);
    checkKnownEntries(dict, twinDataDictEntries());
    checkKnownSubEntries(dict, "noise", {"force", "displacement", "seed"});
    s.targetCase = existingCase(dict, studyDirectory);
    readCommands(dict, s.prepareCommand, s.command, s.jobs, s.scheduler);
    s.seeds = readSeeds(dict, {s.targetCase}, 1, "one Voronoi seed per synthetic specimen");
    if (dict.isDict("effects")) {
        const Dictionary& effects = dict.subDict("effects");
        ModelEffects::read(effects);  // checks names and values now
        for (const Entry& e : effects.entries()) {
            s.hiddenEffects.push_back(e.keyword);
            s.hiddenEffectsText += toString(e, 0) + "\n";
        }
    }
    const Dictionary& noise = dict.subDict("noise");
    s.forceNoise = noise.getScalar("force", Bounds::closed(0, 0.5));
    s.displacementNoise = noise.getScalar("displacement", Bounds::closed(0, 1e-3));
    s.noiseSeed = noise.get<std::uint64_t>("seed");
    s.output = dict.get<std::string>("output");
    s.material = dict.getOrDefault<std::string>("material", "granite");
    if (dict.found("response")) s.responseFile = dict.get<std::string>("response");
    return s;
}

}  // namespace rockfrac::explain
