#include "members.hpp"

#include <algorithm>

#include "core/atomicFile.hpp"
#include "core/dictionary.hpp"
#include "core/dictionaryEditor.hpp"
#include "core/error.hpp"
#include "io/timeSeries.hpp"

namespace rockfrac::runcases {

namespace fs = std::filesystem;

namespace {

fs::path statusPath(const Study& study, const MemberDesign& member)
{
    return study.memberDirectory(member.id) / "runCases.status";
}

std::string quoted(const std::string& text)
{
    std::string out = "\"";
    for (char c : text) out += (c == '"' ? std::string("\\\"") : std::string(1, c));
    return out + "\"";
}

double selectRow(const std::vector<double>& column, const std::string& select)
{
    if (select == "first") return column.front();
    if (select == "max") return *std::max_element(column.begin(), column.end());
    if (select == "min") return *std::min_element(column.begin(), column.end());
    return column.back();
}

std::string collectResult(const fs::path& memberDirectory, const Result& result, std::string& unit)
{
    const fs::path file = memberDirectory / result.file;
    if (!fs::exists(file))
        throw UserError("result '" + result.name + "': no file '" + file.string() +
                        "' (did the command write it?)");
    if (!result.entry.empty()) {
        const Dictionary dict = Dictionary::readFile(file);
        return formatNumber(dict.getScalar(result.entry, Bounds::any()));
    }
    const TimeSeries series = readTimeSeries(file);
    const int c = series.column(result.column);
    if (c < 0)
        throw UserError("result '" + result.name + "': '" + file.string() + "' has no column '" +
                        result.column + "'");
    if (series.rows.empty())
        throw UserError("result '" + result.name + "': '" + file.string() + "' has no rows");
    unit = series.units[c];
    return formatNumber(selectRow(series.values(result.column), result.select));
}

}  // namespace

std::optional<MemberStatus> readStatus(const Study& study, const MemberDesign& member)
{
    const fs::path file = statusPath(study, member);
    if (!fs::exists(file)) return std::nullopt;
    const Dictionary dict = Dictionary::readFile(file);
    MemberStatus status;
    status.state = dict.getWord("state", {"pending", "running", "submitted", "done", "failed"});
    status.slurmJob = dict.getOrDefault<std::string>("slurmJob", "");
    status.exitCode = dict.getOrDefault<int>("exitCode", -1);
    status.message = dict.getOrDefault<std::string>("message", "");
    if (dict.isDict("parameters"))
        for (const Entry& entry : dict.subDict("parameters").entries())
            status.parameters[entry.keyword] = dict.get<std::string>("parameters/" + entry.keyword);
    if (dict.found("seed")) status.seed = dict.get<std::string>("seed");
    return status;
}

void writeStatus(const Study& study, const MemberDesign& member, const std::string& state, int exitCode,
                 const std::string& message, const std::string& slurmJob)
{
    writeFileAtomically(statusPath(study, member), [&](std::ostream& out) {
        out << "FoamFile { format ascii; class dictionary; object runCases.status; }\n"
            << "// Written by runCases: the state of this member of the study.\n"
            << "state       " << state << ";\n"
            << "exitCode    " << exitCode << ";\n";
        if (!message.empty()) out << "message     " << quoted(message) << ";\n";
        if (!slurmJob.empty()) out << "slurmJob    " << quoted(slurmJob) << ";\n";
        out << "parameters\n{\n";
        for (std::size_t j = 0; j < study.parameters.size(); ++j)
            out << "    " << study.parameters[j].name << " " << quoted(member.values[j]) << ";\n";
        out << "}\n";
        if (member.seed) out << "seed        " << quoted(*member.seed) << ";\n";
    });
}

void checkStatusMatchesDesign(const Study& study, const MemberDesign& member, const MemberStatus& status)
{
    auto mismatch = [&](const std::string& name, const std::string& was, const std::string& now) {
        throw UserError(statusPath(study, member).string() + ": member " + member.id + " was run with " +
                        name + " = " + was + ", but " + study.dictionary.string() + " now gives " + now +
                        "; remove '" + study.membersDirectory().string() + "' to start the study again");
    };
    for (std::size_t j = 0; j < study.parameters.size(); ++j) {
        const auto it = status.parameters.find(study.parameters[j].name);
        const std::string was = it == status.parameters.end() ? "nothing" : it->second;
        if (was != member.values[j]) mismatch(study.parameters[j].name, was, member.values[j]);
    }
    if (status.seed.value_or("none") != member.seed.value_or("none"))
        mismatch("seed", status.seed.value_or("none"), member.seed.value_or("none"));
}

void prepareMember(const Study& study, const MemberDesign& member)
{
    const fs::path directory = study.memberDirectory(member.id);
    fs::remove_all(directory);
    fs::create_directories(directory.parent_path());
    fs::copy(study.templateCase, directory, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
    for (std::size_t j = 0; j < study.parameters.size(); ++j) {
        const Parameter& p = study.parameters[j];
        setEntryInFile(directory / p.target.file, p.target.entry, member.values[j],
                       "runCases parameter " + p.name);
    }
    if (member.seed)
        setEntryInFile(directory / study.seedTarget->file, study.seedTarget->entry, *member.seed,
                       "runCases seed");
    writeStatus(study, member, "pending");
}

std::string describeValues(const Study& study, const MemberDesign& member)
{
    std::string text;
    for (std::size_t j = 0; j < study.parameters.size(); ++j)
        text += (j ? " " : "") + study.parameters[j].name + "=" + member.values[j];
    if (member.seed) text += std::string(text.empty() ? "" : " ") + "seed=" + *member.seed;
    return text;
}

std::vector<std::string> collectResults(const Study& study, const MemberDesign& member,
                                        std::vector<std::string>& units)
{
    units.resize(study.results.size());
    std::vector<std::string> values;
    for (std::size_t k = 0; k < study.results.size(); ++k)
        values.push_back(collectResult(study.memberDirectory(member.id), study.results[k], units[k]));
    return values;
}

TextTable ResultsTable::build(std::vector<std::string>& warnings)
{
    TextTable table;
    table.names.push_back("member");
    for (const Parameter& p : study_.parameters) table.names.push_back(p.name), table.units.push_back(p.unit);
    table.units.insert(table.units.begin(), "-");
    if (study_.seedTarget) table.names.push_back("seed"), table.units.push_back("-");
    resultUnits_.resize(study_.results.size());
    for (const MemberDesign& member : study_.members) {
        const std::optional<MemberStatus> status = readStatus(study_, member);
        const std::string state = status ? status->state : "pending";
        std::vector<std::string> row{member.id};
        row.insert(row.end(), member.values.begin(), member.values.end());
        if (member.seed) row.push_back(*member.seed);
        std::vector<std::string> results(study_.results.size(), "-");
        if (state == "done") {
            if (!collected_.count(member.id)) {
                try {
                    std::vector<std::string> units;
                    collected_[member.id] = collectResults(study_, member, units);
                    for (std::size_t k = 0; k < units.size(); ++k)
                        if (resultUnits_[k].empty()) resultUnits_[k] = units[k];
                } catch (const UserError& e) {
                    warnings.push_back("member " + member.id + ": " + e.what());
                    collected_[member.id] = results;
                }
            }
            results = collected_[member.id];
        }
        row.insert(row.end(), results.begin(), results.end());
        row.push_back(state);
        table.rows.push_back(row);
    }
    for (std::size_t k = 0; k < study_.results.size(); ++k) {
        table.names.push_back(study_.results[k].name);
        const std::string& unit = study_.results[k].unit.empty() ? resultUnits_[k] : study_.results[k].unit;
        table.units.push_back(unit.empty() ? "-" : unit);
    }
    table.names.push_back("status");
    table.units.push_back("-");
    return table;
}

void ResultsTable::write(std::vector<std::string>& warnings)
{
    writeTextTable(study_.resultsTable(), build(warnings));
}

}  // namespace rockfrac::runcases
