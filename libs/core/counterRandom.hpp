#pragma once
// Counter-based random numbers: Philox-4x32-10 (Salmon et al., "Parallel random numbers:
// as easy as 1, 2, 3", SC'11), written from the published algorithm.
//
// A counter-based generator has no state: the value is a pure function of
// (key, counter). rockfrac keys it by the case seed and uses the counter for
// (stream id, draw index), so a draw for element 1234 is the same on any machine,
// with any thread count, in any visiting order, and after a restart. Philox passes
// BigCrush and costs about 10 integer multiplications per four 32-bit words.
#include <array>
#include <cstdint>

#include "core/vec3.hpp"  // RF_HD

namespace rockfrac {

using PhiloxBlock = std::array<std::uint32_t, 4>;
using PhiloxKey = std::array<std::uint32_t, 2>;

namespace philoxDetail {

constexpr std::uint32_t multiplier0 = 0xD2511F53u;
constexpr std::uint32_t multiplier1 = 0xCD9E8D57u;
constexpr std::uint32_t keyIncrement0 = 0x9E3779B9u;  // golden ratio
constexpr std::uint32_t keyIncrement1 = 0xBB67AE85u;  // sqrt(3) - 1

RF_HD inline void multiplyHighLow(std::uint32_t a, std::uint32_t b, std::uint32_t& high, std::uint32_t& low)
{
    const std::uint64_t product = static_cast<std::uint64_t>(a) * b;
    high = static_cast<std::uint32_t>(product >> 32);
    low = static_cast<std::uint32_t>(product);
}

RF_HD inline PhiloxBlock round(const PhiloxBlock& c, const PhiloxKey& k)
{
    std::uint32_t high0, low0, high1, low1;
    multiplyHighLow(multiplier0, c[0], high0, low0);
    multiplyHighLow(multiplier1, c[2], high1, low1);
    return {high1 ^ c[1] ^ k[0], low1, high0 ^ c[3] ^ k[1], low0};
}

}  // namespace philoxDetail

// The Philox-4x32 bijection with 10 rounds (the Random123 reference variant).
RF_HD inline PhiloxBlock philox4x32(PhiloxBlock counter, PhiloxKey key)
{
    for (int r = 0; r < 10; ++r) {
        if (r > 0) {
            key[0] += philoxDetail::keyIncrement0;
            key[1] += philoxDetail::keyIncrement1;
        }
        counter = philoxDetail::round(counter, key);
    }
    return counter;
}

// 52 random bits from two 32-bit words mapped to the open interval (0, 1):
// the midpoint of one of 2^52 equal bins, so neither 0 nor 1 is ever returned
// (with 53 bits the last midpoint, 1 - 2^-54, would round to 1.0)
// (safe for log(u) and log(1 - u)).
RF_HD inline double openUnitInterval(std::uint32_t high, std::uint32_t low)
{
    const std::uint64_t bits = ((static_cast<std::uint64_t>(high) << 32) | low) >> 12;
    return (static_cast<double>(bits) + 0.5) * 0x1.0p-52;
}

// Uniform double in (0, 1) for draw `counter` of stream `streamId` under `seed`.
// Reproducible on any platform: the result depends only on the three integers.
RF_HD inline double uniform01(std::uint64_t seed, std::uint64_t streamId, std::uint64_t counter)
{
    const PhiloxBlock block =
        philox4x32({static_cast<std::uint32_t>(counter), static_cast<std::uint32_t>(counter >> 32),
                    static_cast<std::uint32_t>(streamId), static_cast<std::uint32_t>(streamId >> 32)},
                   {static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)});
    return openUnitInterval(block[0], block[1]);
}

}  // namespace rockfrac
