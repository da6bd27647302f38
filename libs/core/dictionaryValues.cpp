// Typed reading of entry values: get<T>, getScalar, getWord.
//
// Each supported type has a Converter: what it expects (for messages) and how
// to read one Value. A `label` names the thing being read in messages, so that
// a wrong item deep in a list is reported as "item 2 of 'points'".
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

#include "core/dictionary.hpp"

namespace rockfrac {

namespace {

[[noreturn]] void wrongType(const Value& value, const std::string& label, const std::string& expected)
{
    throwDictionaryError(value.where, label + " is " + value.describe(), expected);
}

std::string quoted(const std::string& keyword)
{
    return "'" + keyword + "'";
}

template <class T>
struct Converter;

template <>
struct Converter<double> {
    static std::string expected() { return "a number"; }
    static double read(const Value& value, const std::string& label)
    {
        if (!value.isNumber()) wrongType(value, label, expected());
        return value.number;
    }
};

// Integers are read from their text, so that 64-bit seeds keep every digit;
// a number written with a point or exponent is accepted when it is whole.
template <class Integer>
struct IntegerConverter {
    static std::string expected()
    {
        return std::is_signed<Integer>::value ? "an integer" : "a non-negative integer";
    }
    static Integer read(const Value& value, const std::string& label)
    {
        if (!value.isNumber()) wrongType(value, label, expected());
        const std::string digits = value.text[0] == '+' ? value.text.substr(1) : value.text;
        Integer result{};
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), result);
        if (error == std::errc() && end == digits.data() + digits.size()) return result;
        const double whole = value.number;
        const bool isWhole = std::floor(whole) == whole;
        const bool inRange = whole >= static_cast<double>(std::numeric_limits<Integer>::min()) &&
                             whole < std::ldexp(1.0, std::numeric_limits<Integer>::digits);
        if (isWhole && inRange && error != std::errc::result_out_of_range) return static_cast<Integer>(whole);
        const std::string range = "[" + std::to_string(std::numeric_limits<Integer>::min()) + ", " +
                                  std::to_string(std::numeric_limits<Integer>::max()) + "]";
        if (!isWhole)
            throwDictionaryError(value.where, label + " = " + value.text + " is not a whole number",
                                 expected());
        throwDictionaryError(value.where, label + " = " + value.text + " is out of range",
                             expected() + " in " + range);
    }
};

template <>
struct Converter<int> : IntegerConverter<int> {
};
template <>
struct Converter<long> : IntegerConverter<long> {
};
template <>
struct Converter<unsigned long long> : IntegerConverter<unsigned long long> {
};
template <>
struct Converter<unsigned long> : IntegerConverter<unsigned long> {
};

template <>
struct Converter<bool> {
    static std::string expected() { return "a boolean: true/false, on/off or yes/no"; }
    static bool read(const Value& value, const std::string& label)
    {
        if (value.isWord()) {
            const std::string& w = value.text;
            if (w == "true" || w == "on" || w == "yes") return true;
            if (w == "false" || w == "off" || w == "no") return false;
        }
        wrongType(value, label, expected());
    }
};

template <>
struct Converter<std::string> {
    static std::string expected() { return "a word or a quoted string"; }
    static std::string read(const Value& value, const std::string& label)
    {
        if (!value.isWord() && !value.isString()) wrongType(value, label, expected());
        return value.text;
    }
};

template <>
struct Converter<Vec3> {
    static std::string expected() { return "a vector of 3 numbers (x y z)"; }
    static Vec3 read(const Value& value, const std::string& label)
    {
        if (!value.isList() || value.items.size() != 3) wrongType(value, label, expected());
        Vec3 v;
        for (int i = 0; i < 3; ++i)
            v[i] = Converter<double>::read(value.items[i],
                                           "component " + std::to_string(i + 1) + " of " + label);
        return v;
    }
};

template <class T>
struct Converter<std::vector<T>> {
    static std::string expected() { return "a list ( ... ) of " + plural(Converter<T>::expected()); }
    static std::vector<T> read(const Value& value, const std::string& label)
    {
        if (!value.isList()) wrongType(value, label, expected());
        std::vector<T> result;
        result.reserve(value.items.size());
        for (std::size_t i = 0; i < value.items.size(); ++i)
            result.push_back(
                Converter<T>::read(value.items[i], "item " + std::to_string(i + 1) + " of " + label));
        return result;
    }
    // "a number" -> "numbers": good enough for the element descriptions above.
    static std::string plural(const std::string& singular)
    {
        const std::size_t space = singular.find(' ');
        return singular.rfind("a list", 0) == 0 ? "lists" : singular.substr(space + 1) + "s";
    }
};

// The one value of an entry that must hold exactly one.
const Value& singleValue(const Entry& entry, const std::string& expected)
{
    if (entry.isDict())
        throwDictionaryError(entry.valueLocation, quoted(entry.keyword) + " is a dictionary", expected);
    if (entry.values.empty())
        throwDictionaryError(entry.valueLocation, quoted(entry.keyword) + " has no value", expected);
    if (entry.values.size() > 1)
        throwDictionaryError(
            entry.values[1].where,
            quoted(entry.keyword) + " has " + std::to_string(entry.values.size()) + " values",
            "a single value: " + expected);
    return entry.values.front();
}

std::string lowercase(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

}  // namespace

template <class T>
T Dictionary::get(const std::string& key) const
{
    const Entry& e = requireEntry(key);
    return Converter<T>::read(singleValue(e, Converter<T>::expected()), quoted(e.keyword));
}

template <class T>
T Dictionary::getOrDefault(const std::string& key, const T& fallback) const
{
    return found(key) ? get<T>(key) : fallback;
}

#define ROCKFRAC_DICTIONARY_TYPE(T)                          \
    template T Dictionary::get<T>(const std::string&) const; \
    template T Dictionary::getOrDefault<T>(const std::string&, const T&) const;
ROCKFRAC_DICTIONARY_TYPE(double)
ROCKFRAC_DICTIONARY_TYPE(int)
ROCKFRAC_DICTIONARY_TYPE(long)
ROCKFRAC_DICTIONARY_TYPE(unsigned long)
ROCKFRAC_DICTIONARY_TYPE(unsigned long long)
ROCKFRAC_DICTIONARY_TYPE(bool)
ROCKFRAC_DICTIONARY_TYPE(std::string)
ROCKFRAC_DICTIONARY_TYPE(Vec3)
ROCKFRAC_DICTIONARY_TYPE(std::vector<double>)
ROCKFRAC_DICTIONARY_TYPE(std::vector<int>)
ROCKFRAC_DICTIONARY_TYPE(std::vector<std::string>)
ROCKFRAC_DICTIONARY_TYPE(std::vector<Vec3>)
ROCKFRAC_DICTIONARY_TYPE(std::vector<std::vector<double>>)
#undef ROCKFRAC_DICTIONARY_TYPE

double Dictionary::getScalar(const std::string& key, const Bounds& bounds, const Dimensions* expected) const
{
    const Entry& e = requireEntry(key);
    const Value& value = singleValue(e, "a number, " + bounds.description());
    const double number = Converter<double>::read(value, quoted(e.keyword));
    if (expected && e.dimensions && *e.dimensions != *expected)
        throwDictionaryError(e.dimensionsLocation,
                             quoted(e.keyword) + " has dimensions " + e.dimensions->str() + " (" +
                                 e.dimensions->unitString() + ")",
                             expected->str() + " (" + expected->unitString() + ") or no dimension set");
    if (!bounds.contains(number))
        throwDictionaryError(value.where, e.keyword + " = " + value.text + " is out of range",
                             bounds.description());
    return number;
}

double Dictionary::getScalarOrDefault(const std::string& key, double fallback, const Bounds& bounds,
                                      const Dimensions* expected) const
{
    return found(key) ? getScalar(key, bounds, expected) : fallback;
}

std::string Dictionary::getWord(const std::string& key, const std::vector<std::string>& allowed) const
{
    std::string choices;
    for (const std::string& word : allowed) choices += (choices.empty() ? "" : ", ") + word;
    const Entry& e = requireEntry(key);
    const Value& value = singleValue(e, "one of: " + choices);
    const std::string word = Converter<std::string>::read(value, quoted(e.keyword));
    if (std::find(allowed.begin(), allowed.end(), word) != allowed.end()) return word;
    std::string hint;
    for (const std::string& candidate : allowed)
        if (lowercase(candidate) == lowercase(word)) hint = " (did you mean '" + candidate + "'?)";
    throwDictionaryError(value.where, e.keyword + " = " + word + " is not a valid choice",
                         "one of: " + choices + hint);
}

}  // namespace rockfrac
