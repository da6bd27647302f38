#pragma once
// The small vocabulary shared by the dictionary lexer, parser, editor and the
// models that read their own token streams: where a thing is in a file, what a
// token is, and how an error about it is worded.
#include <cstddef>
#include <string>

namespace rockfrac {

// Where something is in a dictionary file. Lines and columns count from 1;
// columns count bytes (a tab is one column), as compilers do.
struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;

    std::string str() const;  // "file:line:column"
};

// Every dictionary error has one shape, so that editors and users can jump to
// it:  "file:line:column: <what is wrong>; expected <what was expected>".
[[noreturn]] void throwDictionaryError(const SourceLocation& where, const std::string& whatIsWrong,
                                       const std::string& expected);

enum class TokenKind {
    word,         // keyword, word value, directive (#include) or macro ($var)
    string,       // "quoted", text holds the unescaped contents
    number,       // text holds the number as written
    punctuation,  // one of ( ) { } ;
    dimensions,   // [ ... ], text holds what is between the brackets
    endOfInput,
};

struct Token {
    TokenKind kind = TokenKind::endOfInput;
    std::string text;
    SourceLocation where;            // first character
    int endLine = 0, endColumn = 0;  // just after the last character
    std::size_t begin = 0, end = 0;  // byte range in the source text

    bool isPunctuation(char c) const { return kind == TokenKind::punctuation && text[0] == c; }
    bool isEnd() const { return kind == TokenKind::endOfInput; }
};

// Readable name of a token for messages: "';'", "word 'abc'", "end of file".
std::string describeToken(const Token& token);

}  // namespace rockfrac
