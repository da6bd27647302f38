// Canonical FoamFile text: OpenFOAM's layout (values aligned at column 16,
// four-space indent, long lists one item per line), so that what caseDict
// prints can be pasted back into a case.
#include <sstream>

#include "core/dictionary.hpp"
#include "core/dictionaryLexer.hpp"

namespace rockfrac {

namespace {

constexpr std::size_t keywordWidth = 16;  // values start at this column, as OpenFOAM writes them
constexpr std::size_t inlineWidth = 80;   // longer lists go one item per line

std::string indentation(int level)
{
    return std::string(4 * static_cast<std::size_t>(level), ' ');
}

std::string quote(const std::string& text)
{
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n')
            out += "\\n";
        else if (c == '\t')
            out += "\\t";
        else
            out += c;
    }
    return out + "\"";
}

// A keyword as it reads back: words stay bare, anything else is quoted.
std::string keywordText(const std::string& keyword)
{
    return isPlainWord(keyword) ? keyword : quote(keyword);
}

std::string inlineText(const Value& value)
{
    switch (value.kind) {
        case Value::Kind::number:
        case Value::Kind::word:
            return value.text;
        case Value::Kind::string:
            return quote(value.text);
        case Value::Kind::list:
            break;
    }
    std::string text = "(";
    for (std::size_t i = 0; i < value.items.size(); ++i) text += (i ? " " : "") + inlineText(value.items[i]);
    return text + ")";
}

// Whether `item` printed before a list on the next line would read back as
// the size prefix of that list (N followed by '(' on a later line).
bool looksLikeSizePrefix(const Value& item, const Value* next)
{
    return next && next->isList() && item.isNumber() &&
           item.text.find_first_not_of("0123456789") == std::string::npos;
}

// A list too long for one line: '(' and ')' on lines of their own.
void writeLongList(std::ostream& out, const Value& list, int level)
{
    out << indentation(level) << "(\n";
    for (std::size_t i = 0; i < list.items.size(); ++i) {
        const Value& item = list.items[i];
        const Value* next = i + 1 < list.items.size() ? &list.items[i + 1] : nullptr;
        const std::string text = inlineText(item);
        if (looksLikeSizePrefix(item, next)) {
            out << indentation(level + 1) << text << " " << inlineText(*next) << "\n";
            ++i;
        } else if (item.isList() && text.size() > inlineWidth) {
            writeLongList(out, item, level + 1);
        } else {
            out << indentation(level + 1) << text << "\n";
        }
    }
    out << indentation(level) << ")\n";
}

std::string paddedKeyword(const std::string& keyword)
{
    std::string text = keywordText(keyword);
    text.resize(std::max(text.size() + 1, keywordWidth), ' ');
    return text;
}

void writeBody(std::ostream& out, const Dictionary& dict, int level)
{
    for (const Entry& entry : dict.entries()) out << toString(entry, level);
}

}  // namespace

std::string valueText(const Entry& entry)
{
    std::string text = entry.dimensions ? entry.dimensions->str() : "";
    for (const Value& value : entry.values) text += (text.empty() ? "" : " ") + inlineText(value);
    return text;
}

std::string toString(const Entry& entry, int indentLevel)
{
    std::ostringstream out;
    const std::string indent = indentation(indentLevel);
    if (entry.isDict()) {
        out << indent << keywordText(entry.keyword) << "\n" << indent << "{\n";
        writeBody(out, *entry.dict, indentLevel + 1);
        out << indent << "}\n";
        return out.str();
    }
    const std::string values = valueText(entry);
    const bool oneLongList = entry.values.size() == 1 && entry.values.front().isList() && !entry.dimensions;
    if (oneLongList && values.size() > inlineWidth) {
        out << indent << keywordText(entry.keyword) << "\n";
        std::ostringstream list;
        writeLongList(list, entry.values.front(), indentLevel);
        std::string listText = list.str();
        listText.insert(listText.size() - 1, ";");  // the ';' follows the closing ')'
        out << listText;
        return out.str();
    }
    if (values.empty()) return indent + keywordText(entry.keyword) + ";\n";
    return indent + paddedKeyword(entry.keyword) + values + ";\n";
}

std::string toString(const Dictionary& dict)
{
    std::ostringstream out;
    if (const Dictionary* header = dict.header()) {
        out << "FoamFile\n{\n";
        writeBody(out, *header, 1);
        out << "}\n\n";
    }
    writeBody(out, dict, 0);
    return out.str();
}

}  // namespace rockfrac
