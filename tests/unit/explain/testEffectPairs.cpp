// Which pairs of effects explainGap refits when no single effect passes the absolute test
// (effectPairs.hpp), and the information criterion they are compared by.
#include <catch2/catch.hpp>

#include "explain/effectPairs.hpp"

using namespace rockfrac::explain;

TEST_CASE("pairs of the top-ranked effects", "[explain][pairs]")
{
    using Pairs = std::vector<std::pair<int, int>>;
    // The top three of a ranking of five: three pairs, the best-ranked first.
    CHECK(pairsToScreen({4, 0, 2, 1, 3}, 3) == Pairs{{4, 0}, {4, 2}, {0, 2}});
    // A smaller budget keeps the best-ranked pairs.
    CHECK(pairsToScreen({4, 0, 2, 1, 3}, 1) == Pairs{{4, 0}});
    CHECK(pairsToScreen({4, 0, 2}, 2) == Pairs{{4, 0}, {4, 2}});
    // Off (0), or fewer than two effects: no pair.
    CHECK(pairsToScreen({4, 0, 2}, 0).empty());
    CHECK(pairsToScreen({4}, 3).empty());
    CHECK(pairsToScreen({}, 3).empty());
    // Two effects: one pair, whatever the budget.
    CHECK(pairsToScreen({1, 0}, 3) == Pairs{{1, 0}});
    // Never more than the top pairRankedEffects enter, nor more than maximumPairs pairs.
    CHECK(pairsToScreen({0, 1, 2, 3, 4, 5}, 10).size() == 3);
    CHECK(maximumPairs == 3);
}

TEST_CASE("Akaike's criterion charges 2 per parameter", "[explain][pairs]")
{
    CHECK(akaike(10.0, 2) == 14.0);
    // A pair (one parameter more than a single effect) must lower chi-square by more than 2.
    CHECK(akaike(7.9, 3) < akaike(10.0, 2));
    CHECK_FALSE(akaike(8.1, 3) < akaike(10.0, 2));
}
