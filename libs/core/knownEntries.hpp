#pragma once
// Unknown entries of a case dictionary: a misspelt entry (`writeIntervall 2e-5;`) would
// otherwise do nothing and nobody would say so. Each reader declares the entries it reads
// (a list next to where it reads them) and checks its dictionary against that list:
//
//     const std::vector<std::string>& controlDictEntries();  // beside the reader
//     checkKnownEntries(controlDict, controlDictEntries());
//
// By default an unknown entry is a warning, one line on stderr naming file:line, the entry,
// the nearest known one ("did you mean 'writeInterval'?") and that it is ignored; with the
// common option -strict it is the usual UserError (exit 1). requireKnownEntries
// (core/selector.hpp) stays an error always: the models' coefficient sub-dictionaries.
// `caseDict -check` checks a whole case against the same declarations.
#include <string>
#include <vector>

#include "core/dictionary.hpp"

namespace rockfrac {

// Set by the application shell from -strict (default: warnings). `program` prefixes warnings.
void setStrictEntries(bool strict, const std::string& program = "");
bool strictEntries();

// One entry of a dictionary that its reader does not know.
struct UnknownEntry {
    std::string keyword;
    SourceLocation where;  // of the keyword
    std::string nearest;   // the nearest known keyword, "" when none is close
    // "file:line:column: unknown entry 'writeIntervall' in dictionary 'controlDict'
    // (did you mean 'writeInterval'?)"
    std::string describe(const std::string& dictionaryName) const;
};

// The entries of `dict` (its own level, not its sub-dictionaries) that `known` does not name.
std::vector<UnknownEntry> unknownEntries(const Dictionary& dict, const std::vector<std::string>& known);

// Warn about each unknown entry of `dict` on stderr, or under -strict throw a UserError for
// the first one. Returns the number of unknown entries (warned about).
std::size_t checkKnownEntries(const Dictionary& dict, const std::vector<std::string>& known);

// When `dict` has `key` as a sub-dictionary, check it against `known`.
void checkKnownSubEntries(const Dictionary& dict, const std::string& key,
                          const std::vector<std::string>& known);

// `base` followed by `more`: a reader's entries built from a shared list.
std::vector<std::string> withEntries(std::vector<std::string> base, const std::vector<std::string>& more);

}  // namespace rockfrac
