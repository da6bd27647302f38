#include "sourceSizes.hpp"

#include <cctype>
#include <cstddef>

namespace rockfrac::sourceSizes {

namespace {

bool isIdent(char c)
{
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

bool isSpace(char c)
{
    return std::isspace(static_cast<unsigned char>(c)) != 0;
}

void blankAt(std::string& out, std::size_t k)
{
    if (out[k] != '\n') {
        out[k] = ' ';
    }
}

// The identifier (or number) that ends just before position i.
std::string tokenBefore(const std::string& s, std::size_t i)
{
    std::size_t b = i;
    while (b > 0 && isIdent(s[b - 1])) {
        --b;
    }
    return s.substr(b, i - b);
}

// Blanks a quoted literal opened at i (quote '"' or '\''); returns the position after it.
std::size_t blankQuoted(const std::string& in, std::string& out, std::size_t i, char quote)
{
    const std::size_t n = in.size();
    ++i;
    while (i < n && in[i] != quote && in[i] != '\n') {
        if (in[i] == '\\' && i + 1 < n) {
            blankAt(out, i);
            ++i;
        }
        blankAt(out, i);
        ++i;
    }
    return i < n && in[i] == quote ? i + 1 : i;
}

// Blanks a raw string R"delim(...)delim" whose quote is at i; returns the position after it.
std::size_t blankRaw(const std::string& in, std::string& out, std::size_t i)
{
    const std::size_t open = in.find('(', i + 1);
    if (open == std::string::npos) {
        return blankQuoted(in, out, i, '"');
    }
    const std::string closing = ")" + in.substr(i + 1, open - i - 1) + "\"";
    const std::size_t close = in.find(closing, open);
    const std::size_t end = close == std::string::npos ? in.size() : close + closing.size();
    for (std::size_t k = i + 1; k + 1 < end; ++k) {
        blankAt(out, k);
    }
    return end;
}

}  // namespace

int countLines(const std::string& text)
{
    int lines = 0;
    for (char c : text) {
        lines += c == '\n';
    }
    return lines + (!text.empty() && text.back() != '\n');
}

std::string blankNonCode(const std::string& in)
{
    std::string out = in;
    const std::size_t n = in.size();
    std::size_t i = 0;
    bool lineStart = true;  // nothing but blanks (and comments) since the last newline
    while (i < n) {
        const char c = in[i];
        if (c == '\n') {
            lineStart = true;
            ++i;
        } else if (c == '/' && i + 1 < n && in[i + 1] == '/') {
            while (i < n && in[i] != '\n') {
                blankAt(out, i++);
            }
        } else if (c == '/' && i + 1 < n && in[i + 1] == '*') {
            const std::size_t close = in.find("*/", i + 2);
            const std::size_t end = close == std::string::npos ? n : close + 2;
            for (; i < end; ++i) {
                blankAt(out, i);
            }
        } else if (lineStart && c == '#') {
            // A directive, with its continuation lines.
            while (i < n && !(in[i] == '\n' && (i == 0 || in[i - 1] != '\\'))) {
                blankAt(out, i++);
            }
        } else if (c == '"') {
            const std::string prefix = tokenBefore(in, i);
            const bool raw =
                prefix == "R" || prefix == "u8R" || prefix == "uR" || prefix == "UR" || prefix == "LR";
            i = raw ? blankRaw(in, out, i) : blankQuoted(in, out, i, '"');
            lineStart = false;
        } else if (c == '\'') {
            const std::string before = tokenBefore(in, i);
            const bool digitSeparator =
                !before.empty() && std::isdigit(static_cast<unsigned char>(before[0])) != 0;
            i = digitSeparator ? i + 1 : blankQuoted(in, out, i, '\'');
            lineStart = false;
        } else {
            lineStart = lineStart && isSpace(c);
            ++i;
        }
    }
    return out;
}

namespace {

enum class Brace { scope, initializer, function };

std::string trim(const std::string& s)
{
    std::size_t b = 0, e = s.size();
    while (b < e && isSpace(s[b])) {
        ++b;
    }
    while (e > b && isSpace(s[e - 1])) {
        --e;
    }
    return s.substr(b, e - b);
}

bool startsWithWord(const std::string& s, const std::string& word)
{
    return s.compare(0, word.size(), word) == 0 && (s.size() == word.size() || !isIdent(s[word.size()]));
}

// The declaration without its leading template<...> parameter lists and [[attributes]].
std::string stripPrefixes(std::string h)
{
    for (bool again = true; again;) {
        again = false;
        h = trim(h);
        if (startsWithWord(h, "template")) {
            std::size_t k = h.find('<');
            int depth = 0;
            for (; k < h.size(); ++k) {
                depth += (h[k] == '<') - (h[k] == '>');
                if (depth == 0) {
                    break;
                }
            }
            h = k < h.size() ? h.substr(k + 1) : std::string();
            again = true;
        } else if (h.compare(0, 2, "[[") == 0 && h.find("]]") != std::string::npos) {
            h = h.substr(h.find("]]") + 2);
            again = true;
        }
    }
    return h;
}

// Position of the first ':' at parenthesis depth 0 after the first top-level ')' that
// is not part of '::' (a constructor's member initializer list), or npos.
std::size_t initListColon(const std::string& h)
{
    int depth = 0;
    bool closed = false;
    for (std::size_t k = 0; k < h.size(); ++k) {
        const char c = h[k];
        if (c == '(') {
            ++depth;
        } else if (c == ')') {
            closed = closed || depth == 1;
            --depth;
        } else if (c == ':' && depth == 0 && closed) {
            if (k + 1 < h.size() && h[k + 1] == ':') {
                ++k;
            } else if (k == 0 || h[k - 1] != ':') {
                return k;
            }
        }
    }
    return std::string::npos;
}

bool hasTopLevel(const std::string& h, char what)
{
    int depth = 0;
    for (std::size_t k = 0; k < h.size(); ++k) {
        const char c = h[k];
        if (depth == 0 && c == what) {
            if (what != '=') {
                return true;
            }
            const char before = k > 0 ? h[k - 1] : ' ';
            const char after = k + 1 < h.size() ? h[k + 1] : ' ';
            const bool comparison =
                after == '=' || before == '=' || before == '!' || before == '<' || before == '>';
            const bool isOperator = h.find("operator") != std::string::npos;
            if (!comparison && !isOperator) {
                return true;
            }
        }
        depth += (c == '(') - (c == ')');
    }
    return false;
}

Brace classify(const std::string& header)
{
    const std::string h = stripPrefixes(header);
    if (startsWithWord(h, "namespace") ||
        (startsWithWord(h, "inline") && trim(h.substr(6)).rfind("namespace", 0) == 0)) {
        return Brace::scope;
    }
    if (startsWithWord(h, "extern") && trim(h.substr(6)).rfind('"', 0) == 0) {
        return Brace::scope;
    }
    for (const char* key : {"class", "struct", "union", "enum", "typedef"}) {
        if (startsWithWord(h, key)) {
            return Brace::scope;
        }
    }
    const std::size_t colon = initListColon(h);
    if (colon != std::string::npos) {
        const std::string t = trim(h);
        const char last = t.empty() ? ' ' : t.back();
        return last == ')' || last == '}' ? Brace::function : Brace::initializer;
    }
    if (hasTopLevel(h, '=') || !hasTopLevel(h, '(')) {
        return Brace::initializer;
    }
    return Brace::function;
}

// The qualified name that ends just before position e (after blanks when
// `skipBlanks`; template arguments of a qualifier included).
std::size_t qualifiedNameStart(const std::string& h, std::size_t e, bool skipBlanks)
{
    std::size_t b = e;
    while (skipBlanks && b > 0 && isSpace(h[b - 1])) {
        --b;
    }
    while (b > 0) {
        const char c = h[b - 1];
        if (isIdent(c) || c == ':' || c == '~') {
            --b;
        } else if (c == '>' && b > 1 && h[b - 2] != '-') {
            int depth = 0;
            std::size_t k = b;
            while (k > 0) {
                --k;
                depth += (h[k] == '>') - (h[k] == '<');
                if (depth == 0) {
                    break;
                }
            }
            if (depth != 0 || k == 0 || !isIdent(h[k - 1])) {
                break;
            }
            b = k;
        } else {
            break;
        }
    }
    return b;
}

std::string collapse(const std::string& s)
{
    std::string out;
    for (char c : s) {
        if (!isSpace(c)) {
            out += c;
        }
    }
    return out;
}

std::string functionName(const std::string& header)
{
    std::string h = stripPrefixes(header);
    const std::size_t colon = initListColon(h);
    if (colon != std::string::npos) {
        h = h.substr(0, colon);
    }
    const std::size_t op = h.find("operator");
    if (op != std::string::npos && (op == 0 || !isIdent(h[op - 1]))) {
        std::size_t k = op + 8;
        while (k < h.size() && isSpace(h[k])) {
            ++k;
        }
        std::size_t paren = h.find('(', h.compare(k, 2, "()") == 0 ? k + 2 : k);
        if (paren == std::string::npos) {
            paren = h.size();
        }
        const std::size_t b = qualifiedNameStart(h, op, false);
        return collapse(h.substr(b, paren - b));
    }
    int depth = 0;
    for (std::size_t k = 0; k < h.size(); ++k) {
        if (h[k] == '(' && depth == 0) {
            const std::size_t b = qualifiedNameStart(h, k, true);
            const std::string name = collapse(h.substr(b, k - b));
            const bool notAName = name.empty() || name == "decltype" || name == "alignas" ||
                                  name == "__attribute__" || name == "__declspec" || name == "noexcept";
            if (!notAName) {
                return name;
            }
        }
        depth += (h[k] == '(') - (h[k] == ')');
    }
    return "?";
}

bool isAccessSpecifier(const std::string& header)
{
    const std::string h = trim(header);
    return h == "public" || h == "protected" || h == "private";
}

}  // namespace

std::vector<FunctionSpan> findFunctions(const std::string& text, std::string& error)
{
    const std::string s = blankNonCode(text);
    const std::size_t n = s.size();
    std::vector<FunctionSpan> found;
    int scopes = 0;  // open namespaces and classes
    int line = 1, headerLine = 0, paren = 0;
    std::string header;  // the declaration read since the last ';', '{' or '}' at scope level
    auto reset = [&] {
        header.clear();
        headerLine = 0;
        paren = 0;
    };
    // From the '{' at i to its matching '}': returns its position, or n on end of text.
    auto skipBraces = [&](std::size_t i) {
        int depth = 0;
        for (; i < n; ++i) {
            line += s[i] == '\n';
            depth += (s[i] == '{') - (s[i] == '}');
            if (depth == 0) {
                return i;
            }
        }
        return n;
    };
    for (std::size_t i = 0; i < n; ++i) {
        const char c = s[i];
        if (c == '\n') {
            ++line;
            header += ' ';
            continue;
        }
        paren += (c == '(') - (c == ')');
        if (c == ';' && paren == 0) {
            reset();
        } else if (c == ':' && isAccessSpecifier(header) && (i + 1 == n || s[i + 1] != ':')) {
            reset();
        } else if (c == '}') {
            if (scopes == 0) {
                error = "line " + std::to_string(line) + ": '}' closes nothing";
                return found;
            }
            --scopes;
            reset();
        } else if (c == '{') {
            const int openLine = line;
            const Brace kind = classify(header);
            if (kind == Brace::scope) {
                ++scopes;
                reset();
                continue;
            }
            i = skipBraces(i);
            if (i == n) {
                error = "line " + std::to_string(openLine) + ": '{' is never closed";
                return found;
            }
            if (kind == Brace::initializer) {
                header += "{}";
            } else {
                found.push_back({functionName(header), headerLine == 0 ? openLine : headerLine, line});
                reset();
            }
        } else {
            if (headerLine == 0 && !isSpace(c)) {
                headerLine = line;
            }
            header += c;
        }
    }
    if (scopes != 0) {
        error = std::to_string(scopes) + " namespace or class brace(s) never closed";
    }
    return found;
}

}  // namespace rockfrac::sourceSizes
