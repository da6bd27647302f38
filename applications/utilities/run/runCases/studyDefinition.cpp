#include "studyDefinition.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "calibration/calibrationStudy.hpp"
#include "core/dictionary.hpp"
#include "core/dictionaryEditor.hpp"
#include "core/error.hpp"
#include "core/knownEntries.hpp"
#include "core/textFile.hpp"
#include "stats/design.hpp"

namespace rockfrac::runcases {

namespace fs = std::filesystem;

namespace {

// The file and entry that `owner` (a parameter or the seeds) sets in each member:
// both must exist in the template, so that a typo cannot add a stray entry.
EntryTarget readTarget(const Dictionary& dict, const std::string& owner, const fs::path& templateCase)
{
    EntryTarget target{dict.get<std::string>("file"), dict.get<std::string>("entry")};
    const fs::path file = templateCase / target.file;
    if (!fs::is_regular_file(file))
        throw UserError(dict.location("file").str() + ": " + owner + ": file '" + target.file.string() +
                        "' is not in the template case '" + templateCase.string() +
                        "'; give a path relative to the template, e.g. constant/rockProperties");
    if (!hasTextEntry(readFileText(file), target.entry, file.string()))
        throw UserError(dict.location("entry").str() + ": " + owner + ": '" + file.string() +
                        "' has no entry '" + target.entry +
                        "'; add it to the template (runCases only changes existing entries)");
    return target;
}

// The values of a `values ( ... )` list as written: numbers or words.
std::vector<std::string> readValueTexts(const Dictionary& dict, const std::string& key)
{
    const Entry& entry = dict.entry(key);
    if (entry.values.size() != 1 || !entry.values[0].isList())
        throw UserError(entry.valueLocation.str() + ": " + key + " must be a list, e.g. '" + key +
                        " (40e9 46e9 52e9);'");
    std::vector<std::string> texts;
    for (const Value& item : entry.values[0].items) {
        if (item.isList())
            throw UserError(item.where.str() + ": " + key + " holds a list; expected numbers or words");
        texts.push_back(item.isString() ? "\"" + item.text + "\"" : item.text);  // written back as it came
    }
    return texts;
}

Parameter readParameter(const Entry& entry, const fs::path& templateCase)
{
    if (!entry.isDict())
        throw UserError(entry.keywordLocation.str() + ": parameter '" + entry.keyword +
                        "' must be a dictionary, e.g. '" + entry.keyword +
                        " { file constant/rockProperties; entry bond/voronoiQNSC/E; values (40e9 46e9); }'");
    const Dictionary& dict = *entry.dict;
    checkKnownEntries(dict, {"file", "entry", "unit", "values", "range"});
    Parameter parameter;
    parameter.name = entry.keyword;
    parameter.target = readTarget(dict, "parameter '" + entry.keyword + "'", templateCase);
    parameter.unit = dict.getOrDefault<std::string>("unit", "-");
    const bool hasValues = dict.found("values"), hasRange = dict.found("range");
    if (hasValues == hasRange)
        throw UserError(
            dict.endLocation().str() + ": parameter '" + entry.keyword +
            "' needs either 'values (a b c);' (full factorial) or 'range (low high);' (Latin hypercube)");
    if (hasValues) {
        parameter.values = readValueTexts(dict, "values");
        return parameter;
    }
    const auto range = dict.get<std::vector<double>>("range");
    if (range.size() != 2 || !(range[0] < range[1]))
        throw UserError(dict.location("range").str() +
                        ": range must be two numbers (low high) with low < high");
    parameter.isRange = true;
    parameter.low = range[0];
    parameter.high = range[1];
    return parameter;
}

Result readResult(const Entry& entry)
{
    if (!entry.isDict())
        throw UserError(entry.keywordLocation.str() + ": result '" + entry.keyword +
                        "' must be a dictionary, e.g. '" + entry.keyword +
                        " { file \"postProcessing/summary/0/summary.dat\"; column peakForce; }'");
    const Dictionary& dict = *entry.dict;
    checkKnownEntries(dict, {"file", "unit", "column", "select", "entry"});
    Result result;
    result.name = entry.keyword;
    result.file = dict.get<std::string>("file");
    result.unit = dict.getOrDefault<std::string>("unit", "");
    if (dict.found("column") == dict.found("entry"))
        throw UserError(dict.endLocation().str() + ": result '" + entry.keyword +
                        "' needs either 'column <name>;' (a .dat file) or 'entry <key>;' (a dictionary)");
    if (dict.found("column")) {
        result.column = dict.get<std::string>("column");
        result.select =
            dict.found("select") ? dict.getWord("select", {"last", "first", "max", "min"}) : "last";
    } else {
        result.entry = dict.get<std::string>("entry");
    }
    return result;
}

// Latin-hypercube values are rounded to 6 significant digits: the value a
// member runs with is exactly the value written in its files and the table.
std::string rangeValue(const Parameter& parameter, double unitValue)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", parameter.low + unitValue * (parameter.high - parameter.low));
    return formatNumber(std::stod(text));
}

void readDesign(const Dictionary& dict, Study& study)
{
    bool anyRange = false;
    for (const Parameter& p : study.parameters) anyRange = anyRange || p.isRange;
    study.design = dict.found("design") ? dict.getWord("design", {"fullFactorial", "latinHypercube"})
                                        : (anyRange ? "latinHypercube" : "fullFactorial");
    if (study.design == "fullFactorial" && anyRange)
        throw UserError(dict.location("design").str() +
                        ": a parameter has a range; ranges are sampled by 'design latinHypercube;'");
    if (study.design == "latinHypercube") {
        if (!anyRange)
            throw UserError(dict.location("design").str() +
                            ": latinHypercube samples 'range (low high)' parameters, and there is none");
        study.samples = static_cast<std::size_t>(dict.getScalar("samples", Bounds::nonNegative()));
        study.designSeed = dict.getOrDefault<std::uint64_t>("seed", 1);
    }
}

std::string describeRunCount(const Study& study)
{
    std::string text;
    for (const Parameter& p : study.parameters)
        if (!p.isRange) text += " " + p.name + ": " + std::to_string(p.values.size()) + " values;";
    if (study.design == "latinHypercube") text += " samples: " + std::to_string(study.samples) + ";";
    if (study.seedTarget) text += " seeds: " + std::to_string(study.seeds.size()) + ";";
    return text;
}

std::string memberId(std::size_t index, std::size_t count)
{
    const std::size_t width = std::max<std::size_t>(4, std::to_string(count - 1).size());
    std::string id = std::to_string(index);
    return std::string(width - std::min(width, id.size()), '0') + id;
}

// Full factorial over the value lists × Latin hypercube over the ranges × seeds.
void expandMembers(Study& study)
{
    std::vector<std::size_t> levels;
    std::vector<std::size_t> rangeDimension(study.parameters.size(), 0);
    std::size_t nRanges = 0;
    for (std::size_t j = 0; j < study.parameters.size(); ++j) {
        if (study.parameters[j].isRange)
            rangeDimension[j] = nRanges++;
        else
            levels.push_back(study.parameters[j].values.size());
    }
    const auto factorial = stats::fullFactorial(levels);
    const auto hypercube = study.design == "latinHypercube"
                               ? stats::latinHypercube(study.samples, nRanges, study.designSeed)
                               : std::vector<std::vector<double>>(1);
    const std::vector<std::optional<std::string>> seeds =
        study.seedTarget ? std::vector<std::optional<std::string>>(study.seeds.begin(), study.seeds.end())
                         : std::vector<std::optional<std::string>>(1);
    for (const auto& levelIndices : factorial)
        for (const auto& point : hypercube)
            for (const auto& seed : seeds) {
                MemberDesign member;
                std::size_t factor = 0;
                for (std::size_t j = 0; j < study.parameters.size(); ++j) {
                    const Parameter& p = study.parameters[j];
                    member.values.push_back(p.isRange ? rangeValue(p, point[rangeDimension[j]])
                                                      : p.values[levelIndices[factor++]]);
                }
                member.seed = seed;
                study.members.push_back(member);
            }
    for (std::size_t i = 0; i < study.members.size(); ++i)
        study.members[i].id = memberId(i, study.members.size());
}

}  // namespace

Study readStudy(const fs::path& studyDirectory)
{
    Study study;
    study.directory = studyDirectory;
    study.dictionary = studyDirectory / "system/runCasesDict";
    if (!fs::is_regular_file(study.dictionary))
        throw UserError("no '" + study.dictionary.string() +
                        "'; a study directory holds system/runCasesDict (see runCases -help)");
    const Dictionary dict = Dictionary::readFile(study.dictionary);
    checkKnownEntries(dict, calibration::runCasesDictEntries());
    study.templateCase = studyDirectory / dict.get<std::string>("template");
    if (!fs::is_directory(study.templateCase))
        throw UserError(dict.location("template").str() + ": template case '" + study.templateCase.string() +
                        "' does not exist; give a case directory relative to the study");
    study.command = dict.get<std::string>("command");
    study.jobs = static_cast<int>(dict.getScalarOrDefault("jobs", 1, Bounds::atLeast(1)));
    study.scheduler = readScheduler(dict);
    if (dict.found("parameters"))
        for (const Entry& entry : dict.subDict("parameters").entries())
            study.parameters.push_back(readParameter(entry, study.templateCase));
    if (dict.found("seeds")) {
        const Dictionary& seeds = dict.subDict("seeds");
        checkKnownEntries(seeds, {"file", "entry", "values"});
        study.seedTarget = readTarget(seeds, "seeds", study.templateCase);
        study.seeds = readValueTexts(seeds, "values");
    }
    if (dict.found("results"))
        for (const Entry& entry : dict.subDict("results").entries())
            study.results.push_back(readResult(entry));
    readDesign(dict, study);
    expandMembers(study);
    if (study.members.empty())
        throw UserError(study.dictionary.string() + ": the design has no runs (" + describeRunCount(study) +
                        " ); give every parameter at least one value");
    return study;
}

}  // namespace rockfrac::runcases
