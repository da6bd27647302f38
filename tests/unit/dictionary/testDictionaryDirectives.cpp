// #include, #includeIfPresent, $macros in all their scopes, #eval.
#include "dictionaryTestSupport.hpp"

using namespace rockfrac;
using rockfrac::test::parse;
using rockfrac::test::ScratchDir;

TEST_CASE("#include is relative to the including file; included entries may be overridden", "[dictionary]")
{
    ScratchDir scratch;
    scratch.write("constant/defaults/bond",
                  "FoamFile { object bond; }\ntensileStrength 20e6;\nmodel parallel;\n");
    scratch.write("constant/rockProperties",
                  "bond\n{\n    #include \"defaults/bond\"\n    tensileStrength 28e6;\n}\n"
                  "#includeIfPresent \"absent\"\n");
    const Dictionary dict = Dictionary::readFile(scratch.path() / "constant/rockProperties");
    CHECK(dict.get<double>("bond/tensileStrength") == 28e6);
    CHECK(dict.get<std::string>("bond/model") == "parallel");
    CHECK(dict.subDict("bond").keys() == std::vector<std::string>{"tensileStrength", "model"});
    CHECK(dict.location("bond/model").file == (scratch.path() / "constant/defaults/bond").string());
    CHECK(dict.header() == nullptr);  // the included file's header is not the including file's
}

TEST_CASE("$var looks in the current scope, then in enclosing ones", "[dictionary]")
{
    const Dictionary dict = parse(R"(
E       [Pa] 77e9;
radius  0.05;
bond
{
    radius  0.01;
    E       $E;
    r       $radius;
    R       $../radius;
    top     $!radius;
}
)");
    CHECK(dict.get<double>("bond/E") == 77e9);
    CHECK(dict.entry("bond/E").dimensions == Dimensions::fromUnits("Pa"));
    CHECK(dict.get<double>("bond/r") == 0.01);
    CHECK(dict.get<double>("bond/R") == 0.05);
    CHECK(dict.get<double>("bond/top") == 0.05);
}

TEST_CASE("$a/b paths and ${...}", "[dictionary]")
{
    const Dictionary dict = parse(R"(
geometry { disc { radius 0.05; } }
loading
{
    r1 $geometry/disc/radius;
    r2 ${geometry/disc/radius};
    r3 $/geometry/disc/radius;
    list ($r1 $r2 2);
}
)");
    CHECK(dict.get<double>("loading/r1") == 0.05);
    CHECK(dict.get<double>("loading/r2") == 0.05);
    CHECK(dict.get<double>("loading/r3") == 0.05);
    CHECK(dict.get<std::vector<double>>("loading/list") == std::vector<double>{0.05, 0.05, 2});
}

TEST_CASE("$sub merges a sub-dictionary; later entries override it", "[dictionary]")
{
    const Dictionary dict = parse(R"(
granite { E 60e9; nu 0.25; bond { sigma 10e6; } }
myRock
{
    $granite;
    E 70e9;
    extra 1;
}
copy $granite;
)");
    CHECK(dict.subDict("myRock").keys() == std::vector<std::string>{"E", "nu", "bond", "extra"});
    CHECK(dict.get<double>("myRock/E") == 70e9);
    CHECK(dict.get<double>("myRock/bond/sigma") == 10e6);
    CHECK(dict.subDict("myRock/bond").name() == "myRock/bond");
    CHECK(dict.get<double>("copy/nu") == 0.25);
    CHECK(dict.subDict("copy").name() == "copy");
}

TEST_CASE("#eval with operators, functions, pi and variables", "[dictionary]")
{
    const Dictionary dict = parse(R"(
radius  0.05;
area    #eval "pi*$radius^2";
n       #eval{ 2*(3+4) - 2^3 };
neg     #eval{ -2^2 };
f       #eval{ sqrt(16) + exp(0) + log(1) + log10(100) + abs(-1) + floor(2.7) + ceil(2.1) };
g       #eval{ min(1, 2) + max(1, 2) + pow(2, 10) + atan2(0, 1) + sin(0) + cos(0) + tan(0) };
h       #eval{ asin(0) + acos(1) + atan(0) };
sub     { d #eval{ 2 * ${radius} }; }
)");
    CHECK(dict.get<double>("area") == Approx(M_PI * 0.0025));
    CHECK(dict.get<int>("n") == 6);
    CHECK(dict.get<double>("neg") == -4);
    CHECK(dict.get<double>("f") == 4 + 1 + 0 + 2 + 1 + 2 + 3);
    CHECK(dict.get<double>("g") == 1 + 2 + 1024 + 0 + 0 + 1 + 0);
    CHECK(dict.get<double>("h") == 0);
    CHECK(dict.get<double>("sub/d") == 0.1);
}
