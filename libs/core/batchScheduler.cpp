#include "core/batchScheduler.hpp"

#include <sstream>

#include "core/error.hpp"
#include "core/knownEntries.hpp"
#include "core/subprocess.hpp"

namespace rockfrac {

namespace {

const std::vector<std::string>& slurmEntries()
{
    static const std::vector<std::string> entries = {"partition", "time",       "cpusPerTask",
                                                     "account",   "maxRunning", "extra"};
    return entries;
}

// The text of a one-value entry (word, string or number as written).
std::string slurmSingleText(const Dictionary& dict, const std::string& key, const std::string& example)
{
    const Entry& entry = dict.entry(key);
    if (entry.isDict() || entry.values.size() != 1 || entry.values[0].isList() ||
        entry.values[0].text.empty())
        throw UserError(dict.location(key).str() + ": slurm/" + key + " must be one value, e.g. '" + key +
                        " " + example + ";'");
    return entry.values[0].text;
}

// Slurm's --time formats: minutes, MM:SS, HH:MM:SS, D-HH, D-HH:MM, D-HH:MM:SS.
bool isSlurmTime(const std::string& text)
{
    const std::size_t dash = text.find('-');
    if (dash != std::string::npos && (dash == 0 || text.find('-', dash + 1) != std::string::npos))
        return false;
    const std::string clock = dash == std::string::npos ? text : text.substr(dash + 1);
    if (dash != std::string::npos &&
        text.substr(0, dash).find_first_not_of("0123456789") != std::string::npos)
        return false;
    int colons = 0;
    bool digitBefore = false;
    for (char c : clock) {
        if (c == ':') {
            if (!digitBefore) return false;
            ++colons;
            digitBefore = false;
        } else if (c >= '0' && c <= '9') {
            digitBefore = true;
        } else {
            return false;
        }
    }
    return digitBefore && colons <= 2;
}

std::vector<std::string> slurmSplitAtBlanks(const std::string& text)
{
    std::istringstream in(text);
    std::vector<std::string> words;
    for (std::string word; in >> word;) words.push_back(word);
    return words;
}

SlurmSettings readSlurm(const Dictionary& dict)
{
    checkKnownEntries(dict, slurmEntries());
    SlurmSettings s;
    if (dict.found("partition")) s.partition = slurmSingleText(dict, "partition", "short");
    if (dict.found("account")) s.account = slurmSingleText(dict, "account", "myproject");
    if (dict.found("time")) {
        s.time = slurmSingleText(dict, "time", "00:30:00");
        if (!isSlurmTime(s.time))
            throw UserError(dict.location("time").str() + ": slurm/time '" + s.time +
                            "' is not a Slurm time limit; give minutes, MM:SS, HH:MM:SS or D-HH:MM:SS, "
                            "e.g. 'time 00:30:00;'");
    }
    s.cpusPerTask = static_cast<int>(dict.getScalarOrDefault("cpusPerTask", 1, Bounds::closed(1, 4096)));
    if (dict.found("cpusPerTask") && dict.getScalar("cpusPerTask", Bounds::any()) != s.cpusPerTask)
        throw UserError(dict.location("cpusPerTask").str() + ": slurm/cpusPerTask must be a whole number");
    s.maxRunning = static_cast<int>(dict.getScalarOrDefault("maxRunning", 0, Bounds::closed(1, 1e6)));
    if (dict.found("extra")) {
        s.extra = slurmSingleText(dict, "extra", "\"--qos=normal\"");
        s.extraOptions = slurmSplitAtBlanks(s.extra);
        for (const std::string& option : s.extraOptions)
            for (const char* own :
                 {"--array", "-a", "--output", "-o", "--error", "-e", "--parsable", "--wrap"})
                if (option == own || option.rfind(std::string(own) + "=", 0) == 0)
                    throw UserError(dict.location("extra").str() + ": slurm/extra holds '" + option +
                                    "', which runCases sets itself; remove it (the members are the array, "
                                    "their logs are in their directories)");
    }
    return s;
}

std::string slurmQuoted(const std::string& text)
{
    std::string q = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') q += '\\';
        q += c;
    }
    return q + "\"";
}

}  // namespace

const std::vector<std::string>& schedulerEntries()
{
    static const std::vector<std::string> entries = {"scheduler", "slurm"};
    return entries;
}

SchedulerSettings readScheduler(const Dictionary& dict)
{
    SchedulerSettings settings;
    if (dict.found("scheduler")) settings.type = dict.getWord("scheduler", {"local", "slurm"});
    const Entry* slurm = dict.findEntry("slurm");
    if (!settings.isSlurm()) {
        if (slurm)
            throw UserError(slurm->keywordLocation.str() +
                            ": 'slurm { ... }' is given but the scheduler is local; add 'scheduler slurm;' "
                            "to run the members through Slurm, or remove the slurm entry");
        return settings;
    }
    if (slurm && !slurm->isDict())
        throw UserError(slurm->keywordLocation.str() +
                        ": 'slurm' must be a dictionary of sbatch settings, e.g. 'slurm { partition short; "
                        "time 00:30:00; }'");
    if (slurm) settings.slurm = readSlurm(*slurm->dict);
    return settings;
}

void requireSlurmCommands()
{
    for (const char* tool : {"sbatch", "squeue", "scancel"})
        if (!findExecutable(tool))
            throw UserError(std::string("scheduler slurm: '") + tool +
                            "' is not on PATH; run where Slurm's commands are (a login node, or inside an "
                            "allocation), or set 'scheduler local;' to run the members on this machine");
}

std::string schedulerText(const SchedulerSettings& settings)
{
    if (!settings.isSlurm()) return "";
    const SlurmSettings& s = settings.slurm;
    std::ostringstream out;
    out << "scheduler  slurm;\nslurm\n{\n";
    if (!s.partition.empty()) out << "    partition   " << slurmQuoted(s.partition) << ";\n";
    if (!s.time.empty()) out << "    time        " << s.time << ";\n";
    out << "    cpusPerTask " << s.cpusPerTask << ";\n";
    if (!s.account.empty()) out << "    account     " << slurmQuoted(s.account) << ";\n";
    if (s.maxRunning > 0) out << "    maxRunning  " << s.maxRunning << ";\n";
    if (!s.extra.empty()) out << "    extra       " << slurmQuoted(s.extra) << ";\n";
    out << "}\n";
    return out.str();
}

}  // namespace rockfrac
