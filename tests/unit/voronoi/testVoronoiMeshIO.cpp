// constant/voronoiMesh files: an exact round trip, and a clear UserError
// naming the file for every kind of damage.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "voronoi/tessellation.hpp"
#include "voronoi/voronoiMeshIO.hpp"
#include "voronoiTestSupport.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

namespace {

// A fresh case directory per test, removed afterwards.
struct ScratchCase {
    explicit ScratchCase(const std::string& name)
        : dir(fs::temp_directory_path() / ("rockfrac-voronoi-" + name + "-" + std::to_string(::getpid())))
    {
        fs::remove_all(dir);
    }
    ~ScratchCase() { fs::remove_all(dir); }
    fs::path file(const char* name) const { return dir / "constant/voronoiMesh" / name; }
    fs::path dir;
};

const VoronoiMesh& discMesh()
{
    static const VoronoiMesh mesh = generateVoronoiMesh(test::bdtDisc(), 300, 2.5e-3, 21);
    return mesh;
}

// The message of the UserError readVoronoiMesh throws ("" if none).
std::string readError(const fs::path& dir)
{
    try {
        readVoronoiMesh(dir);
    } catch (const UserError& e) {
        return e.what();
    }
    return "";
}

void patchByte(const fs::path& file, std::streamoff at, char value)
{
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(at);
    f.put(value);
}

bool mentions(const std::string& message, const std::string& text)
{
    return message.find(text) != std::string::npos;
}

}  // namespace

TEST_CASE("a written mesh reads back bit for bit", "[voronoi][io]")
{
    ScratchCase scratch("roundtrip");
    writeVoronoiMesh(scratch.dir, discMesh());
    for (const char* name : {"meshInfo", "cells", "vertices", "faces", "bonds"})
        CHECK(fs::exists(scratch.file(name)));
    CHECK(test::identical(readVoronoiMesh(scratch.dir), discMesh()));

    // No temporary files are left behind.
    for (const auto& entry : fs::directory_iterator(scratch.dir / "constant/voronoiMesh"))
        CHECK(entry.path().filename().string().find(".tmp.") == std::string::npos);
}

TEST_CASE("a truncated file is reported with the sizes", "[voronoi][io]")
{
    ScratchCase scratch("truncated");
    writeVoronoiMesh(scratch.dir, discMesh());
    fs::resize_file(scratch.file("faces"), 1000);
    const std::string message = readError(scratch.dir);
    INFO(message);
    CHECK(mentions(message, "constant/voronoiMesh/faces: truncated: expected "));
    CHECK(mentions(message, "found 1000"));
    CHECK(mentions(message, "re-run voronoiMesh"));

    fs::resize_file(scratch.file("bonds"), 10);
    CHECK(mentions(readError(scratch.dir), "constant/voronoiMesh/"));
}

TEST_CASE("a wrong magic, version or corrupt payload is reported", "[voronoi][io]")
{
    ScratchCase scratch("magic");
    writeVoronoiMesh(scratch.dir, discMesh());
    patchByte(scratch.file("cells"), 0, 'X');
    std::string message = readError(scratch.dir);
    INFO(message);
    CHECK(mentions(message, "constant/voronoiMesh/cells"));
    CHECK(mentions(message, "magic"));

    writeVoronoiMesh(scratch.dir, discMesh());
    patchByte(scratch.file("vertices"), 16, 9);  // format version 9
    message = readError(scratch.dir);
    CHECK(mentions(message, "constant/voronoiMesh/vertices"));
    CHECK(mentions(message, "version"));

    writeVoronoiMesh(scratch.dir, discMesh());
    patchByte(scratch.file("vertices"), 64 + 1000, 0x55);  // a flipped coordinate
    message = readError(scratch.dir);
    CHECK(mentions(message, "constant/voronoiMesh/vertices"));
    CHECK(mentions(message, "checksum"));
}

TEST_CASE("out-of-range indices are reported, naming the file", "[voronoi][io]")
{
    ScratchCase scratch("index");
    VoronoiMesh broken = discMesh();
    broken.faceVertices[0] = 999;  // cell 0 has far fewer vertices
    writeVoronoiMesh(scratch.dir, broken);
    std::string message = readError(scratch.dir);
    INFO(message);
    CHECK(mentions(message, "constant/voronoiMesh/faces"));
    CHECK(mentions(message, "vertex 999"));

    broken = discMesh();
    for (int f = 0; f < broken.nFaces(); ++f)
        if (broken.faceNeighbour[f] == boundaryFace) {
            broken.faceNeighbour[f] = broken.nCells() + 5;
            break;
        }
    writeVoronoiMesh(scratch.dir, broken);
    message = readError(scratch.dir);
    CHECK(mentions(message, "constant/voronoiMesh/faces"));
    CHECK(mentions(message, "neighbour"));

    broken = discMesh();
    broken.cellFaceOffset[1] = broken.cellFaceOffset[2] + 1;  // offsets not monotone
    writeVoronoiMesh(scratch.dir, broken);
    CHECK(mentions(readError(scratch.dir), "constant/voronoiMesh/cells"));
}

TEST_CASE("a missing or damaged meshInfo is reported", "[voronoi][io]")
{
    ScratchCase scratch("meshInfo");
    CHECK(mentions(readError(scratch.dir), "constant/voronoiMesh/meshInfo"));

    writeVoronoiMesh(scratch.dir, discMesh());
    std::ofstream(scratch.file("meshInfo"), std::ios::app) << "nCells 12;\n";  // given twice
    CHECK(mentions(readError(scratch.dir), "constant/voronoiMesh/meshInfo"));

    writeVoronoiMesh(scratch.dir, discMesh());
    {
        std::ifstream in(scratch.file("meshInfo"));
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        text.replace(text.find("nFaces"), 6, "nFacez");
        std::ofstream(scratch.file("meshInfo")) << text;
    }
    const std::string message = readError(scratch.dir);
    CHECK(mentions(message, "constant/voronoiMesh/meshInfo"));
    CHECK(mentions(message, "nFaces"));
}
