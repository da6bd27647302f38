// The FoamFile lexer: one pass over the text, one token of look-ahead.
#include "core/dictionaryLexer.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/error.hpp"

namespace rockfrac {

namespace {

bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

// Characters that end a word because they are tokens of their own.
bool isDelimiter(char c)
{
    return std::strchr("(){}[];\"", c) != nullptr;
}

bool isControl(char c)
{
    const auto byte = static_cast<unsigned char>(c);
    return (byte < 0x20 && !isSpace(c)) || byte == 0x7f;
}

// The character(s) that a backslash escape in a string stands for. Unknown
// escapes are kept as written, so that Windows-like paths survive.
void appendEscaped(std::string& out, char escaped)
{
    switch (escaped) {
        case 'n':
            out += '\n';
            break;
        case 't':
            out += '\t';
            break;
        case '"':
        case '\\':
            out += escaped;
            break;
        case '\n':
            break;  // a backslash at the end of a line continues the string
        default:
            out += '\\';
            out += escaped;
    }
}

std::string hexByte(char c)
{
    char buffer[8];
    std::snprintf(buffer, sizeof(buffer), "0x%02x", static_cast<unsigned char>(c));
    return buffer;
}

}  // namespace

std::string SourceLocation::str() const
{
    return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

void throwDictionaryError(const SourceLocation& where, const std::string& whatIsWrong,
                          const std::string& expected)
{
    throw UserError(where.str() + ": " + whatIsWrong + "; expected " + expected);
}

std::string describeToken(const Token& token)
{
    switch (token.kind) {
        case TokenKind::endOfInput:
            return "end of file";
        case TokenKind::punctuation:
            return "'" + token.text + "'";
        case TokenKind::number:
            return "number " + token.text;
        case TokenKind::string:
            return "string \"" + token.text + "\"";
        case TokenKind::dimensions:
            return "dimension set [" + token.text + "]";
        case TokenKind::word:
            break;
    }
    return "word '" + token.text + "'";
}

bool looksLikeNumber(const std::string& word)
{
    std::size_t i = 0;
    const std::size_t n = word.size();
    if (i < n && (word[i] == '+' || word[i] == '-')) ++i;
    std::size_t digits = 0;
    while (i < n && isDigit(word[i])) ++i, ++digits;
    if (i < n && word[i] == '.') {
        ++i;
        while (i < n && isDigit(word[i])) ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < n && (word[i] == 'e' || word[i] == 'E')) {
        ++i;
        if (i < n && (word[i] == '+' || word[i] == '-')) ++i;
        std::size_t exponentDigits = 0;
        while (i < n && isDigit(word[i])) ++i, ++exponentDigits;
        if (exponentDigits == 0) return false;
    }
    return i == n;
}

bool isUnsignedInteger(const std::string& word)
{
    if (word.empty()) return false;
    for (char c : word)
        if (!isDigit(c)) return false;
    return true;
}

bool isPlainWord(const std::string& text)
{
    if (text.empty() || text[0] == '#' || text[0] == '$') return false;
    try {
        DictionaryLexer lexer(text, "word");
        const Token token = lexer.next();
        return token.kind == TokenKind::word && token.text == text && lexer.next().isEnd();
    } catch (const UserError&) {
        return false;
    }
}

DictionaryLexer::DictionaryLexer(const std::string& text, std::string fileName)
    : text_(text), fileName_(std::move(fileName))
{
    previousEnd_ = here();
}

Token DictionaryLexer::next()
{
    Token token = peeked_ ? std::move(*peeked_) : lex();
    peeked_.reset();
    previousEnd_ = {fileName_, token.endLine, token.endColumn};
    return token;
}

const Token& DictionaryLexer::peek()
{
    if (!peeked_) peeked_ = lex();
    return *peeked_;
}

void DictionaryLexer::advance()
{
    if (text_[pos_] == '\n') {
        ++line_;
        lineStart_ = pos_ + 1;
    }
    ++pos_;
}

SourceLocation DictionaryLexer::here() const
{
    return {fileName_, line_, static_cast<int>(pos_ - lineStart_) + 1};
}

Token DictionaryLexer::startToken(TokenKind kind) const
{
    Token token;
    token.kind = kind;
    token.where = here();
    token.begin = pos_;
    return token;
}

void DictionaryLexer::finishToken(Token& token) const
{
    token.end = pos_;
    token.endLine = line_;
    token.endColumn = static_cast<int>(pos_ - lineStart_) + 1;
}

void DictionaryLexer::skipSpaceAndComments()
{
    while (pos_ < text_.size()) {
        const char c = text_[pos_];
        const char following = pos_ + 1 < text_.size() ? text_[pos_ + 1] : '\0';
        if (isSpace(c)) {
            advance();
        } else if (c == '/' && following == '/') {
            while (pos_ < text_.size() && text_[pos_] != '\n') advance();
        } else if (c == '/' && following == '*') {
            const SourceLocation opened = here();
            const std::size_t close = text_.find("*/", pos_ + 2);
            if (close == std::string::npos)
                throwDictionaryError(opened, "unterminated comment '/*'",
                                     "'*/' to close the comment opened here");
            while (pos_ < close + 2) advance();
        } else {
            return;
        }
    }
}

Token DictionaryLexer::lex()
{
    skipSpaceAndComments();
    if (pos_ >= text_.size()) {
        Token end = startToken(TokenKind::endOfInput);
        finishToken(end);
        return end;
    }
    const char c = text_[pos_];
    if (c == '"') return lexString();
    if (c == '[') return lexDimensions();
    if (c == ']')
        throwDictionaryError(here(), "unexpected ']' with no matching '['",
                             "a dimension set to look like [1 -1 -2 0 0 0 0]");
    if (isControl(c))
        throwDictionaryError(here(), "unexpected control character (byte " + hexByte(c) + ")",
                             "plain text; remove the character");
    if (isDelimiter(c)) {
        Token token = startToken(TokenKind::punctuation);
        token.text = std::string(1, c);
        advance();
        finishToken(token);
        return token;
    }
    return lexWordOrNumber();
}

Token DictionaryLexer::lexString()
{
    Token token = startToken(TokenKind::string);
    advance();  // opening quote
    while (pos_ < text_.size() && text_[pos_] != '"') {
        if (text_[pos_] == '\\' && pos_ + 1 < text_.size()) {
            advance();
            appendEscaped(token.text, text_[pos_]);
        } else {
            token.text += text_[pos_];
        }
        advance();
    }
    if (pos_ >= text_.size())
        throwDictionaryError(token.where, "unterminated string", "a closing '\"' for the string opened here");
    advance();  // closing quote
    finishToken(token);
    return token;
}

Token DictionaryLexer::lexDimensions()
{
    Token token = startToken(TokenKind::dimensions);
    advance();  // '['
    const std::size_t close = text_.find_first_of("];{}\"", pos_);
    if (close == std::string::npos || text_[close] != ']')
        throwDictionaryError(token.where, "unterminated dimension set '['",
                             "']' to close it, as in [1 -1 -2 0 0 0 0] or [Pa]");
    token.text = text_.substr(pos_, close - pos_);
    while (pos_ <= close) advance();
    finishToken(token);
    return token;
}

Token DictionaryLexer::lexWordOrNumber()
{
    Token token = startToken(TokenKind::word);
    // ${a/b} is one word even though braces are tokens of their own elsewhere.
    if (text_.compare(pos_, 2, "${") == 0) {
        const std::size_t close = text_.find_first_of("}\n;", pos_);
        if (close != std::string::npos && text_[close] == '}')
            while (pos_ <= close) advance();
    }
    while (pos_ < text_.size()) {
        const char c = text_[pos_];
        if (isSpace(c) || isDelimiter(c) || isControl(c) || c == ']') break;
        if (c == '/' && pos_ + 1 < text_.size() && (text_[pos_ + 1] == '/' || text_[pos_ + 1] == '*')) break;
        advance();
    }
    token.text = text_.substr(token.begin, pos_ - token.begin);
    finishToken(token);
    if (looksLikeNumber(token.text)) {
        token.kind = TokenKind::number;
        if (!std::isfinite(std::strtod(token.text.c_str(), nullptr)))
            throwDictionaryError(token.where, "number " + token.text + " is too large",
                                 "a magnitude below 1.8e308");
    }
    return token;
}

std::string DictionaryLexer::readRawBlock(const Token& openBrace, SourceLocation& start)
{
    start = here();
    const std::size_t begin = pos_;
    int depth = 1;
    while (pos_ < text_.size()) {
        const char c = text_[pos_];
        if (c == '{') ++depth;
        if (c == '}' && --depth == 0) {
            std::string raw = text_.substr(begin, pos_ - begin);
            advance();
            previousEnd_ = here();
            return raw;
        }
        advance();
    }
    throwDictionaryError(openBrace.where, "'{' is never closed", "a matching '}' before the end of the file");
}

}  // namespace rockfrac
