// Line counts of C++/CUDA sources and of the functions they define, for the size
// check (checkSourceSizes): a heuristic brace matcher, not a C++ parser.
//
// Comments, string and character literals (raw strings included) and preprocessor
// lines are blanked first, so that the braces they hold do not count. A '{' at
// namespace or class scope then opens:
//   - a namespace (namespace ..., extern "C") or a class (class, struct, union, enum),
//     inside which functions are looked for again;
//   - an initializer (the declaration has '=' outside parentheses, or no parentheses
//     at all, or it is a member initializer of a constructor), skipped;
//   - otherwise a function body: the function spans from the first line of its
//     declaration (template<...> included) to the line of the matching '}'.
// Lambdas and local classes count as part of the function that holds them.
#pragma once

#include <string>
#include <vector>

namespace rockfrac::sourceSizes {

struct FunctionSpan {
    std::string name;  // as written before the parameter list: "Analysis::execute", "operator()"
    int firstLine = 0, lastLine = 0;  // 1-based, inclusive
    int lines() const { return lastLine - firstLine + 1; }
};

// Number of lines of a file's text (a last line without '\n' counts).
int countLines(const std::string& text);

// The text with comments, literals' contents and preprocessor lines replaced by
// spaces; newlines are kept, so line numbers stay.
std::string blankNonCode(const std::string& text);

// The functions defined in a source text. On unbalanced braces, `error` gets the
// line and what is wrong and the result holds what was found before it.
std::vector<FunctionSpan> findFunctions(const std::string& text, std::string& error);

}  // namespace rockfrac::sourceSizes
