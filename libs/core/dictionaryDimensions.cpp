// Dimension sets: seven exponents, or a coherent SI unit expression.
#include "core/dictionaryDimensions.hpp"

#include <cctype>
#include <map>
#include <stdexcept>
#include <vector>

#include "core/dictionaryLexer.hpp"

namespace rockfrac {

namespace {

using Exponents = std::array<int, 7>;

const char* const baseUnitNames[7] = {"kg", "m", "s", "K", "mol", "A", "cd"};

// Coherent SI units only: a dimension set never scales a value.
const std::map<std::string, Exponents>& unitTable()
{
    static const std::map<std::string, Exponents> table = {
        {"kg", {1, 0, 0, 0, 0, 0, 0}},  {"m", {0, 1, 0, 0, 0, 0, 0}},   {"s", {0, 0, 1, 0, 0, 0, 0}},
        {"K", {0, 0, 0, 1, 0, 0, 0}},   {"mol", {0, 0, 0, 0, 1, 0, 0}}, {"A", {0, 0, 0, 0, 0, 1, 0}},
        {"cd", {0, 0, 0, 0, 0, 0, 1}},  {"N", {1, 1, -2, 0, 0, 0, 0}},  {"Pa", {1, -1, -2, 0, 0, 0, 0}},
        {"J", {1, 2, -2, 0, 0, 0, 0}},  {"W", {1, 2, -3, 0, 0, 0, 0}},  {"Hz", {0, 0, -1, 0, 0, 0, 0}},
        {"rad", {0, 0, 0, 0, 0, 0, 0}},
    };
    return table;
}

const char* const unitHelp =
    "7 integer exponents [kg m s K mol A cd] or coherent SI units (kg m s K mol A cd N Pa J W Hz rad, "
    "combined with * / ^, or '-' for none)";

// A syntax mistake at a byte offset inside the brackets.
struct DimensionSyntaxError {
    std::size_t offset;
    std::string whatIsWrong;
    std::string expected;
};

struct Word {
    std::string text;
    std::size_t offset;
};

std::vector<Word> splitWords(const std::string& text)
{
    std::vector<Word> words;
    std::size_t i = 0;
    while (i < text.size()) {
        if (std::isspace(static_cast<unsigned char>(text[i]))) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        words.push_back({text.substr(start, i - start), start});
    }
    return words;
}

bool isSignedInteger(const std::string& word)
{
    const std::size_t digitsFrom = (!word.empty() && (word[0] == '-' || word[0] == '+')) ? 1 : 0;
    return word.size() > digitsFrom && isUnsignedInteger(word.substr(digitsFrom)) && word.size() < 6;
}

Exponents parseExponents(const std::vector<Word>& words)
{
    for (const Word& w : words)
        if (!isSignedInteger(w.text))
            throw DimensionSyntaxError{w.offset, "exponent '" + w.text + "' is not a small integer",
                                       unitHelp};
    if (words.size() != 7)
        throw DimensionSyntaxError{0, "dimension set has " + std::to_string(words.size()) + " exponents",
                                   unitHelp};
    Exponents exponents{};
    for (std::size_t i = 0; i < 7; ++i) exponents[i] = std::stoi(words[i].text);
    return exponents;
}

// Unit expressions: factors joined by '*', '/' (inverts the next factor only)
// or white space; a factor is a unit with an optional ^exponent, or "1".
class UnitParser {
public:
    explicit UnitParser(const std::string& text) : text_(text) {}

    Exponents parse()
    {
        skipSpace();
        if (pos_ < text_.size() && text_[pos_] == '-' &&
            text_.find_first_not_of(" \t", pos_ + 1) == std::string::npos)
            return {};
        if (pos_ >= text_.size()) throw DimensionSyntaxError{0, "empty dimension set", unitHelp};
        Exponents result{};
        int sign = 1;
        for (;;) {
            addFactor(result, sign);
            skipSpace();
            if (pos_ >= text_.size()) return result;
            sign = 1;
            if (text_[pos_] == '*' || text_[pos_] == '/') {
                sign = text_[pos_] == '/' ? -1 : 1;
                ++pos_;
                skipSpace();
            }
        }
    }

private:
    void skipSpace()
    {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    }

    void addFactor(Exponents& result, int sign)
    {
        const std::size_t at = pos_;
        if (pos_ < text_.size() && text_[pos_] == '1') {
            ++pos_;
            return;
        }
        while (pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_]))) ++pos_;
        const std::string name = text_.substr(at, pos_ - at);
        const Exponents& unit = lookup(name, at);
        const int power = sign * exponent();
        for (std::size_t i = 0; i < 7; ++i) result[i] += power * unit[i];
    }

    const Exponents& lookup(const std::string& name, std::size_t at) const
    {
        if (name.empty())
            throw DimensionSyntaxError{at, "unexpected '" + text_.substr(at, 1) + "' in dimension set",
                                       unitHelp};
        const auto found = unitTable().find(name);
        if (found != unitTable().end()) return found->second;
        const bool prefixed = name.size() > 1 &&
                              std::string("kMGTmunpc").find(name[0]) != std::string::npos &&
                              unitTable().count(name.substr(1));
        if (prefixed || name == "g")
            throw DimensionSyntaxError{at, "'" + name + "' is not a coherent SI unit",
                                       "SI units without prefixes (write the value in " +
                                           (name == "g" ? std::string("kg") : name.substr(1)) + ")"};
        throw DimensionSyntaxError{at, "unknown unit '" + name + "'", unitHelp};
    }

    int exponent()
    {
        if (pos_ >= text_.size() || text_[pos_] != '^') return 1;
        const std::size_t at = ++pos_;
        if (pos_ < text_.size() && (text_[pos_] == '-' || text_[pos_] == '+')) ++pos_;
        while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
        const std::string written = text_.substr(at, pos_ - at);
        if (!isSignedInteger(written))
            throw DimensionSyntaxError{at, "bad exponent '" + written + "' after '^'",
                                       "a small integer, as in m^3"};
        return std::stoi(written);
    }

    const std::string& text_;
    std::size_t pos_ = 0;
};

// Seven exponents when the contents look numeric (so that a wrong count or a
// fraction is reported as such), a unit expression otherwise.
Exponents parseInside(const std::string& inside)
{
    const std::vector<Word> words = splitWords(inside);
    bool allNumbers = !words.empty();
    for (const Word& w : words) allNumbers = allNumbers && looksLikeNumber(w.text);
    const bool numeric = allNumbers || (words.size() >= 3 && looksLikeNumber(words[0].text));
    return numeric ? parseExponents(words) : UnitParser(inside).parse();
}

}  // namespace

Dimensions parseDimensionSet(const std::string& inside, const SourceLocation& openBracket)
{
    try {
        return Dimensions{parseInside(inside)};
    } catch (const DimensionSyntaxError& error) {
        SourceLocation where = openBracket;
        where.column += 1 + static_cast<int>(error.offset);
        throwDictionaryError(where, error.whatIsWrong, error.expected);
    }
}

Dimensions Dimensions::fromUnits(const std::string& units)
{
    try {
        return Dimensions{parseInside(units)};
    } catch (const DimensionSyntaxError& error) {
        throw std::invalid_argument("Dimensions::fromUnits(\"" + units + "\"): " + error.whatIsWrong);
    }
}

std::string Dimensions::str() const
{
    std::string text = "[";
    for (std::size_t i = 0; i < 7; ++i) text += (i ? " " : "") + std::to_string(exponents[i]);
    return text + "]";
}

std::string Dimensions::unitString() const
{
    std::string text;
    for (std::size_t i = 0; i < 7; ++i) {
        if (exponents[i] == 0) continue;
        if (!text.empty()) text += ' ';
        text += baseUnitNames[i];
        if (exponents[i] != 1) text += "^" + std::to_string(exponents[i]);
    }
    return text.empty() ? "-" : text;
}

}  // namespace rockfrac
