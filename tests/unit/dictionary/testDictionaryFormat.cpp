// toString prints a canonical dictionary that reads back to the same content.
#include "dictionaryTestSupport.hpp"

using namespace rockfrac;
using rockfrac::test::parse;

namespace {

// Structural equality of two dictionaries: keys, values, dimension sets.
bool sameValues(const Value& a, const Value& b)
{
    if (a.kind != b.kind || a.text != b.text || a.items.size() != b.items.size()) return false;
    for (std::size_t i = 0; i < a.items.size(); ++i)
        if (!sameValues(a.items[i], b.items[i])) return false;
    return true;
}

bool sameDictionary(const Dictionary& a, const Dictionary& b)
{
    if (a.keys() != b.keys()) return false;
    for (std::size_t i = 0; i < a.entries().size(); ++i) {
        const Entry& x = a.entries()[i];
        const Entry& y = b.entries()[i];
        if (x.isDict() != y.isDict() || x.dimensions != y.dimensions || x.values.size() != y.values.size())
            return false;
        if (x.isDict() && !sameDictionary(*x.dict, *y.dict)) return false;
        for (std::size_t k = 0; k < x.values.size(); ++k)
            if (!sameValues(x.values[k], y.values[k])) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("toString prints OpenFOAM's layout", "[dictionary][format]")
{
    const Dictionary dict = parse(
        "FoamFile { format ascii; object x; }\n a 1; veryLongKeywordName 2;\nE [Pa] 7e9;\n"
        "sub { s \"quoted \\\"text\\\"\"; l (1 (2 3) w); } empty;\n");
    CHECK(toString(dict) ==
          "FoamFile\n{\n    format          ascii;\n    object          x;\n}\n\n"
          "a               1;\n"
          "veryLongKeywordName 2;\n"
          "E               [1 -1 -2 0 0 0 0] 7e9;\n"
          "sub\n{\n    s               \"quoted \\\"text\\\"\";\n    l               (1 (2 3) w);\n}\n"
          "empty;\n");
}

TEST_CASE("long lists go one item per line", "[dictionary][format]")
{
    const Dictionary dict = parse("points 30{(0.125 0.25 0.5)};\n");
    const std::string text = toString(dict);
    CHECK(text.rfind("points\n(\n    (0.125 0.25 0.5)\n", 0) == 0);
    CHECK(text.substr(text.size() - 3) == ");\n");
}

TEST_CASE("toString round trips", "[dictionary][format]")
{
    const Dictionary dict = parse(R"(
FoamFile { format ascii; class dictionary; object rockProperties; }
rho [kg/m^3] 2650;
r 0.05;
area #eval{ pi*$r^2 };
bond { sigma 28e6; model parallel; profile ((0 0.1) (0.2 0.3)); }
copy { $bond; sigma 1; }
names (a "b c" "d\\e");
field 100{1.5};
"odd key" 1;
)");
    const std::string once = toString(dict);
    const Dictionary again = parse(once);
    CHECK(sameDictionary(dict, again));
    CHECK(toString(again) == once);
}
