#include "fragments/fragments.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "dem/bondLaw.hpp"
#include "fragments/unionFind.hpp"

namespace rockfrac {

namespace {

constexpr double pi = 3.14159265358979323846;

Mat3 add(const Mat3& a, const Mat3& b)
{
    Mat3 c;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) c(i, j) = a(i, j) + b(i, j);
    return c;
}

// Inertia tensor of a point volume V at offset d (parallel-axis term): V (|d|^2 1 - d d^T).
Mat3 parallelAxis(double volume, const Vec3& d)
{
    Mat3 m;
    const double d2 = norm2(d);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = volume * ((i == j ? d2 : 0.0) - d[i] * d[j]);
    return m;
}

// Rotation taking a cell from its t = 0 orientation to the current one: R(q) R(q0)^T.
Mat3 rotationSinceStart(const Quat& initial, const Quat& current)
{
    return rotationMatrix(current) * transpose(rotationMatrix(initial));
}

// Unit principal axes (columns) of a symmetric tensor.
Mat3 principalAxes(const Mat3& tensor)
{
    Eigen::Matrix3d a;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a(i, j) = tensor(i, j);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(a);
    Mat3 axes;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) axes(i, j) = eigen.eigenvectors()(i, j);
    return axes;
}

// Cells grouped by fragment (CSR, cells ascending within a fragment).
void groupCells(const FragmentLabels& labels, std::vector<int>& offset, std::vector<int>& cells)
{
    offset.assign(labels.n_fragments + 1, 0);
    for (int f : labels.fragment_of_cell) ++offset[f + 1];
    std::partial_sum(offset.begin(), offset.end(), offset.begin());
    cells.resize(labels.fragment_of_cell.size());
    std::vector<int> next(offset.begin(), offset.end() - 1);
    for (int c = 0; c < static_cast<int>(labels.fragment_of_cell.size()); ++c)
        cells[next[labels.fragment_of_cell[c]]++] = c;
}

}  // namespace

double volumeEquivalentDiameter(double volume)
{
    return std::cbrt(6.0 * volume / pi);
}

std::vector<std::array<int, 2>> demBondCells(const VoronoiMesh& mesh)
{
    // The same ordering as DemModel::buildBonds: stable sort by (min, max) cell pair.
    std::vector<std::array<int, 2>> pairs(mesh.bonds.size());
    for (std::size_t b = 0; b < pairs.size(); ++b) {
        const VoronoiBond& bond = mesh.bonds[b];
        pairs[b] = {std::min(bond.cellI, bond.cellJ), std::max(bond.cellI, bond.cellJ)};
    }
    std::stable_sort(pairs.begin(), pairs.end());
    return pairs;
}

FragmentLabels labelFragments(int n_cells, const std::vector<std::array<int, 2>>& bond_cells,
                              const std::vector<std::uint8_t>& bond_stage)
{
    if (bond_cells.size() != bond_stage.size())
        throw std::invalid_argument("labelFragments: " + std::to_string(bond_cells.size()) + " bonds but " +
                                    std::to_string(bond_stage.size()) + " bond stages");
    UnionFind sets(n_cells);
    for (std::size_t b = 0; b < bond_cells.size(); ++b) {
        const auto [i, j] = bond_cells[b];
        if (i < 0 || j < 0 || i >= n_cells || j >= n_cells)
            throw std::invalid_argument("labelFragments: bond " + std::to_string(b) +
                                        " names a cell outside 0.." + std::to_string(n_cells - 1));
        if (bond_stage[b] != bondBroken) sets.unite(i, j);
    }
    // Number the sets by their smallest cell: the first cell met of each root.
    FragmentLabels labels;
    labels.fragment_of_cell.resize(n_cells);
    std::vector<int> id_of_root(n_cells, -1);
    for (int c = 0; c < n_cells; ++c) {
        int& id = id_of_root[sets.find(c)];
        if (id < 0) id = labels.n_fragments++;
        labels.fragment_of_cell[c] = id;
    }
    return labels;
}

std::vector<Quat> initialCellOrientations(const VoronoiMesh& mesh, double density)
{
    // Mirrors DemModel::buildCells (libs/dem/demModel.cpp) step by step.
    std::vector<Quat> orientation(mesh.nCells());
    for (int cell = 0; cell < mesh.nCells(); ++cell) {
        Eigen::Matrix3d inertia;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) inertia(i, j) = density * mesh.inertia[cell](i, j);
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia);
        Eigen::Matrix3d axes = eigen.eigenvectors();
        if (axes.determinant() < 0.0) axes.col(2) *= -1.0;
        Mat3 body_to_world;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) body_to_world(i, j) = axes(i, j);
        orientation[cell] = quatFromRotationMatrix(body_to_world);
    }
    return orientation;
}

std::vector<Vec3> movedVertices(const VoronoiMesh& mesh, const std::vector<Quat>& initial_orientation,
                                const CellPoses& poses)
{
    std::vector<Vec3> points(mesh.vertices.size());
    for (int c = 0; c < mesh.nCells(); ++c) {
        const Mat3 R0 = rotationMatrix(initial_orientation[c]);
        const Mat3 R = rotationMatrix(poses.orientation[c]);
        for (int v = mesh.cellVertexOffset[c]; v < mesh.cellVertexOffset[c + 1]; ++v) {
            const Vec3 body = transposeTimes(R0, mesh.vertices[v] - mesh.centroids[c]);
            points[v] = poses.position[c] + R * body;
        }
    }
    return points;
}

FragmentAnalysis analyseFragments(const VoronoiMesh& mesh, const std::vector<std::array<int, 2>>& bond_cells,
                                  const std::vector<std::uint8_t>& bond_stage, const CellPoses& poses,
                                  const std::vector<Quat>& initial_orientation, double density)
{
    const int n_cells = mesh.nCells();
    if (static_cast<int>(poses.position.size()) != n_cells ||
        static_cast<int>(poses.orientation.size()) != n_cells ||
        static_cast<int>(initial_orientation.size()) != n_cells)
        throw std::invalid_argument("analyseFragments: poses and orientations must have one entry per cell");
    FragmentAnalysis a;
    a.labels = labelFragments(n_cells, bond_cells, bond_stage);
    a.vertices = movedVertices(mesh, initial_orientation, poses);

    std::vector<int> offset, cells;
    groupCells(a.labels, offset, cells);
    a.fragments.resize(a.labels.n_fragments);
    for (int f = 0; f < a.labels.n_fragments; ++f) {
        Fragment& frag = a.fragments[f];
        frag.first_cell = cells[offset[f]];
        frag.n_cells = offset[f + 1] - offset[f];
        Vec3 moment;
        for (int k = offset[f]; k < offset[f + 1]; ++k) {
            const int c = cells[k];
            frag.volume += mesh.volumes[c];
            moment += mesh.volumes[c] * poses.position[c];
        }
        frag.centroid = moment / frag.volume;
        frag.mass = density * frag.volume;
        frag.equivalent_diameter = volumeEquivalentDiameter(frag.volume);

        // Inertia of the fragment's volume about its centroid: each cell's own tensor,
        // turned with the cell, plus its parallel-axis term.
        Mat3 inertia;
        for (int k = offset[f]; k < offset[f + 1]; ++k) {
            const int c = cells[k];
            const Mat3 Q = rotationSinceStart(initial_orientation[c], poses.orientation[c]);
            inertia = add(inertia, Q * mesh.inertia[c] * transpose(Q));
            inertia = add(inertia, parallelAxis(mesh.volumes[c], poses.position[c] - frag.centroid));
        }
        const Mat3 axes = principalAxes(inertia);

        // Extents of the vertices along the three axes.
        Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
        for (int k = offset[f]; k < offset[f + 1]; ++k) {
            const int c = cells[k];
            for (int v = mesh.cellVertexOffset[c]; v < mesh.cellVertexOffset[c + 1]; ++v) {
                const Vec3 along = transposeTimes(axes, a.vertices[v] - frag.centroid);
                for (int i = 0; i < 3; ++i) {
                    lo[i] = std::min(lo[i], along[i]);
                    hi[i] = std::max(hi[i], along[i]);
                }
            }
        }
        std::array<double, 3> extent{hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
        std::sort(extent.begin(), extent.end(), std::greater<double>());
        frag.principal_extents = {extent[0], extent[1], extent[2]};
        frag.sieve_size = extent[1];
        a.total_mass += frag.mass;
        a.total_volume += frag.volume;
    }
    return a;
}

}  // namespace rockfrac
