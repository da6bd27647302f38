#pragma once
// The region a Voronoi mesh fills: a convex body described by half-spaces
// (e.g. the facets of a scanned rock's convex hull) and, for Brazilian discs,
// a circular cylinder capped by two planes.
//
// Seeding draws points inside the domain (contains), the tessellation clips
// every Voronoi cell with the same planes and cylinder, and the sum of the
// cell volumes is checked against volume().
#include <optional>
#include <vector>

#include "core/halfSpace.hpp"
#include "core/vec3.hpp"

namespace rockfrac {

// An infinite circular cylinder: points within `radius` of the axis line.
struct Cylinder {
    Vec3 axisPoint;
    Vec3 axisDirection;  // unit vector
    double radius = 0.0;

    double distanceFromAxis(const Vec3& p) const;
};

struct BoundingBox {
    Vec3 lower;
    Vec3 upper;

    Vec3 size() const { return upper - lower; }
    Vec3 centre() const { return 0.5 * (lower + upper); }
    double volume() const;
};

class Domain {
public:
    // The bounded convex polytope where every half-space holds. The normals
    // need not be unit length (they are normalised). UserError if a normal is
    // zero or not finite, or the planes do not enclose a bounded volume.
    static Domain fromPlanes(std::vector<HalfSpace> planes);

    // The axis-aligned box [lower, upper] (six planes).
    static Domain box(const Vec3& lower, const Vec3& upper);

    // A Brazilian disc: a cylinder of the given diameter around `axis`
    // through `centre`, cut to `thickness` by two planes normal to the axis.
    static Domain disc(const Vec3& centre, const Vec3& axis, double diameter, double thickness);

    const std::vector<HalfSpace>& planes() const { return planes_; }
    const std::optional<Cylinder>& cylinder() const { return cylinder_; }
    const BoundingBox& boundingBox() const { return boundingBox_; }

    // Exact volume: of the polytope for plane domains, pi r^2 t for a disc [m^3].
    double volume() const { return volume_; }

    // True if p is inside or on the boundary.
    bool contains(const Vec3& p) const;

private:
    Domain() = default;

    std::vector<HalfSpace> planes_;
    std::optional<Cylinder> cylinder_;
    BoundingBox boundingBox_;
    double volume_ = 0.0;
};

}  // namespace rockfrac
