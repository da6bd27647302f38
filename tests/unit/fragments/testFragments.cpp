// Fragments of hand-built 2 x 2 x 2 box meshes with known answers: two halves,
// one chipped corner, every cell separate; ids that do not depend on the order
// of the bonds; and the bond order and body frames of DemModel reproduced.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>
#include <random>

#include "../dem/boxMeshes.hpp"
#include "dem/bondLaw.hpp"
#include "dem/demModel.hpp"
#include "fragments/fragmentCase.hpp"
#include "fragments/fragments.hpp"
#include "fragments/unionFind.hpp"
#include "voronoi/tessellation.hpp"

using namespace rockfrac;

namespace {

constexpr double density = 2540.0;
const Vec3 cell_size{0.01, 0.015, 0.025};  // distinct, so every principal frame is unique
constexpr double pi = 3.14159265358979323846;

// Cell index of box (i, j, k) in a 2 x 2 x 2 block (boxBlockMesh's numbering).
int cellAt(int i, int j, int k)
{
    return (k * 2 + j) * 2 + i;
}
int iOf(int c)
{
    return c % 2;
}

struct Specimen {
    VoronoiMesh mesh = test::boxBlockMesh(2, 2, 2, cell_size, 1e-4);
    std::vector<std::array<int, 2>> bond_cells = demBondCells(mesh);
    std::vector<Quat> initial = initialCellOrientations(mesh, density);
    CellPoses at_rest() const { return {mesh.centroids, initial}; }

    // Stage per bond: broken where `broken(i, j)` says so.
    template <class Pred>
    std::vector<std::uint8_t> stages(Pred broken) const
    {
        std::vector<std::uint8_t> s(bond_cells.size(), bondElastic);
        for (std::size_t b = 0; b < s.size(); ++b)
            if (broken(bond_cells[b][0], bond_cells[b][1])) s[b] = bondBroken;
        return s;
    }
    FragmentAnalysis analyse(const std::vector<std::uint8_t>& stage, const CellPoses& poses) const
    {
        return analyseFragments(mesh, bond_cells, stage, poses, initial, density);
    }
};

double cellVolume()
{
    return cell_size.x * cell_size.y * cell_size.z;
}

// The rotation about axis by angle, as a quaternion.
Quat turn(const Vec3& axis, double angle)
{
    return quatFromRotationVector(angle * normalised(axis));
}

// Move the cells `which` rigidly: rotate by q about `pivot`, then translate.
void moveRigidly(CellPoses& poses, const std::vector<int>& which, const Quat& q, const Vec3& pivot,
                 const Vec3& shift)
{
    const Mat3 R = rotationMatrix(q);
    for (int c : which) {
        poses.position[c] = pivot + R * (poses.position[c] - pivot) + shift;
        poses.orientation[c] = normalised(q * poses.orientation[c]);
    }
}

}  // namespace

TEST_CASE("union-find merges sets and counts them", "[fragments]")
{
    UnionFind sets(6);
    CHECK(sets.sets() == 6);
    CHECK(sets.unite(0, 1));
    CHECK(sets.unite(2, 3));
    CHECK(sets.unite(1, 3));
    CHECK_FALSE(sets.unite(0, 2));
    CHECK(sets.sets() == 3);
    CHECK(sets.find(0) == sets.find(3));
    CHECK(sets.find(4) != sets.find(5));
}

TEST_CASE("two halves: 2 fragments of 4 cells with exact masses and sizes", "[fragments]")
{
    const Specimen s;
    const auto stage = s.stages([](int a, int b) { return iOf(a) != iOf(b); });
    const double V = cellVolume();

    auto check = [&](const FragmentAnalysis& a) {
        REQUIRE(a.labels.n_fragments == 2);
        for (int c = 0; c < 8; ++c) CHECK(a.labels.fragment_of_cell[c] == iOf(c));  // cell 0 is in fragment 0
        for (const Fragment& f : a.fragments) {
            CHECK(f.n_cells == 4);
            CHECK(f.volume == Approx(4 * V).epsilon(1e-14));
            CHECK(f.mass == Approx(density * 4 * V).epsilon(1e-14));
            CHECK(f.equivalent_diameter == Approx(std::cbrt(6 * 4 * V / pi)).epsilon(1e-14));
            // A half is 1 x 2 x 2 cells: 0.01 x 0.03 x 0.05 m.
            CHECK(f.principal_extents.x == Approx(0.05).epsilon(1e-12));
            CHECK(f.principal_extents.y == Approx(0.03).epsilon(1e-12));
            CHECK(f.principal_extents.z == Approx(0.01).epsilon(1e-12));
            CHECK(f.sieve_size == Approx(0.03).epsilon(1e-12));
        }
        CHECK(a.fragments[0].first_cell == 0);
        CHECK(a.fragments[1].first_cell == 1);
        CHECK(a.total_mass == Approx(density * 8 * V).epsilon(1e-14));
    };

    SECTION("at rest")
    {
        const FragmentAnalysis a = s.analyse(stage, s.at_rest());
        check(a);
        CHECK(a.fragments[0].centroid.x == Approx(0.005));
        CHECK(a.fragments[1].centroid.x == Approx(0.015));
        CHECK(a.fragments[0].centroid.y == Approx(0.015));
        CHECK(a.fragments[0].centroid.z == Approx(0.025));
    }
    SECTION("the halves flown apart and tumbled: same sizes, moved vertices")
    {
        CellPoses poses = s.at_rest();
        const std::vector<int> right{1, 3, 5, 7};
        const Vec3 pivot{0.015, 0.015, 0.025};
        moveRigidly(poses, right, turn({1, 2, 3}, 1.1), pivot, {0.2, -0.1, 0.05});
        const FragmentAnalysis a = s.analyse(stage, poses);
        check(a);
        CHECK(a.fragments[1].centroid.x == Approx(0.215).margin(1e-12));
        CHECK(a.fragments[1].centroid.y == Approx(-0.085).margin(1e-12));
        // Every vertex of the moved half is where the rigid motion puts it.
        const Mat3 R = rotationMatrix(turn({1, 2, 3}, 1.1));
        for (int c : right)
            for (int v = s.mesh.cellVertexOffset[c]; v < s.mesh.cellVertexOffset[c + 1]; ++v) {
                const Vec3 expected = pivot + R * (s.mesh.vertices[v] - pivot) + Vec3{0.2, -0.1, 0.05};
                CHECK(norm(a.vertices[v] - expected) < 1e-14);
            }
    }
}

TEST_CASE("one chipped cell: fragments of 7 and 1 cells", "[fragments]")
{
    const Specimen s;
    const int corner = cellAt(1, 1, 1);
    const auto stage = s.stages([&](int a, int b) { return a == corner || b == corner; });
    const FragmentAnalysis a = s.analyse(stage, s.at_rest());
    const double V = cellVolume();
    REQUIRE(a.labels.n_fragments == 2);
    CHECK(a.fragments[0].n_cells == 7);
    CHECK(a.fragments[1].n_cells == 1);
    CHECK(a.fragments[1].first_cell == corner);
    CHECK(a.labels.fragment_of_cell[corner] == 1);
    CHECK(a.fragments[0].mass == Approx(7 * density * V).epsilon(1e-14));
    CHECK(a.fragments[1].mass == Approx(density * V).epsilon(1e-14));
    CHECK(a.fragments[1].sieve_size == Approx(0.015).epsilon(1e-12));
    CHECK(a.fragments[1].equivalent_diameter == Approx(std::cbrt(6 * V / pi)).epsilon(1e-14));
    // The 7-cell L-block is no bigger than the whole block along any direction
    // (at most its diagonal) and at least its smallest side.
    const double diagonal = 2 * norm(cell_size);
    CHECK(a.fragments[0].principal_extents.x <= diagonal);
    CHECK(a.fragments[0].principal_extents.z >= 2 * cell_size.x - 1e-12);

    // The PSD of it: largest fragment 7/8 of the mass.
    const FragmentSizeReport r = reportSizes(a);
    CHECK(r.largest_mass_fraction == Approx(7.0 / 8.0));
    CHECK(r.original_size == Approx(std::cbrt(6 * 8 * V / pi)));
}

TEST_CASE("every bond broken: 8 fragments, one per cell", "[fragments]")
{
    const Specimen s;
    const auto stage = s.stages([](int, int) { return true; });
    const FragmentAnalysis a = s.analyse(stage, s.at_rest());
    REQUIRE(a.labels.n_fragments == 8);
    for (int c = 0; c < 8; ++c) {
        CHECK(a.labels.fragment_of_cell[c] == c);
        CHECK(a.fragments[c].n_cells == 1);
        CHECK(a.fragments[c].principal_extents.x == Approx(0.025).epsilon(1e-12));
        CHECK(a.fragments[c].principal_extents.y == Approx(0.015).epsilon(1e-12));
        CHECK(a.fragments[c].principal_extents.z == Approx(0.01).epsilon(1e-12));
        CHECK(norm(a.fragments[c].centroid - s.mesh.centroids[c]) < 1e-15);
    }
    // All the same size: everything passes at that size, nothing below it.
    const FragmentSizeReport r = reportSizes(a);
    CHECK(r.by_sieve_size.size.size() == 1);
    CHECK(r.sieve_size.p80 == Approx(0.015));
    CHECK(r.sieve_size.t10 == 0.0);
    CHECK(r.largest_mass_fraction == Approx(1.0 / 8.0));
}

TEST_CASE("softening bonds still hold; no bond broken is one fragment", "[fragments]")
{
    const Specimen s;
    std::vector<std::uint8_t> stage(s.bond_cells.size(), bondSoftening);
    CHECK(s.analyse(stage, s.at_rest()).labels.n_fragments == 1);
    // One softening bond per interface is enough to hold the cells together.
    for (std::size_t b = 0; b < stage.size(); ++b)
        stage[b] = (b == 0 || s.bond_cells[b] != s.bond_cells[b - 1]) ? bondSoftening : bondBroken;
    CHECK(s.analyse(stage, s.at_rest()).labels.n_fragments == 1);
}

TEST_CASE("fragment ids do not depend on the order of the bonds", "[fragments]")
{
    // A chain of 12 cells with some links broken; union in many orders.
    const int n = 12;
    std::vector<std::array<int, 2>> bonds;
    std::vector<std::uint8_t> stage;
    for (int c = 0; c + 1 < n; ++c) {
        bonds.push_back({c, c + 1});
        stage.push_back((c == 2 || c == 7) ? bondBroken : bondElastic);
    }
    bonds.push_back({0, 11});  // closes the ring: {0,1,2} and {8..11} join
    stage.push_back(bondElastic);
    const FragmentLabels reference = labelFragments(n, bonds, stage);
    CHECK(reference.n_fragments == 2);
    CHECK(reference.fragment_of_cell == std::vector<int>{0, 0, 0, 1, 1, 1, 1, 1, 0, 0, 0, 0});

    std::mt19937 random(7);
    std::vector<std::size_t> order(bonds.size());
    std::iota(order.begin(), order.end(), 0);
    for (int trial = 0; trial < 20; ++trial) {
        std::shuffle(order.begin(), order.end(), random);
        std::vector<std::array<int, 2>> b2;
        std::vector<std::uint8_t> s2;
        for (std::size_t k : order) {
            b2.push_back(trial % 2 ? std::array<int, 2>{bonds[k][1], bonds[k][0]} : bonds[k]);
            s2.push_back(stage[k]);
        }
        const FragmentLabels labels = labelFragments(n, b2, s2);
        CHECK(labels.fragment_of_cell == reference.fragment_of_cell);
    }
}

TEST_CASE("bad input to labelFragments is refused", "[fragments]")
{
    CHECK_THROWS_AS(labelFragments(2, {{0, 1}}, {}), std::invalid_argument);
    CHECK_THROWS_AS(labelFragments(2, {{0, 2}}, {0}), std::invalid_argument);
}

TEST_CASE("bond order and body frames are DemModel's", "[fragments]")
{
    // A real Voronoi mesh (general inertia tensors) with its bonds shuffled, so
    // DemModel's stable sort by cell pair has work to do.
    VoronoiMesh mesh = generateVoronoiMesh(Domain::box({0, 0, 0}, {0.04, 0.03, 0.02}), 40, 0.0, 11, 0.1);
    std::mt19937 random(3);
    std::shuffle(mesh.bonds.begin(), mesh.bonds.end(), random);
    for (std::size_t b = 0; b < mesh.bonds.size(); b += 3) {  // some bonds stored as (J, I)
        VoronoiBond& bond = mesh.bonds[b];
        std::swap(bond.cellI, bond.cellJ);
        std::swap(bond.faceI, bond.faceJ);
        std::swap(bond.lI, bond.lJ);
        bond.normalI = -bond.normalI;
    }
    DemParameters parameters;
    parameters.rock_density = density;
    const DemModel model(mesh, parameters);

    const auto bond_cells = demBondCells(mesh);
    const InterfaceArrays& faces = model.interfaces();
    REQUIRE(static_cast<int>(bond_cells.size()) == model.nBonds());
    for (int k = 0; k < faces.size(); ++k)
        for (int b = faces.bond_offset[k]; b < faces.bond_offset[k + 1]; ++b) {
            CHECK(bond_cells[b][0] == faces.cell_i[k]);
            CHECK(bond_cells[b][1] == faces.cell_j[k]);
        }

    const auto initial = initialCellOrientations(mesh, density);
    const auto& q = model.cells().orientation;
    for (int c = 0; c < mesh.nCells(); ++c) {
        CHECK(initial[c].w == q[c].w);
        CHECK(initial[c].x == q[c].x);
        CHECK(initial[c].y == q[c].y);
        CHECK(initial[c].z == q[c].z);
    }
    // At rest the moved vertices are the mesh vertices (to rounding).
    const auto moved = movedVertices(mesh, initial, {mesh.centroids, initial});
    for (std::size_t v = 0; v < moved.size(); ++v) CHECK(norm(moved[v] - mesh.vertices[v]) < 1e-15);
}
