// VTK output is read back with VTK's own XML readers (what ParaView uses).
#include <sys/resource.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <csignal>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "io/vtkOutput.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / "rockfrac-test-io";
    fs::create_directories(dir);
    return dir / name;
}

// Two unit cubes side by side as polyhedra (each with its own 8 points).
PolyhedronSet twoCubes()
{
    PolyhedronSet s;
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    s.cellFaceOffset.push_back(0);
    s.faceVertexOffset.push_back(0);
    for (int c = 0; c < 2; ++c) {
        const int base = static_cast<int>(s.points.size());
        for (int i = 0; i < 8; ++i)
            s.points.push_back({1.0 * (i & 1) + c, 1.0 * ((i >> 1) & 1), 1.0 * ((i >> 2) & 1)});
        for (const auto& q : quads) {
            for (int k : q) s.faceVertices.push_back(base + k);
            s.faceVertexOffset.push_back(static_cast<int>(s.faceVertices.size()));
        }
        s.cellFaceOffset.push_back(static_cast<int>(s.faceVertexOffset.size()) - 1);
    }
    return s;
}

}  // namespace

TEST_CASE("polyhedra round trip through VTK's reader", "[io]")
{
    const fs::path file = scratch("cells.vtu");
    writePolyhedraVtu(file, twoCubes(),
                      {Field::scalar("volume", {1.0, 1.0}), Field::integer("cellId", {0, 1})}, 0.25);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(file.string().c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    REQUIRE(grid->GetNumberOfCells() == 2);
    CHECK(grid->GetCellType(0) == VTK_POLYHEDRON);
    CHECK(grid->GetNumberOfPoints() == 16);
    CHECK(grid->GetCellData()->GetArray("volume")->GetTuple1(1) == 1.0);
    CHECK(grid->GetCellData()->GetArray("cellId")->GetTuple1(1) == 1.0);
    CHECK(grid->GetFieldData()->GetArray("TimeValue")->GetTuple1(0) == 0.25);
    // No temporary file is left behind.
    int leftovers = 0;
    for (const auto& e : fs::directory_iterator(file.parent_path()))
        if (e.path().filename().string().rfind(".tmp.", 0) == 0) ++leftovers;
    CHECK(leftovers == 0);
}

TEST_CASE("lines round trip with cell and point fields", "[io]")
{
    const fs::path file = scratch("bonds.vtp");
    writeLinesVtp(file, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1}, {1, 2}}, {Field::scalar("D", {0.0, 0.5})},
                  {Field::vector("v", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}})}, 1.0);
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(file.string().c_str());
    reader->Update();
    vtkPolyData* poly = reader->GetOutput();
    CHECK(poly->GetNumberOfLines() == 2);
    CHECK(poly->GetCellData()->GetArray("D")->GetTuple1(1) == 0.5);
    CHECK(poly->GetPointData()->GetArray("v")->GetNumberOfComponents() == 3);
}

TEST_CASE("tetrahedra round trip", "[io]")
{
    const fs::path file = scratch("tets.vtu");
    writeTetsVtu(file, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2, 3}},
                 {Field::scalar("D1", {1.0})}, {}, 0.0);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(file.string().c_str());
    reader->Update();
    CHECK(reader->GetOutput()->GetCellType(0) == VTK_TETRA);
}

TEST_CASE("a field of the wrong size is a programming error", "[io]")
{
    CHECK_THROWS(writeTetsVtu(scratch("bad.vtu"), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                              {{0, 1, 2, 3}}, {Field::scalar("D1", {1.0, 2.0})}, {}, 0.0));
}

TEST_CASE("series file continues after a restart", "[io]")
{
    const fs::path file = scratch("cells.vtu.series");
    fs::remove(file);
    {
        SeriesFile series(file);
        series.add("cells_0.vtu", 0.0);
        series.add("cells_1.vtu", 1e-4);
        series.add("cells_2.vtu", 2e-4);
        series.write();
    }
    SeriesFile restarted(file);
    REQUIRE(restarted.entries().size() == 3);
    restarted.add("cells_2.vtu", 1.5e-4);  // restart from 1e-4: later entries dropped
    CHECK(restarted.entries().size() == 3);
    CHECK(restarted.entries().back().second == 1.5e-4);
    restarted.write();
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    CHECK_THAT(text.str(), Catch::Contains("\"file-series-version\""));
}

// A full disk, imitated by the file-size limit (writes beyond it fail with EFBIG): VTK's own
// writer reported success and left a torn frame; the frame is refused and the old one kept.
TEST_CASE("a frame cut short by a full disk is refused and the previous frame kept", "[io][reliability]")
{
    const fs::path file = scratch("short.vtp");
    std::vector<Vec3> small = {{0, 0, 0}, {1, 0, 0}};
    writeLinesVtp(file, small, {{0, 1}}, {}, {}, 0.0);
    const auto before = fs::file_size(file);
    std::vector<Vec3> points(20000);
    std::vector<std::array<int, 2>> lines;
    for (int i = 0; i < 20000; ++i) points[i] = {std::sin(i * 1.1), std::cos(i * 0.7), 1e-3 * i};
    for (int i = 0; i + 1 < 20000; i += 2) lines.push_back({i, i + 1});

    struct rlimit old {};
    REQUIRE(getrlimit(RLIMIT_FSIZE, &old) == 0);
    struct rlimit limit = old;
    limit.rlim_cur = 8192;
    void (*oldHandler)(int) = std::signal(SIGXFSZ, SIG_IGN);
    REQUIRE(setrlimit(RLIMIT_FSIZE, &limit) == 0);
    bool refused = false;
    std::string message;
    try {
        writeLinesVtp(file, points, lines, {}, {}, 1.0);
    } catch (const UserError& e) {
        refused = true;
        message = e.what();
    }
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldHandler);
    CHECK(refused);
    CHECK(message.find("disk full") != std::string::npos);
    CHECK(fs::file_size(file) == before);  // the previous, complete frame
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(file.string().c_str());
    reader->Update();
    CHECK(reader->GetOutput()->GetNumberOfLines() == 1);
    int leftovers = 0;
    for (const auto& e : fs::directory_iterator(file.parent_path()))
        if (e.path().filename().string().rfind(".tmp.", 0) == 0) ++leftovers;
    CHECK(leftovers == 0);
}
