// postProcessing .dat files: header with units, restart continuation.
#include <catch2/catch.hpp>
#include <fstream>

#include "core/error.hpp"
#include "io/timeSeries.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

TEST_CASE("time series is written, read back and continued on restart", "[io]")
{
    const fs::path caseDir = fs::temp_directory_path() / "rockfrac-test-io" / "case";
    fs::remove_all(caseDir);
    {
        TimeSeriesWriter w(caseDir, "plateForce", {{"Time", "s"}, {"force", "N"}});
        for (int i = 0; i < 5; ++i) w.append({i * 1e-4, 100.0 * i});
    }
    const fs::path file = caseDir / "postProcessing/plateForce/0/plateForce.dat";
    TimeSeries s = readTimeSeries(file);
    CHECK(s.names == std::vector<std::string>{"Time", "force"});
    CHECK(s.units[1] == "N");
    CHECK(s.rows.size() == 5);

    {
        TimeSeriesWriter w(caseDir, "plateForce", {{"Time", "s"}, {"force", "N"}}, 2e-4);
        w.append({3e-4, -1.0});
    }
    s = readTimeSeries(file);
    REQUIRE(s.rows.size() == 4);  // rows at t <= 2e-4 kept, one new
    CHECK(s.values("force").back() == -1.0);
}

// A run killed while appending a row leaves it torn; "0.0002" cut from
// "0.00025" reads as a time at or before the restart time, and used to be kept.
TEST_CASE("a torn last row is dropped when the series is continued", "[io][reliability]")
{
    const fs::path caseDir = fs::temp_directory_path() / "rockfrac-test-io" / "torn";
    fs::remove_all(caseDir);
    const fs::path file = caseDir / "postProcessing/plateForce/0/plateForce.dat";
    {
        TimeSeriesWriter w(caseDir, "plateForce", {{"Time", "s"}, {"force", "N"}});
        w.append({1e-4, 1.0});
        w.append({2e-4, 2.0});
    }
    {
        std::ofstream out(file, std::ios::app);
        out << "0.0002";  // the start of the row of t = 0.00025, cut by SIGKILL
    }
    {
        TimeSeriesWriter w(caseDir, "plateForce", {{"Time", "s"}, {"force", "N"}}, 2e-4);
        w.append({3e-4, 3.0});
    }
    const TimeSeries s = readTimeSeries(file);
    REQUIRE(s.rows.size() == 3);
    CHECK(s.values("force") == std::vector<double>{1.0, 2.0, 3.0});
}

TEST_CASE("malformed time series files are refused with the line", "[io]")
{
    const fs::path file = fs::temp_directory_path() / "rockfrac-test-io" / "bad.dat";
    std::ofstream(file) << "# Time [s]\tforce [N]\n0\t1\n1e-4\tabc\n";
    CHECK_THROWS_WITH(readTimeSeries(file), Catch::Contains("bad.dat:3") && Catch::Contains("not a number"));
    std::ofstream(file) << "0\t1\n";
    CHECK_THROWS_WITH(readTimeSeries(file), Catch::Contains("no '#' header"));
    std::ofstream(file) << "# Time [s]\tforce [N]\n0\t1\t2\n";
    CHECK_THROWS_WITH(readTimeSeries(file), Catch::Contains("3 values"));
}
