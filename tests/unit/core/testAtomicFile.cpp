// core/atomicFile: the checked write path and the closing-marker check used for files that a
// third-party program writes itself (gmsh's .msh, gnuplot's PNG).
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/atomicFile.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

TEST_CASE("a file is written whole and renamed; its tail holds the closing marker", "[atomicFile]")
{
    const fs::path dir = fs::temp_directory_path() / "rockfrac-test-atomicFile";
    fs::remove_all(dir);
    const fs::path msh = dir / "mesh.msh";
    writeFileAtomically(msh, [](std::ostream& out) {
        out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Elements\n"
            << std::string(5000, 'x') << "\n$EndElements\n";
    });
    CHECK(fileTailContains(msh, "$End", 64));
    CHECK_FALSE(fileTailContains(msh, "IEND", 64));
    // Cut short, as a full disk leaves it: the marker is gone.
    fs::resize_file(msh, 3000);
    CHECK_FALSE(fileTailContains(msh, "$End", 64));
    CHECK_FALSE(fileTailContains(dir / "missing", "$End", 64));
    // A marker further back than the window does not count.
    writeFileAtomically(msh, [](std::ostream& out) { out << "$End" << std::string(100, 'y'); });
    CHECK_FALSE(fileTailContains(msh, "$End", 64));
    CHECK(fileTailContains(msh, "$End", 200));
    int leftovers = 0;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().rfind(".tmp.", 0) == 0) ++leftovers;
    CHECK(leftovers == 0);
}
