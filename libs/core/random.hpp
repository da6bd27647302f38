#pragma once
// Small, portable random numbers: SplitMix64 (Steele, Lea & Flood 2014).
//
// std::mt19937 is portable but the std distributions are not (their results
// differ between standard libraries), so every random choice in rockfrac maps
// raw 64-bit words to reals itself: a case seed gives the same mesh and the
// same result on any machine.
#include <cstdint>

namespace rockfrac {

class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next()
    {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1) with 53 random bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

private:
    std::uint64_t state_;
};

}  // namespace rockfrac
