// The size check's brace matcher (sourceSizes.hpp) on small sources that hold each
// construct it must see through.
#include <catch2/catch.hpp>

#include "sourceSizes.hpp"

using namespace rockfrac::sourceSizes;

namespace {

std::vector<FunctionSpan> spans(const std::string& text)
{
    std::string error;
    auto found = findFunctions(text, error);
    INFO(error);
    CHECK(error.empty());
    return found;
}

}  // namespace

TEST_CASE("countLines counts a last line without a newline", "[sourceSizes]")
{
    CHECK(countLines("") == 0);
    CHECK(countLines("a\n") == 1);
    CHECK(countLines("a\nb") == 2);
    CHECK(countLines("\n\n\n") == 3);
}

TEST_CASE("a function spans its declaration to its closing brace", "[sourceSizes]")
{
    const auto f = spans(
        "#include <x>\n"
        "\n"
        "template <typename T>\n"
        "static int\n"
        "twice(T a)\n"
        "{\n"
        "    if (a) {\n"
        "        return 2 * a;\n"
        "    }\n"
        "    return 0;\n"
        "}\n");
    REQUIRE(f.size() == 1);
    CHECK(f[0].name == "twice");
    CHECK(f[0].firstLine == 3);
    CHECK(f[0].lastLine == 11);
    CHECK(f[0].lines() == 9);
}

TEST_CASE("braces in comments, literals and directives do not count", "[sourceSizes]")
{
    const auto f = spans(
        "#define OPEN {\n"
        "#define MANY(x) \\\n"
        "    { x; }\n"
        "int f() // {\n"
        "{\n"
        "    /* } */ const char* s = \"}\\\"}\";\n"
        "    char c = '}', d = '\\'';\n"
        "    long n = 1'000'000;\n"
        "    const char* r = R\"x(} \" })x\";\n"
        "    return 0;\n"
        "}\n"
        "int g() { return 1; }\n");
    REQUIRE(f.size() == 2);
    CHECK(f[0].name == "f");
    CHECK(f[0].firstLine == 4);
    CHECK(f[0].lastLine == 11);
    CHECK(f[1].name == "g");
    CHECK(f[1].lines() == 1);
}

TEST_CASE("namespaces and classes are entered, initializers skipped", "[sourceSizes]")
{
    const auto f = spans(
        "namespace a::b {\n"
        "extern \"C\" {\n"
        "const int table[] = {1, 2, 3};\n"
        "std::array<int, 2> pair{4, 5};\n"
        "}\n"
        "namespace {\n"
        "struct Point : Base<int> {\n"
        "    int x{0};\n"
        "public:\n"
        "    Point(int v) : Base<int>{v}, x{v} { check(); }\n"
        "    bool operator<(const Point& o) const { return x < o.x; }\n"
        "    int operator()(int k) const\n"
        "    {\n"
        "        return k;\n"
        "    }\n"
        "    enum class Kind : int { one, two };\n"
        "};\n"
        "auto square = [](int v) { return v * v; };\n"
        "}  // namespace\n"
        "auto Point::get() const -> decltype(x)\n"
        "{\n"
        "    auto inner = [](int v) {\n"
        "        return v;\n"
        "    };\n"
        "    return inner(x);\n"
        "}\n"
        "}\n");
    REQUIRE(f.size() == 4);
    CHECK(f[0].name == "Point");
    CHECK(f[0].firstLine == 10);
    CHECK(f[0].lastLine == 10);
    CHECK(f[1].name == "operator<");
    CHECK(f[2].name == "operator()");
    CHECK(f[2].lines() == 4);
    CHECK(f[3].name == "Point::get");
    CHECK(f[3].firstLine == 20);
    CHECK(f[3].lastLine == 26);
}

TEST_CASE("unbalanced braces are reported with their line", "[sourceSizes]")
{
    std::string error;
    findFunctions("int f()\n{\n", error);
    CHECK(error == "line 2: '{' is never closed");
    error.clear();
    findFunctions("}\n", error);
    CHECK(error == "line 1: '}' closes nothing");
    error.clear();
    findFunctions("namespace a {\n", error);
    CHECK(error == "1 namespace or class brace(s) never closed");
}
