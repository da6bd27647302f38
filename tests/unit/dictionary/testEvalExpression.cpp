// The #eval arithmetic on its own.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/evalExpression.hpp"

using namespace rockfrac;

namespace {

double eval(const std::string& text)
{
    return evaluateExpression(text, [](const std::string& name, std::size_t offset) -> double {
        if (name == "x") return 2.0;
        throw EvalError{offset, "no " + name, "x"};
    });
}

EvalError evalError(const std::string& text)
{
    try {
        eval(text);
    } catch (const EvalError& error) {
        return error;
    }
    FAIL("expected an EvalError for " << text);
    return {};
}

}  // namespace

TEST_CASE("precedence and associativity", "[eval]")
{
    CHECK(eval("1 + 2 * 3") == 7);
    CHECK(eval("(1 + 2) * 3") == 9);
    CHECK(eval("2 ^ 3 ^ 2") == 512);  // right-associative
    CHECK(eval("-2 ^ 2") == -4);
    CHECK(eval("2 ^ -1") == 0.5);
    CHECK(eval("8 / 4 / 2") == 1);
    CHECK(eval("10 - 4 - 3") == 3);
    CHECK(eval("--3") == 3);
    CHECK(eval("+3") == 3);
    CHECK(eval("1.5e3 + .5") == 1500.5);
    CHECK(eval("$x * ${x}") == 4);
    CHECK(eval("2*pi") == Approx(2 * M_PI));
}

TEST_CASE("errors carry the offset inside the expression", "[eval]")
{
    CHECK(evalError("1 / 0").offset == 2);
    CHECK(evalError("1 / 0").whatIsWrong == "division by zero in #eval expression");
    CHECK(evalError("").whatIsWrong == "empty #eval expression");
    CHECK(evalError("1 +").offset == 3);
    CHECK(evalError("2 3").offset == 2);
    CHECK(evalError("foo").whatIsWrong == "unknown name 'foo' in #eval expression");
    CHECK(evalError("max(1)").whatIsWrong == "'max' takes 2 argument(s), not 1");
    CHECK(evalError("$y + 1").whatIsWrong == "no y");
    CHECK(evalError("log(0)").whatIsWrong == "'log' of these arguments is not a finite number");
    CHECK(evalError("10^400").whatIsWrong == "'^' is not a finite number");
    CHECK(evalError("1.2.3").whatIsWrong == "malformed number '1.2.3' in #eval expression");
    CHECK(evalError(std::string(1000, '(') + "1" + std::string(1000, ')')).whatIsWrong ==
          "#eval expression nested too deeply");
    CHECK(evalError(std::string(1000, '-') + "1").whatIsWrong == "#eval expression nested too deeply");
}
