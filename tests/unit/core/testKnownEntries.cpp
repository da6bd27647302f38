// Unknown entries are refused at their line, with the nearest known keyword when one is close:
// a misspelt optional entry must not be silently ignored.
#include <algorithm>
#include <catch2/catch.hpp>
#include <iostream>
#include <sstream>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/knownEntries.hpp"
#include "core/selector.hpp"

using namespace rockfrac;

TEST_CASE("nearestKeyword: close misspellings, and nothing for a stranger", "[dictionary][knownEntries]")
{
    const std::vector<std::string> known{"writeInterval", "writeControl", "placeOnPlate", "nSegments",
                                         "seed"};
    CHECK(nearestKeyword("writeIntervall", known) == "writeInterval");
    CHECK(nearestKeyword("writeinterval", known) == "writeInterval");  // case is not a spelling
    CHECK(nearestKeyword("placeOnPlat", known) == "placeOnPlate");
    CHECK(nearestKeyword("nSegment", known) == "nSegments");
    CHECK(nearestKeyword("sed", known) == "seed");
    CHECK(nearestKeyword("diameter", known).empty());
    CHECK(nearestKeyword("frobnicate", known).empty());
    CHECK(nearestKeyword("anything", {}).empty());
}

TEST_CASE("requireKnownEntries names the line, the nearest keyword and the known ones",
          "[dictionary][knownEntries]")
{
    const Dictionary d = Dictionary::parse("seed 1;\nplaceOnPlat yes;\n", "meshRockDict");
    CHECK_NOTHROW(requireKnownEntries(d, {"seed", "placeOnPlat"}));
    CHECK_THROWS_WITH(requireKnownEntries(d, {"seed", "placeOnPlate"}),
                      Catch::Contains("meshRockDict:2") && Catch::Contains("did you mean 'placeOnPlate'?") &&
                          Catch::Contains("seed, placeOnPlate"));
    const Dictionary far = Dictionary::parse("colour red;\n", "meshRockDict");
    CHECK_THROWS_WITH(requireKnownEntries(far, {"seed"}), !Catch::Contains("did you mean"));
}

namespace {

// What checkKnownEntries writes to stderr while `body` runs.
template <class Body>
std::string capturedStderr(Body body)
{
    std::ostringstream captured;
    std::streambuf* const old = std::cerr.rdbuf(captured.rdbuf());
    try {
        body();
    } catch (...) {
        std::cerr.rdbuf(old);
        throw;
    }
    std::cerr.rdbuf(old);
    return captured.str();
}

}  // namespace

TEST_CASE("checkKnownEntries: one warning line per unknown entry by default, an error with -strict",
          "[dictionary][knownEntries]")
{
    const Dictionary d = Dictionary::parse(
        "FoamFile { format ascii; class dictionary; object controlDict; }\n"
        "endTime 1;\nwriteIntervall 2e-5;\nwriteInterval 1e-5;\n",
        "case/system/controlDict");
    const std::vector<std::string> known{"endTime", "writeInterval", "writeControl"};

    setStrictEntries(false, "bondedDemFoam");
    std::size_t count = 0;
    const std::string warning = capturedStderr([&] { count = checkKnownEntries(d, known); });
    CHECK(count == 1);
    CHECK(std::count(warning.begin(), warning.end(), '\n') == 1);  // exactly one line
    CHECK_THAT(warning, Catch::StartsWith("bondedDemFoam: warning: case/system/controlDict:3:") &&
                            Catch::Contains("unknown entry 'writeIntervall'") &&
                            Catch::Contains("did you mean 'writeInterval'?") && Catch::Contains("ignored") &&
                            Catch::Contains("-strict"));
    // The FoamFile header and the known entries are never reported.
    CHECK(capturedStderr([&] { checkKnownEntries(Dictionary::parse("endTime 1;\n", "x"), known); }).empty());

    setStrictEntries(true, "bondedDemFoam");
    CHECK_THROWS_AS(checkKnownEntries(d, known), UserError);
    CHECK_THROWS_WITH(checkKnownEntries(d, known), Catch::Contains("case/system/controlDict:3") &&
                                                       Catch::Contains("did you mean 'writeInterval'?"));
    setStrictEntries(false);
}

TEST_CASE("checkKnownSubEntries checks a sub-dictionary only when it is there", "[dictionary][knownEntries]")
{
    const Dictionary d = Dictionary::parse("stop { forceDropFraction 0.3; minPeakForc 10; }\n", "loading");
    setStrictEntries(true);
    CHECK_NOTHROW(checkKnownSubEntries(d, "settling", {"duration"}));
    CHECK_THROWS_WITH(checkKnownSubEntries(d, "stop", {"forceDropFraction", "minPeakForce"}),
                      Catch::Contains("loading:1") && Catch::Contains("did you mean 'minPeakForce'?"));
    setStrictEntries(false);
    const std::vector<UnknownEntry> unknown =
        unknownEntries(d.subDict("stop"), {"forceDropFraction", "minPeakForce"});
    REQUIRE(unknown.size() == 1);
    CHECK(unknown[0].keyword == "minPeakForc");
    CHECK(unknown[0].nearest == "minPeakForce");
}
