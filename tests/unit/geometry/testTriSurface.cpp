// Triangulated surfaces: STL round trips, watertightness, mass properties.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <fstream>

#include "core/error.hpp"
#include "geometry/triSurface.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

namespace {

// Unit cube [0,1]^3 as 12 outward triangles.
TriSurface cube(double a = 1.0)
{
    TriSurface s;
    for (int i = 0; i < 8; ++i) s.points.push_back({a * (i & 1), a * ((i >> 1) & 1), a * ((i >> 2) & 1)});
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        s.triangles.push_back({q[0], q[1], q[2]});
        s.triangles.push_back({q[0], q[2], q[3]});
    }
    return s;
}

fs::path scratch(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / "rockfrac-test-geometry";
    fs::create_directories(dir);
    return dir / name;
}

void writeBinaryStl(const fs::path& file, const TriSurface& s, std::uint32_t announced)
{
    std::ofstream out(file, std::ios::binary);
    char header[80] = "solid binary written by a test";
    out.write(header, 80);
    out.write(reinterpret_cast<const char*>(&announced), 4);
    for (const auto& t : s.triangles) {
        float data[12] = {};
        for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d) data[3 + 3 * k + d] = static_cast<float>(s.points[t[k]][d]);
        out.write(reinterpret_cast<const char*>(data), 48);
        const std::uint16_t attr = 0;
        out.write(reinterpret_cast<const char*>(&attr), 2);
    }
}

}  // namespace

TEST_CASE("cube mass properties are exact", "[geometry]")
{
    const MassProperties p = massProperties(cube(2.0));
    CHECK(p.volume == Approx(8.0).epsilon(1e-14));
    CHECK(p.centroid.x == Approx(1.0));
    CHECK(p.centroid.z == Approx(1.0));
    // Second moment of volume of a cube of side a about its centre: a^5/6 on the diagonal.
    CHECK(p.inertia(0, 0) == Approx(32.0 / 6.0).epsilon(1e-12));
    CHECK(std::abs(p.inertia(0, 1)) < 1e-12);
    CHECK(p.principalExtents.x == Approx(2.0));
    CHECK(checkSurface(cube()).watertight());
}

TEST_CASE("disc surface encloses the polygonal prism volume", "[geometry]")
{
    const int n = 64;
    const TriSurface disc = discSurface(0.0448, 0.0138, {0, 0, 0}, n);
    const double r = 0.0224;
    const double prism = 0.5 * n * r * r * std::sin(2 * M_PI / n) * 0.0138;
    CHECK(checkSurface(disc).watertight());
    CHECK(massProperties(disc).volume == Approx(prism).epsilon(1e-12));
}

TEST_CASE("ASCII STL round trip keeps the solid", "[geometry]")
{
    const fs::path file = scratch("cube.stl");
    writeStl(file, cube(0.01), "cube");
    const TriSurface back = readStl(file);
    CHECK(back.points.size() == 8);  // vertices welded
    CHECK(back.triangles.size() == 12);
    CHECK(massProperties(back).volume == Approx(1e-6).epsilon(1e-12));
}

TEST_CASE("binary STL is read and a truncated one refused", "[geometry]")
{
    const fs::path file = scratch("cube-binary.stl");
    writeBinaryStl(file, cube(), 12);
    CHECK(readStl(file).triangles.size() == 12);

    const fs::path truncated = scratch("truncated.stl");
    writeBinaryStl(truncated, cube(), 20);  // announces more facets than it holds
    CHECK_THROWS_WITH(readStl(truncated),
                      Catch::Contains("truncated binary STL") && Catch::Contains("truncated.stl"));
}

TEST_CASE("bad STL input gives one clear error", "[geometry]")
{
    CHECK_THROWS_WITH(readStl(scratch("does-not-exist.stl")), Catch::Contains("cannot read STL"));
    const fs::path empty = scratch("empty.stl");
    std::ofstream(empty).close();
    CHECK_THROWS_WITH(readStl(empty), Catch::Contains("empty file"));

    const fs::path nan = scratch("nan.stl");
    std::ofstream(nan) << "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex nan 0 0\n"
                          "vertex 0 1 0\nendloop\nendfacet\nendsolid x\n";
    CHECK_THROWS_WITH(readStl(nan), Catch::Contains("non-finite"));
}

TEST_CASE("holes and non-manifold edges are detected", "[geometry]")
{
    TriSurface open = cube();
    open.triangles.pop_back();
    const SurfaceCheck c = checkSurface(open);
    CHECK_FALSE(c.watertight());
    CHECK(c.boundaryEdges == 3);
    CHECK_THAT(c.reason(), Catch::Contains("holes"));

    TriSurface flipped = cube();
    std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
    CHECK(checkSurface(flipped).misorientedEdges > 0);

    TriSurface fin = cube();
    fin.points.push_back({0.5, 0.5, 2});
    fin.triangles.push_back({0, 2, 8});  // a third triangle on edge 0-2
    CHECK(checkSurface(fin).nonManifoldEdges >= 1);
}

TEST_CASE("rotation from degrees is a proper rotation", "[geometry]")
{
    const Mat3 R = rotationFromDegrees({30, 45, 60});
    const Mat3 I = R * transpose(R);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) CHECK(I(i, j) == Approx(i == j ? 1.0 : 0.0).margin(1e-14));
    const Vec3 z = rotationFromDegrees({0, 0, 90}) * Vec3{1, 0, 0};
    CHECK(z.y == Approx(1.0));
}
