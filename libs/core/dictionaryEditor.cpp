// The dictionary editor: finds an entry in the text as written (byte offsets
// of keyword, value and ';'), then splices new text in, leaving every other
// byte alone. Nothing is expanded: #include and $macros are skipped as text.
#include "core/dictionaryEditor.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <vector>

#include "core/dictionaryLexer.hpp"
#include "core/error.hpp"

namespace rockfrac {

namespace {

struct TextDictionary;

// One entry as it appears in the text.
struct TextEntry {
    std::string keyword;
    SourceLocation keywordLocation;
    std::size_t keywordBegin = 0, keywordEnd = 0;
    std::size_t dimensionsBegin = std::string::npos;  // a dimension set before the value, if any
    std::size_t valueBegin = 0, valueEnd = 0;         // value tokens; empty at the ';' of `keyword;`
    std::size_t terminatorEnd = 0;                    // just after the ';' or the closing '}'
    int valueColumn = 0;
    std::unique_ptr<TextDictionary> dict;
};

struct TextDictionary {
    std::string name;
    std::size_t openBrace = std::string::npos;  // npos for the file itself
    std::size_t close = 0;                      // offset of '}', or the text size
    SourceLocation closeLocation;
    std::vector<TextEntry> entries;

    const TextEntry* find(const std::string& keyword) const
    {
        for (auto e = entries.rbegin(); e != entries.rend(); ++e)
            if (e->keyword == keyword) return &*e;
        return nullptr;
    }
};

// Reads the structure of a dictionary text: entries and their byte ranges.
class TextScanner {
public:
    TextScanner(const std::string& text, const std::string& fileName)
        : lexer_(text, fileName), size_(text.size())
    {
    }

    TextDictionary scan(const std::string& name)
    {
        TextDictionary root;
        root.name = name;
        scanBody(root, nullptr);
        return root;
    }

private:
    void scanBody(TextDictionary& dict, const Token* open)
    {
        dict.openBrace = open ? open->begin : std::string::npos;
        for (;;) {
            const Token token = lexer_.next();
            if (token.isEnd() || token.isPunctuation('}')) {
                if (token.isEnd() != (open == nullptr))
                    throwDictionaryError(token.where, "unbalanced braces: unexpected " + describeToken(token),
                                         "every '{' closed by one '}'");
                dict.close = token.isEnd() ? size_ : token.begin;
                dict.closeLocation = token.where;
                return;
            }
            if (token.isPunctuation(';')) continue;
            const bool directiveOrMacro =
                token.kind == TokenKind::word && (token.text[0] == '#' || token.text[0] == '$');
            if (directiveOrMacro)
                skipDirectiveOrMacro(token);
            else if (token.kind == TokenKind::word || token.kind == TokenKind::string)
                scanEntry(dict, token);
            else
                throwDictionaryError(token.where, "unexpected " + describeToken(token), "a keyword or '}'");
        }
    }

    void skipDirectiveOrMacro(const Token& token)
    {
        if (token.text[0] == '#')
            lexer_.next();  // the file name of #include
        else if (lexer_.peek().isPunctuation(';'))
            lexer_.next();
    }

    void scanEntry(TextDictionary& dict, const Token& keyword)
    {
        TextEntry entry;
        entry.keyword = keyword.text;
        entry.keywordLocation = keyword.where;
        entry.keywordBegin = keyword.begin;
        entry.keywordEnd = keyword.end;
        if (lexer_.peek().isPunctuation('{')) {
            const Token open = lexer_.next();
            entry.valueBegin = open.begin;
            entry.dict = std::make_unique<TextDictionary>();
            const bool parentIsFile = dict.openBrace == std::string::npos;
            entry.dict->name = parentIsFile ? keyword.text : dict.name + "/" + keyword.text;
            scanBody(*entry.dict, &open);
            entry.valueEnd = entry.terminatorEnd = entry.dict->close + 1;
        } else {
            scanValue(entry);
        }
        dict.entries.push_back(std::move(entry));
    }

    // Value tokens up to the ';' at bracket depth zero.
    void scanValue(TextEntry& entry)
    {
        int depth = 0;
        bool first = true;
        for (;;) {
            const Token token = lexer_.next();
            if (token.isEnd())
                throwDictionaryError(lexer_.previousEnd(),
                                     "missing ';' after the value of '" + entry.keyword + "'",
                                     "';' to end the entry");
            if (depth == 0 && token.isPunctuation(';')) {
                if (first) entry.valueBegin = entry.valueEnd = token.begin;
                entry.terminatorEnd = token.end;
                return;
            }
            if (first && token.kind == TokenKind::dimensions && entry.dimensionsBegin == std::string::npos) {
                entry.dimensionsBegin = token.begin;  // kept when only the value changes
                continue;
            }
            if (first) entry.valueBegin = token.begin, entry.valueColumn = token.where.column;
            first = false;
            entry.valueEnd = token.end;
            if (token.isPunctuation('(') || token.isPunctuation('{')) ++depth;
            if ((token.isPunctuation(')') || token.isPunctuation('}')) && --depth < 0)
                throwDictionaryError(
                    token.where,
                    "unbalanced " + describeToken(token) + " in the value of '" + entry.keyword + "'",
                    "';' to end the entry");
            if (token.text == "#eval" && lexer_.peek().isPunctuation('{')) {
                SourceLocation start;
                lexer_.readRawBlock(lexer_.next(), start);
                entry.valueEnd = lexer_.position();
            }
        }
    }

    DictionaryLexer lexer_;
    std::size_t size_;
};

std::vector<std::string> splitKeyPath(const std::string& keyPath)
{
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (;;) {
        const std::size_t slash = keyPath.find('/', start);
        parts.push_back(keyPath.substr(start, slash - start));
        if (slash == std::string::npos) break;
        start = slash + 1;
    }
    for (const std::string& part : parts)
        if (part.empty())
            throw UserError("bad entry path '" + keyPath +
                            "'; expected keywords separated by single '/', as in bond/tensileStrength");
    return parts;
}

// Where an entry is, or where it would go: the deepest existing dictionary on
// the path, and the path components still missing below it.
struct Position {
    const TextDictionary* dict;
    const TextEntry* entry;            // null when the entry is missing
    std::vector<std::string> missing;  // components from `dict` down, when missing
};

Position locate(const TextDictionary& root, const std::string& keyPath)
{
    const std::vector<std::string> parts = splitKeyPath(keyPath);
    const TextDictionary* dict = &root;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const TextEntry* entry = dict->find(parts[i]);
        if (!entry) return {dict, nullptr, std::vector<std::string>(parts.begin() + i, parts.end())};
        if (i + 1 == parts.size()) return {dict, entry, {}};
        if (!entry->dict)
            throwDictionaryError(
                entry->keywordLocation, "'" + parts[i] + "' is not a dictionary",
                "a sub-dictionary '" + parts[i] + " { ... }' to hold '" + parts.back() + "'");
        dict = entry->dict.get();
    }
    return {dict, nullptr, {}};  // not reached
}

TextDictionary scanText(const std::string& text, const std::string& fileName)
{
    return TextScanner(text, fileName).scan(std::filesystem::path(fileName).filename().string());
}

bool startsDictionary(const std::string& valueText)
{
    const std::size_t first = valueText.find_first_not_of(" \t\n");
    return first != std::string::npos && valueText[first] == '{';
}

// The new value must be value tokens only: no ';' at the outer level (which
// would smuggle in another entry), balanced brackets, not empty.
void checkValueText(const std::string& valueText, const std::string& keyPath)
{
    const std::string expected = "value tokens such as 28e6, (0 0 1) or \"text\", without ';'";
    DictionaryLexer lexer(valueText, "new value of '" + keyPath + "'");
    int depth = 0;
    bool empty = true;
    for (Token token = lexer.next(); !token.isEnd(); token = lexer.next()) {
        empty = false;
        if (token.isPunctuation('(') || token.isPunctuation('{')) ++depth;
        if (token.isPunctuation(')') || token.isPunctuation('}')) --depth;
        if (depth < 0 || (depth == 0 && token.isPunctuation(';')))
            throw UserError("new value '" + valueText + "' for '" + keyPath + "' has an unexpected " +
                            describeToken(token) + "; expected " + expected);
    }
    if (empty) throw UserError("empty new value for '" + keyPath + "'; expected " + expected);
    if (depth != 0)
        throw UserError("new value '" + valueText + "' for '" + keyPath +
                        "' has unbalanced brackets; expected " + expected);
}

std::size_t lineStartOf(const std::string& text, std::size_t offset)
{
    const std::size_t newline = offset == 0 ? std::string::npos : text.rfind('\n', offset - 1);
    return newline == std::string::npos ? 0 : newline + 1;
}

std::string leadingSpace(const std::string& text, std::size_t offset)
{
    const std::size_t start = lineStartOf(text, offset);
    const std::size_t end = text.find_first_not_of(" \t", start);
    return text.substr(start, (end == std::string::npos ? text.size() : end) - start);
}

// After `offset`: spaces, then optionally a // comment, then the end of the
// line? Returns where that line ends (the '\n' or the text end), else npos.
std::size_t restOfLineIsComment(const std::string& text, std::size_t offset)
{
    std::size_t pos = text.find_first_not_of(" \t\r", offset);
    if (pos == std::string::npos) return text.size();
    if (text.compare(pos, 2, "//") == 0) pos = text.find('\n', pos);
    if (pos == std::string::npos) return text.size();
    return text[pos] == '\n' ? pos : std::string::npos;
}

// `keyword value;` (or nested sub-dictionaries for the missing components),
// one line per element of the result, without indentation.
std::vector<std::string> newEntryLines(const std::vector<std::string>& missing, const std::string& valueText,
                                       std::size_t valueOffset)
{
    const std::string& keyword = missing.front();
    if (missing.size() == 1) {
        std::string line = keyword;
        line.resize(std::max(keyword.size() + 1, valueOffset), ' ');
        return {line + valueText + (startsDictionary(valueText) ? "" : ";")};
    }
    std::vector<std::string> lines = {keyword, "{"};
    for (const std::string& inner :
         newEntryLines(std::vector<std::string>(missing.begin() + 1, missing.end()), valueText, 0))
        lines.push_back("    " + inner);
    lines.push_back("}");
    return lines;
}

// The column offset at which siblings start their values, when they align
// them (OpenFOAM pads keywords to 16); 0 when they use a single space.
std::size_t siblingValueOffset(const TextDictionary& dict)
{
    for (auto e = dict.entries.rbegin(); e != dict.entries.rend(); ++e) {
        if (e->dict || e->valueBegin == e->valueEnd) continue;
        const std::size_t offset = static_cast<std::size_t>(e->valueColumn - e->keywordLocation.column);
        return offset > e->keyword.size() + 1 ? offset : 0;
    }
    return 0;
}

// A keyword the editor writes must read back as that keyword: one plain word,
// not a number, directive or macro.
void checkNewKeyword(const std::string& keyword, const std::string& keyPath)
{
    if (!isPlainWord(keyword))
        throw UserError("cannot add '" + keyPath + "': '" + keyword +
                        "' is not a plain keyword; expected words of letters, digits and _ . : - such as "
                        "bond/tensileStrength");
}

std::string insertEntry(const std::string& text, const TextDictionary& dict,
                        const std::vector<std::string>& missing, const std::string& valueText,
                        const std::string& keyPath)
{
    for (const std::string& keyword : missing) checkNewKeyword(keyword, keyPath);
    std::string indent;
    std::size_t insertAt;
    std::string closing;  // text put back before a '}' that shared the line of its '{'
    if (!dict.entries.empty()) {
        const TextEntry& last = dict.entries.back();
        indent = leadingSpace(text, last.keywordBegin);
        const std::size_t lineEnd = restOfLineIsComment(text, last.terminatorEnd);
        insertAt = lineEnd != std::string::npos ? lineEnd : last.terminatorEnd;
    } else if (dict.openBrace != std::string::npos) {
        indent = leadingSpace(text, dict.openBrace) + "    ";
        insertAt = dict.openBrace + 1;
        if (text.find('\n', insertAt) > dict.close) closing = "\n" + leadingSpace(text, dict.openBrace);
    } else {
        insertAt = text.size();
    }
    std::string block;
    for (const std::string& line : newEntryLines(missing, valueText, siblingValueOffset(dict)))
        block += "\n" + indent + line;
    if (insertAt == text.size() && dict.entries.empty()) {
        // An empty file, or one with comments only: append as whole lines.
        block = block.substr(1) + "\n";
        if (!text.empty() && text.back() != '\n') block = "\n" + block;
    }
    return text.substr(0, insertAt) + block + closing + text.substr(insertAt);
}

// Put "// comment" after the entry's ';', replacing a comment already there.
std::string withComment(const std::string& text, std::size_t terminatorEnd, const std::string& comment)
{
    if (comment.empty()) return text;
    if (comment.find('\n') != std::string::npos)
        throw UserError("comment '" + comment + "' spans lines; expected a one-line comment");
    std::size_t pos = text.find_first_not_of(" \t", terminatorEnd);
    const bool hasComment = pos != std::string::npos && text.compare(pos, 2, "//") == 0;
    const std::size_t end = hasComment ? std::min(text.find('\n', pos), text.size()) : terminatorEnd;
    if (!hasComment) pos = terminatorEnd;
    return text.substr(0, pos) + (hasComment ? "" : " ") + "// " + comment + text.substr(end);
}

std::string replaceValue(const std::string& text, const TextEntry& entry, const std::string& valueText,
                         const std::string& comment)
{
    const std::string commented = withComment(text, entry.terminatorEnd, comment);
    // A sub-dictionary becoming a value, or the other way round: rewrite all
    // after the keyword. Otherwise only the value tokens change.
    if (entry.dict || startsDictionary(valueText)) {
        const std::string terminator = startsDictionary(valueText) ? "" : ";";
        return commented.substr(0, entry.keywordEnd) + " " + valueText + terminator +
               commented.substr(entry.terminatorEnd);
    }
    // A new value with its own dimension set replaces the old set too.
    const bool newDimensions = valueText.find_first_not_of(" \t") != std::string::npos &&
                               valueText[valueText.find_first_not_of(" \t")] == '[';
    const bool hasDimensions = entry.dimensionsBegin != std::string::npos;
    const std::size_t begin = newDimensions && hasDimensions ? entry.dimensionsBegin : entry.valueBegin;
    const std::string spacing = entry.valueBegin == entry.valueEnd && begin == entry.valueBegin ? " " : "";
    return commented.substr(0, begin) + spacing + valueText + commented.substr(entry.valueEnd);
}

}  // namespace

std::string setEntry(const std::string& text, const std::string& keyPath, const std::string& newValueText,
                     const std::string& fileName, const std::string& comment)
{
    checkValueText(newValueText, keyPath);
    const TextDictionary root = scanText(text, fileName);
    const Position position = locate(root, keyPath);
    if (position.entry) return replaceValue(text, *position.entry, newValueText, comment);
    const std::string added = insertEntry(text, *position.dict, position.missing, newValueText, keyPath);
    if (comment.empty()) return added;
    // The new entry is the last of its dictionary: find it again to comment it.
    const TextDictionary again = scanText(added, fileName);
    return withComment(added, locate(again, keyPath).entry->terminatorEnd, comment);
}

bool hasTextEntry(const std::string& text, const std::string& keyPath, const std::string& fileName)
{
    const TextDictionary root = scanText(text, fileName);
    return locate(root, keyPath).entry != nullptr;
}

std::string addEntry(const std::string& text, const std::string& keyPath, const std::string& newValueText,
                     const std::string& fileName, const std::string& comment)
{
    const TextDictionary root = scanText(text, fileName);
    if (const TextEntry* existing = locate(root, keyPath).entry)
        throwDictionaryError(existing->keywordLocation, "entry '" + keyPath + "' exists already",
                             "a new entry; to change its value, set it instead (caseDict -set)");
    return setEntry(text, keyPath, newValueText, fileName, comment);
}

std::string replaceEntry(const std::string& text, const std::string& keyPath, const std::string& newValueText,
                         const std::string& fileName, const std::string& comment)
{
    const TextDictionary root = scanText(text, fileName);
    const Position position = locate(root, keyPath);
    if (!position.entry)
        throwDictionaryError(
            position.dict->closeLocation,
            "no entry '" + keyPath + "' in the text of dictionary '" + position.dict->name + "'",
            "an existing entry (caseDict -keywords lists them), or add it (caseDict -add)");
    return setEntry(text, keyPath, newValueText, fileName, comment);
}

std::string removeEntry(const std::string& text, const std::string& keyPath, const std::string& fileName)
{
    const TextDictionary root = scanText(text, fileName);
    const Position position = locate(root, keyPath);
    if (!position.entry)
        throwDictionaryError(
            position.dict->closeLocation,
            "no entry '" + keyPath + "' to remove in dictionary '" + position.dict->name + "'",
            "an existing entry (caseDict -keywords lists them)");
    const TextEntry& entry = *position.entry;
    const std::size_t lineStart = lineStartOf(text, entry.keywordBegin);
    const bool aloneBefore = text.find_first_not_of(" \t", lineStart) == entry.keywordBegin;
    const std::size_t lineEnd = restOfLineIsComment(text, entry.terminatorEnd);
    if (aloneBefore && lineEnd != std::string::npos) {
        // The entry has its line(s) to itself: remove them, newline included.
        const std::size_t end = lineEnd < text.size() ? lineEnd + 1 : lineEnd;
        const std::size_t start = (end == text.size() && lineStart > 0) ? lineStart - 1 : lineStart;
        return text.substr(0, start) + text.substr(end);
    }
    const std::size_t end = std::min(text.find_first_not_of(" \t", entry.terminatorEnd), text.size());
    return text.substr(0, entry.keywordBegin) + text.substr(end);
}

}  // namespace rockfrac
