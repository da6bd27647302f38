#include "core/selector.hpp"

#include <algorithm>
#include <cctype>

namespace rockfrac {

namespace {

// Levenshtein distance, case-insensitive: how far a misspelt keyword is from a known one.
std::size_t editDistance(const std::string& a, const std::string& b)
{
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                              std::tolower(static_cast<unsigned char>(b[j - 1]));
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string nearestKeyword(const std::string& word, const std::vector<std::string>& known)
{
    std::string best;
    std::size_t best_distance = std::max<std::size_t>(2, word.size() / 4) + 1;
    for (const std::string& k : known) {
        const std::size_t d = editDistance(word, k);
        if (d < best_distance) {
            best = k;
            best_distance = d;
        }
    }
    return best;
}

void requireKnownEntries(const Dictionary& dict, const std::vector<std::string>& known,
                         const std::string& hint)
{
    for (const Entry& e : dict.entries()) {
        if (std::find(known.begin(), known.end(), e.keyword) != known.end()) continue;
        std::string list;
        for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
        const std::string nearest = nearestKeyword(e.keyword, known);
        throwDictionaryError(e.keywordLocation,
                             "unknown entry '" + e.keyword + "' in dictionary '" + dict.name() + "'" +
                                 (nearest.empty() ? "" : " (did you mean '" + nearest + "'?)") +
                                 (hint.empty() ? "" : " (" + hint + ")"),
                             list.empty() ? "no entries" : "one of: " + list);
    }
}

}  // namespace rockfrac
