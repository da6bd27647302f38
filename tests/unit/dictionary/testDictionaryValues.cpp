// Typed lookups: get<T>, getOrDefault, getScalar with bounds and dimensions, getWord.
#include "dictionaryTestSupport.hpp"

using namespace rockfrac;
using rockfrac::test::errorOf;
using rockfrac::test::parse;

TEST_CASE("get<T> for every supported type", "[dictionary]")
{
    const Dictionary dict = parse(R"(
d 2.5; i -7; l 9000000000; seed 18446744073709551615; b on; w word; s "a string";
v (1 2 3); vd (0.5 1.5); vi (1 2 3); vs (a "b c"); vv ((0 0 1) (0 1 0)); vvd ((0 0.1) (0.2 0.3 0.4));
whole 1e3;
)");
    CHECK(dict.get<double>("d") == 2.5);
    CHECK(dict.get<int>("i") == -7);
    CHECK(dict.get<long>("l") == 9000000000L);
    CHECK(dict.get<std::uint64_t>("seed") == 18446744073709551615ULL);
    CHECK(dict.get<bool>("b"));
    CHECK(dict.get<std::string>("w") == "word");
    CHECK(dict.get<std::string>("s") == "a string");
    CHECK(dict.get<Vec3>("v") == Vec3{1, 2, 3});
    CHECK(dict.get<std::vector<double>>("vd") == std::vector<double>{0.5, 1.5});
    CHECK(dict.get<std::vector<int>>("vi") == std::vector<int>{1, 2, 3});
    CHECK(dict.get<std::vector<std::string>>("vs") == std::vector<std::string>{"a", "b c"});
    CHECK(dict.get<std::vector<Vec3>>("vv").size() == 2);
    CHECK(dict.get<std::vector<std::vector<double>>>("vvd")[1].size() == 3);
    CHECK(dict.get<int>("whole") == 1000);
    CHECK(dict.get<double>("i") == -7.0);
}

TEST_CASE("getOrDefault falls back only when the entry is missing", "[dictionary]")
{
    const Dictionary dict = parse("a 1; sub { b abc; }");
    CHECK(dict.getOrDefault<int>("missing", 5) == 5);
    CHECK(dict.getOrDefault<int>("sub/missing", 6) == 6);
    CHECK(dict.getOrDefault<int>("nosub/x", 7) == 7);
    CHECK(dict.getOrDefault<int>("a", 5) == 1);
    CHECK(dict.getOrDefault<std::string>("sub/b", "x") == "abc");
    CHECK_THROWS_AS(dict.getOrDefault<double>("sub/b", 1.0), UserError);
    CHECK(dict.getScalarOrDefault("missing", 0.3, Bounds::closedOpen(0, 0.5)) == 0.3);
}

TEST_CASE("Bounds describe themselves and check their ends", "[dictionary]")
{
    CHECK(Bounds::positive().description() == "a value > 0");
    CHECK(Bounds::nonNegative().description() == "a value >= 0");
    CHECK(Bounds::closedOpen(0, 0.5).description() == "a value in [0, 0.5)");
    CHECK(Bounds::closed(0, 1).description() == "a value in [0, 1]");
    CHECK(Bounds::open(0, 1e9).description() == "a value in (0, 1e9)");
    CHECK(Bounds::atLeast(1).description() == "a value >= 1");
    CHECK(Bounds::closedOpen(0, 0.5).contains(0));
    CHECK(!Bounds::closedOpen(0, 0.5).contains(0.5));
    CHECK(!Bounds::positive().contains(0));
    CHECK(Bounds::nonNegative().contains(0));
    CHECK(!Bounds::open(0, 1).contains(1));
    CHECK(Bounds::closed(0, 1).contains(1));
    CHECK(Bounds::any().contains(-1e300));
}

TEST_CASE("getScalar checks range and dimensions", "[dictionary]")
{
    const Dictionary dict = parse("nu 0.25;\nE [Pa] 77e9;\nL [m] 2;\n");
    const Dimensions pascal = Dimensions::fromUnits("Pa");
    CHECK(dict.getScalar("nu", Bounds::closedOpen(0, 0.5)) == 0.25);
    CHECK(dict.getScalar("E", Bounds::positive(), &pascal) == 77e9);
    CHECK(dict.getScalar("nu", Bounds::positive(), &pascal) == 0.25);  // no set given: accepted
    CHECK(errorOf([&] { dict.getScalar("L", Bounds::positive(), &pascal); }) ==
          "constant/rockProperties:3:3: 'L' has dimensions [0 1 0 0 0 0 0] (m); expected [1 -1 -2 0 0 0 0] "
          "(kg m^-1 s^-2) or no dimension set");
}

TEST_CASE("getWord accepts only the allowed words and suggests a near miss", "[dictionary]")
{
    const Dictionary dict = parse("stopAt endTime;\nwriteControl timestep;\n");
    CHECK(dict.getWord("stopAt", {"endTime", "writeNow"}) == "endTime");
    CHECK(errorOf([&] {
              dict.getWord("writeControl", {"timeStep", "runTime", "clockTime"});
          }) ==
          "constant/rockProperties:2:14: writeControl = timestep is not a valid choice; expected one of: "
          "timeStep, runTime, clockTime (did you mean 'timeStep'?)");
}

TEST_CASE("formatNumber gives the shortest text that reads back", "[dictionary]")
{
    CHECK(formatNumber(0.5) == "0.5");
    CHECK(formatNumber(77e9) == "7.7e10");
    CHECK(formatNumber(1e-5) == "1e-5");
    CHECK(formatNumber(0.1) == "0.1");
    CHECK(formatNumber(100) == "100");
    CHECK(std::stod(formatNumber(M_PI)) == M_PI);
}
