// DemModel: construction from a Voronoi mesh, cells and bonds appended (feed), the laws set up.
#include "dem/demModel.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "core/error.hpp"
#include "dem/cellCore.hpp"
#include "dem/demModelDetail.hpp"

namespace rockfrac {

using demDetail::buildCellIncidence;
using demDetail::pi;

namespace {

// Hertz–Mindlin constants of a material pairing (physics.md §3.3).
ContactConstants contactConstants(double E1, double nu1, double E2, double nu2, double friction,
                                  double restitution)
{
    ContactConstants k;
    k.effective_modulus = 1.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2);
    const double G1 = E1 / (2.0 * (1.0 + nu1)), G2 = E2 / (2.0 * (1.0 + nu2));
    k.effective_shear_modulus = 1.0 / ((2.0 - nu1) / G1 + (2.0 - nu2) / G2);
    k.friction = friction;
    const double log_e = std::log(restitution);
    k.restitution_beta = log_e / std::sqrt(log_e * log_e + pi * pi);
    return k;
}

}  // namespace

namespace demDetail {

// Build CSR lists "which items does each cell take part in": entry 2*item + side,
// in increasing item order, so the gather sums in a fixed order.
void buildCellIncidence(int n_cells, const std::vector<int>& first, const std::vector<int>& second,
                        std::vector<int>& offset, std::vector<int>& entries)
{
    offset.assign(n_cells + 1, 0);
    for (std::size_t k = 0; k < first.size(); ++k) {
        ++offset[first[k] + 1];
        ++offset[second[k] + 1];
    }
    for (int c = 0; c < n_cells; ++c) offset[c + 1] += offset[c];
    entries.resize(offset[n_cells]);
    std::vector<int> fill(offset.begin(), offset.end() - 1);
    for (std::size_t k = 0; k < first.size(); ++k) {
        entries[fill[first[k]]++] = 2 * static_cast<int>(k);
        entries[fill[second[k]]++] = 2 * static_cast<int>(k) + 1;
    }
}

}  // namespace demDetail

std::string DemStatus::message() const
{
    std::ostringstream out;
    switch (code) {
        case DemStatusCode::ok:
            out << "DEM step " << step << " ok";
            break;
        case DemStatusCode::nonFiniteState:
            out << "DEM state became NaN/Inf at step " << step << " (t = " << time << " s) in cell " << cell
                << ": the time step is most likely too large (compare it with the Rayleigh step and the bond"
                   " stiffness and damping), or a parameter is invalid";
            break;
        case DemStatusCode::energyGrowth:
            out << "DEM energy grew without input at step " << step << " (t = " << time
                << " s): balance error " << energy_error << " J against an energy scale of " << energy_scale
                << " J; the time step is most likely too large for the bond stiffness and damping";
            break;
    }
    return out.str();
}

DemModel::DemModel(const VoronoiMesh& mesh, const DemParameters& parameters) : parameters_(parameters)
{
    setUpLaws();
    if (mesh.nCells() == 0) throw UserError("the Voronoi mesh has no cells");
    const std::vector<Quat> mesh_orientation = appendCells(mesh, WallMotion{}, true);
    appendBonds(mesh, 0, mesh_orientation);
    buildIncidence();
    shrinkToFit();
    refreshKinematicCaches();
    computeForces(0.0);
    measureCells(0.0);
    initial_balance_ = energies_.balance();
}

DemModel::DemModel(const DemParameters& parameters) : parameters_(parameters)
{
    setUpLaws();
    skin_ = parameters_.skin_distance;
    interfaces_.bond_offset.assign(1, 0);
    resizeFields(cells_, 0);  // the CSR offsets start at {0}
    buildIncidence();
    refreshKinematicCaches();
    computeForces(0.0);
    measureCells(0.0);
    initial_balance_ = energies_.balance();
}

void DemModel::setUpLaws()
{
    parameters_.validate();
    rock_rock_ = contactConstants(parameters_.rock_youngs_modulus, parameters_.rock_poisson_ratio,
                                  parameters_.rock_youngs_modulus, parameters_.rock_poisson_ratio,
                                  parameters_.rock_rock_friction, parameters_.rock_rock_restitution);
    rock_steel_ = contactConstants(parameters_.rock_youngs_modulus, parameters_.rock_poisson_ratio,
                                   parameters_.steel_youngs_modulus, parameters_.steel_poisson_ratio,
                                   parameters_.rock_steel_friction, parameters_.rock_steel_restitution);
}

// ---- Construction -----------------------------------------------------------

std::vector<Quat> DemModel::appendCells(const VoronoiMesh& mesh, const WallMotion& pose, bool identity)
{
    const int n = mesh.nCells();
    if (static_cast<int>(mesh.centroids.size()) != n || static_cast<int>(mesh.inertia.size()) != n ||
        static_cast<int>(mesh.cellFaceOffset.size()) != n + 1 ||
        static_cast<int>(mesh.cellVertexOffset.size()) != n + 1)
        throw UserError(
            "the Voronoi mesh is incomplete: centroids, inertia, vertices and faces are needed per cell");
    const double dilation =
        parameters_.dilation_radius > 0.0 ? parameters_.dilation_radius : mesh.dilationRadius;
    if (!(dilation > 0.0))
        throw UserError("the dilation radius is zero: set it in the mesh or the DEM parameters");
    if (!(skin_ > 0.0)) skin_ = parameters_.skin_distance > 0.0 ? parameters_.skin_distance : dilation;

    CellArrays& c = cells_;
    const int first = c.size();
    const Mat3 pose_rotation = rotationMatrix(normalised(pose.orientation));
    std::vector<Quat> mesh_orientation(n);
    resizeFields(c, first + n);  // at rest, no forces, no bonds yet
    for (int local = 0; local < n; ++local) {
        const int cell = first + local;
        const double density = parameters_.rock_density;
        c.mass[cell] = density * mesh.volumes[local];
        smallest_radius_ = std::min(smallest_radius_, std::cbrt(3.0 * mesh.volumes[local] / (4.0 * pi)));
        // Principal axes: the body frame is the eigenbasis of the inertia tensor.
        Eigen::Matrix3d inertia;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) inertia(i, j) = density * mesh.inertia[local](i, j);
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia);
        Eigen::Matrix3d axes = eigen.eigenvectors();
        if (axes.determinant() < 0.0) axes.col(2) *= -1.0;
        Mat3 body_to_mesh;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) body_to_mesh(i, j) = axes(i, j);
        mesh_orientation[local] = quatFromRotationMatrix(body_to_mesh);
        const Mat3 R = rotationMatrix(mesh_orientation[local]);
        c.principal_inertia[cell] = {eigen.eigenvalues()(0), eigen.eigenvalues()(1), eigen.eigenvalues()(2)};
        const Vec3 centroid = mesh.centroids[local];
        if (identity) {
            c.orientation[cell] = mesh_orientation[local];
            c.position[cell] = centroid;
        } else {
            c.orientation[cell] = normalised(pose.orientation * mesh_orientation[local]);
            c.position[cell] = pose.translation + pose_rotation * centroid;
            c.velocity[cell] =
                pose.velocity + cross(pose.angular_velocity, c.position[cell] - pose.translation);
            c.angular_velocity[cell] =
                transposeTimes(rotationMatrix(c.orientation[cell]), pose.angular_velocity);
        }

        // The core: the cell eroded by r_d, stored in the body frame.
        std::vector<Vec3> vertices;
        for (int v = mesh.cellVertexOffset[local]; v < mesh.cellVertexOffset[local + 1]; ++v)
            vertices.push_back(mesh.vertices[v] - centroid);
        std::vector<CellPlane> planes;
        std::vector<std::array<int, 2>> cell_edges;  // for a core shrunk instead of eroded
        for (int f = mesh.cellFaceOffset[local]; f < mesh.cellFaceOffset[local + 1]; ++f) {
            const int first_node = mesh.faceVertexOffset[f], end_node = mesh.faceVertexOffset[f + 1];
            const Vec3 on_face = vertices[mesh.faceVertices[first_node]];
            planes.push_back({mesh.faceNormal[f], dot(mesh.faceNormal[f], on_face)});
            for (int k = first_node; k < end_node; ++k) {
                const int a = mesh.faceVertices[k],
                          b = mesh.faceVertices[k + 1 < end_node ? k + 1 : first_node];
                const std::array<int, 2> edge{std::min(a, b), std::max(a, b)};
                if (std::find(cell_edges.begin(), cell_edges.end(), edge) == cell_edges.end())
                    cell_edges.push_back(edge);
            }
        }
        const ErodedCore core = dilatedCellCore(vertices, planes, cell_edges, dilation);
        if (core.shrunk) ++counters_.shrunk_cores;
        if (core.radius != dilation) ++counters_.own_radius_cells;
        c.dilation_radius[cell] = core.radius;
        if (core.vertices.size() > 255)  // the core's edge table holds 1-byte vertex indices
            throw UserError("cell " + std::to_string(local) + " of the Voronoi mesh has a core of " +
                            std::to_string(core.vertices.size()) +
                            " vertices (at most 255): its faces follow too many facets of the rock's "
                            "surface; decimate the scan (fewer triangles and hull facets) or mesh "
                            "larger cells (nCells or mesoConstant in system/voronoiMeshDict)");
        double reach = 0.0;
        for (const Vec3& v : core.vertices) {
            c.core_vertices.push_back(transposeTimes(R, v));
            reach = std::max(reach, norm(v));
        }
        c.core_vertex_offset.push_back(static_cast<int>(c.core_vertices.size()));
        for (const auto& edge : core.edges) {
            c.core_edges.push_back(static_cast<std::uint8_t>(edge[0]));
            c.core_edges.push_back(static_cast<std::uint8_t>(edge[1]));
        }
        c.core_edge_offset.push_back(static_cast<int>(c.core_edges.size()));
        // The core's facets lie on the cell's face planes moved inward (or scaled, for a
        // shrunk core), so each cell face normal at the core's support bounds it. Faces eroded
        // away touch the core in a vertex or an edge only: they lie outside, never decide a
        // depth, and are left out (a facet holds at least three core vertices).
        const double on_plane = 1e-6 * std::max(reach, 1e-300);  // the float normal: ~1e-7 reach
        const std::size_t core_begin = c.core_vertices.size() - core.vertices.size();  // this core's
        for (const CellPlane& plane : planes) {
            const Vec3 body = transposeTimes(R, plane.normal);
            CorePlane stored;
            stored.normal_x = static_cast<float>(body.x);
            stored.normal_y = static_cast<float>(body.y);
            stored.normal_z = static_cast<float>(body.z);
            const Vec3 normal = stored.normal();  // as stored, body frame
            double support = -1e300;
            for (std::size_t k = core_begin; k < c.core_vertices.size(); ++k)
                support = std::max(support, dot(normal, c.core_vertices[k]));
            int touching = 0;
            for (std::size_t k = core_begin; k < c.core_vertices.size(); ++k)
                touching += dot(normal, c.core_vertices[k]) > support - on_plane;
            if (touching < 3) continue;
            stored.offset = static_cast<float>(support);
            if (double(stored.offset) < support) stored.offset = std::nextafter(stored.offset, 1e30f);
            c.core_planes.push_back(stored);
        }
        c.core_plane_offset.push_back(static_cast<int>(c.core_planes.size()));
        c.bounding_radius[cell] = reach + core.radius;
    }
    const double G = parameters_.rock_youngs_modulus / (2.0 * (1.0 + parameters_.rock_poisson_ratio));
    rayleigh_time_step_ = pi * smallest_radius_ * std::sqrt(parameters_.rock_density / G) /
                          (0.1631 * parameters_.rock_poisson_ratio + 0.8766);
    return mesh_orientation;
}

void DemModel::appendBonds(const VoronoiMesh& mesh, int first_cell, const std::vector<Quat>& mesh_orientation)
{
    // Interfaces = cell pairs; their bonds are contiguous (sorted by pair, stable).
    // New cells have the highest indices, so appended interfaces keep the (i, j) order.
    std::vector<int> order(mesh.nBonds());
    std::iota(order.begin(), order.end(), 0);
    auto pairOf = [&](int b) {
        const VoronoiBond& bond = mesh.bonds[b];
        return std::make_pair(std::min(bond.cellI, bond.cellJ), std::max(bond.cellI, bond.cellJ));
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return pairOf(a) < pairOf(b); });

    // Anchor nodes: the distinct bond points of each new cell (a face node carries the
    // bonds of up to three faces of the cell), sorted by cell and coordinates, each
    // in its cell's body frame once. end = 2 * bond + (0: the mesh's cellI, 1: cellJ).
    for (const VoronoiBond& bond : mesh.bonds)
        if (bond.cellI == bond.cellJ || std::min(bond.cellI, bond.cellJ) < 0 ||
            std::max(bond.cellI, bond.cellJ) >= mesh.nCells())
            throw UserError("the Voronoi mesh has an invalid bond");
    CellArrays& c = cells_;
    std::vector<int> ends(2 * std::size_t(mesh.nBonds()));
    std::iota(ends.begin(), ends.end(), 0);
    auto endCell = [&](int e) { return e % 2 == 0 ? mesh.bonds[e / 2].cellI : mesh.bonds[e / 2].cellJ; };
    auto endKey = [&](int e) {
        const Vec3& p = mesh.bonds[e / 2].point;
        return std::make_tuple(endCell(e), p.x, p.y, p.z);
    };
    std::sort(ends.begin(), ends.end(), [&](int a, int b) { return endKey(a) < endKey(b); });
    // The bond points of a face come from the tessellation of one of its two cells, so
    // the same node seen from the other cell's faces may differ in the last bits: points
    // within 1e-9 of the cell size are one node (the other end then starts ~1e-16 of the
    // cell size away instead of exactly at the point: an initial opening far below any
    // elastic displacement, docs/theory-dem.md §7).
    std::vector<std::uint16_t> end_node(ends.size());
    std::vector<Vec3> points;  // the current cell's nodes, mesh frame
    for (std::size_t e = 0, local = 0; local < std::size_t(mesh.nCells()); ++local) {
        const Mat3 R = rotationMatrix(mesh_orientation[local]);
        const double tolerance = 1e-9 * std::cbrt(std::abs(mesh.volumes[local]));
        points.clear();
        for (; e < ends.size() && endCell(ends[e]) == static_cast<int>(local); ++e) {
            const Vec3& point = mesh.bonds[ends[e] / 2].point;
            std::size_t node = 0;
            while (node < points.size() && norm2(points[node] - point) > tolerance * tolerance) ++node;
            if (node == points.size()) {
                if (node > 65535)
                    throw UserError(
                        "a Voronoi cell has more than 65536 bond nodes: the mesh is not a tessellation");
                points.push_back(point);
                c.anchor_nodes.push_back(transposeTimes(R, point - mesh.centroids[local]));
            }
            end_node[ends[e]] = static_cast<std::uint16_t>(node);
        }
        c.anchor_node_offset.push_back(static_cast<int>(c.anchor_nodes.size()));
    }

    InterfaceArrays& f = interfaces_;
    BondStorage& b = bonds_;
    if (f.bond_offset.empty()) f.bond_offset.assign(1, 0);
    const double beta = parameters_.bond_damping;
    for (std::size_t head_index = 0; head_index < order.size();) {
        std::size_t last = head_index;
        while (last < order.size() && pairOf(order[last]) == pairOf(order[head_index])) ++last;
        const VoronoiBond& head = mesh.bonds[order[head_index]];
        const bool swapped = head.cellI > head.cellJ;
        const int li = swapped ? head.cellJ : head.cellI, lj = swapped ? head.cellI : head.cellJ;
        if (li == lj || li < 0 || lj >= mesh.nCells())
            throw UserError("the Voronoi mesh has an invalid bond");
        const int ci = first_cell + li, cj = first_cell + lj;
        // Outward normals of each cell's face (cell J's face normal from the mesh when known).
        const Vec3 normal_I = head.normalI;
        const Vec3 normal_J =
            head.faceJ >= 0 && head.faceJ < mesh.nFaces() ? mesh.faceNormal[head.faceJ] : -normal_I;
        // Body frames relative to the mesh frame (where the bond points are given).
        const Mat3 Ri = rotationMatrix(mesh_orientation[li]);
        const Mat3 Rj = rotationMatrix(mesh_orientation[lj]);
        f.cell_i.push_back(ci);
        f.cell_j.push_back(cj);
        f.normal_i.push_back(transposeTimes(Ri, swapped ? normal_J : normal_I));
        f.normal_j.push_back(transposeTimes(Rj, swapped ? normal_I : normal_J));
        f.length_i.push_back(swapped ? head.lJ : head.lI);
        f.length_j.push_back(swapped ? head.lI : head.lJ);
        f.bond_area.push_back(head.area);
        // beta in seconds: as given, or from a fraction zeta of the critical damping of one
        // bond (axial stiffness k = k_n A/(n l_ij) between the reduced mass m*):
        // c = 2 zeta sqrt(k m*) = beta_eff k  =>  beta_eff = 2 zeta sqrt(m*/k).
        const double l = head.lI + head.lJ;
        const double stiffness = parameters_.bond_law->normalModulus() * head.area / l;
        const double reduced_mass = cells_.mass[ci] * cells_.mass[cj] / (cells_.mass[ci] + cells_.mass[cj]);
        f.damping_beta.push_back(parameters_.damping_reading == DampingReading::absolute
                                     ? beta
                                     : 2.0 * beta * std::sqrt(reduced_mass / stiffness));
        // The optional Weibull size effect: a larger interface is weaker (weakest link).
        const double size_factor =
            parameters_.bondSizeFactor(head.area * static_cast<double>(last - head_index));
        // (An empty array means 1 everywhere: it is filled at the first factor that is not 1.)
        if (!f.strength_scale.empty() || size_factor != 1.0) {
            f.strength_scale.resize(f.cell_i.size() - 1, 1.0);
            f.strength_scale.push_back(size_factor);
        }
        f.softening_slot.push_back(-1);
        for (std::size_t e = head_index; e < last; ++e) {
            const int bond = order[e];
            const bool cell_i_is_mesh_I = mesh.bonds[bond].cellI == li;
            b.node_i.push_back(end_node[2 * bond + (cell_i_is_mesh_I ? 0 : 1)]);
            b.node_j.push_back(end_node[2 * bond + (cell_i_is_mesh_I ? 1 : 0)]);
        }
        const int n_bonds = static_cast<int>(last - head_index);
        f.intact_bonds.push_back(n_bonds);
        f.bond_offset.push_back(f.bond_offset.back() + n_bonds);
        cells_.initial_bond_count[ci] += n_bonds;
        cells_.initial_bond_count[cj] += n_bonds;
        head_index = last;
    }
    const int n_interfaces = f.size(), n_bonds = static_cast<int>(b.node_i.size());
    resizeFields<derivedField>(f, n_interfaces);  // no forces yet
    resizeFields(b, n_bonds);                     // stage: bondElastic
    counters_.bonds = n_bonds;
}

// ---- Cells entering and leaving ------------------------------------------------

int DemModel::insertCells(const VoronoiMesh& mesh, const WallMotion& pose)
{
    if (mesh.nCells() == 0) throw UserError("insertCells: the mesh to insert has no cells");
    const int first = cells_.size();
    const std::vector<Quat> mesh_orientation = appendCells(mesh, pose, false);
    appendBonds(mesh, first, mesh_orientation);
    buildIncidence();
    // The kinetic energy the new cells bring (they start unstrained and, placed
    // clear of everything, without contacts).
    double kinetic = 0.0;
    for (int c = first; c < cells_.size(); ++c) {
        const Vec3 w = cells_.angular_velocity[c], inertia = cells_.principal_inertia[c];
        kinetic += 0.5 * cells_.mass[c] * norm2(cells_.velocity[c]) +
                   0.5 * (inertia.x * w.x * w.x + inertia.y * w.y * w.y + inertia.z * w.z * w.z);
    }
    energies_.exchanged -= kinetic;
    energy_floor_ = 0.0;  // re-derived from the bonds at the next check
    lists_valid_ = forces_valid_ = false;
    return first;
}

void DemModel::buildIncidence()
{
    const int n = cells_.size();
    buildCellIncidence(n, interfaces_.cell_i, interfaces_.cell_j, cell_interface_offset_, cell_interfaces_);
    // Each cell's interfaces sorted by neighbour, for the pair -> interface lookup (the
    // ranges of cell_interface_offset_; the neighbour is the interface's other cell).
    neighbour_interface_.resize(cell_interfaces_.size());
    for (int c = 0; c < n; ++c) {
        std::vector<std::pair<int, int>> list;
        for (int e = cell_interface_offset_[c]; e < cell_interface_offset_[c + 1]; ++e) {
            const int k = cell_interfaces_[e] / 2;
            list.emplace_back(interfaces_.cell_i[k] == c ? interfaces_.cell_j[k] : interfaces_.cell_i[k], k);
        }
        std::sort(list.begin(), list.end());
        for (std::size_t i = 0; i < list.size(); ++i)
            neighbour_interface_[static_cast<std::size_t>(cell_interface_offset_[c]) + i] = list[i].second;
    }
    rotation_.resize(n);
    angular_velocity_world_.resize(n);
    cell_wall_item_offset_.assign(n + 1, 0);
    cell_pair_offset_.assign(n + 1, 0);
}

// ---- Bond strengths ---------------------------------------------------------

void DemModel::scaleInterfaceStrength(int interface, double factor)
{
    if (interface < 0 || interface >= interfaces_.size() || !(factor > 0) || !std::isfinite(factor))
        throw std::invalid_argument("DemModel::scaleInterfaceStrength: bad interface or factor");
    if (interfaces_.strength_scale.empty()) interfaces_.strength_scale.assign(interfaces_.size(), 1.0);
    interfaces_.strength_scale[interface] *= factor;
}

}  // namespace rockfrac
