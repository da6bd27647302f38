#include "core/selector.hpp"

#include <algorithm>

namespace rockfrac {

void requireKnownEntries(const Dictionary& dict, const std::vector<std::string>& known,
                         const std::string& hint)
{
    for (const Entry& e : dict.entries()) {
        if (std::find(known.begin(), known.end(), e.keyword) != known.end()) continue;
        std::string list;
        for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
        throwDictionaryError(e.keywordLocation,
                             "unknown entry '" + e.keyword + "' in dictionary '" + dict.name() + "'" +
                                 (hint.empty() ? "" : " (" + hint + ")"),
                             list.empty() ? "no entries" : "one of: " + list);
    }
}

}  // namespace rockfrac
