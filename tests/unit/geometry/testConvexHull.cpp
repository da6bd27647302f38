// Convex hulls and generated rocks.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "geometry/convexHull.hpp"
#include "geometry/specimen.hpp"

using namespace rockfrac;

TEST_CASE("hull of a cube's corners plus interior points is the cube", "[geometry]")
{
    std::vector<Vec3> points;
    for (int i = 0; i < 8; ++i) points.push_back({1.0 * (i & 1), 1.0 * ((i >> 1) & 1), 1.0 * ((i >> 2) & 1)});
    points.push_back({0.5, 0.5, 0.5});
    points.push_back({0.2, 0.7, 0.3});
    const ConvexHull hull = convexHull(points);
    CHECK(hull.planes.size() == 6);  // coplanar triangles merged
    CHECK(massProperties(hull.surface).volume == Approx(1.0).epsilon(1e-12));
    CHECK(checkSurface(hull.surface).watertight());
    for (const auto& p : points)
        for (const auto& h : hull.planes) CHECK(h.signedDistance(p) <= 1e-12);
}

TEST_CASE("coplanar points are refused", "[geometry]")
{
    std::vector<Vec3> flat = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.2, 0}};
    CHECK_THROWS_AS(convexHull(flat), UserError);
}

TEST_CASE("generated rocks have the requested volume and are reproducible", "[geometry]")
{
    RockShape shape;
    shape.volume = 82.7e-6;
    shape.elongation = 0.78;
    shape.flatness = 0.7;
    shape.seed = 101;
    const ConvexHull a = generateRock(shape);
    const ConvexHull b = generateRock(shape);
    const MassProperties p = massProperties(a.surface);
    CHECK(p.volume == Approx(82.7e-6).epsilon(1e-12));
    CHECK(checkSurface(a.surface).watertight());
    REQUIRE(a.surface.points.size() == b.surface.points.size());
    for (std::size_t i = 0; i < a.surface.points.size(); ++i)
        CHECK(a.surface.points[i] == b.surface.points[i]);

    // Shape ratios follow the request roughly (the roughness scatters them).
    const double elongation = p.principalExtents.y / p.principalExtents.x;
    const double flatness = p.principalExtents.z / p.principalExtents.y;
    CHECK(elongation == Approx(0.78).margin(0.2));
    CHECK(flatness == Approx(0.7).margin(0.2));

    shape.seed = 102;
    const ConvexHull c = generateRock(shape);
    CHECK_FALSE(c.surface.points[0] == a.surface.points[0]);
}
