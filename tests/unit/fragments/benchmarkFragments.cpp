// Timing of the fragment analysis on 10^5 cells (hidden: run with
// `test_fragments "[.benchmark]"`; docs/user-guide.md quotes the result).
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>

#include "../dem/boxMeshes.hpp"
#include "dem/bondLaw.hpp"
#include "fragments/fragmentCase.hpp"
#include "io/stateFile.hpp"
#include "voronoi/tessellation.hpp"
#include "voronoi/voronoiMeshIO.hpp"

using namespace rockfrac;

namespace {

double secondsSince(std::chrono::steady_clock::time_point t)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Break whole interfaces with probability p, tumble every cell a little, and time
// the analysis (labels, poses, sizes) and the PSD.
// A case fragmentPSD can read (mesh, rockProperties, 1/demState), to time the application.
void writeCase(const std::filesystem::path& dir, const VoronoiMesh& mesh, const CellPoses& poses,
               const std::vector<std::uint8_t>& stage)
{
    writeVoronoiMesh(dir, mesh);
    std::filesystem::create_directories(dir / "1");
    std::ofstream(dir / "constant/rockProperties") << "rock { density 2540; }\n";
    StateFile s;
    s.put("cell.position", poses.position);
    std::vector<double> q;
    for (const Quat& o : poses.orientation) q.insert(q.end(), {o.w, o.x, o.y, o.z});
    s.put("cell.orientation", q);
    s.put("bond.stage", stage);
    s.putScalar("time", 1.0);
    s.write(dir / "1/demState");
}

void timeAnalysis(const char* name, const VoronoiMesh& mesh, double p, const char* caseDir = nullptr)
{
    const double density = 2540;
    auto t0 = std::chrono::steady_clock::now();
    const auto bond_cells = demBondCells(mesh);
    const auto initial = initialCellOrientations(mesh, density);
    const double setup = secondsSince(t0);

    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<std::uint8_t> stage(bond_cells.size(), bondElastic);
    for (std::size_t b = 0; b < stage.size(); ++b) {
        static bool broken = false;
        if (b == 0 || bond_cells[b] != bond_cells[b - 1]) broken = u(random) < p;
        stage[b] = broken ? bondBroken : bondSoftening;
    }
    CellPoses poses{mesh.centroids, initial};
    for (int c = 0; c < mesh.nCells(); ++c)
        poses.orientation[c] = normalised(
            quatFromRotationVector({0.1 * u(random), 0.2 * u(random), 0.3 * u(random)}) * initial[c]);

    t0 = std::chrono::steady_clock::now();
    const FragmentAnalysis a = analyseFragments(mesh, bond_cells, stage, poses, initial, density);
    const double analysis = secondsSince(t0);
    t0 = std::chrono::steady_clock::now();
    const FragmentSizeReport r = reportSizes(a);
    const double psd = secondsSince(t0);
    std::printf(
        "%s: %d cells, %zu vertices, %d bonds -> %d fragments (P80 %.3g mm); setup %.3f s, "
        "analysis %.3f s, PSD %.3f s\n",
        name, mesh.nCells(), mesh.vertices.size(), mesh.nBonds(), a.labels.n_fragments,
        1e3 * r.sieve_size.p80, setup, analysis, psd);
    CHECK(a.labels.n_fragments > 1);
    if (caseDir) writeCase(caseDir, mesh, poses, stage);
}

}  // namespace

TEST_CASE("fragment analysis of 10^5 cells", "[.benchmark][fragments]")
{
    // 50 x 50 x 40 boxes glued at a 3 x 3 lattice per face (about Voronoi's bonds per cell).
    timeAnalysis("box block", test::boxBlockMesh(50, 50, 40, {0.001, 0.001, 0.001}, 1e-5, true, {}, {3, 3}),
                 0.5);
    auto t0 = std::chrono::steady_clock::now();
    const VoronoiMesh voronoi =
        generateVoronoiMesh(Domain::box({0, 0, 0}, {0.1, 0.1, 0.1}), 100000, 0.0, 5, 0.1);
    std::printf("(Voronoi mesh of 10^5 cells generated in %.1f s)\n", secondsSince(t0));
    timeAnalysis("Voronoi", voronoi, 0.8, ROCKFRAC_BINARY_DIR "/fragmentBenchmarkCase");
    std::printf("(case written to %s: time `fragmentPSD -case` on it)\n",
                ROCKFRAC_BINARY_DIR "/fragmentBenchmarkCase");
}
