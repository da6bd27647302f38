// Results tables: written atomically, read back with words and units.
#include <catch2/catch.hpp>
#include <fstream>

#include "core/error.hpp"
#include "io/textTable.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

TEST_CASE("text table round trip, ragged rows refused", "[io]")
{
    const fs::path dir = fs::path(ROCKFRAC_BINARY_DIR) / "tests/stats-tmp/table";
    fs::remove_all(dir);
    TextTable table;
    table.names = {"member", "E", "status"};
    table.units = {"", "Pa", ""};
    table.rows = {{"0000", "4e10", "done"}, {"0001", "-", "failed"}};
    writeTextTable(dir / "results.dat", table);
    const TextTable back = readTextTable(dir / "results.dat");
    CHECK(back.names == table.names);
    CHECK(back.units == std::vector<std::string>{"-", "Pa", "-"});
    CHECK(back.rows == table.rows);
    CHECK(back.column("E") == 1);
    CHECK(back.column("nope") == -1);
    CHECK(parseNumber("4e10") == 4e10);
    CHECK_FALSE(parseNumber("-").has_value());

    std::ofstream(dir / "ragged.dat") << "# a [-]\tb [-]\n1\t2\n3\n";
    CHECK_THROWS_WITH(readTextTable(dir / "ragged.dat"), Catch::Contains("ragged.dat:3"));
    std::ofstream(dir / "empty.dat") << "";
    CHECK_THROWS_AS(readTextTable(dir / "empty.dat"), rockfrac::UserError);
}
