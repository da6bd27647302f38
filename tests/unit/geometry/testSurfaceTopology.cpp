// What a closed surface must also be to bound one rock: the degenerate-triangle and
// near-duplicate checks of geometry/surfaceTopology.
#include <catch2/catch.hpp>

#include "geometry/surfaceTopology.hpp"

using namespace rockfrac;

namespace {

// Octahedron of half-diagonal 1, outward triangles.
TriSurface octahedron()
{
    TriSurface s;
    s.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    s.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return s;
}

}  // namespace

TEST_CASE("collapsed triangles are dropped, the rest kept in order", "[geometry][surfaceTopology]")
{
    TriSurface s = octahedron();
    s.triangles.insert(s.triangles.begin() + 3, {0, 0, 2});
    s.triangles.push_back({4, 4, 4});
    CHECK(dropCollapsedTriangles(s) == 2);
    CHECK(s.triangles == octahedron().triangles);
    CHECK(dropCollapsedTriangles(s) == 0);
}

TEST_CASE("a needle (three vertices on a line) is found; a thin sound triangle is not",
          "[geometry][surfaceTopology]")
{
    TriSurface s = octahedron();
    CHECK(needleTriangles(s).empty());
    // Split face 0 at the midpoint m of its edge 0-2 and close the gap with the needle (0, 2, m).
    s.points.push_back({0.5, 0.5, 0});
    const int m = 6;
    s.triangles[0] = {0, m, 4};
    s.triangles.push_back({m, 2, 4});
    s.triangles.push_back({0, 2, m});
    CHECK(needleTriangles(s) == std::vector<int>{9});
    // Lifted by 1e-6 of its length, the third vertex makes a thin but sound triangle.
    s.points[m] = {0.5, 0.5, 1e-6};
    CHECK(needleTriangles(s).empty());
}

TEST_CASE("vertices within a distance of another are counted", "[geometry][surfaceTopology]")
{
    TriSurface s = octahedron();
    CHECK(nearDuplicateVertices(s, 1e-6) == 0);
    s.points.push_back({1e-9, 0, 1});  // beside vertex 4
    s.points.push_back({1, 0, 1e-7});  // beside vertex 0
    CHECK(nearDuplicateVertices(s, 1e-6) == 4);
    CHECK(nearDuplicateVertices(s, 1e-8) == 2);
    CHECK(nearDuplicateVertices(s, 0.0) == 0);
}
