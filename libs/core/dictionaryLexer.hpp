#pragma once
// Tokens of the FoamFile format, read in one linear pass with no backtracking
// beyond one token of look-ahead (so a 1 MB field of numbers lexes in
// milliseconds). Comments and white space are skipped here; directives and
// macros are words and are the parser's business.
#include <optional>
#include <string>

#include "core/dictionaryToken.hpp"

namespace rockfrac {

class DictionaryLexer {
public:
    // `text` must outlive the lexer.
    DictionaryLexer(const std::string& text, std::string fileName);

    Token next();
    const Token& peek();

    // The raw text of a { } block whose '{' was the last token read, up to its
    // matching '}' (consumed). Used by #eval{ ... }; `start` locates the text.
    std::string readRawBlock(const Token& openBrace, SourceLocation& start);

    const std::string& fileName() const { return fileName_; }
    // Byte offset of the next unread character (after a peeked token, if any).
    std::size_t position() const { return peeked_ ? peeked_->begin : pos_; }
    // Just after the last token that next() returned: where a forgotten ';' belongs.
    const SourceLocation& previousEnd() const { return previousEnd_; }

private:
    Token lex();
    void skipSpaceAndComments();
    void advance();
    SourceLocation here() const;
    Token startToken(TokenKind kind) const;
    void finishToken(Token& token) const;

    Token lexString();
    Token lexDimensions();
    Token lexWordOrNumber();

    const std::string& text_;
    std::string fileName_;
    std::size_t pos_ = 0;
    int line_ = 1;
    std::size_t lineStart_ = 0;
    std::optional<Token> peeked_;
    SourceLocation previousEnd_;
};

// Whether `word` is a number in the format's syntax: [+-]digits[.digits][e[+-]digits].
bool looksLikeNumber(const std::string& word);
// Whether `text` reads back as exactly this one word: not a number, string,
// directive (#...) or macro ($...); no white space, control or delimiter
// characters. Keywords written by the formatter and the editor must be.
bool isPlainWord(const std::string& text);
// Whether `word` is an unsigned integer without sign, point or exponent (a list size).
bool isUnsignedInteger(const std::string& word);

}  // namespace rockfrac
