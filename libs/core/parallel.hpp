#pragma once
// When an OpenMP loop is worth a parallel region.
//
// A parallel region costs a fork and a barrier (microseconds, far more when
// the cores are shared and threads spin-wait); a loop over a few hundred
// cheap items is faster on one thread, so loops below this count run
// serially. Results do not depend on it: every kernel writes per-item slots
// that are gathered in a fixed order. The tests set ROCKFRAC_OMP_MIN_ITEMS=1
// so that the thread-count reproducibility checks exercise the parallel path
// even on small meshes.
#include <cstdlib>

namespace rockfrac {

inline int parallelMinimumItems()
{
    static const int value = [] {
        const char* text = std::getenv("ROCKFRAC_OMP_MIN_ITEMS");
        const int parsed = text ? std::atoi(text) : 0;
        return parsed > 0 ? parsed : 512;
    }();
    return value;
}

}  // namespace rockfrac
