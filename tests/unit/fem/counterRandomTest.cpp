// The counter-based random stream: known answers, range, reproducibility.
#include <catch2/catch.hpp>

#include "core/counterRandom.hpp"

using namespace rockfrac;

TEST_CASE("Philox-4x32-10 reproduces the Random123 known-answer vectors", "[fem][random]")
{
    CHECK(philox4x32({0, 0, 0, 0}, {0, 0}) ==
          PhiloxBlock{0x6627e8d5u, 0xe169c58du, 0xbc57ac4cu, 0x9b00dbd8u});
    CHECK(philox4x32({0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu}, {0xffffffffu, 0xffffffffu}) ==
          PhiloxBlock{0x408f276du, 0x41c83b0eu, 0xa20bc7c6u, 0x6d5451fdu});
    CHECK(philox4x32({0x243f6a88u, 0x85a308d3u, 0x13198a2eu, 0x03707344u}, {0xa4093822u, 0x299f31d0u}) ==
          PhiloxBlock{0xd16cfe09u, 0x94fdccebu, 0x5001e420u, 0x24126ea1u});
}

TEST_CASE("uniform01 lies in (0, 1), is a pure function and has mean 1/2", "[fem][random]")
{
    double sum = 0.0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const double u = uniform01(42, 7, i);
        REQUIRE(u > 0.0);
        REQUIRE(u < 1.0);
        sum += u;
    }
    CHECK(sum / n == Approx(0.5).margin(0.005));
    CHECK(uniform01(42, 7, 3) == uniform01(42, 7, 3));
    CHECK(uniform01(42, 7, 3) != uniform01(43, 7, 3));
    CHECK(uniform01(42, 7, 3) != uniform01(42, 8, 3));
    CHECK(openUnitInterval(0, 0) > 0.0);
    CHECK(openUnitInterval(0xffffffffu, 0xffffffffu) < 1.0);
}
