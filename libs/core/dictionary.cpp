// Dictionary lookups: path resolution, typed conversion and range checks.
// Parsing is in dictionaryParser.cpp, printing in dictionaryFormat.cpp.
#include "core/dictionary.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace rockfrac {

// ---- Values and entries -------------------------------------------------

std::string Value::describe() const
{
    switch (kind) {
        case Kind::number:
            return "a number (" + text + ")";
        case Kind::string:
            return "a string (\"" + text + "\")";
        case Kind::list:
            return "a list of " + std::to_string(items.size()) + " values";
        case Kind::word:
            break;
    }
    return "a word ('" + text + "')";
}

Entry::Entry() = default;
Entry::Entry(Entry&& other) noexcept = default;
Entry& Entry::operator=(Entry&& other) noexcept = default;
Entry::~Entry() = default;

Entry::Entry(const Entry& other)
    : keyword(other.keyword),
      keywordLocation(other.keywordLocation),
      valueLocation(other.valueLocation),
      dimensions(other.dimensions),
      dimensionsLocation(other.dimensionsLocation),
      values(other.values),
      dict(other.dict ? std::make_unique<Dictionary>(*other.dict) : nullptr),
      overridable(other.overridable)
{
}

Entry& Entry::operator=(const Entry& other)
{
    if (this != &other) *this = Entry(other);
    return *this;
}

namespace {

Token tokenFor(TokenKind kind, std::string text, const SourceLocation& where)
{
    Token token;
    token.kind = kind;
    token.text = std::move(text);
    token.where = where;
    return token;
}

void appendTokens(const Value& value, std::vector<Token>& out)
{
    switch (value.kind) {
        case Value::Kind::number:
            out.push_back(tokenFor(TokenKind::number, value.text, value.where));
            return;
        case Value::Kind::word:
            out.push_back(tokenFor(TokenKind::word, value.text, value.where));
            return;
        case Value::Kind::string:
            out.push_back(tokenFor(TokenKind::string, value.text, value.where));
            return;
        case Value::Kind::list:
            break;
    }
    out.push_back(tokenFor(TokenKind::punctuation, "(", value.where));
    for (const Value& item : value.items) appendTokens(item, out);
    out.push_back(tokenFor(TokenKind::punctuation, ")", value.where));
}

}  // namespace

std::vector<Token> Entry::tokens() const
{
    std::vector<Token> out;
    if (dimensions) {
        const std::string inside = dimensions->str();
        out.push_back(
            tokenFor(TokenKind::dimensions, inside.substr(1, inside.size() - 2), dimensionsLocation));
    }
    for (const Value& value : values) appendTokens(value, out);
    return out;
}

// ---- Bounds -------------------------------------------------------------

Bounds::Bounds(double lo, bool loIncluded, double hi, bool hiIncluded, std::string description)
    : lo_(lo), hi_(hi), loIncluded_(loIncluded), hiIncluded_(hiIncluded), description_(std::move(description))
{
}

namespace {
const double infinity = std::numeric_limits<double>::infinity();

std::string interval(double lo, bool loIncluded, double hi, bool hiIncluded)
{
    return std::string("a value in ") + (loIncluded ? "[" : "(") + formatNumber(lo) + ", " +
           formatNumber(hi) + (hiIncluded ? "]" : ")");
}
}  // namespace

Bounds Bounds::any()
{
    return {-infinity, false, infinity, false, "a finite number"};
}
Bounds Bounds::positive()
{
    return {0.0, false, infinity, false, "a value > 0"};
}
Bounds Bounds::nonNegative()
{
    return {0.0, true, infinity, false, "a value >= 0"};
}
Bounds Bounds::atLeast(double lo)
{
    return {lo, true, infinity, false, "a value >= " + formatNumber(lo)};
}
Bounds Bounds::closed(double lo, double hi)
{
    return {lo, true, hi, true, interval(lo, true, hi, true)};
}
Bounds Bounds::open(double lo, double hi)
{
    return {lo, false, hi, false, interval(lo, false, hi, false)};
}
Bounds Bounds::closedOpen(double lo, double hi)
{
    return {lo, true, hi, false, interval(lo, true, hi, false)};
}

bool Bounds::contains(double value) const
{
    if (!std::isfinite(value)) return false;
    const bool aboveLo = loIncluded_ ? value >= lo_ : value > lo_;
    const bool belowHi = hiIncluded_ ? value <= hi_ : value < hi_;
    return aboveLo && belowHi;
}

namespace {
// "1e+09" -> "1e9", "1e-05" -> "1e-5": the way people write them in dictionaries.
std::string tidyExponent(const std::string& text)
{
    const std::size_t e = text.find('e');
    if (e == std::string::npos) return text;
    const bool negative = text[e + 1] == '-';
    std::size_t digits = text.find_first_not_of("+-0", e + 1);
    if (digits == std::string::npos) digits = text.size() - 1;
    return text.substr(0, e) + "e" + (negative ? "-" : "") + text.substr(digits);
}
}  // namespace

std::string formatNumber(double value)
{
    char buffer[40];
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(buffer, sizeof(buffer), "%.*g", precision, value);
        if (std::strtod(buffer, nullptr) == value) break;
    }
    const std::string general = tidyExponent(buffer);
    // Whole numbers read better without an exponent unless that makes them longer (100, not 1e2).
    if (std::fabs(value) < 1e17 && std::floor(value) == value) {
        std::snprintf(buffer, sizeof(buffer), "%.0f", value);
        if (std::string(buffer).size() <= general.size()) return buffer;
    }
    return general;
}

// ---- Dictionary: structure ------------------------------------------------

Dictionary::Dictionary(std::string name, std::string fileName)
    : name_(std::move(name)), fileName_(std::move(fileName))
{
    end_.file = fileName_;
}

void Dictionary::setHeader(const Dictionary& header)
{
    header_ = std::make_shared<const Dictionary>(header);
}

void Dictionary::rename(const std::string& name)
{
    name_ = name;
    for (Entry& e : entries_)
        if (e.dict) e.dict->rename(name + "/" + e.keyword);
}

// Duplicate policy (docs): a keyword written twice in one dictionary is an
// error, because one of the two values is silently ignored otherwise; an entry
// that came from #include or $sub is a default and a later entry replaces it.
void Dictionary::add(Entry entry)
{
    const auto found = index_.find(entry.keyword);
    if (found == index_.end()) {
        index_.emplace(entry.keyword, entries_.size());
        entries_.push_back(std::move(entry));
        return;
    }
    Entry& existing = entries_[found->second];
    if (!existing.overridable)
        throwDictionaryError(entry.keywordLocation,
                             "duplicate entry '" + entry.keyword + "' in dictionary '" + name_ +
                                 "' (first defined at " + existing.keywordLocation.str() + ")",
                             "each keyword once; remove or rename one of them");
    existing = std::move(entry);
}

const Entry* Dictionary::findLocal(const std::string& keyword) const
{
    const auto found = index_.find(keyword);
    return found == index_.end() ? nullptr : &entries_[found->second];
}

namespace {
std::vector<std::string> splitPath(const std::string& key)
{
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (;;) {
        const std::size_t slash = key.find('/', start);
        parts.push_back(key.substr(start, slash - start));
        if (slash == std::string::npos) return parts;
        start = slash + 1;
    }
}
}  // namespace

const Entry* Dictionary::findEntry(const std::string& key) const
{
    const Dictionary* dict = this;
    const std::vector<std::string> parts = splitPath(key);
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
        const Entry* e = dict->findLocal(parts[i]);
        if (!e || !e->isDict()) return nullptr;
        dict = e->dict.get();
    }
    return dict->findLocal(parts.back());
}

const Entry& Dictionary::requireEntry(const std::string& key) const
{
    const Dictionary* dict = this;
    const std::vector<std::string> parts = splitPath(key);
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const Entry* e = dict->findLocal(parts[i]);
        const bool last = i + 1 == parts.size();
        if (!e)
            throwDictionaryError(dict->end_,
                                 std::string("missing required ") + (last ? "entry '" : "sub-dictionary '") +
                                     parts[i] + "' in dictionary '" + dict->name_ + "'",
                                 last ? "a line '" + parts[i] + " <value>;' in it"
                                      : "a sub-dictionary '" + parts[i] + " { ... }' in it");
        if (last) return *e;
        if (!e->isDict())
            throwDictionaryError(
                e->valueLocation, "'" + parts[i] + "' is not a dictionary",
                "a sub-dictionary '" + parts[i] + " { ... }' holding '" + parts.back() + "'");
        dict = e->dict.get();
    }
    return *dict->findLocal(parts.back());  // not reached: the loop returns or throws
}

bool Dictionary::found(const std::string& key) const
{
    return findEntry(key) != nullptr;
}

bool Dictionary::isDict(const std::string& key) const
{
    const Entry* e = findEntry(key);
    return e && e->isDict();
}

const Entry& Dictionary::entry(const std::string& key) const
{
    return requireEntry(key);
}

const Dictionary& Dictionary::subDict(const std::string& key) const
{
    const Entry& e = requireEntry(key);
    if (!e.isDict())
        throwDictionaryError(e.valueLocation, "'" + e.keyword + "' is a value, not a dictionary",
                             "'" + e.keyword + " { ... }'");
    return *e.dict;
}

std::vector<std::string> Dictionary::keys() const
{
    std::vector<std::string> result;
    for (const Entry& e : entries_) result.push_back(e.keyword);
    return result;
}

SourceLocation Dictionary::location(const std::string& key) const
{
    return requireEntry(key).valueLocation;
}

std::vector<Token> Dictionary::tokens(const std::string& key) const
{
    return requireEntry(key).tokens();
}

}  // namespace rockfrac
