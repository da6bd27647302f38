// Inputs found by fuzzing (tests/fuzz/dictionary) that once misbehaved; each
// must now end in a UserError or a clean parse, never a crash or a hang.
#include "core/dictionaryEditor.hpp"
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

namespace {

// The fuzz target's promise: the canonical form reads back to itself.
bool roundTrips(const std::string& text)
{
    const std::string once = toString(Dictionary::parse(text, "f", fuzzLimits()));
    return toString(Dictionary::parse(once, "f", fuzzLimits())) == once;
}

}  // namespace

TEST_CASE("regression: an integer before a list in a long list is not read back as its size",
          "[dictionary][regression]")
{
    // crash-b230e72a: "1 (12)" printed on two lines became the sized list 1((12)).
    CHECK(roundTrips(
        "mixed (plate \"a long string that makes the list longer than a line\" \"more text\" 1 (12) on);"));
}

TEST_CASE("regression: the editor only creates keywords that read back", "[dictionary][regression]")
{
    // crash-9a0f4008: adding "a/#" wrote '#' as a keyword, which reads back as a directive.
    CHECK(
        errorOf([] { setEntry("", "a/#", "1", "f", "note"); }) ==
        "cannot add 'a/#': '#' is not a plain keyword; expected words of letters, digits and _ . : - such as "
        "bond/tensileStrength");
    CHECK(errorOf([] { setEntry("", "12", "1", "f"); }).rfind("cannot add '12'", 0) == 0);
    CHECK(errorOf([] { setEntry("", "a b", "1", "f"); }).rfind("cannot add 'a b'", 0) == 0);
    CHECK(setEntry("\"my key\" 1;", "my key", "2", "f") == "\"my key\" 2;");
}

TEST_CASE("regression: keywords with control characters or white space are printed quoted",
          "[dictionary][regression]")
{
    // crash-0534d855: the string keyword "qo-\0...\f\0" was printed bare and read back differently.
    CHECK(
        roundTrips(std::string("\"qo-\0\0\f\0\" yes;\n\"a b\" 1;\n\"12\" 2;\n\"#x\" 3;\n\"a//b\" 4;\n", 50)));
    CHECK(toString(Dictionary::parse("\"a b\" 1;", "f")) == "\"a b\"           1;\n");
}
