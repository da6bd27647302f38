// The measurements reader: the paper's data sets, and one clear error for
// each way a user's own file can be wrong.
#include <catch2/catch.hpp>
#include <fstream>

#include "core/error.hpp"
#include "stats/measurements.hpp"
#include "stats/sampleSource.hpp"

using namespace rockfrac::stats;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
namespace fs = std::filesystem;

namespace {

const fs::path experiments = fs::path(ROCKFRAC_SOURCE_DIR) / "cases/experiments";

fs::path scratch(const std::string& name)
{
    const fs::path dir = fs::path(ROCKFRAC_BINARY_DIR) / "tests/stats-tmp/measurements" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void write(const fs::path& file, const std::string& text)
{
    std::ofstream(file) << text;
}

const std::string header = "FoamFile { format ascii; class dictionary; object measurements; }\n";

// A one-specimen set whose curve file holds `curveText`.
fs::path setWithCurve(const std::string& name, const std::string& curveText)
{
    const fs::path dir = scratch(name);
    write(dir / "measurements", header + "specimens { S1 { curve \"curves/S1.dat\"; } }\n");
    fs::create_directories(dir / "curves");
    write(dir / "curves/S1.dat", curveText);
    return dir / "measurements";
}

}  // namespace

TEST_CASE("the paper's measured data sets read back with their counts and means", "[stats]")
{
    const MeasurementSet granite = readMeasurements(experiments / "BDT/granite/measurements");
    REQUIRE(granite.specimens.size() == 10);
    CHECK(granite.specimens[0].id == "BD-G-01");
    CHECK(granite.specimens[0].failureLoad == 10.9e3);
    CHECK(*granite.specimens[0].tensileStrength == 11.0e6);
    CHECK(*granite.specimens[9].geometry.diameter == 44.8e-3);  // from the set's geometry
    CHECK(*granite.specimens[9].geometry.thickness == 13.8e-3);
    CHECK_THAT(mean(granite.failureLoads()), WithinAbs(13.19e3, 1e-6));
    CHECK(granite.label() == "measured granite BDT");

    const MeasurementSet limestone = readMeasurements(experiments / "BDT/limestone/measurements");
    CHECK(limestone.specimens.size() == 6);
    CHECK_THAT(mean(limestone.failureLoads()), WithinAbs(9.7167e3, 0.1));

    const MeasurementSet rocks = readMeasurements(experiments / "SPB/granite/measurements");
    REQUIRE(rocks.specimens.size() == 7);
    CHECK(rocks.specimens[3].failureLoad == 28.7e3);
    CHECK(*rocks.specimens[0].cells == 376);
    CHECK_THAT(*rocks.specimens[0].geometry.volume, WithinAbs(82.7e-6, 1e-15));
    CHECK(readMeasurements(experiments / "SPB/limestone/measurements").specimens.size() == 7);
}

TEST_CASE("a curve gives the failure load when none is written", "[stats]")
{
    const fs::path file =
        setWithCurve("peak", "# displacement [m]\tforce [N]\n0\t0\n1e-4\t5000\n2e-4\t9000\n3e-4\t100\n");
    const MeasurementSet set = readMeasurements(file);
    REQUIRE(set.specimens[0].curve);
    CHECK(set.specimens[0].curve->force.size() == 4);
    CHECK(set.specimens[0].failureLoad == 9000.0);
}

TEST_CASE("a wrong measurements file gives one clear error each", "[stats]")
{
    SECTION("a curve without a force column")
    {
        const fs::path file = setWithCurve("missingColumn", "# displacement [m]\tload [N]\n0\t0\n");
        CHECK_THROWS_WITH(readMeasurements(file), Contains("S1.dat") && Contains("no column 'force'"));
    }
    SECTION("a curve in mm")
    {
        const fs::path file = setWithCurve("mm", "# displacement [mm]\tforce [N]\n0\t0\n");
        CHECK_THROWS_WITH(readMeasurements(file), Contains("S1.dat") && Contains("[mm]") && Contains("[m]"));
    }
    SECTION("an empty curve file, and one with a header but no rows")
    {
        CHECK_THROWS_WITH(readMeasurements(setWithCurve("empty", "")), Contains("S1.dat"));
        CHECK_THROWS_WITH(readMeasurements(setWithCurve("noRows", "# displacement [m]\tforce [N]\n")),
                          Contains("S1.dat") && Contains("no data rows"));
    }
    SECTION("a negative force in a curve")
    {
        const fs::path file = setWithCurve("negativeCurve", "# displacement [m]\tforce [N]\n0\t-50\n");
        CHECK_THROWS_WITH(readMeasurements(file), Contains("S1.dat") && Contains("negative force"));
    }
    SECTION("a curve that never rises above zero (found by fuzzing: failure load 0)")
    {
        const fs::path file = setWithCurve("zeroPeak", "# displacement [m]\tforce [N]\n0\t0\n1e-5\t0\n");
        CHECK_THROWS_WITH(readMeasurements(file), Contains("S1.dat") && Contains("never rises above 0 N"));
    }
    SECTION("a curve with an infinite force")
    {
        const fs::path file = setWithCurve("infinite", "# displacement [m]\tforce [N]\n0\t0\n1e-5\tinf\n");
        CHECK_THROWS_WITH(readMeasurements(file), Contains("S1.dat") && Contains("not a finite number"));
    }
    SECTION("a negative failure load")
    {
        const fs::path dir = scratch("negativeLoad");
        write(dir / "measurements", header + "specimens { S1 { failureLoad [N] -10900; } }\n");
        CHECK_THROWS_WITH(readMeasurements(dir / "measurements"),
                          Contains("measurements:2:") && Contains("failureLoad"));
    }
    SECTION("a failure load whose unit is not a force")
    {
        const fs::path dir = scratch("wrongUnit");
        write(dir / "measurements", header + "specimens { S1 { failureLoad [Pa] 10900; } }\n");
        CHECK_THROWS_WITH(readMeasurements(dir / "measurements"), Contains("measurements:2:"));
    }
    SECTION("a failure load without a unit")
    {
        const fs::path dir = scratch("noUnit");
        write(dir / "measurements", header + "specimens { S1 { failureLoad 10900; } }\n");
        CHECK_THROWS_WITH(readMeasurements(dir / "measurements"),
                          Contains("measurements:2:") && Contains("no dimension set"));
    }
    SECTION("an empty measurements file, and one without specimens")
    {
        const fs::path dir = scratch("emptySet");
        write(dir / "measurements", "");
        CHECK_THROWS_WITH(readMeasurements(dir / "measurements"),
                          Contains("measurements") && Contains("specimens"));
        write(dir / "measurements", header + "specimens { }\n");
        CHECK_THROWS_WITH(readMeasurements(dir / "measurements"), Contains("no specimens"));
    }
    SECTION("a misspelt entry and a missing load")
    {
        const fs::path dir = scratch("typo");
        write(dir / "measurements", header + "specimens { S1 { failureload [N] 1; } }\n");
        CHECK_THROWS_WITH(readMeasurements(dir / "measurements"),
                          Contains("unknown specimen entry 'failureload'"));
        write(dir / "measurements", header + "specimens { S1 { cells 3; } }\n");
        CHECK_THROWS_WITH(readMeasurements(dir / "measurements"), Contains("has no failureLoad"));
    }
    SECTION("a missing file")
    {
        CHECK_THROWS_AS(readMeasurements(scratch("missing") / "measurements"), rockfrac::UserError);
    }
}

TEST_CASE("samples come from measurement sets or from results tables", "[stats]")
{
    const LabelledSample measured = readSample(experiments / "BDT/limestone/measurements", "");
    CHECK(measured.values.size() == 6);
    CHECK(measured.unit == "N");

    const fs::path dir = scratch("table");
    write(dir / "results.dat",
          "# member [-]\tx [-]\tpeakForce [N]\tstatus "
          "[-]\n0000\t1\t10\tdone\n0001\t2\t-\tfailed\n0002\t3\t30\tdone\n");
    const LabelledSample simulated = readSample(dir / "results.dat", "peakForce");
    CHECK(simulated.values == Sample{10, 30});
    CHECK(simulated.unit == "N");
    CHECK_THROWS_WITH(readSample(dir / "results.dat", "nope"), Contains("no column 'nope'"));
    CHECK_THROWS_WITH(readSample(dir / "results.dat", ""), Contains("-column"));
}
