// Every saved input of the fuzz targets, replayed through the same harness
// functions the fuzzers call, linked against the ordinary libraries. A harness
// aborts on a broken promise and lets any exception but a UserError escape, so
// a regression fails this test (and, under the sanitize preset, any memory
// error is reported).
#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>

#include "../common/fuzzTarget.hpp"

namespace {

namespace fs = std::filesystem;
using Harness = int (*)(const std::uint8_t*, std::size_t);

// Replays tests/fuzz/<target>/{corpus,regressions}/*; returns how many inputs.
int replay(const char* target, Harness harness)
{
    int count = 0;
    for (const char* kind : {"corpus", "regressions"}) {
        const fs::path dir = fs::path(ROCKFRAC_SOURCE_DIR) / "tests/fuzz" / target / kind;
        if (!fs::is_directory(dir)) continue;
        for (const auto& entry : fs::directory_iterator(dir)) {
            if (!entry.is_regular_file()) continue;
            std::ifstream in(entry.path(), std::ios::binary);
            const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            INFO(entry.path().string());
            CHECK(harness(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()) == 0);
            ++count;
        }
    }
    return count;
}

}  // namespace

TEST_CASE("saved STL fuzz inputs read or give a UserError", "[fuzz][geometry]")
{
    CHECK(replay("stl", rockfrac::fuzz::fuzzStl) > 0);
}

TEST_CASE("saved state file fuzz inputs read or give a UserError", "[fuzz][io]")
{
    CHECK(replay("stateFile", rockfrac::fuzz::fuzzStateFile) > 0);
}

TEST_CASE("saved Voronoi mesh fuzz inputs read or give a UserError", "[fuzz][voronoi]")
{
    CHECK(replay("voronoiMesh", rockfrac::fuzz::fuzzVoronoiMesh) > 0);
}

TEST_CASE("saved measurements fuzz inputs read or give a UserError", "[fuzz][stats]")
{
    CHECK(replay("measurements", rockfrac::fuzz::fuzzMeasurements) > 0);
}

TEST_CASE("saved dictionary fuzz inputs parse, round-trip and edit, or give a UserError",
          "[fuzz][dictionary]")
{
    CHECK(replay("dictionary", rockfrac::fuzz::fuzzDictionary) >= 6);
}
