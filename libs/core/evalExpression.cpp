// A recursive-descent evaluator for #eval: one function per precedence level.
#include "core/evalExpression.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <vector>

namespace rockfrac {

namespace {

struct Function {
    int arity;
    double (*apply)(const std::vector<double>&);
};

const std::map<std::string, Function>& functions()
{
    using Args = const std::vector<double>&;
    static const std::map<std::string, Function> table = {
        {"sqrt", {1, [](Args a) { return std::sqrt(a[0]); }}},
        {"exp", {1, [](Args a) { return std::exp(a[0]); }}},
        {"log", {1, [](Args a) { return std::log(a[0]); }}},
        {"log10", {1, [](Args a) { return std::log10(a[0]); }}},
        {"sin", {1, [](Args a) { return std::sin(a[0]); }}},
        {"cos", {1, [](Args a) { return std::cos(a[0]); }}},
        {"tan", {1, [](Args a) { return std::tan(a[0]); }}},
        {"asin", {1, [](Args a) { return std::asin(a[0]); }}},
        {"acos", {1, [](Args a) { return std::acos(a[0]); }}},
        {"atan", {1, [](Args a) { return std::atan(a[0]); }}},
        {"atan2", {2, [](Args a) { return std::atan2(a[0], a[1]); }}},
        {"pow", {2, [](Args a) { return std::pow(a[0], a[1]); }}},
        {"abs", {1, [](Args a) { return std::fabs(a[0]); }}},
        {"min", {2, [](Args a) { return std::fmin(a[0], a[1]); }}},
        {"max", {2, [](Args a) { return std::fmax(a[0], a[1]); }}},
        {"floor", {1, [](Args a) { return std::floor(a[0]); }}},
        {"ceil", {1, [](Args a) { return std::ceil(a[0]); }}},
    };
    return table;
}

const char* const functionList =
    "sqrt exp log log10 sin cos tan asin acos atan atan2 pow abs min max floor ceil";

const double pi = std::acos(-1.0);

// Deep enough for any honest expression, shallow enough for any stack.
constexpr int maxDepth = 200;

class ExpressionParser {
public:
    ExpressionParser(const std::string& text, const EvalVariableLookup& lookup) : text_(text), lookup_(lookup)
    {
    }

    double evaluate()
    {
        skipSpace();
        if (pos_ >= text_.size())
            fail(pos_, "empty #eval expression", "an arithmetic expression such as 2*pi*0.05");
        const double result = sum();
        if (pos_ < text_.size())
            fail(pos_, "unexpected '" + std::string(1, text_[pos_]) + "' in #eval expression",
                 "an operator (+ - * / ^) or the end of the expression");
        return result;
    }

private:
    [[noreturn]] void fail(std::size_t at, const std::string& what, const std::string& expected) const
    {
        throw EvalError{at, what, expected};
    }

    void skipSpace()
    {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    }

    bool accept(char c)
    {
        skipSpace();
        if (pos_ < text_.size() && text_[pos_] == c) {
            ++pos_;
            skipSpace();
            return true;
        }
        return false;
    }

    double finite(double value, std::size_t at, const std::string& operation) const
    {
        if (!std::isfinite(value))
            fail(at, operation + " is not a finite number", "arguments within the domain of the operation");
        return value;
    }

    void enter(std::size_t at)
    {
        if (++depth_ > maxDepth) fail(at, "#eval expression nested too deeply", "fewer nested parentheses");
    }

    double sum()
    {
        double value = product();
        for (;;) {
            const std::size_t at = pos_;
            if (accept('+'))
                value = finite(value + product(), at, "'+'");
            else if (accept('-'))
                value = finite(value - product(), at, "'-'");
            else
                return value;
        }
    }

    double product()
    {
        double value = unary();
        for (;;) {
            const std::size_t at = pos_;
            if (accept('*')) {
                value = finite(value * unary(), at, "'*'");
            } else if (accept('/')) {
                const double divisor = unary();
                if (divisor == 0.0) fail(at, "division by zero in #eval expression", "a non-zero divisor");
                value = finite(value / divisor, at, "'/'");
            } else {
                return value;
            }
        }
    }

    double unary()
    {
        enter(pos_);
        double value;
        if (accept('-'))
            value = -unary();
        else if (accept('+'))
            value = unary();
        else
            value = power();
        --depth_;
        return value;
    }

    // '^' binds tighter than unary minus on its left (-2^2 = -4) and is right-associative.
    double power()
    {
        const double base = primary();
        const std::size_t at = pos_;
        if (!accept('^')) return base;
        return finite(std::pow(base, unary()), at, "'^'");
    }

    double primary()
    {
        skipSpace();
        if (pos_ >= text_.size())
            fail(pos_, "#eval expression ends too early", "a number, '(', a function, pi or a $variable");
        const char c = text_[pos_];
        const std::size_t at = pos_;
        if (accept('(')) {
            enter(at);
            const double value = sum();
            if (!accept(')'))
                fail(pos_, "missing ')' in #eval expression",
                     "')' to close the '(' at character " + std::to_string(at + 1));
            --depth_;
            return value;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
        if (c == '$') return variable();
        if (std::isalpha(static_cast<unsigned char>(c))) return nameOrCall();
        fail(at, "unexpected '" + std::string(1, c) + "' in #eval expression",
             "a number, '(', a function, pi or a $variable");
    }

    double number()
    {
        const std::size_t at = pos_;
        while (pos_ < text_.size() &&
               (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.'))
            ++pos_;
        // An exponent only when digits follow, so that "2e" is reported, not misread.
        if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
            std::size_t probe = pos_ + 1;
            if (probe < text_.size() && (text_[probe] == '+' || text_[probe] == '-')) ++probe;
            if (probe < text_.size() && std::isdigit(static_cast<unsigned char>(text_[probe]))) {
                pos_ = probe;
                while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
            }
        }
        const std::string written = text_.substr(at, pos_ - at);
        char* end = nullptr;
        const double value = std::strtod(written.c_str(), &end);
        if (end != written.c_str() + written.size())
            fail(at, "malformed number '" + written + "' in #eval expression",
                 "a number such as 2, 0.5 or 1e-3");
        skipSpace();
        return finite(value, at, "number " + written);
    }

    std::string identifier()
    {
        const std::size_t at = pos_;
        while (pos_ < text_.size() &&
               (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
            ++pos_;
        return text_.substr(at, pos_ - at);
    }

    double variable()
    {
        const std::size_t at = pos_++;
        std::string name;
        if (pos_ < text_.size() && text_[pos_] == '{') {
            const std::size_t close = text_.find('}', pos_);
            if (close == std::string::npos)
                fail(at, "unterminated ${ in #eval expression", "'}' after the variable name");
            name = text_.substr(pos_ + 1, close - pos_ - 1);
            pos_ = close + 1;
        } else {
            while (pos_ < text_.size() &&
                   (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_' ||
                    text_[pos_] == '.' || text_[pos_] == '!' || text_[pos_] == ':'))
                ++pos_;
            name = text_.substr(at + 1, pos_ - at - 1);
        }
        if (name.empty())
            fail(at, "'$' without a variable name in #eval expression", "$name or ${path/to/name}");
        skipSpace();
        return finite(lookup_(name, at), at, "$" + name);
    }

    double nameOrCall()
    {
        const std::size_t at = pos_;
        const std::string name = identifier();
        skipSpace();
        if (pos_ >= text_.size() || text_[pos_] != '(') {
            if (name == "pi") return pi;
            fail(at, "unknown name '" + name + "' in #eval expression",
                 "a number, pi, a function call such as sqrt(2), or a $variable");
        }
        const auto found = functions().find(name);
        if (found == functions().end())
            fail(at, "unknown function '" + name + "' in #eval expression",
                 std::string("one of ") + functionList);
        const std::vector<double> args = arguments(at);
        const Function& function = found->second;
        if (static_cast<int>(args.size()) != function.arity)
            fail(at,
                 "'" + name + "' takes " + std::to_string(function.arity) + " argument(s), not " +
                     std::to_string(args.size()),
                 std::to_string(function.arity) + " comma-separated argument(s)");
        return finite(function.apply(args), at, "'" + name + "' of these arguments");
    }

    std::vector<double> arguments(std::size_t callAt)
    {
        enter(callAt);
        accept('(');
        std::vector<double> args;
        if (!accept(')')) {
            do args.push_back(sum());
            while (accept(','));
            if (!accept(')')) fail(pos_, "missing ')' after the arguments of a function", "')' or ','");
        }
        --depth_;
        return args;
    }

    const std::string& text_;
    const EvalVariableLookup& lookup_;
    std::size_t pos_ = 0;
    int depth_ = 0;
};

}  // namespace

double evaluateExpression(const std::string& expression, const EvalVariableLookup& lookupVariable)
{
    return ExpressionParser(expression, lookupVariable).evaluate();
}

}  // namespace rockfrac
