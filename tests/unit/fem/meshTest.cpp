// Tet geometry, quality checks and gmsh reading.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cstdio>

#include "core/error.hpp"
#include "fem/elementGeometry.hpp"
#include "femTestSupport.hpp"

using namespace rockfrac;
using namespace rockfrac::fem;

TEST_CASE("regular tet: volume, smallest height and constant shape gradients", "[fem][mesh]")
{
    const double a = 2.0;
    const TetMesh mesh = test::regularTet(a);
    CHECK(tetVolumes(mesh)[0] == Approx(a * a * a / (6.0 * std::sqrt(2.0))));
    CHECK(tetSmallestHeights(mesh)[0] == Approx(a * std::sqrt(2.0 / 3.0)));
    const ElementGeometry g = makeElementGeometry(mesh);
    // sum_a x_a (x) grad N_a = I for any tet: gradients reproduce linear fields.
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double sum = 0.0;
            for (int n = 0; n < 4; ++n) sum += mesh.nodes[n][i] * g.gradients[3 * n + j];
            CHECK(sum == Approx(i == j ? 1.0 : 0.0).margin(1e-14));
        }
}

TEST_CASE("inverted and degenerate tets are rejected by name", "[fem][mesh]")
{
    TetMesh mesh = test::regularTet(1.0);
    std::swap(mesh.tets[0][1], mesh.tets[0][2]);
    CHECK_THROWS_WITH(checkTetQuality(mesh), Catch::Contains("tet 0") && Catch::Contains("inverted"));
    TetMesh flat = test::regularTet(1.0);
    flat.nodes[3].z = 0.0;
    CHECK_THROWS_WITH(checkTetQuality(flat), Catch::Contains("tet 0") && Catch::Contains("degenerate"));
    CHECK_THROWS_AS(checkTetQuality(TetMesh{}), UserError);
}

TEST_CASE("readGmshMesh reads msh 2 and msh 4 files and their physical groups", "[fem][mesh]")
{
    const std::string path4 = std::string(ROCKFRAC_BINARY_DIR) + "/fem_test_box4.msh";
    const std::string path2 = std::string(ROCKFRAC_BINARY_DIR) + "/fem_test_box2.msh";
    std::size_t numTets = 0;
    {
        test::GmshSession gmshSession;
        const TetMesh generated = test::boxMesh(gmshSession, 1, 1, 1, 0.4);
        numTets = generated.numTets();
        gmsh::model::addPhysicalGroup(3, {1}, 7);
        gmsh::model::setPhysicalName(3, 7, "rock");
        gmsh::model::addPhysicalGroup(2, {1}, 8);
        gmsh::model::setPhysicalName(2, 8, "left");
        gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
        gmsh::write(path4);
        gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
        gmsh::write(path2);
    }
    const int threads = omp_get_max_threads();
    for (const auto& path : {path4, path2}) {
        const TetMesh mesh = readGmshMesh(path);  // gmsh not initialised here
        CHECK(omp_get_max_threads() == threads);  // gmsh::initialize must not leak its thread count
        CHECK(mesh.numTets() == numTets);
        CHECK(mesh.tetTags[0] == 7);
        REQUIRE(mesh.nodeGroups.count("left") == 1);
        for (int node : mesh.nodeGroups.at("left")) CHECK(mesh.nodes[node].x == Approx(0.0).margin(1e-12));
        double volume = 0.0;
        for (double v : tetVolumes(mesh)) volume += v;
        CHECK(volume == Approx(1.0));
    }
    CHECK_THROWS_AS(readGmshMesh(std::string(ROCKFRAC_BINARY_DIR) + "/no_such_mesh.msh"), UserError);
    std::remove(path4.c_str());
    std::remove(path2.c_str());
}

TEST_CASE("a file without tetrahedra is a user error", "[fem][mesh]")
{
    const std::string path = std::string(ROCKFRAC_BINARY_DIR) + "/fem_test_square.msh";
    {
        test::GmshSession gmshSession;
        gmsh::model::occ::addRectangle(0, 0, 0, 1, 1);
        gmsh::model::occ::synchronize();
        gmsh::model::mesh::generate(2);
        gmsh::write(path);
    }
    CHECK_THROWS_WITH(readGmshMesh(path), Catch::Contains("no linear tetrahedra"));
    std::remove(path.c_str());
}
