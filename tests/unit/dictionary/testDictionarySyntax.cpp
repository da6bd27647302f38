// The FoamFile syntax: header, entries, sub-dictionaries, comments, numbers,
// words, strings, lists in all their forms, dimension sets.
#include "dictionaryTestSupport.hpp"

using namespace rockfrac;
using rockfrac::test::parse;

TEST_CASE("header, entries and sub-dictionaries are read in file order", "[dictionary]")
{
    const Dictionary dict = parse(R"(
FoamFile
{
    format      ascii;
    class       dictionary;
    object      rockProperties;
}
density     2650;   // kg/m^3
/* a block
   comment */
bond
{
    tensileStrength 28e6;
    model   parallel;
}
)");
    REQUIRE(dict.header() != nullptr);
    CHECK(dict.header()->get<std::string>("object") == "rockProperties");
    CHECK(!dict.found("FoamFile"));
    CHECK(dict.keys() == std::vector<std::string>{"density", "bond"});
    CHECK(dict.isDict("bond"));
    CHECK(!dict.isDict("density"));
    CHECK(dict.get<double>("bond/tensileStrength") == 28e6);
    CHECK(dict.subDict("bond").keys() == std::vector<std::string>{"tensileStrength", "model"});
    CHECK(dict.subDict("bond").name() == "bond");
    CHECK(dict.name() == "rockProperties");
    CHECK(dict.fileName() == "constant/rockProperties");
}

TEST_CASE("numbers keep their text and value", "[dictionary]")
{
    const Dictionary dict = parse("a 42; b -3.5; c 1e-3; d +2.5E+2; e .5; f 7.;");
    CHECK(dict.get<int>("a") == 42);
    CHECK(dict.get<double>("b") == -3.5);
    CHECK(dict.get<double>("c") == 1e-3);
    CHECK(dict.get<double>("d") == 250.0);
    CHECK(dict.get<double>("e") == 0.5);
    CHECK(dict.get<double>("f") == 7.0);
    CHECK(dict.entry("c").values.front().text == "1e-3");
}

TEST_CASE("words and quoted strings with escapes", "[dictionary]")
{
    const Dictionary dict =
        parse(R"(model kst-dfh; title "a \"quoted\" word\twith\\tab\n"; path "C:\data";)");
    CHECK(dict.get<std::string>("model") == "kst-dfh");
    CHECK(dict.get<std::string>("title") == "a \"quoted\" word\twith\\tab\n");
    CHECK(dict.get<std::string>("path") == "C:\\data");
    CHECK(dict.entry("title").values.front().isString());
}

TEST_CASE("booleans in all six spellings", "[dictionary]")
{
    const Dictionary dict = parse("a true; b false; c on; d off; e yes; f no;");
    CHECK(dict.get<bool>("a"));
    CHECK(!dict.get<bool>("b"));
    CHECK(dict.get<bool>("c"));
    CHECK(!dict.get<bool>("d"));
    CHECK(dict.get<bool>("e"));
    CHECK(!dict.get<bool>("f"));
}

TEST_CASE("lists: plain, nested, heterogeneous, size-prefixed, uniform", "[dictionary]")
{
    const Dictionary dict = parse(R"(
plain   (1 2 3);
nested  ((0 0.1) (0.2 0.3));
mixed   (plate "name" 3 (1 2));
sized   3(4 5 6);
sizedNL 2
(
    a
    b
);
uniform 4{0.5};
vectors ((0 0 1) (1 0 0));
empty   ();
)");
    CHECK(dict.get<std::vector<double>>("plain") == std::vector<double>{1, 2, 3});
    CHECK(dict.get<std::vector<std::vector<double>>>("nested") ==
          std::vector<std::vector<double>>{{0, 0.1}, {0.2, 0.3}});
    const Value& mixed = dict.entry("mixed").values.front();
    REQUIRE(mixed.items.size() == 4);
    CHECK(mixed.items[0].isWord());
    CHECK(mixed.items[1].isString());
    CHECK(mixed.items[2].isNumber());
    CHECK(mixed.items[3].isList());
    CHECK(dict.get<std::vector<int>>("sized") == std::vector<int>{4, 5, 6});
    CHECK(dict.get<std::vector<std::string>>("sizedNL") == std::vector<std::string>{"a", "b"});
    CHECK(dict.get<std::vector<double>>("uniform") == std::vector<double>{0.5, 0.5, 0.5, 0.5});
    CHECK(dict.get<std::vector<Vec3>>("vectors") == std::vector<Vec3>{{0, 0, 1}, {1, 0, 0}});
    CHECK(dict.get<std::vector<double>>("empty").empty());
}

TEST_CASE("an entry with several values keeps them all, with a raw token stream", "[dictionary]")
{
    const Dictionary dict = parse("loading { type plate (0 0 1) 0.25; }");
    const Entry& entry = dict.entry("loading/type");
    REQUIRE(entry.values.size() == 3);
    const std::vector<Token> tokens = dict.tokens("loading/type");
    std::string joined;
    for (const Token& t : tokens) joined += t.text + "|";
    CHECK(joined == "plate|(|0|0|1|)|0.25|");
    CHECK(tokens[0].kind == TokenKind::word);
    CHECK(tokens[1].kind == TokenKind::punctuation);
    CHECK(tokens[6].kind == TokenKind::number);
    CHECK(tokens[6].where.str() == "constant/rockProperties:1:30");
}

TEST_CASE("locations point at the value, counting from 1", "[dictionary]")
{
    const Dictionary dict = parse("a 1;\n  bond\n  {\n    E\t77e9;\n  }\n");
    CHECK(dict.location("a").str() == "constant/rockProperties:1:3");
    CHECK(dict.location("bond/E").str() == "constant/rockProperties:4:7");
    CHECK(dict.entry("bond/E").keywordLocation.str() == "constant/rockProperties:4:5");
    CHECK(dict.subDict("bond").endLocation().str() == "constant/rockProperties:5:3");
}

TEST_CASE("dimension sets: seven exponents or named units", "[dictionary]")
{
    const Dictionary dict = parse(R"(
E       [1 -1 -2 0 0 0 0] 77e9;
Es      [Pa] 77e9;
rho     [kg/m^3] 2650;
v       [m/s] 1.5;
k       [N/m] 1e6;
t       [s] 0.1;
f       [1/s] 50;
nu      [-] 0.25;
g       [m s^-2] 9.81;
)");
    const Dimensions pascal = Dimensions::fromUnits("Pa");
    CHECK(dict.entry("E").dimensions == pascal);
    CHECK(dict.entry("Es").dimensions == pascal);
    CHECK(dict.entry("rho").dimensions->str() == "[1 -3 0 0 0 0 0]");
    CHECK(dict.entry("v").dimensions->str() == "[0 1 -1 0 0 0 0]");
    CHECK(dict.entry("k").dimensions->str() == "[1 0 -2 0 0 0 0]");
    CHECK(dict.entry("t").dimensions->str() == "[0 0 1 0 0 0 0]");
    CHECK(dict.entry("f").dimensions->str() == "[0 0 -1 0 0 0 0]");
    CHECK(dict.entry("nu").dimensions->str() == "[0 0 0 0 0 0 0]");
    CHECK(dict.entry("g").dimensions->str() == "[0 1 -2 0 0 0 0]");
    CHECK(dict.getScalar("E", Bounds::positive(), &pascal) == 77e9);
    CHECK(pascal.unitString() == "kg m^-1 s^-2");
    CHECK(Dimensions{}.unitString() == "-");
    CHECK_THROWS_AS(Dimensions::fromUnits("furlong"), std::invalid_argument);
}

TEST_CASE("stray semicolons and an empty file are fine", "[dictionary]")
{
    CHECK(parse("").keys().empty());
    CHECK(parse("// only a comment\n").keys().empty());
    CHECK(parse(";; a 1;;").get<int>("a") == 1);
}

TEST_CASE("a keyword may be quoted", "[dictionary]")
{
    const Dictionary dict = parse("\"my key\" 3;");
    CHECK(dict.get<int>("my key") == 3);
}

TEST_CASE("a 1 MB dictionary of numbers parses well under a second", "[dictionary][performance]")
{
    std::string text = "values\n(\n";
    int count = 0;
    while (text.size() < (1u << 20)) {
        text += std::to_string(count * 0.001) + " " + std::to_string(count) + "\n";
        count += 2;
    }
    text += ");\n";
    const auto start = std::chrono::steady_clock::now();
    const Dictionary dict = parse(text);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(dict.get<std::vector<double>>("values").size() == static_cast<std::size_t>(count));
    WARN("1 MB (" << count << " numbers) parsed in " << seconds << " s");
    CHECK(seconds < 1.0);
}
