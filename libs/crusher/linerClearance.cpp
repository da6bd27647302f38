#include "crusher/linerClearance.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "dem/quat.hpp"

namespace rockfrac {

RevolvedLiner revolvedLiner(const TriSurface& surface, int wall, SurfaceFacing facing,
                            const std::string& name)
{
    struct RZ {
        double r, z;
    };
    std::vector<RZ> points;
    double extent = 0.0;
    for (const Vec3& p : surface.points) {
        points.push_back({std::hypot(p.x, p.y), p.z});
        extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    if (points.size() < 3) throw UserError(name + ": the liner has fewer than three points");
    // Heights and ring radii equal to round-off (float STL files: ~1e-7 relative).
    const double tolZ = 1e-7 * std::max(extent, 1e-3), tolR = 1e-6 * std::max(extent, 1e-3);
    std::sort(points.begin(), points.end(),
              [](const RZ& a, const RZ& b) { return a.z < b.z || (a.z == b.z && a.r < b.r); });
    RevolvedLiner liner;
    liner.wall = wall;
    liner.free_outside = facing == SurfaceFacing::awayFromAxis;
    for (std::size_t i = 0; i < points.size();) {
        // One height: its rings (runs of equal r).
        std::size_t end = i;
        while (end < points.size() && points[end].z - points[i].z <= tolZ) ++end;
        std::sort(points.begin() + i, points.begin() + end,
                  [](const RZ& a, const RZ& b) { return a.r < b.r; });
        double nearest = liner.free_outside ? -1.0 : std::numeric_limits<double>::infinity();
        for (std::size_t j = i; j < end;) {
            std::size_t ringEnd = j;
            while (ringEnd < end && points[ringEnd].r - points[j].r <= tolR) ++ringEnd;
            const bool onAxis = points[j].r <= tolR;
            if (!onAxis && ringEnd - j < 3)
                throw UserError(
                    name + ": not a surface of revolution about z (the ring of radius " +
                    std::to_string(points[j].r) + " m at z = " + std::to_string(points[j].z) + " m has " +
                    std::to_string(ringEnd - j) +
                    " point(s)); the feed needs meshCrusher's liners to place rocks between them");
            nearest = liner.free_outside ? std::max(nearest, points[j].r) : std::min(nearest, points[j].r);
            j = ringEnd;
        }
        liner.profile.push_back({nearest, points[i].z});
        i = end;
    }
    if (liner.profile.size() < 2) throw UserError(name + ": the liner spans no height (all points at one z)");
    return liner;
}

double linerClearance(const RevolvedLiner& liner, const WallState& wall, const Vec3& x)
{
    const Vec3 local = transposeTimes(rotationMatrix(wall.orientation), x - wall.origin);
    const Profile& p = liner.profile;
    if (local.z < p.front().z || local.z > p.back().z) return std::numeric_limits<double>::infinity();
    const auto above = std::upper_bound(p.begin(), p.end(), local.z,
                                        [](double z, const ProfilePoint& q) { return z < q.z; });
    const ProfilePoint& b = above == p.end() ? p.back() : *above;
    const ProfilePoint& a = above == p.end() ? *(above - 2) : *(above - 1);
    const double slope = (b.r - a.r) / (b.z - a.z);  // dr/dz of the segment
    const double r = a.r + slope * (local.z - a.z);
    const double outward = std::hypot(local.x, local.y) - r;  // horizontal, + away from the axis
    // Normal to the segment: the horizontal distance times cos of the segment's tilt.
    const double normal = outward / std::sqrt(1.0 + slope * slope);
    return liner.free_outside ? normal : -normal;
}

}  // namespace rockfrac
