#pragma once
// The feed of the unit tests' fed runs: rocks of 15-25 mm falling fast into a funnel of two
// inclined plates (testFeedDischarge.cpp, testCrusherState.cpp).
#include <cstdint>

#include "crusher/machineLoading.hpp"

namespace rockfrac {

inline FeedSpec funnelFeedSpec(std::uint64_t seed)
{
    FeedSpec spec;
    spec.size_min = 0.015;
    spec.size_max = 0.025;
    spec.mass_rate = 2000.0;  // [kg/s]
    spec.total_mass = 0.2;
    spec.z_min = 0.03;
    spec.z_max = 0.15;
    spec.r_min = 0.0;
    spec.r_max = 0.01;
    spec.velocity = {0.0, 0.0, -15.0};
    spec.interval = 1e-4;
    spec.seed = seed;
    return spec;
}

}  // namespace rockfrac
