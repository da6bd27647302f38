#pragma once
// A small random number generator whose output is fixed by its seed on every
// machine and standard library: xoshiro256** (Blackman & Vigna) seeded through
// SplitMix64, and our own mapping to doubles. std::mt19937 would be portable,
// but std::uniform_real_distribution is not (libstdc++ and libc++ differ), and
// a mesh must be reproducible from (domain, nCells, pd, seed) alone.
#include <cstdint>

#include "core/random.hpp"

namespace rockfrac {

class RandomStream {
public:
    explicit RandomStream(std::uint64_t seed)
    {
        // SplitMix64 spreads any seed (even 0) over the 256-bit state.
        SplitMix64 spreader(seed);
        for (std::uint64_t& word : state_) word = spreader.next();
    }

    // Next 64 random bits (xoshiro256**).
    std::uint64_t nextBits()
    {
        const std::uint64_t result = rotateLeft(state_[1] * 5, 7) * 9;
        const std::uint64_t t = state_[1] << 17;
        state_[2] ^= state_[0];
        state_[3] ^= state_[1];
        state_[1] ^= state_[2];
        state_[0] ^= state_[3];
        state_[2] ^= t;
        state_[3] = rotateLeft(state_[3], 45);
        return result;
    }

    // Uniform double in [0, 1): the top 53 bits scaled by 2^-53 (exact, no rounding).
    double uniform() { return static_cast<double>(nextBits() >> 11) * 0x1.0p-53; }

    // Uniform double in [lower, upper).
    double uniform(double lower, double upper) { return lower + (upper - lower) * uniform(); }

private:
    static std::uint64_t rotateLeft(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

    std::uint64_t state_[4];
};

}  // namespace rockfrac
