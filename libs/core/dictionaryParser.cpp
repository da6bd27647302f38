// The FoamFile parser: tokens to a Dictionary, expanding #include, $macros and
// #eval as it goes, so that what the applications see is plain entries.
//
// Macros are resolved at the point where they are written, against what has
// been read so far (as in OpenFOAM): an entry can only refer to entries above
// it, which also makes self-reference and copy cycles impossible.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/dictionary.hpp"
#include "core/dictionaryLexer.hpp"
#include "core/evalExpression.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

namespace {

std::size_t countValues(const Value& value)
{
    std::size_t count = 1;
    for (const Value& item : value.items) count += countValues(item);
    return count;
}

std::size_t countValues(const std::vector<Value>& values)
{
    std::size_t count = 0;
    for (const Value& value : values) count += countValues(value);
    return count;
}

std::size_t countValues(const Dictionary& dict)
{
    std::size_t count = 0;
    for (const Entry& e : dict.entries())
        count += 1 + countValues(e.values) + (e.dict ? countValues(*e.dict) : 0);
    return count;
}

Value valueFromToken(const Token& token)
{
    Value value;
    value.text = token.text;
    value.where = token.where;
    if (token.kind == TokenKind::number) {
        value.kind = Value::Kind::number;
        value.number = std::strtod(token.text.c_str(), nullptr);
    } else {
        value.kind = token.kind == TokenKind::string ? Value::Kind::string : Value::Kind::word;
    }
    return value;
}

std::string childName(const Dictionary& parent, const std::string& keyword, bool parentIsRoot)
{
    return parentIsRoot ? keyword : parent.name() + "/" + keyword;
}

bool isDirective(const Token& token)
{
    return token.kind == TokenKind::word && token.text[0] == '#';
}
bool isMacro(const Token& token)
{
    return token.kind == TokenKind::word && token.text[0] == '$';
}

// Where character `offset` of an expression that starts at `start` is.
SourceLocation locateInside(SourceLocation start, const std::string& text, std::size_t offset)
{
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++start.line;
            start.column = 1;
        } else {
            ++start.column;
        }
    }
    return start;
}

// An expression as one short line, for messages.
std::string oneLine(std::string text)
{
    for (char& c : text)
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    const std::size_t first = text.find_first_not_of(' ');
    text = first == std::string::npos ? "" : text.substr(first, text.find_last_not_of(' ') - first + 1);
    return text.size() > 60 ? text.substr(0, 57) + "..." : text;
}

std::string readTextFile(const fs::path& path, const std::string& shownName,
                         const SourceLocation* requestedAt)
{
    std::error_code ec;
    const bool isFile = fs::is_regular_file(path, ec);
    std::ifstream in;
    if (isFile) in.open(path, std::ios::binary);
    if (!in.is_open()) {
        const std::string what = "cannot read " + std::string(requestedAt ? "included " : "") + "file '" +
                                 shownName + "' (" +
                                 (fs::exists(path, ec) ? "not a readable file" : "no such file") + ")";
        const std::string expected =
            requestedAt
                ? "an existing file; the path is relative to the directory of '" + requestedAt->file + "'"
                : "an existing dictionary file; check the case directory and the file name";
        if (requestedAt) throwDictionaryError(*requestedAt, what, expected);
        throw UserError(shownName + ": " + what + "; expected " + expected);
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string canonicalName(const fs::path& path)
{
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(path, ec);
    return ec ? path.lexically_normal().string() : canonical.string();
}

class DictionaryParser {
public:
    explicit DictionaryParser(const ParseLimits& limits) : limits_(limits) {}

    Dictionary parseTop(const std::string& text, const std::string& fileName)
    {
        Dictionary root(fs::path(fileName).filename().string(), fileName);
        includeChain_.push_back({canonicalName(fileName), fileName});
        DictionaryLexer lexer(text, fileName);
        scopes_.push_back(&root);
        const Token end = parseBody(lexer, root, nullptr, 0);
        root.setEndLocation(end.where);
        return root;
    }

private:
    struct IncludedFile {
        std::string canonical;
        std::string shown;
    };

    bool atTopLevel() const { return scopes_.size() == 1; }

    void checkDepth(int depth, const SourceLocation& where) const
    {
        if (depth > limits_.maxNesting)
            throwDictionaryError(where,
                                 "nesting deeper than " + std::to_string(limits_.maxNesting) + " levels",
                                 "a flatter structure of lists and dictionaries");
    }

    // Every value made, read or copied is counted, so that macros copying each
    // other or a huge uniform list fail with a message instead of exhausting memory.
    void charge(std::size_t values, const SourceLocation& where)
    {
        valueCount_ += values;
        if (values > limits_.maxValues || valueCount_ > limits_.maxValues)
            throwDictionaryError(
                where, "the dictionary expands to more than " + std::to_string(limits_.maxValues) + " values",
                "fewer values (look for macros that copy each other, or a huge uniform list)");
    }

    // Entries until '}' (when `openBrace` is given) or the end of the text;
    // returns the token that ended the body.
    Token parseBody(DictionaryLexer& lexer, Dictionary& dict, const Token* openBrace, int depth)
    {
        for (;;) {
            Token token = lexer.next();
            if (token.isEnd()) {
                if (openBrace)
                    throwDictionaryError(openBrace->where,
                                         "'{' of dictionary '" + dict.name() + "' is never closed",
                                         "a matching '}' before the end of the file");
                return token;
            }
            if (token.isPunctuation('}')) {
                if (!openBrace)
                    throwDictionaryError(token.where, "unexpected '}' with no matching '{'",
                                         "a keyword, a directive or the end of the file");
                return token;
            }
            if (token.isPunctuation(';')) continue;
            if (isDirective(token))
                parseDirective(lexer, dict, token, depth);
            else if (isMacro(token))
                mergeMacro(lexer, dict, token);
            else if (token.kind == TokenKind::word || token.kind == TokenKind::string)
                parseEntry(lexer, dict, token, depth);
            else
                throwDictionaryError(token.where, "unexpected " + describeToken(token),
                                     "a keyword, a directive such as #include, or '}'");
        }
    }

    void parseEntry(DictionaryLexer& lexer, Dictionary& dict, const Token& keyword, int depth)
    {
        Entry entry;
        entry.keyword = keyword.text;
        entry.keywordLocation = keyword.where;
        entry.overridable = includeDepth() > 0;
        charge(1, keyword.where);
        if (lexer.peek().isPunctuation('{'))
            parseSubDictionary(lexer, dict, entry, depth + 1);
        else
            parseValues(lexer, dict, entry, depth);

        // The FoamFile header describes the file; it is kept apart from the
        // data. Included files often carry their own, which is ignored.
        if (scopes_.size() == fileTopDepth_ && entry.keyword == "FoamFile" && entry.isDict()) {
            if (includeDepth() > 0) return;
            if (dict.header())
                throwDictionaryError(keyword.where, "second FoamFile header",
                                     "one FoamFile { } block per file");
            dict.setHeader(*entry.dict);
            return;
        }
        dict.add(std::move(entry));
    }

    void parseSubDictionary(DictionaryLexer& lexer, Dictionary& parent, Entry& entry, int depth)
    {
        const Token open = lexer.next();
        checkDepth(depth, open.where);
        entry.valueLocation = open.where;
        entry.dict =
            std::make_unique<Dictionary>(childName(parent, entry.keyword, atTopLevel()), lexer.fileName());
        scopes_.push_back(entry.dict.get());
        const Token close = parseBody(lexer, *entry.dict, &open, depth);
        scopes_.pop_back();
        entry.dict->setEndLocation(close.where);
    }

    // Values up to ';'. A word at the outer level on a new line means the ';'
    // of this entry was forgotten: report that rather than a puzzling value.
    void parseValues(DictionaryLexer& lexer, Dictionary& dict, Entry& entry, int depth)
    {
        for (;;) {
            const SourceLocation previousEnd = lexer.previousEnd();
            Token token = lexer.next();
            if (token.isPunctuation(';')) {
                entry.valueLocation = entry.values.empty() ? token.where : entry.values.front().where;
                return;
            }
            const bool newLineWord =
                token.kind == TokenKind::word && !entry.values.empty() && token.where.line > previousEnd.line;
            if (token.isEnd() || token.isPunctuation('}') || newLineWord) {
                const std::string before = token.isEnd() ? "the end of the file"
                                           : token.isPunctuation('}')
                                               ? "'}'"
                                               : "'" + token.text + "' on the next line";
                throwDictionaryError(previousEnd, "missing ';' after the value of '" + entry.keyword + "'",
                                     "';' to end the entry before " + before);
            }
            if (token.kind == TokenKind::dimensions) {
                readDimensions(entry, token);
            } else if (isMacro(token) && entry.values.empty() && !entry.dimensions) {
                if (copyMacroIntoEntry(lexer, dict, entry, token)) return;
            } else if (!parseItem(lexer, token, entry.values, depth)) {
                throwDictionaryError(
                    token.where,
                    "unexpected " + describeToken(token) + " in the value of '" + entry.keyword + "'",
                    "a value or ';' to end the entry");
            }
        }
    }

    void readDimensions(Entry& entry, const Token& token)
    {
        if (!entry.values.empty() || entry.dimensions)
            throwDictionaryError(token.where, "dimension set [" + token.text + "] after the value",
                                 "the dimension set right after the keyword, as in 'E [Pa] 77e9;'");
        entry.dimensions = parseDimensionSet(token.text, token.where);
        entry.dimensionsLocation = token.where;
    }

    // `keyword $other;` copies other's values and dimension set, or the whole
    // sub-dictionary when it names one. Returns true when the entry is complete.
    bool copyMacroIntoEntry(DictionaryLexer& lexer, const Dictionary& dict, Entry& entry, const Token& macro)
    {
        const Entry& source = resolveMacro(macro);
        if (!source.isDict()) {
            charge(countValues(source.values), macro.where);
            entry.values = source.values;
            entry.dimensions = source.dimensions;
            entry.dimensionsLocation = source.dimensionsLocation;
            return false;
        }
        const Token end = lexer.next();
        if (!end.isPunctuation(';'))
            throwDictionaryError(end.where,
                                 "'" + macro.text + "' names a dictionary and is followed by more values",
                                 "';' right after it, as in 'keyword " + macro.text + ";'");
        charge(countValues(*source.dict), macro.where);
        entry.dict = std::make_unique<Dictionary>(*source.dict);
        entry.dict->rename(childName(dict, entry.keyword, atTopLevel()));
        entry.valueLocation = macro.where;
        return true;
    }

    // One value starting at `token`, appended to `out`; false when `token`
    // cannot start a value.
    bool parseItem(DictionaryLexer& lexer, const Token& token, std::vector<Value>& out, int depth)
    {
        switch (token.kind) {
            case TokenKind::number:
                if (isSizePrefix(lexer, token, '('))
                    out.push_back(parseList(lexer, lexer.next(), depth + 1, &token));
                else if (isSizePrefix(lexer, token, '{'))
                    out.push_back(parseUniformList(lexer, token, depth + 1));
                else
                    charge(1, token.where), out.push_back(valueFromToken(token));
                return true;
            case TokenKind::string:
                charge(1, token.where);
                out.push_back(valueFromToken(token));
                return true;
            case TokenKind::word:
                appendWordValue(lexer, token, out);
                return true;
            case TokenKind::punctuation:
                if (!token.isPunctuation('(')) return false;
                out.push_back(parseList(lexer, token, depth + 1, nullptr));
                return true;
            case TokenKind::dimensions:
            case TokenKind::endOfInput:
                break;
        }
        return false;
    }

    // N(...) and N{v} need the bracket right after N, or on a later line (as
    // OpenFOAM writes long lists); "plate 2 (0 0 1)" is a number and a vector.
    static bool isSizePrefix(DictionaryLexer& lexer, const Token& number, char bracket)
    {
        const Token& next = lexer.peek();
        return isUnsignedInteger(number.text) && next.isPunctuation(bracket) &&
               (next.begin == number.end || next.where.line > number.endLine);
    }

    void appendWordValue(DictionaryLexer& lexer, const Token& token, std::vector<Value>& out)
    {
        if (token.text == "#eval") {
            charge(1, token.where);
            out.push_back(parseEval(lexer, token));
        } else if (isDirective(token)) {
            throwDictionaryError(token.where, "directive '" + token.text + "' inside a value",
                                 "#eval here, or #include on a line of its own between entries");
        } else if (isMacro(token)) {
            const Entry& source = resolveMacro(token);
            if (source.isDict())
                throwDictionaryError(
                    token.where, "'" + token.text + "' names a dictionary inside a value",
                    "a macro naming a value, or 'keyword " + token.text + ";' to copy the dictionary");
            charge(countValues(source.values), token.where);
            out.insert(out.end(), source.values.begin(), source.values.end());
        } else {
            charge(1, token.where);
            out.push_back(valueFromToken(token));
        }
    }

    // A ( ) list; `sizeToken` is the N of N( ... ), whose count is checked.
    Value parseList(DictionaryLexer& lexer, const Token& open, int depth, const Token* sizeToken)
    {
        checkDepth(depth, open.where);
        charge(1, open.where);
        Value list;
        list.kind = Value::Kind::list;
        list.where = sizeToken ? sizeToken->where : open.where;
        for (;;) {
            const Token token = lexer.next();
            if (token.isPunctuation(')')) break;
            if (token.isEnd())
                throwDictionaryError(open.where, "'(' is never closed",
                                     "a matching ')' before the end of the file");
            if (token.isPunctuation(';') || token.isPunctuation('}'))
                throwDictionaryError(token.where,
                                     "unexpected '" + token.text + "' inside the list opened at line " +
                                         std::to_string(open.where.line) + ", column " +
                                         std::to_string(open.where.column),
                                     "')' to close the list first");
            if (!parseItem(lexer, token, list.items, depth))
                throwDictionaryError(token.where, "unexpected " + describeToken(token) + " inside a list",
                                     "a value or ')' to close the list");
        }
        if (sizeToken && sizeToken->text != std::to_string(list.items.size()))
            throwDictionaryError(sizeToken->where,
                                 "list size " + sizeToken->text + " does not match its " +
                                     std::to_string(list.items.size()) + " values",
                                 "a size of " + std::to_string(list.items.size()) + " or " + sizeToken->text +
                                     " values in the list");
        return list;
    }

    // N{value}: N copies of one value.
    Value parseUniformList(DictionaryLexer& lexer, const Token& countToken, int depth)
    {
        const Token open = lexer.next();
        checkDepth(depth, open.where);
        const std::string expected = "a single value inside the braces, as in " + countToken.text + "{0}";
        std::vector<Value> inside;
        const Token first = lexer.next();
        if (!parseItem(lexer, first, inside, depth) || inside.size() != 1)
            throwDictionaryError(first.where,
                                 "bad uniform list " + countToken.text + "{...}: " + describeToken(first) +
                                     " is not a single value",
                                 expected);
        const Token close = lexer.next();
        if (!close.isPunctuation('}'))
            throwDictionaryError(
                close.where,
                "bad uniform list " + countToken.text + "{...}: " + describeToken(close) + " after its value",
                expected);
        std::size_t count = 0;
        try {
            count = std::stoull(countToken.text);
        } catch (const std::out_of_range&) {
            count = limits_.maxValues + 1;
        }
        charge(count > limits_.maxValues ? count : count * countValues(inside.front()), countToken.where);
        Value list;
        list.kind = Value::Kind::list;
        list.where = countToken.where;
        list.items.assign(count, inside.front());
        return list;
    }

    Value parseEval(DictionaryLexer& lexer, const Token& directive)
    {
        const Token argument = lexer.next();
        std::string expression;
        SourceLocation start = argument.where;
        if (argument.kind == TokenKind::string) {
            expression = argument.text;
            start.column += 1;  // past the opening quote
        } else if (argument.isPunctuation('{')) {
            expression = lexer.readRawBlock(argument, start);
        } else {
            throwDictionaryError(argument.where, "#eval is followed by " + describeToken(argument),
                                 "an expression: #eval \"2*pi*$radius\" or #eval{ 2*pi*$radius }");
        }
        Value value;
        value.kind = Value::Kind::number;
        value.where = directive.where;
        try {
            value.number =
                evaluateExpression(expression, [this](const std::string& name, std::size_t offset) {
                    return numericVariable(name, offset);
                });
        } catch (const EvalError& error) {
            throwDictionaryError(locateInside(start, expression, error.offset),
                                 error.whatIsWrong + " (character " + std::to_string(error.offset + 1) +
                                     " of '" + oneLine(expression) + "')",
                                 error.expected);
        }
        value.text = formatNumber(value.number);
        return value;
    }

    double numericVariable(const std::string& name, std::size_t offset)
    {
        const Entry* source = resolveReference(name);
        if (!source)
            throw EvalError{offset, "undefined variable '$" + name + "' in #eval expression",
                            "an entry '" + name + "' defined above, in this dictionary or an enclosing one"};
        if (source->isDict() || source->values.size() != 1 || !source->values.front().isNumber())
            throw EvalError{offset, "'$" + name + "' is not a single number",
                            "a variable holding one number, as in 'radius 0.05;'"};
        return source->values.front().number;
    }

    // $name (innermost scope outwards), $a/b (path from the first scope that
    // has a), $!name or $/a/b (top level), $../name (enclosing dictionary), ${...}.
    const Entry* resolveReference(std::string reference) const
    {
        if (reference.size() >= 2 && reference.front() == '{' && reference.back() == '}')
            reference = reference.substr(1, reference.size() - 2);
        if (reference.empty()) return nullptr;
        if (reference[0] == '!' || reference[0] == '/')
            return scopes_.front()->findEntry(reference.substr(1));
        std::size_t up = 0;
        while (reference.compare(0, 3, "../") == 0) ++up, reference.erase(0, 3);
        if (up > 0)
            return up < scopes_.size() ? scopes_[scopes_.size() - 1 - up]->findEntry(reference) : nullptr;
        const std::string first = reference.substr(0, reference.find('/'));
        for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope)
            if ((*scope)->findEntry(first)) return (*scope)->findEntry(reference);
        return nullptr;
    }

    const Entry& resolveMacro(const Token& macro) const
    {
        const Entry* source = resolveReference(macro.text.substr(1));
        if (!source)
            throwDictionaryError(macro.where, "undefined variable '" + macro.text + "'",
                                 "an entry '" + macro.text.substr(1) +
                                     "' defined above, in this dictionary or an enclosing one");
        return *source;
    }

    // `$sub` between entries merges sub's entries here, as defaults that later
    // entries may override.
    void mergeMacro(DictionaryLexer& lexer, Dictionary& dict, const Token& macro)
    {
        const Entry& source = resolveMacro(macro);
        if (!source.isDict())
            throwDictionaryError(
                macro.where, "'" + macro.text + "' names a value where an entry was expected",
                "a dictionary to merge here, or 'keyword " + macro.text + ";' to copy a value");
        charge(countValues(*source.dict), macro.where);
        const Dictionary copy = *source.dict;  // `dict` may hold the source: adding may move it
        for (Entry entry : copy.entries()) {
            entry.overridable = true;
            if (entry.dict) entry.dict->rename(childName(dict, entry.keyword, atTopLevel()));
            dict.add(std::move(entry));
        }
        if (lexer.peek().isPunctuation(';')) lexer.next();
    }

    void parseDirective(DictionaryLexer& lexer, Dictionary& dict, const Token& directive, int depth)
    {
        if (directive.text == "#include" || directive.text == "#includeIfPresent")
            include(lexer, dict, directive, depth);
        else if (directive.text == "#eval")
            throwDictionaryError(directive.where, "#eval in place of an entry",
                                 "#eval inside a value, as in 'radius #eval{ 0.1/2 };'");
        else
            throwDictionaryError(directive.where, "unknown directive '" + directive.text + "'",
                                 "#include \"file\", #includeIfPresent \"file\", or #eval inside a value");
    }

    int includeDepth() const { return static_cast<int>(includeChain_.size()) - 1; }

    void include(DictionaryLexer& lexer, Dictionary& dict, const Token& directive, int depth)
    {
        const Token name = lexer.next();
        if (name.kind != TokenKind::string && name.kind != TokenKind::word)
            throwDictionaryError(name.where, directive.text + " is followed by " + describeToken(name),
                                 "a file name: " + directive.text + " \"file\"");
        if (!limits_.allowIncludes)
            throwDictionaryError(directive.where, directive.text + " is not allowed here",
                                 "a self-contained dictionary");
        const fs::path target = (fs::path(lexer.fileName()).parent_path() / name.text).lexically_normal();
        std::error_code ec;
        if (directive.text == "#includeIfPresent" && !fs::exists(target, ec)) return;
        const IncludedFile file{canonicalName(target), target.string()};
        checkIncludeCycle(directive, file);
        const std::string text = readTextFile(target, file.shown, &name.where);
        includeChain_.push_back(file);
        const std::size_t includingTopDepth = fileTopDepth_;
        fileTopDepth_ = scopes_.size();
        DictionaryLexer includedLexer(text, file.shown);
        parseBody(includedLexer, dict, nullptr, depth);
        fileTopDepth_ = includingTopDepth;
        includeChain_.pop_back();
    }

    void checkIncludeCycle(const Token& directive, const IncludedFile& file) const
    {
        bool cycle = false;
        std::string chain;
        for (const IncludedFile& open : includeChain_) {
            cycle = cycle || open.canonical == file.canonical;
            chain += open.shown + " -> ";
        }
        if (cycle)
            throwDictionaryError(directive.where, "#include cycle: " + chain + file.shown,
                                 "includes that never lead back to a file being read");
        if (includeDepth() >= limits_.maxIncludeDepth)
            throwDictionaryError(
                directive.where,
                "#include nested deeper than " + std::to_string(limits_.maxIncludeDepth) + " files",
                "fewer levels of #include");
    }

    const ParseLimits& limits_;
    std::vector<Dictionary*> scopes_;         // outermost first; the last is being filled
    std::vector<IncludedFile> includeChain_;  // the file being read, and the files including it
    std::size_t valueCount_ = 0;
    std::size_t fileTopDepth_ = 1;  // scopes_.size() at the top level of the file being read
};

}  // namespace

Dictionary Dictionary::parse(const std::string& text, const std::string& fileName, const ParseLimits& limits)
{
    return DictionaryParser(limits).parseTop(text, fileName);
}

Dictionary Dictionary::readFile(const std::filesystem::path& path, const ParseLimits& limits)
{
    const std::string shownName = path.lexically_normal().string();
    return parse(readTextFile(path, shownName, nullptr), shownName, limits);
}

}  // namespace rockfrac
