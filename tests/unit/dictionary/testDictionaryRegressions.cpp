// Inputs found by fuzzing (tests/fuzz/dictionary) that once misbehaved; each
// must now end in a UserError or a clean parse, never a crash or a hang.
#include "dictionaryTestSupport.hpp"

using namespace rockfrac;
using rockfrac::test::errorOf;

namespace {

ParseLimits fuzzLimits()
{
    ParseLimits limits;
    limits.maxValues = 100000;
    limits.allowIncludes = false;
    return limits;
}

}  // namespace

TEST_CASE("regression: nesting is limited instead of overflowing the stack", "[dictionary][regression]")
{
    CHECK(errorOf([] {
              Dictionary::parse("a " + std::string(100000, '(') + ";", "f");
          }).find("nesting deeper than 200 levels") != std::string::npos);
    std::string nested;
    for (int i = 0; i < 1000; ++i) nested += "a{";
    CHECK(errorOf([&] { Dictionary::parse(nested, "f"); }).find("nesting deeper than 200 levels") !=
          std::string::npos);
}

TEST_CASE("regression: macros that double each other hit the value limit", "[dictionary][regression]")
{
    std::string text = "a0 (1 2);\n";
    for (int i = 1; i < 40; ++i)
        text +=
            "a" + std::to_string(i) + " ($a" + std::to_string(i - 1) + " $a" + std::to_string(i - 1) + ");\n";
    CHECK(errorOf([&] {
              Dictionary::parse(text, "f", fuzzLimits());
          }).find("expands to more than 100000 values") != std::string::npos);
}

TEST_CASE("regression: huge uniform list sizes", "[dictionary][regression]")
{
    CHECK(errorOf([] {
              Dictionary::parse("a 99999999999999999999999{0};", "f", fuzzLimits());
          }).find("expands to more than") != std::string::npos);
    CHECK(errorOf([] {
              Dictionary::parse("a 1000000{0};", "f", fuzzLimits());
          }).find("expands to more than") != std::string::npos);
}

TEST_CASE("regression: includes can be disabled", "[dictionary][regression]")
{
    CHECK(errorOf([] { Dictionary::parse("#include \"/dev/zero\"", "f", fuzzLimits()); }) ==
          "f:1:1: #include is not allowed here; expected a self-contained dictionary");
}
