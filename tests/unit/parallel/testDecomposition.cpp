// system/decomposeParDict as read, and the halo of a decomposition against a lattice whose
// ghosts and cut interfaces are counted by hand.
#include <catch2/catch.hpp>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "parallel/decomposition.hpp"

using namespace rockfrac;

namespace {

DecomposeParameters read(const std::string& text)
{
    return readDecomposeParameters(Dictionary::parse(text, "decomposeParDict"));
}

}  // namespace

TEST_CASE("decomposeParDict: the entries as read", "[decomposition]")
{
    const DecomposeParameters p = read("numberOfSubdomains 4;\nmethod rcb;\nweights uniform;\n");
    CHECK(p.n_subdomains == 4);
    CHECK(std::string(p.method->type()) == "rcb");
    CHECK_FALSE(p.cost_weights);
    CHECK(read("numberOfSubdomains 2;\nmethod rcb;\nweights cost;\n").cost_weights);
}

TEST_CASE("decomposeParDict: bad entries name their line", "[decomposition][badInput]")
{
    CHECK_THROWS_WITH(read("numberOfSubdomains 2.5;\nmethod rcb;\nweights cost;\n"),
                      Catch::Contains("decomposeParDict:1") && Catch::Contains("whole number"));
    CHECK_THROWS_WITH(read("numberOfSubdomains 0;\nmethod rcb;\nweights cost;\n"),
                      Catch::Contains("decomposeParDict:1"));
    CHECK_THROWS_WITH(read("numberOfSubdomains 2;\nmethod scotch;\nweights cost;\n"),
                      Catch::Contains("decomposeParDict:2") && Catch::Contains("rcb"));
    CHECK_THROWS_WITH(read("numberOfSubdomains 2;\nmethod rcb;\nweights cost;\nrebalance 0.1;\n"),
                      Catch::Contains("decomposeParDict:4") && Catch::Contains("rebalance"));
    CHECK_THROWS_WITH(read("numberOfSubdomains 2;\nmethod rcb;\n"), Catch::Contains("weights"));
    CHECK_THROWS_WITH(read("numberOfSubdomains 2;\nmethod rcb;\nweights cost;\nrcb { axis x; }\n"),
                      Catch::Contains("decomposeParDict:4") && Catch::Contains("axis"));
}

TEST_CASE("halo of a lattice cut in two: one layer of ghosts on each side", "[decomposition][halo]")
{
    // 10 x 10 x 10 cells of unit spacing, reach 0.5 (touching cubes); cut at x = 4.5.
    std::vector<Vec3> c;
    std::vector<int> part;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
            for (int k = 0; k < 10; ++k) {
                c.push_back({double(i), double(j), double(k)});
                part.push_back(i < 5 ? 0 : 1);
            }
    auto id = [](int i, int j, int k) { return 100 * i + 10 * j + k; };
    std::vector<std::pair<int, int>> faces;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
            for (int k = 0; k < 10; ++k) {
                if (i < 9) faces.emplace_back(id(i, j, k), id(i + 1, j, k));
                if (j < 9) faces.emplace_back(id(i, j, k), id(i, j + 1, k));
                if (k < 9) faces.emplace_back(id(i, j, k), id(i, j, k + 1));
            }
    const std::vector<double> reach(c.size(), 0.5), weights(c.size(), 1.0);

    // Margin 0.1: only face neighbours (distance 1) interact, not diagonals (sqrt 2).
    HaloReport r = haloReport(c, reach, weights, faces, part, 2, 0.1);
    CHECK(r.cut_interfaces == 100);
    CHECK(r.ghost_cells == 200);
    for (const SubdomainHalo& s : r.subdomains) {
        CHECK(s.cells == 500);
        CHECK(s.ghost_cells == 100);
        CHECK(s.cut_interfaces == 100);
        CHECK(s.neighbours == 1);
    }
    CHECK(r.imbalance == Approx(0.0).margin(1e-15));

    // Margin 1.1 (range 2.1): two layers on each side.
    r = haloReport(c, reach, weights, faces, part, 2, 1.1);
    CHECK(r.subdomains[0].ghost_cells == 200);
    CHECK(r.subdomains[1].ghost_cells == 200);

    // Uneven weights: the imbalance is max/mean - 1.
    std::vector<double> heavy = weights;
    for (std::size_t i = 0; i < c.size(); ++i)
        if (part[i] == 1) heavy[i] = 3.0;
    r = haloReport(c, reach, heavy, faces, part, 2, 0.1);
    CHECK(r.imbalance == Approx(0.5));
}
