// Tetrahedral meshes through gmsh: volume, orientation, quality.
#include <catch2/catch.hpp>
#include <cmath>

#include "geometry/convexHull.hpp"
#include "geometry/tetMesher.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

TEST_CASE("regular tetrahedron has quality 1", "[geometry]")
{
    const Vec3 a{1, 1, 1}, b{1, -1, -1}, c{-1, 1, -1}, d{-1, -1, 1};
    CHECK(tetQuality(a, b, c, d) == Approx(1.0).epsilon(1e-12));
    CHECK(tetQuality(a, b, c, 0.5 * (a + b)) == Approx(0.0).margin(1e-12));
}

TEST_CASE("disc tetrahedral mesh fills the cylinder", "[geometry]")
{
    const fs::path msh = fs::temp_directory_path() / "rockfrac-test-geometry" / "disc.msh";
    TetMeshRequest request;
    request.elementSize = 3e-3;
    const TetMeshingResult mesh = meshDiscWithGmsh(0.0448, 0.0138, {0, 0, 0}, request, msh);
    CHECK(fs::exists(msh));
    CHECK(mesh.tets.size() > 500);
    // Faceted cylinder: volume slightly below pi r^2 t.
    CHECK(std::abs(mesh.relativeVolumeError()) < 0.01);
    CHECK(mesh.minQuality > 0.05);
    for (const auto& t : mesh.tets) {
        const double v = dot(mesh.nodes[t[1]] - mesh.nodes[t[0]],
                             cross(mesh.nodes[t[2]] - mesh.nodes[t[0]], mesh.nodes[t[3]] - mesh.nodes[t[0]]));
        REQUIRE(v > 0);
    }
}

TEST_CASE("a generated rock is meshed to a target element count", "[geometry]")
{
    RockShape shape;
    shape.volume = 45e-6;
    shape.seed = 3;
    const ConvexHull rock = generateRock(shape);
    const fs::path msh = fs::temp_directory_path() / "rockfrac-test-geometry" / "rock.msh";
    TetMeshRequest request;
    request.elementCount = 3000;
    const TetMeshingResult mesh = meshSurfaceWithGmsh(rock.surface, request, msh);
    CHECK(std::abs(mesh.relativeVolumeError()) < 1e-6);  // flat facets are meshed exactly
    CHECK(static_cast<double>(mesh.tets.size()) == Approx(3000).epsilon(0.35));
}
