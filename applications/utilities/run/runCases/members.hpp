#pragma once
// The members of a study on disk: each is <study>/members/<id>, a copy of the
// template with the member's parameter values written in (by the dictionary
// editor, which keeps the rest of every file), and a runCases.status file that
// says how far it got. The status file is what makes runCases resumable.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/textTable.hpp"
#include "studyDefinition.hpp"

namespace rockfrac::runcases {

// pending: made, not run (or interrupted); running: started by a runCases that
// may have died; submitted: in a Slurm job array (slurmJob "<array>_<index>");
// done: the command succeeded and every result was read; failed.
struct MemberStatus {
    std::string state = "pending";
    std::string slurmJob;
    int exitCode = -1;
    std::string message;
    std::map<std::string, std::string> parameters;  // name -> value, as the member was made
    std::optional<std::string> seed;
};

std::optional<MemberStatus> readStatus(const Study& study, const MemberDesign& member);
void writeStatus(const Study& study, const MemberDesign& member, const std::string& state, int exitCode = -1,
                 const std::string& message = "", const std::string& slurmJob = "");

// UserError when a done member was made with other values than the design now
// gives: its results would be mislabelled.
void checkStatusMatchesDesign(const Study& study, const MemberDesign& member, const MemberStatus& status);

// A fresh member directory from the template, with its values set; state pending.
void prepareMember(const Study& study, const MemberDesign& member);

// "E=4e10 x=1 seed=3": how log lines name a member's values.
std::string describeValues(const Study& study, const MemberDesign& member);

// The value of every result of a member, formatted for the table; UserError
// naming the file when one cannot be read. `units` receives the units found.
std::vector<std::string> collectResults(const Study& study, const MemberDesign& member,
                                        std::vector<std::string>& units);

// The results table from the members' states and results. Results are read
// once per member and kept in `collected` (id -> values); a done member whose
// results cannot be read gets "-" and a line on `warnings`.
class ResultsTable {
public:
    explicit ResultsTable(const Study& study) : study_(study) {}
    // Forget a member's results (it is run again).
    void forget(const std::string& id) { collected_.erase(id); }
    TextTable build(std::vector<std::string>& warnings);
    void write(std::vector<std::string>& warnings);

private:
    const Study& study_;
    std::map<std::string, std::vector<std::string>> collected_;
    std::vector<std::string> resultUnits_;
};

}  // namespace rockfrac::runcases
