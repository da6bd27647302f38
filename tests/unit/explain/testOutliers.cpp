// The rule for specimens that fail differently from the rest (outliers.hpp), the absolute
// held-out test (chiSquare.hpp) and the geometry comparison (geometryCheck.hpp).
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "explain/chiSquare.hpp"
#include "explain/geometryCheck.hpp"
#include "explain/outliers.hpp"

using namespace rockfrac::explain;

TEST_CASE("odd specimens: the median and the rule", "[explain][outliers]")
{
    CHECK(medianOf({}) == 0.0);
    CHECK(medianOf({3.0, 1.0, 2.0}) == 2.0);
    CHECK(medianOf({4.0, 1.0, 3.0, 2.0}) == 2.5);
    // The case: 24 discs near 18 kN, one lost a contact cell at 1.1 kN, one was
    // crushed to 70 kN without a split.
    std::vector<double> peaks;
    for (int i = 0; i < 22; ++i) peaks.push_back(18e3 * (1.0 + 0.15 * std::sin(1.7 * i)));
    peaks.insert(peaks.begin() + 5, 1.1e3);
    peaks.push_back(70e3);
    const auto odd = oddFailures(peaks);
    REQUIRE(odd.size() == 2);
    CHECK(odd[0].index == 5);
    CHECK(odd[0].peak == 1.1e3);
    CHECK(odd[0].ratio == Approx(1.1e3 / medianOf(peaks)));
    CHECK(odd[1].index == 23);
    CHECK(odd[1].ratio > oddHighRatio);
    CHECK_FALSE(tooManyOdd(odd.size(), peaks.size()));
}

TEST_CASE("odd specimens: scatter is not odd, the bounds, small sets", "[explain][outliers]")
{
    // A coefficient of variation of 30 %: nothing within 0.5-2 times the median is odd.
    CHECK(oddFailures({10.0, 13.0, 7.0, 16.0, 5.1, 19.9, 10.0}).empty());
    CHECK(oddFailures({10.0, 10.0, 10.0, 4.99}).size() == 1);   // just below half
    CHECK(oddFailures({10.0, 10.0, 10.0, 20.01}).size() == 1);  // just above twice
    CHECK(oddFailures({10.0, 1.0}).empty());                    // fewer than 3: no median to judge by
    CHECK(oddFailures({0.0, 0.0, 0.0}).empty());
}

TEST_CASE("odd specimens: too many for one failure mode", "[explain][outliers]")
{
    CHECK_FALSE(tooManyOdd(0, 8));
    CHECK_FALSE(tooManyOdd(2, 8));  // a quarter: medians still describe the rest
    CHECK(tooManyOdd(3, 8));
    CHECK(tooManyOdd(1, 2));  // one of two model seeds
    CHECK_FALSE(tooManyOdd(6, 24));
    CHECK(tooManyOdd(7, 24));
}

TEST_CASE("absolute held-out test", "[explain][chiSquare]")
{
    SECTION("errors within the scatter: consistent, nothing remains")
    {
        const HeldOutTest t = heldOutTest({0.5, -1.0, 1.2, 0.3, -0.7, 0.9}, 0.01);
        CHECK(t.degreesOfFreedom == 6);
        CHECK(t.chiSquare == Approx(0.25 + 1.0 + 1.44 + 0.09 + 0.49 + 0.81));
        CHECK(t.pValue == Approx(chiSquareSurvival(t.chiSquare, 6.0)));
        CHECK(t.consistent);
        CHECK(t.remaining.empty());
    }
    SECTION("the issue's case: peak force 3.6 and toe index 15 standard errors off")
    {
        const HeldOutTest t = heldOutTest({3.6, 0.4, -1.1, 15.0, 0.2, -2.5}, 0.01);
        CHECK_FALSE(t.consistent);
        CHECK(t.pValue < 1e-10);
        REQUIRE(t.remaining.size() == 3);  // largest first
        CHECK(t.remaining[0] == 3);
        CHECK(t.remaining[1] == 0);
        CHECK(t.remaining[2] == 5);
    }
    SECTION("a diffuse misfit names its largest feature")
    {
        // Six errors of 1.9: chi-square 21.7 on 6, p = 0.0014, none beyond 2.
        const HeldOutTest t = heldOutTest({1.9, -1.9, 1.9, 1.9, -1.9, 1.95}, 0.01);
        CHECK_FALSE(t.consistent);
        REQUIRE(t.remaining.size() == 1);
        CHECK(t.remaining[0] == 5);
    }
    SECTION("the quadratic form of correlated errors replaces the sum of squares")
    {
        const HeldOutTest t = heldOutTest({3.0, 3.0}, 0.01, 4.0);
        CHECK(t.chiSquare == 4.0);
        CHECK(t.pValue == Approx(std::exp(-2.0)));
        CHECK(t.consistent);
        CHECK(t.remaining.size() == 2);  // still named beyond 2 standard errors each
    }
    SECTION("at the significance level's boundary")
    {
        // chi-square 6.635 on 1 degree of freedom is the 1 % point.
        CHECK(heldOutTest({std::sqrt(6.6)}, 0.01).consistent);
        CHECK_FALSE(heldOutTest({std::sqrt(6.7)}, 0.01).consistent);
    }
}

TEST_CASE("geometry check: the specimens' dimensions against the model's", "[explain][geometry]")
{
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "rockfracTestGeometryCheck";
    fs::create_directories(dir);
    const fs::path file = dir / "geometryProperties";
    std::ofstream(file) << "FoamFile { format ascii; class dictionary; object geometryProperties; }\n"
                        << "type disc;\nvolume 2.1753292312e-05;\nequivalentDiameter 0.034633;\n"
                        << "disc { diameter 0.0448; thickness 0.0138; centre (0 0 0); axis (0 1 0); }\n";
    rockfrac::stats::MeasurementSet m;
    for (double d : {0.0412, 0.0413, 0.0411}) {
        rockfrac::stats::Specimen sp;
        sp.geometry.diameter = d;
        sp.geometry.thickness = 0.0138 * (1.0 + (d - 0.0412) / 0.0412);
        m.specimens.push_back(sp);
    }
    m.specimens.push_back({});  // a specimen without dimensions is left out of the median
    const auto c = compareGeometry(m, file);
    REQUIRE(c.size() == 2);
    CHECK(c[0].quantity == "diameter");
    CHECK(c[0].specimens == 3);
    CHECK(c[0].measured == Approx(0.0412));
    CHECK(c[0].relative == Approx(0.0412 / 0.0448 - 1.0));
    CHECK(c[0].mismatch);  // 8 % smaller
    CHECK(c[1].quantity == "thickness");
    CHECK_FALSE(c[1].mismatch);
    CHECK(describeComparison(c[0]).find("-8.0 %") != std::string::npos);
    CHECK(compareGeometry(m, dir / "none").empty());
    fs::remove_all(dir);
}
