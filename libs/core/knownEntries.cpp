#include "core/knownEntries.hpp"

#include <algorithm>
#include <iostream>

#include "core/error.hpp"
#include "core/selector.hpp"

namespace rockfrac {

namespace {

struct EntryCheck {
    bool strict = false;
    std::string program;
};

EntryCheck& entryCheck()
{
    static EntryCheck check;
    return check;
}

}  // namespace

void setStrictEntries(bool strict, const std::string& program)
{
    entryCheck().strict = strict;
    entryCheck().program = program;
}

bool strictEntries()
{
    return entryCheck().strict;
}

std::string UnknownEntry::describe(const std::string& dictionaryName) const
{
    return where.str() + ": unknown entry '" + keyword + "' in dictionary '" + dictionaryName + "'" +
           (nearest.empty() ? "" : " (did you mean '" + nearest + "'?)");
}

std::vector<UnknownEntry> unknownEntries(const Dictionary& dict, const std::vector<std::string>& known)
{
    std::vector<UnknownEntry> unknown;
    for (const Entry& e : dict.entries())
        if (std::find(known.begin(), known.end(), e.keyword) == known.end())
            unknown.push_back({e.keyword, e.keywordLocation, nearestKeyword(e.keyword, known)});
    return unknown;
}

std::size_t checkKnownEntries(const Dictionary& dict, const std::vector<std::string>& known)
{
    const std::vector<UnknownEntry> unknown = unknownEntries(dict, known);
    for (const UnknownEntry& u : unknown) {
        const std::string text = u.describe(dict.name());
        if (entryCheck().strict)
            throw UserError(text + "; correct or remove it (-strict refuses unknown entries)");
        std::cout << std::flush;
        std::cerr << (entryCheck().program.empty() ? "" : entryCheck().program + ": ") << "warning: " << text
                  << " is ignored; correct or remove it (-strict makes this an error)" << std::endl;
    }
    return unknown.size();
}

void checkKnownSubEntries(const Dictionary& dict, const std::string& key,
                          const std::vector<std::string>& known)
{
    if (dict.isDict(key)) checkKnownEntries(dict.subDict(key), known);
}

std::vector<std::string> withEntries(std::vector<std::string> base, const std::vector<std::string>& more)
{
    base.insert(base.end(), more.begin(), more.end());
    return base;
}

}  // namespace rockfrac
