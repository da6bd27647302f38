#pragma once
// Case dictionaries in the FoamFile format (docs/file-formats.md, "Dictionaries").
//
// Every rockfrac application reads its input through this class:
//
//   const auto dict = rockfrac::Dictionary::readFile(app.path("constant/rockProperties"));
//   const double E  = dict.getScalar("E", rockfrac::Bounds::positive(), &pascal);
//   const double nu = dict.getScalar("poissonRatio", rockfrac::Bounds::closedOpen(0, 0.5));
//   const double st = dict.get<double>("bond/tensileStrength");
//
// A Dictionary is the file after #include, $macro and #eval expansion: plain
// entries in file order, each either a sub-dictionary or a sequence of values.
// Lookups take slash paths ("bond/tensileStrength"). Every error is a UserError
// whose one-line message starts with "file:line:column: ".
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/dictionaryDimensions.hpp"
#include "core/dictionaryToken.hpp"
#include "core/error.hpp"
#include "core/vec3.hpp"

namespace rockfrac {

class Dictionary;

// One value of an entry: a number, a word, a quoted string or a ( ) list of values.
struct Value {
    enum class Kind { number, word, string, list };

    Kind kind = Kind::word;
    std::string text;          // number as written, word, or string contents
    double number = 0.0;       // when kind == number
    std::vector<Value> items;  // when kind == list
    SourceLocation where;

    bool isNumber() const { return kind == Kind::number; }
    bool isWord() const { return kind == Kind::word; }
    bool isString() const { return kind == Kind::string; }
    bool isList() const { return kind == Kind::list; }

    // For messages: "a word ('abc')", "a number (2.5)", "a list of 3 values".
    std::string describe() const;
};

// One `keyword value...;` or `keyword { ... }` of a dictionary.
struct Entry {
    std::string keyword;
    SourceLocation keywordLocation;
    SourceLocation valueLocation;  // first value, '{' of a sub-dictionary, or the ';'
    std::optional<Dimensions> dimensions;
    SourceLocation dimensionsLocation;
    std::vector<Value> values;         // empty for a sub-dictionary
    std::unique_ptr<Dictionary> dict;  // set for a sub-dictionary
    bool overridable = false;          // came from #include or $sub: a later entry may replace it

    Entry();
    Entry(const Entry& other);
    Entry(Entry&& other) noexcept;
    Entry& operator=(const Entry& other);
    Entry& operator=(Entry&& other) noexcept;
    ~Entry();

    bool isDict() const { return dict != nullptr; }

    // The values as a flat token stream, lists bracketed by '(' and ')', for
    // models that parse their own syntax (`type plate (0 0 1) 0.25;`).
    std::vector<Token> tokens() const;
};

// Allowed range of a scalar, with the wording used in error messages.
class Bounds {
public:
    static Bounds any();                             // any finite number
    static Bounds positive();                        // > 0
    static Bounds nonNegative();                     // >= 0
    static Bounds atLeast(double lo);                // >= lo
    static Bounds closed(double lo, double hi);      // [lo, hi]
    static Bounds open(double lo, double hi);        // (lo, hi)
    static Bounds closedOpen(double lo, double hi);  // [lo, hi), e.g. Poisson's ratio [0, 0.5)

    bool contains(double value) const;
    const std::string& description() const { return description_; }  // "a value in [0, 0.5)"

private:
    Bounds(double lo, bool loIncluded, double hi, bool hiIncluded, std::string description);
    double lo_, hi_;
    bool loIncluded_, hiIncluded_;
    std::string description_;
};

// Guards against inputs that would exhaust memory or stack (fuzzing found them);
// the defaults are far above any real case dictionary.
struct ParseLimits {
    std::size_t maxValues = std::size_t(1) << 24;  // values after macro and uniform-list expansion
    int maxNesting = 200;                          // depth of ( ) lists and { } dictionaries
    int maxIncludeDepth = 32;
    bool allowIncludes = true;
};

class Dictionary {
public:
    Dictionary() = default;
    Dictionary(std::string name, std::string fileName);

    // Read and expand a file; its name as given appears in every message.
    static Dictionary readFile(const std::filesystem::path& path, const ParseLimits& limits = {});
    // Parse text as if it were the file `fileName` (#include is relative to it).
    static Dictionary parse(const std::string& text, const std::string& fileName,
                            const ParseLimits& limits = {});

    const std::string& name() const { return name_; }  // "controlDict", or "bond" for a sub-dictionary
    const std::string& fileName() const { return fileName_; }
    const Dictionary* header() const { return header_.get(); }  // the FoamFile { } block, if any
    const SourceLocation& endLocation() const { return end_; }  // closing '}' or end of file

    // ---- Lookups; keys are slash paths relative to this dictionary --------
    bool found(const std::string& key) const;
    bool isDict(const std::string& key) const;
    const Dictionary& subDict(const std::string& key) const;
    const Entry& entry(const std::string& key) const;      // UserError when missing
    const Entry* findEntry(const std::string& key) const;  // nullptr when missing
    const std::vector<Entry>& entries() const { return entries_; }
    std::vector<std::string> keys() const;                    // in file order
    SourceLocation location(const std::string& key) const;    // of the value
    std::vector<Token> tokens(const std::string& key) const;  // raw token stream of a value

    // T: double, int, long, std::uint64_t, bool, std::string (word or string),
    // Vec3, std::vector<double|int|std::string|Vec3>, std::vector<std::vector<double>>.
    template <class T>
    T get(const std::string& key) const;
    template <class T>
    T getOrDefault(const std::string& key, const T& fallback) const;

    // A number within `bounds`; when `expected` is given and the entry has a
    // dimension set, the two must agree.
    double getScalar(const std::string& key, const Bounds& bounds,
                     const Dimensions* expected = nullptr) const;
    double getScalarOrDefault(const std::string& key, double fallback, const Bounds& bounds,
                              const Dimensions* expected = nullptr) const;
    // A word chosen from `allowed` (a model or mode selection).
    std::string getWord(const std::string& key, const std::vector<std::string>& allowed) const;

    // ---- Building (the parser); duplicate policy in docs ------------------
    void add(Entry entry);
    void setHeader(const Dictionary& header);
    void setEndLocation(const SourceLocation& end) { end_ = end; }
    void rename(const std::string& name);  // this and, recursively, its sub-dictionaries

private:
    const Entry* findLocal(const std::string& keyword) const;
    const Entry& requireEntry(const std::string& key) const;

    std::string name_;
    std::string fileName_;
    SourceLocation end_;
    std::shared_ptr<const Dictionary> header_;
    std::vector<Entry> entries_;
    std::unordered_map<std::string, std::size_t> index_;
};

// Canonical FoamFile text of a dictionary (header, aligned entries, expanded values).
std::string toString(const Dictionary& dict);
// `keyword value;` (or `keyword { ... }`) as toString prints it, at `indentLevel`.
std::string toString(const Entry& entry, int indentLevel = 0);
// The values of an entry as they would appear between keyword and ';'.
std::string valueText(const Entry& entry);

// Shortest text that reads back as the same double ("0.5", "7.7e10").
std::string formatNumber(double value);

}  // namespace rockfrac
