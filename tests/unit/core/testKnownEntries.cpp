// Unknown entries are refused at their line, with the nearest known keyword when one is close:
// a misspelt optional entry must not be silently ignored.
#include <catch2/catch.hpp>

#include "core/dictionary.hpp"
#include "core/error.hpp"
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
