#pragma once
// The arithmetic of `#eval "..."` and `#eval{ ... }` in dictionaries:
// + - * / ^ (power, right-associative), unary minus, parentheses, the constant
// pi, the functions sqrt exp log log10 sin cos tan asin acos atan atan2 pow abs
// min max floor ceil, and $variables, resolved by the caller.
#include <cstddef>
#include <functional>
#include <string>

namespace rockfrac {

// A mistake in an expression, at a byte offset inside it; the dictionary
// parser turns it into a file:line:column message.
struct EvalError {
    std::size_t offset;
    std::string whatIsWrong;
    std::string expected;
};

// Value of a variable named in the expression (without '$' or braces), or an
// exception of the caller's choosing. `offset` is where the '$' is.
using EvalVariableLookup = std::function<double(const std::string& name, std::size_t offset)>;

// Throws EvalError. Every intermediate result must be finite.
double evaluateExpression(const std::string& expression, const EvalVariableLookup& lookupVariable);

}  // namespace rockfrac
