// libFuzzer target: arbitrary bytes as an STL file (ASCII or binary). Besides
// "a surface or a UserError", a surface that is returned has only finite
// points and triangle indices within range.
#include <cmath>
#include <cstdlib>

#include "../common/fuzzTarget.hpp"
#include "core/error.hpp"
#include "geometry/triSurface.hpp"

namespace rockfrac::fuzz {

int fuzzStl(const std::uint8_t* data, std::size_t size)
{
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        const TriSurface surface = parseStl(bytes, "fuzz.stl");
        const int nPoints = static_cast<int>(surface.points.size());
        for (const auto& p : surface.points)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) std::abort();
        for (const auto& t : surface.triangles)
            for (int v : t)
                if (v < 0 || v >= nPoints) std::abort();
        (void)checkSurface(surface);  // the next thing meshRock does with it
    } catch (const UserError&) {
    }
    return 0;
}

}  // namespace rockfrac::fuzz

ROCKFRAC_FUZZ_ENTRY(rockfrac::fuzz::fuzzStl)
