#include "crusher/destructor.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cstdint>

#include "fragments/fragments.hpp"

namespace rockfrac {

Vec3 principalExtents(const DemModel& model, const std::vector<int>& members)
{
    const CellArrays& cells = model.cells();
    std::vector<Vec3> points;
    double dilation = 0.0;
    for (int c : members) {
        const Mat3 R = rotationMatrix(cells.orientation[c]);
        for (int v = cells.core_vertex_offset[c]; v < cells.core_vertex_offset[c + 1]; ++v)
            points.push_back(cells.position[c] + R * cells.core_vertices[v]);
        dilation = std::max(dilation, cells.dilation_radius[c]);
    }
    if (points.empty()) return {};
    Vec3 mean;
    for (const Vec3& p : points) mean += p;
    mean = (1.0 / points.size()) * mean;
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const Vec3& p : points) {
        const Eigen::Vector3d d(p.x - mean.x, p.y - mean.y, p.z - mean.z);
        scatter += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
    std::array<double, 3> extent{};
    for (int axis = 0; axis < 3; ++axis) {
        const Eigen::Vector3d e = eigen.eigenvectors().col(axis);
        double lo = 1e300, hi = -1e300;
        for (const Vec3& p : points) {
            const double t = e.x() * p.x + e.y() * p.y + e.z() * p.z;
            lo = std::min(lo, t);
            hi = std::max(hi, t);
        }
        extent[axis] = hi - lo + 2.0 * dilation;
    }
    std::sort(extent.begin(), extent.end(), std::greater<double>());
    return {extent[0], extent[1], extent[2]};
}

DestructorResult destroyBelow(DemModel& model, double below)
{
    DestructorResult result;
    const CellArrays& cells = model.cells();
    const int n = cells.size();
    bool any = false;
    for (int c = 0; c < n && !any; ++c) any = cells.position[c].z < below;
    if (!any) return result;

    // Fragments over the intact bonds of the current state.
    const InterfaceArrays& faces = model.interfaces();
    std::vector<std::array<int, 2>> bond_cells(model.nBonds());
    for (int k = 0; k < faces.size(); ++k)
        for (int b = faces.bond_offset[k]; b < faces.bond_offset[k + 1]; ++b)
            bond_cells[b] = {faces.cell_i[k], faces.cell_j[k]};
    const std::vector<std::uint8_t> stage(model.bondStorage().stage.begin(), model.bondStorage().stage.end());
    const FragmentLabels labels = labelFragments(n, bond_cells, stage);
    std::vector<char> leaving(labels.n_fragments, 0);
    for (int c = 0; c < n; ++c)
        if (cells.position[c].z < below) leaving[labels.fragment_of_cell[c]] = 1;
    std::vector<std::vector<int>> members(labels.n_fragments);
    std::vector<char> remove(n, 0);
    for (int c = 0; c < n; ++c)
        if (leaving[labels.fragment_of_cell[c]]) {
            members[labels.fragment_of_cell[c]].push_back(c);
            remove[c] = 1;
        }
    const double density = model.parameters().rock_density;
    for (int f = 0; f < labels.n_fragments; ++f) {
        if (!leaving[f]) continue;
        DischargedFragment d;
        d.time = model.time();
        d.n_cells = static_cast<int>(members[f].size());
        for (int c : members[f]) d.mass += cells.mass[c];
        d.volume = d.mass / density;
        d.equivalent_diameter = volumeEquivalentDiameter(d.volume);
        d.sieve_size = principalExtents(model, members[f]).y;
        result.mass += d.mass;
        result.fragments.push_back(d);
    }
    result.new_index = model.removeCells(remove);
    return result;
}

}  // namespace rockfrac
