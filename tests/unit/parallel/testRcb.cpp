// The weighted recursive coordinate bisection: parts balanced to the granularity of the
// weights, the same parts whatever the order of the input, every item owned by the leaf of
// the cut tree it lies in, and clear refusals.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "core/error.hpp"
#include "parallel/rcb.hpp"

using namespace rockfrac;

namespace {

std::vector<Vec3> randomPoints(int n, unsigned seed, Vec3 extent = {1.0, 1.0, 1.0})
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec3> p(n);
    for (Vec3& x : p) x = {extent.x * u(rng), extent.y * u(rng), extent.z * u(rng)};
    return p;
}

}  // namespace

TEST_CASE("uniform weights: part sizes differ by at most one item per cut level", "[rcb]")
{
    const std::vector<Vec3> points = randomPoints(1000, 1);
    const std::vector<double> weights(points.size(), 1.0);
    for (int parts : {1, 2, 3, 4, 5, 7, 8, 16}) {
        INFO(parts << " parts");
        const RcbDecomposition d = rcbDecompose(points, weights, parts);
        const PartBalance b = partBalance(d.part_of, weights, parts);
        const auto [lo, hi] = std::minmax_element(b.items.begin(), b.items.end());
        CHECK(*lo >= 1);
        // floor(1000 / p) or ceil, up to one item of rounding per level of the tree.
        const int levels = static_cast<int>(std::ceil(std::log2(parts)));
        CHECK(*hi - *lo <= std::max(1, levels));
        CHECK(b.imbalance <= static_cast<double>(levels + 1) * parts / 1000.0);
        CHECK(static_cast<int>(d.nodes.size()) == 2 * parts - 1);
    }
}

TEST_CASE("weights are balanced, not counts: a heavy corner gets fewer cells", "[rcb]")
{
    const std::vector<Vec3> points = randomPoints(20000, 2);
    std::vector<double> weights(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        weights[i] = points[i].x < 0.25 && points[i].y < 0.25 ? 100.0 : 1.0;  // the crusher's nip
    const RcbDecomposition d = rcbDecompose(points, weights, 4);
    const PartBalance b = partBalance(d.part_of, weights, 4);
    CHECK(b.imbalance < 0.01);  // one heavy item is 1/500 of a part's weight
    CHECK(*std::min_element(b.items.begin(), b.items.end()) < 1000);  // the heavy corner's part
    CHECK(*std::max_element(b.items.begin(), b.items.end()) > 5000);  // the light bulk's
    // By counts instead, the same points are balanced in items and far out in weight.
    const PartBalance counts =
        partBalance(rcbDecompose(points, std::vector<double>(points.size(), 1.0), 4).part_of, weights, 4);
    CHECK(counts.imbalance > 0.5);
}

TEST_CASE("the same parts whatever the order of the items", "[rcb]")
{
    const std::vector<Vec3> points = randomPoints(3000, 3, {2.0, 1.0, 0.5});
    std::vector<double> weights(points.size());
    std::mt19937_64 rng(4);
    for (double& w : weights) w = 1.0 + (rng() % 50);
    const RcbDecomposition d = rcbDecompose(points, weights, 6);

    std::vector<int> order(points.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<Vec3> shuffled_points(points.size());
    std::vector<double> shuffled_weights(points.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        shuffled_points[k] = points[order[k]];
        shuffled_weights[k] = weights[order[k]];
    }
    const RcbDecomposition e = rcbDecompose(shuffled_points, shuffled_weights, 6);
    for (std::size_t k = 0; k < order.size(); ++k) REQUIRE(e.part_of[k] == d.part_of[order[k]]);
    // The first cut is across the longest extent, x.
    CHECK(d.nodes[0].axis == 0);
}

TEST_CASE("the cut tree owns every item where the decomposition put it, and any point", "[rcb]")
{
    const std::vector<Vec3> points = randomPoints(2000, 5);
    const std::vector<double> weights(points.size(), 1.0);
    const RcbDecomposition d = rcbDecompose(points, weights, 5);
    for (std::size_t i = 0; i < points.size(); ++i) REQUIRE(d.partOf(points[i]) == d.part_of[i]);
    // A point that moved (a cell in flight) is owned by the leaf it now lies in, and points
    // outside the items' box still find a part.
    const int far = d.partOf({-10.0, -10.0, -10.0});
    CHECK(far >= 0);
    CHECK(far < 5);
}

TEST_CASE("items on a lattice with equal coordinates are cut between distinct planes", "[rcb]")
{
    std::vector<Vec3> points;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) points.push_back({double(i), double(j), double(k)});
    const std::vector<double> weights(points.size(), 1.0);
    const RcbDecomposition d = rcbDecompose(points, weights, 8);
    const PartBalance b = partBalance(d.part_of, weights, 8);
    for (int n : b.items) CHECK(n == 8);  // the 2 x 2 x 2 blocks
    for (std::size_t i = 0; i < points.size(); ++i) REQUIRE(d.partOf(points[i]) == d.part_of[i]);
}

TEST_CASE("impossible decompositions are refused with what to do", "[rcb][badInput]")
{
    const std::vector<Vec3> points = randomPoints(10, 6);
    const std::vector<double> ones(points.size(), 1.0);
    CHECK_THROWS_AS(rcbDecompose(points, ones, 0), UserError);
    CHECK_THROWS_WITH(rcbDecompose(points, ones, 11),
                      Catch::Contains("numberOfSubdomains must be in [1, 10]"));
    std::vector<double> bad = ones;
    bad[3] = 0.0;
    CHECK_THROWS_WITH(rcbDecompose(points, bad, 2), Catch::Contains("item 3") && Catch::Contains("positive"));
    bad[3] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(rcbDecompose(points, bad, 2), UserError);
    const std::vector<Vec3> same(4, Vec3{1.0, 2.0, 3.0});
    CHECK_THROWS_WITH(rcbDecompose(same, std::vector<double>(4, 1.0), 2),
                      Catch::Contains("use fewer subdomains"));
}
