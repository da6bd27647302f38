// Whole-state files: exact round trip, and every corruption reported.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

#include "core/error.hpp"
#include "io/stateFile.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / "rockfrac-test-state";
    fs::create_directories(dir);
    return dir / name;
}
std::string slurp(const fs::path& f)
{
    std::ifstream in(f, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}
void spit(const fs::path& f, const std::string& s)
{
    std::ofstream(f, std::ios::binary) << s;
}
}  // namespace

TEST_CASE("state round trip is bit-exact", "[io]")
{
    StateFile s;
    s.put("position", std::vector<Vec3>{{1, 2, 3}, {std::nextafter(1.0, 2.0), -0.0, 1e-300}});
    s.put("bondState", std::vector<std::uint8_t>{0, 1, 1});
    s.put("step", std::vector<std::int64_t>{123456789012345});
    s.putScalar("time", 1.25e-4);
    const fs::path f = scratch("state");
    s.write(f);
    const StateFile r = StateFile::read(f);
    const auto p = r.vectors("position", 2);
    CHECK(p[1].x == std::nextafter(1.0, 2.0));
    CHECK(std::signbit(p[1].y));
    CHECK(r.bytes("bondState")[2] == 1);
    CHECK(r.integers("step")[0] == 123456789012345);
    CHECK(r.scalar("time") == 1.25e-4);
    CHECK_THROWS_WITH(r.doubles("velocity"), Catch::Contains("no real array 'velocity'"));
    CHECK_THROWS_WITH(r.vectors("position", 3), Catch::Contains("does not belong to this mesh"));
}

TEST_CASE("corrupt state files are refused with the file named", "[io]")
{
    StateFile s;
    s.put("x", std::vector<double>(100, 1.0));
    const fs::path f = scratch("good");
    s.write(f);
    const std::string good = slurp(f);

    const fs::path bad = scratch("bad");
    spit(bad, good.substr(0, good.size() / 2));
    CHECK_THROWS_WITH(StateFile::read(bad),
                      Catch::Contains("bad") && Catch::Contains("truncated") || Catch::Contains("shorter"));
    std::string flipped = good;
    flipped[good.size() / 2] ^= 0x10;
    spit(bad, flipped);
    CHECK_THROWS_WITH(StateFile::read(bad), Catch::Contains("checksum"));
    spit(bad, "not a state file at all");
    CHECK_THROWS_WITH(StateFile::read(bad), Catch::Contains("magic") || Catch::Contains("truncated"));
    spit(bad, "");
    CHECK_THROWS_AS(StateFile::read(bad), UserError);
    CHECK_THROWS_WITH(StateFile::read(scratch("absent")), Catch::Contains("cannot read"));
}
