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

TEST_CASE("contact refinement makes the elements under the plates finer", "[geometry]")
{
    RockShape shape;
    shape.volume = 45e-6;
    shape.seed = 3;
    const ConvexHull rock = generateRock(shape);
    const fs::path msh = fs::temp_directory_path() / "rockfrac-test-geometry" / "refinedRock.msh";
    TetMeshRequest request;
    request.elementSize = 6e-3;
    const TetMeshingResult uniform = meshSurfaceWithGmsh(rock.surface, request, msh);
    request.contactSize = 2e-3;
    request.contactDistance = 4e-3;
    const TetMeshingResult refined = meshSurfaceWithGmsh(rock.surface, request, msh);
    CHECK(std::abs(refined.relativeVolumeError()) < 1e-6);  // the same solid, exactly
    CHECK(refined.tets.size() > 2 * uniform.tets.size());

    // Mean element volume in the slabs next to the lowest and highest z and in the middle.
    double zMin = 1e30, zMax = -1e30;
    for (const auto& p : refined.nodes) zMin = std::min(zMin, p.z), zMax = std::max(zMax, p.z);
    double volumeNear = 0, volumeMiddle = 0;
    int near = 0, middle = 0;
    for (const auto& t : refined.tets) {
        const Vec3 a = refined.nodes[t[0]], b = refined.nodes[t[1]], c = refined.nodes[t[2]],
                   d = refined.nodes[t[3]];
        const double z = 0.25 * (a.z + b.z + c.z + d.z);
        const double v = dot(b - a, cross(c - a, d - a)) / 6.0;
        REQUIRE(v > 0);
        const double fromPlate = std::min(z - zMin, zMax - z);
        if (fromPlate < 3e-3) volumeNear += v, ++near;
        if (fromPlate > 9e-3) volumeMiddle += v, ++middle;
    }
    REQUIRE(near > 0);
    REQUIRE(middle > 0);
    // Volumes scale as h^3: 2 mm against 6 mm is 27 x; ask for a clear 5 x.
    CHECK(volumeMiddle / middle > 5.0 * volumeNear / near);
}

TEST_CASE("contact refinement rejects a size that is not finer, and an element count", "[geometry]")
{
    RockShape shape;
    shape.volume = 45e-6;
    const ConvexHull rock = generateRock(shape);
    const fs::path msh = fs::temp_directory_path() / "rockfrac-test-geometry" / "badRefinement.msh";
    TetMeshRequest request;
    request.elementSize = 4e-3;
    request.contactSize = 4e-3;
    request.contactDistance = 5e-3;
    CHECK_THROWS_WITH(meshSurfaceWithGmsh(rock.surface, request, msh), Catch::Contains("below the mesh's"));
    request.contactSize = 2e-3;
    request.contactDistance = 0.0;
    CHECK_THROWS_WITH(meshSurfaceWithGmsh(rock.surface, request, msh),
                      Catch::Contains("distance must be > 0"));
    request.elementSize = 0.0;
    request.elementCount = 1000;
    request.contactDistance = 5e-3;
    CHECK_THROWS_WITH(meshSurfaceWithGmsh(rock.surface, request, msh), Catch::Contains("not 'elementCount'"));
}
