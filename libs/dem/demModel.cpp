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
#include "core/parallel.hpp"
#include "dem/cellCore.hpp"
#include "dem/cellKernels.hpp"
#include "dem/surfaceFeatures.hpp"

namespace rockfrac {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr int cell_block_size = 512;

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

BondMaterial bondMaterial(const DemParameters& p)
{
    BondMaterial m;
    const double E = p.bond_youngs_modulus, nu = p.bond_poisson_ratio;
    m.normal_modulus = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));  // Eq. 7
    m.shear_modulus = E / (2.0 * (1.0 + nu));                             // Eq. 8
    m.tensile_strength = p.bond_tensile_strength;
    m.cohesion = p.bond_cohesion;
    m.friction = p.bond_friction;
    m.fracture_energy_I = p.fracture_energy_mode_I;
    m.fracture_energy_II = p.fracture_energy_mode_II;
    m.bk_exponent = p.bk_exponent;
    m.rupture_tolerance = p.rupture_tolerance;
    return m;
}

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

template <class T>
std::size_t bytes(const std::vector<T>& v)
{
    return v.capacity() * sizeof(T);
}

void requireCount(std::size_t got, int expected)
{
    if (static_cast<int>(got) != expected)
        throw UserError("removeCells: the mask has " + std::to_string(got) + " entries for " +
                        std::to_string(expected) + " cells");
}

// Angle of the rotation between two orientations.
double rotationAngle(const Quat& a, const Quat& b)
{
    const double c = std::fabs(a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z);
    return 2.0 * std::acos(std::min(1.0, c));
}

}  // namespace

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
    cells_.core_vertex_offset.assign(1, 0);
    cells_.core_edge_offset.assign(1, 0);
    cells_.core_plane_offset.assign(1, 0);
    cells_.anchor_node_offset.assign(1, 0);
    buildIncidence();
    refreshKinematicCaches();
    computeForces(0.0);
    measureCells(0.0);
    initial_balance_ = energies_.balance();
}

void DemModel::setUpLaws()
{
    parameters_.validate();
    bond_runner_ = bondLawRunner(parameters_.bond_law);
    contact_runners_ = contactLawRunners(parameters_.contact_law);
    bond_material_ = bondMaterial(parameters_);
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
    c.position.resize(first + n);
    c.velocity.resize(first + n, Vec3{});
    c.angular_velocity.resize(first + n, Vec3{});
    c.orientation.resize(first + n);
    c.force.resize(first + n, Vec3{});
    c.torque.resize(first + n, Vec3{});
    c.mass.resize(first + n);
    c.principal_inertia.resize(first + n);
    c.dilation_radius.resize(first + n, dilation);
    c.bounding_radius.resize(first + n);
    c.initial_bond_count.resize(first + n, 0);
    if (c.core_vertex_offset.empty()) c.core_vertex_offset.assign(1, 0);
    if (c.core_edge_offset.empty()) c.core_edge_offset.assign(1, 0);
    if (c.core_plane_offset.empty()) c.core_plane_offset.assign(1, 0);
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
        const ErodedCore core = erodeConvexCell(vertices, planes, cell_edges, dilation);
        if (core.shrunk) ++counters_.shrunk_cores;
        if (core.vertices.size() > 255)
            throw std::runtime_error(
                "a cell core with more than 255 vertices (the edge table holds 1-byte indices)");
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
        c.bounding_radius[cell] = reach + dilation;
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
    if (c.anchor_node_offset.empty()) c.anchor_node_offset.assign(1, 0);
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
        const double stiffness = bond_material_.normal_modulus * head.area / l;
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
    f.force_on_i.resize(n_interfaces, Vec3{});
    f.torque_on_i.resize(n_interfaces, Vec3{});
    f.torque_on_j.resize(n_interfaces, Vec3{});
    b.stage.resize(n_bonds, bondElastic);
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

namespace {

// Keep the entries whose flag is set, in order.
template <class T>
void keepFlagged(std::vector<T>& v, const std::vector<char>& keep)
{
    std::size_t out = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (keep[i]) v[out++] = v[i];
    v.resize(out);
}

// Keep the CSR ranges [offset[i], offset[i+1]) whose flag is set, in order.
template <class T>
void keepFlaggedRanges(std::vector<int>& offset, std::vector<T>& values, const std::vector<char>& keep)
{
    std::vector<int> kept_offset(1, 0);
    std::vector<T> kept;
    for (std::size_t i = 0; i + 1 < offset.size(); ++i) {
        if (!keep[i]) continue;
        kept.insert(kept.end(), values.begin() + offset[i], values.begin() + offset[i + 1]);
        kept_offset.push_back(static_cast<int>(kept.size()));
    }
    offset = std::move(kept_offset);
    values = std::move(kept);
}

}  // namespace

std::vector<int> DemModel::removeCells(const std::vector<char>& remove)
{
    const int n = cells_.size();
    requireCount(remove.size(), n);
    std::vector<int> new_index(n, -1);
    std::vector<char> keep_cell(n);
    int kept = 0;
    for (int c = 0; c < n; ++c) {
        keep_cell[c] = !remove[c];
        if (keep_cell[c]) new_index[c] = kept++;
    }
    if (kept == n) return new_index;
    const double energy_before = energies_.kinetic() + energies_.stored();

    // Cells, with their core vertex and anchor node ranges.
    CellArrays& c = cells_;
    keepFlaggedRanges(c.core_vertex_offset, c.core_vertices, keep_cell);
    keepFlaggedRanges(c.core_edge_offset, c.core_edges, keep_cell);
    keepFlaggedRanges(c.core_plane_offset, c.core_planes, keep_cell);
    keepFlaggedRanges(c.anchor_node_offset, c.anchor_nodes, keep_cell);
    keepFlagged(c.position, keep_cell);
    keepFlagged(c.velocity, keep_cell);
    keepFlagged(c.orientation, keep_cell);
    keepFlagged(c.angular_velocity, keep_cell);
    keepFlagged(c.force, keep_cell);
    keepFlagged(c.torque, keep_cell);
    keepFlagged(c.mass, keep_cell);
    keepFlagged(c.principal_inertia, keep_cell);
    keepFlagged(c.dilation_radius, keep_cell);
    keepFlagged(c.bounding_radius, keep_cell);
    keepFlagged(c.initial_bond_count, keep_cell);

    // Interfaces and their bonds: kept when both cells stay (a bond to a removed cell
    // goes with it). Monotone renumbering keeps the (cell_i, cell_j) order.
    InterfaceArrays& f = interfaces_;
    std::vector<char> keep_face(f.size()), keep_bond(bonds_.size(), 0);
    std::vector<int> bond_offset(1, 0);
    std::vector<BondSoftening> softening;  // the pool, compacted in interface order
    for (int k = 0; k < f.size(); ++k) {
        keep_face[k] = keep_cell[f.cell_i[k]] && keep_cell[f.cell_j[k]];
        if (!keep_face[k]) continue;
        f.cell_i[k] = new_index[f.cell_i[k]];
        f.cell_j[k] = new_index[f.cell_j[k]];
        const int n_bonds = f.bond_offset[k + 1] - f.bond_offset[k];
        for (int b = f.bond_offset[k]; b < f.bond_offset[k + 1]; ++b) keep_bond[b] = 1;
        bond_offset.push_back(bond_offset.back() + n_bonds);
        if (f.softening_slot[k] >= 0) {
            const int slot = static_cast<int>(softening.size());
            softening.insert(softening.end(), bonds_.softening.begin() + f.softening_slot[k],
                             bonds_.softening.begin() + f.softening_slot[k] + n_bonds);
            f.softening_slot[k] = slot;
        }
    }
    f.bond_offset = std::move(bond_offset);
    bonds_.softening = std::move(softening);
    keepFlagged(f.softening_slot, keep_face);
    keepFlagged(f.cell_i, keep_face);
    keepFlagged(f.cell_j, keep_face);
    keepFlagged(f.intact_bonds, keep_face);
    keepFlagged(f.normal_i, keep_face);
    keepFlagged(f.normal_j, keep_face);
    keepFlagged(f.length_i, keep_face);
    keepFlagged(f.length_j, keep_face);
    keepFlagged(f.bond_area, keep_face);
    keepFlagged(f.damping_beta, keep_face);
    if (!f.strength_scale.empty()) keepFlagged(f.strength_scale, keep_face);
    keepFlagged(f.force_on_i, keep_face);
    keepFlagged(f.torque_on_i, keep_face);
    keepFlagged(f.torque_on_j, keep_face);
    BondStorage& b = bonds_;
    keepFlagged(b.node_i, keep_bond);
    keepFlagged(b.node_j, keep_bond);
    keepFlagged(b.stage, keep_bond);
    counters_.bonds = b.size();

    // Contact histories: pairs and wall items of remaining cells, renumbered (the
    // keys stay sorted); the interface of a kept pair is renumbered too.
    std::vector<int> new_face(keep_face.size(), -1);
    for (int k = 0, next = 0; k < static_cast<int>(keep_face.size()); ++k)
        if (keep_face[k]) new_face[k] = next++;
    ContactPairArrays& p = pairs_;
    std::vector<char> keep_pair(p.size());
    for (int k = 0; k < p.size(); ++k) {
        keep_pair[k] = keep_cell[p.cell_a[k]] && keep_cell[p.cell_b[k]];
        if (!keep_pair[k]) continue;
        p.cell_a[k] = new_index[p.cell_a[k]];
        p.cell_b[k] = new_index[p.cell_b[k]];
        if (p.interface[k] >= 0) p.interface[k] = new_face[p.interface[k]];
    }
    keepFlagged(p.cell_a, keep_pair);
    keepFlagged(p.cell_b, keep_pair);
    keepFlagged(p.interface, keep_pair);
    keepFlagged(p.tangential_spring, keep_pair);
    keepFlagged(p.last_normal, keep_pair);
    keepFlagged(p.separation_margin, keep_pair);
    keepFlagged(p.seat, keep_pair);
    keepFlagged(p.force_on_b, keep_pair);
    keepFlagged(p.point_or_torque, keep_pair);
    keepFlagged(p.status, keep_pair);
    keepFlagged(p.stiffness, keep_pair);
    WallContactArrays& w = wall_items_;
    std::vector<char> keep_item(w.size());
    std::vector<int> triangle_offset(1, 0), triangles;
    for (int k = 0; k < w.size(); ++k) {
        keep_item[k] = keep_cell[w.cell[k]];
        if (!keep_item[k]) continue;
        w.cell[k] = new_index[w.cell[k]];
        triangles.insert(triangles.end(), w.triangles.begin() + w.triangle_offset[k],
                         w.triangles.begin() + w.triangle_offset[k + 1]);
        triangle_offset.push_back(static_cast<int>(triangles.size()));
    }
    w.triangle_offset = std::move(triangle_offset);
    w.triangles = std::move(triangles);
    keepFlagged(w.cell, keep_item);
    keepFlagged(w.wall, keep_item);
    keepFlagged(w.tangential_spring, keep_item);
    keepFlagged(w.last_normal, keep_item);
    keepFlagged(w.force_on_cell, keep_item);
    keepFlagged(w.torque_on_cell, keep_item);
    keepFlagged(w.elastic_energy, keep_item);
    keepFlagged(w.damping_power, keep_item);
    keepFlagged(w.friction_dissipation, keep_item);
    keepFlagged(w.wall_power, keep_item);
    keepFlagged(w.status, keep_item);
    keepFlagged(w.stiffness, keep_item);

    buildIncidence();
    energy_floor_ = 0.0;
    lists_valid_ = false;
    // Forces of the remaining cells without the removed ones; the energy that left
    // is what the kinetic and stored energies lost.
    computeForces(0.0);
    measureCells(last_dt_);
    energies_.exchanged += energy_before - (energies_.kinetic() + energies_.stored());
    updateStatus(-1);
    return new_index;
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

void DemModel::shrinkToFit()
{
    CellArrays& c = cells_;
    c.core_vertices.shrink_to_fit();
    c.core_vertex_offset.shrink_to_fit();
    c.core_edges.shrink_to_fit();
    c.core_edge_offset.shrink_to_fit();
    c.core_planes.shrink_to_fit();
    c.core_plane_offset.shrink_to_fit();
    InterfaceArrays& f = interfaces_;
    for (auto* v : {&f.cell_i, &f.cell_j, &f.bond_offset, &f.intact_bonds}) v->shrink_to_fit();
    for (auto* v : {&f.normal_i, &f.normal_j}) v->shrink_to_fit();
    for (auto* v : {&f.length_i, &f.length_j, &f.bond_area, &f.damping_beta}) v->shrink_to_fit();
    f.softening_slot.shrink_to_fit();
    c.anchor_node_offset.shrink_to_fit();
    c.anchor_nodes.shrink_to_fit();
    bonds_.node_i.shrink_to_fit();
    bonds_.node_j.shrink_to_fit();
    bonds_.stage.shrink_to_fit();
}

// ---- Bond strengths ---------------------------------------------------------

void DemModel::scaleInterfaceStrength(int interface, double factor)
{
    if (interface < 0 || interface >= interfaces_.size() || !(factor > 0) || !std::isfinite(factor))
        throw std::invalid_argument("DemModel::scaleInterfaceStrength: bad interface or factor");
    if (interfaces_.strength_scale.empty()) interfaces_.strength_scale.assign(interfaces_.size(), 1.0);
    interfaces_.strength_scale[interface] *= factor;
}

// ---- Walls ------------------------------------------------------------------

int DemModel::addPlate(const Vec3& point, const Vec3& normal_into_domain, const Vec3& velocity)
{
    if (!(norm(normal_into_domain) > 0.0)) throw UserError("a plate needs a non-zero normal");
    WallState w;
    w.kind = wallPlate;
    w.origin = w.initial_origin = point;
    w.normal = normalised(normal_into_domain);
    w.velocity = velocity;
    walls_.push_back(w);
    wall_extent_.push_back(0.0);
    triangle_grids_.emplace_back();
    lists_valid_ = forces_valid_ = false;
    return nWalls() - 1;
}

int DemModel::addTriSurface(const std::vector<Vec3>& vertices,
                            const std::vector<std::array<int, 3>>& triangles, const WallMotion& motion)
{
    if (triangles.empty()) throw UserError("a triangulated wall needs at least one triangle");
    WallState w;
    w.kind = wallTriSurface;
    w.first_triangle = static_cast<int>(triangle_vertices_.size() / 3);
    w.n_triangles = static_cast<int>(triangles.size());
    std::vector<Vec3> local;
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) {
            if (t[k] < 0 || t[k] >= static_cast<int>(vertices.size()))
                throw UserError("a triangle of a wall refers to a vertex that does not exist");
            local.push_back(vertices[t[k]]);
        }
    triangle_vertices_.insert(triangle_vertices_.end(), local.begin(), local.end());
    const std::vector<std::uint16_t> features = surfaceFeatureFlags(vertices, triangles);
    triangle_features_.insert(triangle_features_.end(), features.begin(), features.end());
    triangle_grids_.emplace_back(local);
    walls_.push_back(w);
    double extent = 0.0;
    for (const Vec3& v : local) extent = std::max(extent, norm(v));
    wall_extent_.push_back(extent);
    setWallMotion(nWalls() - 1, motion);
    walls_.back().initial_origin = motion.translation;
    lists_valid_ = false;
    return nWalls() - 1;
}

// The forces of the last step stay valid when the wall's motion is set to what it
// already is (a solver re-asserting its plate speeds every step): the wall contacts'
// dashpots and friction see the wall velocity, so any change makes them stale and the
// next step re-evaluates them first.
void DemModel::setWallVelocity(int wall, const Vec3& velocity, const Vec3& angular_velocity)
{
    WallState& w = walls_.at(wall);
    if (w.velocity == velocity && w.angular_velocity == angular_velocity) return;
    w.velocity = velocity;
    w.angular_velocity = angular_velocity;
    forces_valid_ = false;
}

void DemModel::setWallMotion(int wall, const WallMotion& motion)
{
    WallState& w = walls_.at(wall);
    const Quat orientation = normalised(motion.orientation);
    if (w.origin == motion.translation && w.orientation == orientation && w.velocity == motion.velocity &&
        w.angular_velocity == motion.angular_velocity)
        return;
    w.origin = motion.translation;
    w.orientation = orientation;
    w.velocity = motion.velocity;
    w.angular_velocity = motion.angular_velocity;
    forces_valid_ = false;
}

void DemModel::setWallState(int wall, const WallState& state)
{
    walls_.at(wall) = state;
    lists_valid_ = forces_valid_ = false;
}

WallPose DemModel::wallPose(const WallState& w) const
{
    WallPose pose;
    pose.kind = w.kind;
    pose.origin = w.origin;
    pose.rotation = rotationMatrix(w.orientation);
    pose.velocity = w.velocity;
    pose.angular_velocity = w.angular_velocity;
    pose.normal = w.normal;
    pose.first_triangle = w.first_triangle;
    pose.n_triangles = w.n_triangles;
    return pose;
}

void DemModel::moveWalls(double dt)
{
    for (WallState& w : walls_) {
        w.origin += dt * w.velocity;
        w.orientation = normalised(quatFromRotationVector(dt * w.angular_velocity) * w.orientation);
    }
}

// ---- Stable time step -----------------------------------------------------------

namespace {

// Linearised bond system: generalised displacement per cell (translation u, world;
// rotation theta, world), bond stiffness K_b = (A/n)/l (k_n n n^T + k_t (1 - n n^T))
// acting on the relative displacement of the anchor points.
struct BondSystem {
    const CellArrays& cells;
    const InterfaceArrays& faces;
    const BondStorage& bonds;
    const BondMaterial& material;
    std::vector<Mat3> rotation;

    // (fu, ftheta) = K x (the gradient of the bond energy); x^T K_k x per interface in energy.
    void apply(const std::vector<Vec3>& u, const std::vector<Vec3>& theta, std::vector<Vec3>& fu,
               std::vector<Vec3>& ftheta, std::vector<double>* energy) const
    {
        const int n = cells.size();
        fu.assign(n, Vec3{});
        ftheta.assign(n, Vec3{});
        if (energy) energy->assign(faces.size(), 0.0);
        for (int k = 0; k < faces.size(); ++k) {
            const int i = faces.cell_i[k], j = faces.cell_j[k];
            const Vec3 normal = normalised(rotation[i] * faces.normal_i[k] - rotation[j] * faces.normal_j[k]);
            const double scale = faces.bond_area[k] / (faces.length_i[k] + faces.length_j[k]);
            for (int b = faces.bond_offset[k]; b < faces.bond_offset[k + 1]; ++b) {
                if (bonds.stage[b] == bondBroken) continue;
                const Vec3 ri =
                    rotation[i] * cells.anchor_nodes[cells.anchor_node_offset[i] + bonds.node_i[b]];
                const Vec3 rj =
                    rotation[j] * cells.anchor_nodes[cells.anchor_node_offset[j] + bonds.node_j[b]];
                const Vec3 d = (u[j] + cross(theta[j], rj)) - (u[i] + cross(theta[i], ri));
                const double dn = dot(d, normal);
                const Vec3 f = scale * (material.normal_modulus * dn * normal +
                                        material.shear_modulus * (d - dn * normal));  // K_b d
                fu[j] += f;
                ftheta[j] += cross(rj, f);
                fu[i] -= f;
                ftheta[i] -= cross(ri, f);
                if (energy) (*energy)[k] += dot(d, f);
            }
        }
    }
};

}  // namespace

CriticalTimeStep DemModel::criticalTimeStep() const
{
    CriticalTimeStep result;
    const int n = cells_.size();
    BondSystem system{cells_, interfaces_, bonds_, bond_material_, {}};
    system.rotation.resize(n);
    for (int c = 0; c < n; ++c) system.rotation[c] = rotationMatrix(cells_.orientation[c]);
    // World inverse inertia R I^-1 R^T applied to a vector.
    auto inverseInertia = [&](int c, const Vec3& v) {
        const Vec3 body = transposeTimes(system.rotation[c], v);
        const Vec3 I = cells_.principal_inertia[c];
        return system.rotation[c] * Vec3{body.x / I.x, body.y / I.y, body.z / I.z};
    };
    auto inertiaTimes = [&](int c, const Vec3& v) {
        const Vec3 body = transposeTimes(system.rotation[c], v);
        const Vec3 I = cells_.principal_inertia[c];
        return system.rotation[c] * Vec3{body.x * I.x, body.y * I.y, body.z * I.z};
    };

    // Gershgorin bounds of the translation and rotation blocks, per cell (undamped).
    std::vector<double> row_u(n, 0.0), row_theta(n, 0.0);
    for (int k = 0; k < interfaces_.size(); ++k) {
        const int i = interfaces_.cell_i[k], j = interfaces_.cell_j[k];
        const double stiffness = bond_material_.normal_modulus * interfaces_.bond_area[k] /
                                 (interfaces_.length_i[k] + interfaces_.length_j[k]);
        const double mi = cells_.mass[i], mj = cells_.mass[j];
        const Vec3 Ii = cells_.principal_inertia[i], Ij = cells_.principal_inertia[j];
        const double ii = std::min({Ii.x, Ii.y, Ii.z}), ij = std::min({Ij.x, Ij.y, Ij.z});
        for (int b = interfaces_.bond_offset[k]; b < interfaces_.bond_offset[k + 1]; ++b) {
            if (bonds_.stage[b] == bondBroken) continue;
            const double ri = norm(cells_.anchor_nodes[cells_.anchor_node_offset[i] + bonds_.node_i[b]]);
            const double rj = norm(cells_.anchor_nodes[cells_.anchor_node_offset[j] + bonds_.node_j[b]]);
            row_u[i] += stiffness * (1.0 / mi + 1.0 / std::sqrt(mi * mj));
            row_u[j] += stiffness * (1.0 / mj + 1.0 / std::sqrt(mi * mj));
            row_theta[i] += stiffness * (ri * ri / ii + ri * rj / std::sqrt(ii * ij));
            row_theta[j] += stiffness * (rj * rj / ij + ri * rj / std::sqrt(ii * ij));
        }
    }
    const double largest_u = n > 0 ? *std::max_element(row_u.begin(), row_u.end()) : 0.0;
    const double largest_theta = n > 0 ? *std::max_element(row_theta.begin(), row_theta.end()) : 0.0;
    result.bond_translation_bound = largest_u > 0.0 ? 2.0 / std::sqrt(largest_u) : 1e300;
    result.bond_rotation_bound = largest_theta > 0.0 ? 2.0 / std::sqrt(largest_theta) : 1e300;

    // Power iteration on M^-1 K (M-normalised), deterministic start vector.
    std::vector<Vec3> u(n), theta(n), fu, ftheta;
    std::uint64_t state = 88172645463325252ULL;
    auto random = [&]() {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return double(state >> 11) / double(1ULL << 53) - 0.5;
    };
    for (int c = 0; c < n; ++c) {
        u[c] = {random(), random(), random()};
        theta[c] = Vec3{random(), random(), random()} * (1.0 / std::max(cells_.bounding_radius[c], 1e-300));
    }
    auto massNorm2 = [&]() {
        double sum = 0.0;
        for (int c = 0; c < n; ++c)
            sum += cells_.mass[c] * norm2(u[c]) + dot(theta[c], inertiaTimes(c, theta[c]));
        return sum;
    };
    double lambda = 0.0;
    std::vector<double> energy;
    const int iterations = 400;
    for (int it = 0; it < iterations && largest_u + largest_theta > 0.0; ++it) {
        const double scale = 1.0 / std::sqrt(massNorm2());
        for (int c = 0; c < n; ++c) {
            u[c] *= scale;
            theta[c] *= scale;
        }
        system.apply(u, theta, fu, ftheta, it + 1 == iterations ? &energy : nullptr);
        // Rayleigh quotient x^T K x / x^T M x (x is M-normalised).
        double quotient = 0.0;
        for (int c = 0; c < n; ++c) quotient += dot(u[c], fu[c]) + dot(theta[c], ftheta[c]);
        lambda = quotient;
        for (int c = 0; c < n; ++c) {
            u[c] = (1.0 / cells_.mass[c]) * fu[c];
            theta[c] = inverseInertia(c, ftheta[c]);
        }
    }
    if (lambda > 0.0) {
        result.bond_frequency = std::sqrt(lambda);
        // Damping ratio of that mode: C = sum_k beta_k K_k, zeta = omega/2 sum beta_k e_k / sum e_k.
        double weighted = 0.0, total = 0.0;
        for (int k = 0; k < interfaces_.size(); ++k) {
            weighted += interfaces_.damping_beta[k] * energy[k];
            total += energy[k];
        }
        const double beta = total > 0.0 ? weighted / total : 0.0;
        const double zeta = 0.5 * beta * result.bond_frequency;
        result.bond_damping_ratio = zeta;
        result.bond = 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta) / result.bond_frequency;
    } else {
        result.bond = 1e300;
    }

    // Contacts: a rock–steel Hertz contact at an overlap of 0.1 r_d on the lightest cell,
    // acting at its bounding radius (translation and rotation), with its restitution damping.
    double contact_omega2 = 0.0;
    for (int c = 0; c < n; ++c) {
        const double r = cells_.dilation_radius[c];
        const double stiffness = 2.0 * std::max(rock_steel_.effective_modulus, rock_rock_.effective_modulus) *
                                 std::sqrt(r * 0.1 * r);
        contact_omega2 = std::max(
            contact_omega2, contactFrequency2(stiffness, 0.0, cells_.mass[c], cells_.principal_inertia[c],
                                              cells_.bounding_radius[c]));
    }
    const double contact_zeta = contactDampingRatio();
    result.contact =
        contact_omega2 > 0.0
            ? 2.0 * (std::sqrt(1.0 + contact_zeta * contact_zeta) - contact_zeta) / std::sqrt(contact_omega2)
            : 1e300;
    result.value = std::min(result.bond, result.contact);
    return result;
}

// ---- Neighbour lists ---------------------------------------------------------

bool DemModel::neighbourListsStale() const
{
    if (!lists_valid_ || wall_origin_at_build_.size() != walls_.size()) return true;
    double cell_move2 = 0.0;
    for (int c = 0; c < cells_.size(); ++c)
        cell_move2 = std::max(cell_move2, norm2(cells_.position[c] - position_at_build_[c]));
    return neighbourListsStale(std::sqrt(cell_move2));
}

// Stale when a cell has moved half the skin since the build, or a cell and a wall
// together a whole skin (cell_move: the largest cell displacement since the build).
bool DemModel::neighbourListsStale(double cell_move) const
{
    if (!lists_valid_ || wall_origin_at_build_.size() != walls_.size()) return true;
    double wall_move = 0.0;
    for (int w = 0; w < nWalls(); ++w)
        wall_move = std::max(wall_move, norm(walls_[w].origin - wall_origin_at_build_[w]) +
                                            wall_extent_[w] * rotationAngle(walls_[w].orientation,
                                                                            wall_orientation_at_build_[w]));
    return cell_move > 0.5 * skin_ || cell_move + wall_move > skin_ || !(cell_move == cell_move);
}

void DemModel::rebuildNeighbourLists()
{
    const int n = cells_.size();
    const std::vector<std::pair<int, int>> near =
        findNearPairs(cells_.position, cells_.bounding_radius, skin_);
    ContactPairArrays next;
    for (auto* list : {&next.cell_a, &next.cell_b, &next.interface}) list->reserve(near.size());
    next.tangential_spring.reserve(near.size());
    next.last_normal.reserve(near.size());
    // Seats only for patch contacts (8 bytes per pair the point contact never reads).
    const bool seats = parameters_.cell_contact_patch;
    if (seats) next.seat.reserve(near.size());
    std::size_t old = 0;
    for (const auto& [a, b] : near) {
        // The interface of the pair, if it shares a bonded face. Pairs whose every bond
        // is intact are left out: when their first bond breaks the lists are rebuilt.
        const auto neighbour = [&](int k) {
            return interfaces_.cell_i[k] == a ? interfaces_.cell_j[k] : interfaces_.cell_i[k];
        };
        const auto begin = neighbour_interface_.begin() + cell_interface_offset_[a];
        const auto end = neighbour_interface_.begin() + cell_interface_offset_[a + 1];
        const auto found =
            std::lower_bound(begin, end, b, [&](int k, int cell) { return neighbour(k) < cell; });
        const int iface = found != end && neighbour(*found) == b ? *found : -1;
        if (iface >= 0 && interfaces_.intact_bonds[iface] ==
                              interfaces_.bond_offset[iface + 1] - interfaces_.bond_offset[iface])
            continue;
        next.cell_a.push_back(a);
        next.cell_b.push_back(b);
        next.interface.push_back(iface);
        // Carry the contact history by key (both lists sorted by (a, b)).
        while (old < pairs_.cell_a.size() &&
               std::make_pair(pairs_.cell_a[old], pairs_.cell_b[old]) < std::make_pair(a, b))
            ++old;
        const bool kept = old < pairs_.cell_a.size() && pairs_.cell_a[old] == a && pairs_.cell_b[old] == b;
        next.tangential_spring.push_back(kept ? pairs_.tangential_spring[old] : Vec3{});
        next.last_normal.push_back(kept ? pairs_.last_normal[old] : Vec3{});
        if (seats) next.seat.push_back(kept && old < pairs_.seat.size() ? pairs_.seat[old] : -1.0);
    }
    // Most near pairs are still bonded and left out: give back what was reserved for them
    // (about half the contact pairs' memory in an intact specimen).
    for (auto* list : {&next.cell_a, &next.cell_b, &next.interface}) list->shrink_to_fit();
    next.tangential_spring.shrink_to_fit();
    next.last_normal.shrink_to_fit();
    next.seat.shrink_to_fit();
    const std::size_t m = next.cell_a.size();
    next.separation_margin.assign(m, 0.0f);
    next.force_on_b.assign(m, Vec3{});
    next.point_or_torque.assign(m, Vec3{});
    next.status.assign(m, contactNone);
    next.stiffness.assign(m, 0.0f);
    pairs_ = std::move(next);
    buildCellIncidence(n, pairs_.cell_a, pairs_.cell_b, cell_pair_offset_, cell_pairs_);
    counters_.contact_pairs_listed = pairs_.size();
    buildWallItems();
    position_at_build_ = cells_.position;
    wall_origin_at_build_.clear();
    wall_orientation_at_build_.clear();
    for (const WallState& w : walls_) {
        wall_origin_at_build_.push_back(w.origin);
        wall_orientation_at_build_.push_back(w.orientation);
    }
    interfaces_cracked_at_build_ = counters_.interfaces_cracked;
    lists_valid_ = true;
    ++counters_.neighbour_rebuilds;
}

void DemModel::buildWallItems()
{
    const int n = cells_.size();
    WallContactArrays next;
    next.triangle_offset.assign(1, 0);
    cell_wall_item_offset_.assign(n + 1, 0);
    std::vector<int> found;
    std::size_t old = 0;
    for (int c = 0; c < n; ++c) {
        for (int w = 0; w < nWalls(); ++w) {
            const WallState& wall = walls_[w];
            const double reach = cells_.bounding_radius[c] + skin_;
            found.clear();
            if (wall.kind == wallPlate) {
                if (dot(cells_.position[c] - wall.origin, wall.normal) > reach) continue;
            } else {
                const Mat3 R = rotationMatrix(wall.orientation);
                triangle_grids_[w].query(transposeTimes(R, cells_.position[c] - wall.origin), reach, found);
                if (found.empty()) continue;
            }
            next.cell.push_back(c);
            next.wall.push_back(w);
            for (int t : found) next.triangles.push_back(wall.first_triangle + t);
            next.triangle_offset.push_back(static_cast<int>(next.triangles.size()));
            while (old < wall_items_.cell.size() &&
                   std::make_pair(wall_items_.cell[old], wall_items_.wall[old]) < std::make_pair(c, w))
                ++old;
            const bool kept =
                old < wall_items_.cell.size() && wall_items_.cell[old] == c && wall_items_.wall[old] == w;
            next.tangential_spring.push_back(kept ? wall_items_.tangential_spring[old] : Vec3{});
            next.last_normal.push_back(kept ? wall_items_.last_normal[old] : Vec3{});
        }
        cell_wall_item_offset_[c + 1] = static_cast<int>(next.cell.size());
    }
    const std::size_t m = next.cell.size();
    next.force_on_cell.assign(m, Vec3{});
    next.torque_on_cell.assign(m, Vec3{});
    next.elastic_energy.assign(m, 0.0);
    next.damping_power.assign(m, 0.0);
    next.friction_dissipation.assign(m, 0.0);
    next.wall_power.assign(m, 0.0);
    next.status.assign(m, contactNone);
    next.stiffness.assign(m, 0.0f);
    wall_items_ = std::move(next);
}

// ---- Forces -------------------------------------------------------------------

void DemModel::refreshKinematicCaches()
{
    const int n = cells_.size();
#pragma omp parallel for schedule(static) if (n >= parallelMinimumItems())
    for (int c = 0; c < n; ++c)
        refreshCellKinematics(cells_.orientation.data(), cells_.angular_velocity.data(), rotation_.data(),
                              angular_velocity_world_.data(), c);
    wall_poses_.clear();
    for (const WallState& w : walls_) wall_poses_.push_back(wallPose(w));
}

BondKernelArgs DemModel::bondArgs()
{
    BondKernelArgs a;
    a.material = bond_material_;
    a.n_interfaces = interfaces_.size();
    a.position = cells_.position.data();
    a.velocity = cells_.velocity.data();
    a.angular_velocity_world = angular_velocity_world_.data();
    a.rotation = rotation_.data();
    a.cell_i = interfaces_.cell_i.data();
    a.cell_j = interfaces_.cell_j.data();
    a.bond_offset = interfaces_.bond_offset.data();
    a.normal_i_body = interfaces_.normal_i.data();
    a.normal_j_body = interfaces_.normal_j.data();
    a.length_i = interfaces_.length_i.data();
    a.length_j = interfaces_.length_j.data();
    a.bond_area = interfaces_.bond_area.data();
    a.damping_beta = interfaces_.damping_beta.data();
    a.strength_scale = interfaces_.strength_scale.empty() ? nullptr : interfaces_.strength_scale.data();
    a.softening_slot = interfaces_.softening_slot.data();
    a.intact_bonds = interfaces_.intact_bonds.data();
    a.force_on_i = interfaces_.force_on_i.data();
    a.torque_on_i = interfaces_.torque_on_i.data();
    a.torque_on_j = interfaces_.torque_on_j.data();
    a.anchor_node_offset = cells_.anchor_node_offset.data();
    a.anchor_nodes = cells_.anchor_nodes.data();
    a.node_i = bonds_.node_i.data();
    a.node_j = bonds_.node_j.data();
    a.stage = bonds_.stage.data();
    a.softening = bonds_.softening.data();
    bond_block_sums_.resize((a.n_interfaces + a.block_size - 1) / a.block_size);
    a.block_sums = bond_block_sums_.data();
    return a;
}

CellContactView DemModel::cellView() const
{
    CellContactView v;
    v.position = cells_.position.data();
    v.velocity = cells_.velocity.data();
    v.angular_velocity_world = angular_velocity_world_.data();
    v.rotation = rotation_.data();
    v.mass = cells_.mass.data();
    v.dilation_radius = cells_.dilation_radius.data();
    v.bounding_radius = cells_.bounding_radius.data();
    v.core_vertex_offset = cells_.core_vertex_offset.data();
    v.core_vertices = cells_.core_vertices.data();
    v.core_edge_offset = cells_.core_edge_offset.data();
    v.core_edges = cells_.core_edges.data();
    v.core_plane_offset = cells_.core_plane_offset.data();
    v.core_planes = cells_.core_planes.data();
    return v;
}

void DemModel::runBondKernel(double dt)
{
    bond_runner_(bondArgs());
    // Interfaces whose first onset found no softening slot: claimed in interface order
    // (deterministic whatever the thread count), then evaluated again, now stored.
    int pending = 0;
    for (const BondBlockSums& s : bond_block_sums_) pending += s.pending_onsets;
    if (pending > 0) {
        std::vector<int> onsets;
        for (int k = 0; k < interfaces_.size(); ++k)
            if (interfaces_.intact_bonds[k] == bondOnsetPending) {
                claimSofteningSlot(k);
                onsets.push_back(k);
            }
        BondKernelArgs again = bondArgs();
        again.only_interfaces = onsets.data();
        again.n_only = static_cast<int>(onsets.size());
        bond_runner_(again);
    }
    double strain = 0.0;
    force_rates_.bond_damping = 0.0;
    for (const BondBlockSums& s : bond_block_sums_) {
        strain += s.strain_energy;
        force_rates_.bond_damping += s.damping_power;
        energies_.fracture += s.fracture_dissipation;
    }
    // These forces act over the second half kick of this step (the first half kick of the
    // next one is booked by step(), see bookFirstHalfKick).
    energies_.bond_damping += force_rates_.bond_damping * 0.5 * dt;
    energies_.bond_strain = strain;
    int broken = 0, open = 0, cracked = 0;
    for (int k = 0; k < interfaces_.size(); ++k) {
        const int broken_here =
            interfaces_.bond_offset[k + 1] - interfaces_.bond_offset[k] - interfaces_.intact_bonds[k];
        broken += broken_here;
        open += interfaces_.intact_bonds[k] == 0;
        cracked += broken_here > 0;
    }
    counters_.bonds_broken = broken;
    counters_.interfaces_open = open;
    counters_.interfaces_cracked = cracked;
}

namespace {

template <class Arrays>
ContactItemOutputs itemOutputs(Arrays& items)
{
    ContactItemOutputs o;
    o.tangential_spring = items.tangential_spring.data();
    o.last_normal = items.last_normal.data();
    o.elastic_energy = items.elastic_energy.data();
    o.damping_power = items.damping_power.data();
    o.friction_dissipation = items.friction_dissipation.data();
    o.status = items.status.data();
    o.stiffness = items.stiffness.data();
    return o;
}

// Sums over contact items in item order (deterministic); returns the active count.
template <class Arrays>
int sumContactEnergies(const Arrays& items, DemEnergies& energies, double& damping_power, int& intersections)
{
    int active = 0;
    for (int i = 0; i < items.size(); ++i) {
        if (items.status[i] == contactNone) continue;
        ++active;
        intersections += items.status[i] == contactCoresIntersect;
        energies.contact_elastic += items.elastic_energy[i];
        damping_power += items.damping_power[i];
        energies.friction += items.friction_dissipation[i];
    }
    return active;
}

}  // namespace

void DemModel::runContactKernels(double dt)
{
    PairKernelArgs pa;
    pa.constants = rock_rock_;
    pa.dt = dt;
    pa.n_pairs = pairs_.size();
    pa.cells = cellView();
    pa.intact_bonds = interfaces_.intact_bonds.data();
    pa.bond_offset = interfaces_.bond_offset.data();
    pa.cell_a = pairs_.cell_a.data();
    pa.cell_b = pairs_.cell_b.data();
    pa.interface = pairs_.interface.data();
    pa.separation_margin = pairs_.separation_margin.data();
    pa.seat = pairs_.seat.data();
    pa.items.tangential_spring = pairs_.tangential_spring.data();
    pa.items.last_normal = pairs_.last_normal.data();
    pa.items.status = pairs_.status.data();  // energies: block sums
    pa.items.stiffness = pairs_.stiffness.data();
    pa.force_on_b = pairs_.force_on_b.data();
    pa.point_or_torque = pairs_.point_or_torque.data();
    pa.patch = parameters_.cell_contact_patch;
    pair_block_sums_.assign((pa.n_pairs + pa.block_size - 1) / pa.block_size, ContactBlockSums{});
    pa.block_sums = pair_block_sums_.data();
    contact_runners_.pairs(pa);

    WallKernelArgs wa;
    wa.constants = rock_steel_;
    wa.dt = dt;
    wa.n_items = wall_items_.size();
    wa.cells = pa.cells;
    wa.walls = wall_poses_.data();
    wa.triangle_vertices = triangle_vertices_.data();
    wa.triangle_features = triangle_features_.data();
    wa.item_cell = wall_items_.cell.data();
    wa.item_wall = wall_items_.wall.data();
    wa.item_triangle_offset = wall_items_.triangle_offset.data();
    wa.item_triangles = wall_items_.triangles.data();
    wa.items = itemOutputs(wall_items_);
    wa.force_on_cell = wall_items_.force_on_cell.data();
    wa.torque_on_cell = wall_items_.torque_on_cell.data();
    wa.wall_power = wall_items_.wall_power.data();
    contact_runners_.walls(wa);

    energies_.contact_elastic = 0.0;
    counters_.core_intersections = 0;
    counters_.contacts_active = 0;
    force_rates_.contact_damping = 0.0;
    for (const ContactBlockSums& s : pair_block_sums_) {
        energies_.contact_elastic += s.elastic_energy;
        force_rates_.contact_damping += s.damping_power;
        energies_.friction += s.friction_dissipation;
        counters_.contacts_active += s.active;
        counters_.core_intersections += s.cores_intersect;
    }
    counters_.pair_core_intersections = counters_.core_intersections;
    counters_.wall_contacts_active = sumContactEnergies(wall_items_, energies_, force_rates_.contact_damping,
                                                        counters_.core_intersections);
    energies_.contact_damping += force_rates_.contact_damping * 0.5 * dt;  // second half kick
    for (WallState& w : walls_) {
        w.reaction = w.reaction_torque = Vec3{};
        w.power = 0.0;
    }
    for (int i = 0; i < wall_items_.size(); ++i) {
        WallState& w = walls_[wall_items_.wall[i]];
        const Vec3 force = wall_items_.force_on_cell[i];
        w.reaction -= force;
        // Torque on the wall about its origin: minus the cell's force system moved there.
        w.reaction_torque -=
            cross(cells_.position[wall_items_.cell[i]] - w.origin, force) + wall_items_.torque_on_cell[i];
        w.power += wall_items_.wall_power[i];
    }
    for (WallState& w : walls_) {  // second half kick
        w.work += w.power * 0.5 * dt;
        energies_.wall_work += w.power * 0.5 * dt;
    }
}

GatherArgs DemModel::gatherArgs()
{
    GatherArgs a;
    a.gravity = parameters_.gravity;
    a.mass = cells_.mass.data();
    a.interface_offset = cell_interface_offset_.data();
    a.interface_entries = cell_interfaces_.data();
    a.interface_force_on_i = interfaces_.force_on_i.data();
    a.interface_torque_on_i = interfaces_.torque_on_i.data();
    a.interface_torque_on_j = interfaces_.torque_on_j.data();
    a.pair_offset = cell_pair_offset_.data();
    a.pair_entries = cell_pairs_.data();
    a.pair_force_on_b = pairs_.force_on_b.data();
    a.pair_point_or_torque = pairs_.point_or_torque.data();
    a.pair_torques = parameters_.cell_contact_patch;
    a.pair_cell_b = pairs_.cell_b.data();
    a.position = cells_.position.data();
    a.wall_item_offset = cell_wall_item_offset_.data();
    a.wall_force_on_cell = wall_items_.force_on_cell.data();
    a.wall_torque_on_cell = wall_items_.torque_on_cell.data();
    a.force = cells_.force.data();
    a.torque = cells_.torque.data();
    a.pair_stiffness = pairs_.stiffness.data();
    a.wall_stiffness = wall_items_.stiffness.data();
    a.principal_inertia = cells_.principal_inertia.data();
    a.bounding_radius = cells_.bounding_radius.data();
    contact_frequency2_.resize(cells_.size());
    a.contact_frequency2 = contact_frequency2_.data();
    return a;
}

// Each cell sums the items it takes part in, in a fixed order (cellKernels.hpp).
void DemModel::gatherForces()
{
    const int n = cells_.size();
    const GatherArgs a = gatherArgs();
#pragma omp parallel for schedule(static) if (n >= parallelMinimumItems())
    for (int c = 0; c < n; ++c) gatherCellForces(a, c);
    float largest = 0.0f;  // a maximum: the same whatever the thread count
#pragma omp parallel for schedule(static) reduction(max : largest) if (n >= parallelMinimumItems())
    for (int c = 0; c < n; ++c) largest = std::max(largest, contact_frequency2_[c]);
    max_contact_frequency2_ = largest;
}

void DemModel::computeForces(double dt)
{
    refreshKinematicCaches();
    runBondKernel(dt);
    // Moved too far, or an interface lost its first bond (its pair must enter the list).
    if (neighbourListsStale() || counters_.interfaces_cracked != interfaces_cracked_at_build_)
        rebuildNeighbourLists();
    runContactKernels(dt);
    gatherForces();
    forces_valid_ = true;
}

void DemModel::evaluateForces(double dt)
{
    computeForces(dt);
    measureCells(0.0);
}

// ---- Integration ----------------------------------------------------------------

IntegrationArgs DemModel::integrationArgs()
{
    IntegrationArgs a;
    a.gravity = parameters_.gravity;
    a.mass = cells_.mass.data();
    a.principal_inertia = cells_.principal_inertia.data();
    a.force = cells_.force.data();
    a.torque = cells_.torque.data();
    a.rotation = rotation_.data();
    a.position = cells_.position.data();
    a.velocity = cells_.velocity.data();
    a.orientation = cells_.orientation.data();
    a.angular_velocity = cells_.angular_velocity.data();
    return a;
}

// First half kick, drift and rotation update (kickDriftCell), gravity's work summed per block.
void DemModel::kickDrift(double dt)
{
    const int n = cells_.size();
    const int n_blocks = (n + cell_block_size - 1) / cell_block_size;
    cell_block_sums_.assign(n_blocks, CellBlockSums{});
    const IntegrationArgs a = integrationArgs();
#pragma omp parallel for schedule(static) if (n_blocks > 1)
    for (int block = 0; block < n_blocks; ++block) {
        double gravity_work = 0.0;
        for (int c = block * cell_block_size; c < std::min(n, (block + 1) * cell_block_size); ++c)
            gravity_work += kickDriftCell(a, c, dt);
        cell_block_sums_[block].gravity_work = gravity_work;
    }
    for (const CellBlockSums& s : cell_block_sums_) energies_.gravity_work += s.gravity_work;
}

// Second half kick (kickCell).
void DemModel::kick(double dt)
{
    const int n = cells_.size();
    const IntegrationArgs a = integrationArgs();
#pragma omp parallel for schedule(static) if (n >= parallelMinimumItems())
    for (int c = 0; c < n; ++c) kickCell(a, c, dt);
}

// Kinetic energy and the finiteness check, summed per block in a fixed order.
void DemModel::measureCells(double sync_dt)
{
    const int n = cells_.size();
    const int n_blocks = (n + cell_block_size - 1) / cell_block_size;
    cell_block_sums_.assign(n_blocks, CellBlockSums{});
    const IntegrationArgs a = integrationArgs();
#pragma omp parallel for schedule(static) if (n_blocks > 1)
    for (int block = 0; block < n_blocks; ++block) {
        CellBlockSums s;
        for (int c = block * cell_block_size; c < std::min(n, (block + 1) * cell_block_size); ++c) {
            const CellEnergyTerms t = measureCell(a, c, sync_dt);
            s.kinetic_translation += t.kinetic_translation;
            s.kinetic_rotation += t.kinetic_rotation;
            if (!t.finite && s.non_finite_cell < 0) s.non_finite_cell = c;
        }
        cell_block_sums_[block] = s;
    }
    energies_.kinetic_translation = energies_.kinetic_rotation = 0.0;
    int non_finite = -1;
    for (const CellBlockSums& s : cell_block_sums_) {
        energies_.kinetic_translation += s.kinetic_translation;
        energies_.kinetic_rotation += s.kinetic_rotation;
        if (non_finite < 0) non_finite = s.non_finite_cell;
    }
    finishMeasurement(energies_.kinetic_translation, energies_.kinetic_rotation, non_finite);
}

// The kinetic energies are known: rebase the balance if asked, then check the state.
void DemModel::finishMeasurement(double kinetic_translation, double kinetic_rotation, int non_finite_cell)
{
    energies_.kinetic_translation = kinetic_translation;
    energies_.kinetic_rotation = kinetic_rotation;
    // A state set by the caller is an energy input: the balance is measured from here.
    if (rebase_energy_) {
        initial_balance_ = energies_.balance();
        energy_scale_ = 0.0;
        rebase_energy_ = false;
    }
    updateStatus(non_finite_cell);
}

void DemModel::updateStatus(int non_finite_cell)
{
    status_ = DemStatus{};
    status_.step = counters_.steps;
    status_.time = time_;
    status_.cell = non_finite_cell;
    const DemEnergies& e = energies_;
    energy_scale_ = std::max(energy_scale_, e.kinetic() + e.stored() + e.dissipated() +
                                                std::fabs(e.wall_work) + std::fabs(e.gravity_work));
    status_.energy_scale = energy_scale_;
    status_.energy_error = e.balance() - initial_balance_;
    // Below the fracture energy of one average bond the balance is round-off
    // (a plate that has just touched a vertex): the growth check starts above it.
    if (energy_floor_ == 0.0) {
        double area = 0.0;
        for (int k = 0; k < interfaces_.size(); ++k)
            area += interfaces_.bond_area[k] * (interfaces_.bond_offset[k + 1] - interfaces_.bond_offset[k]);
        const int n_bonds = std::max(1, bonds_.size());
        energy_floor_ = std::max(1e-300, parameters_.fracture_energy_mode_I * area / n_bonds);
    }
    if (non_finite_cell >= 0 || !std::isfinite(status_.energy_error))
        status_.code = DemStatusCode::nonFiniteState;
    else if (status_.energy_error >
                 parameters_.energy_growth_tolerance * std::max(energy_scale_, energy_floor_) &&
             status_.energy_error > 0.0)
        status_.code = DemStatusCode::energyGrowth;
}

// The power of the velocity-dependent forces (dashpots) and of the walls is booked half a
// step at a time, with the forces of the half kick it acts in: the first half kick of a
// step uses the forces of the last evaluation, which the previous step booked for its own
// second half only, or a re-evaluation after the caller changed a wall's motion (with the
// velocities after the kick and the new wall velocity: a crusher re-evaluates every step,
// and booking the step's own evaluation over the whole step left a quarter of the liners'
// dashpot losses out).
void DemModel::bookFirstHalfKick(double dt)
{
    energies_.bond_damping += force_rates_.bond_damping * 0.5 * dt;
    energies_.contact_damping += force_rates_.contact_damping * 0.5 * dt;
    for (WallState& w : walls_) {
        w.work += w.power * 0.5 * dt;
        energies_.wall_work += w.power * 0.5 * dt;
    }
}

std::string stepCheckSummary(const DemCounters& counters)
{
    std::ostringstream line;
    line << "Step check: " << counters.split_steps << " step(s) split into substeps";
    if (counters.split_steps > 0)
        line << " (" << counters.substeps << " substeps, at most " << counters.most_substeps
             << " in one step): contacts stiffened a cell beyond the step";
    return line.str();
}

void DemModel::setStepLimit(double fraction, double bond_frequency, double bond_damping_ratio)
{
    if (!(fraction >= 0.0) || !(bond_frequency >= 0.0) || !(bond_damping_ratio >= 0.0))
        throw std::invalid_argument("DemModel::setStepLimit: negative or NaN argument");
    step_limit_.fraction = fraction;
    step_limit_.bond_frequency2 = bond_frequency * bond_frequency;
    step_limit_.bond_damping_ratio = bond_damping_ratio;
    step_limit_.contact_damping_ratio = contactDampingRatio();
}

// Damping ratio of the stiffer-damped contact pairing, sqrt(5/6) |beta_e| (restitution).
double DemModel::contactDampingRatio() const
{
    return std::sqrt(5.0 / 6.0) *
           std::fabs(std::min(rock_steel_.restitution_beta, rock_rock_.restitution_beta));
}

double DemModel::currentCriticalStep() const
{
    // The larger of the bonds' frequency and the stiffest cell's contact bound: the bound
    // (a trace, gatherCellForces) exceeds the cell's highest contact mode (5.5x in omega^2
    // for a box cell's face pressed flat on a plate), which stands in for the bonds' share
    // that the sum would add; the sum split nearly every step of the Brazilian disc test,
    // whose runs are stable (docs/theory-dem.md §2).
    const double omega2 = std::max(step_limit_.bond_frequency2, max_contact_frequency2_);
    if (step_limit_.fraction <= 0.0 || !(omega2 > 0.0)) return 1e300;
    const double zeta = max_contact_frequency2_ > step_limit_.bond_frequency2
                            ? step_limit_.contact_damping_ratio
                            : step_limit_.bond_damping_ratio;
    return 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta) / std::sqrt(omega2);
}

int DemModel::substepsNeeded(double dt) const
{
    if (step_limit_.fraction <= 0.0) return 1;
    const double parts = std::ceil(dt / (step_limit_.fraction * currentCriticalStep()));
    return parts <= 1.0 ? 1 : static_cast<int>(std::min<double>(parts, max_substeps));
}

double DemModel::step(double dt)
{
    if (!forces_valid_) computeForces(0.0);
    return stepInParts(dt, [this](double part) { singleStep(part); });
}

// Velocity Verlet over dt (forces valid at the start).
void DemModel::singleStep(double dt)
{
    last_dt_ = dt;
    bookFirstHalfKick(dt);
    kickDrift(dt);
    moveWalls(dt);
    computeForces(dt);
    kick(dt);
    time_ += dt;
    ++counters_.steps;
    measureCells(dt);
}

// ---- State access -----------------------------------------------------------------

namespace {

void requireSize(std::size_t got, int expected, const char* what)
{
    if (static_cast<int>(got) != expected) {
        std::ostringstream message;
        message << "restart data does not match the model: " << what << " has " << got
                << " entries, expected " << expected;
        throw UserError(message.str());
    }
}

}  // namespace

void DemModel::setCellState(const std::vector<Vec3>& position, const std::vector<Vec3>& velocity,
                            const std::vector<Quat>& orientation, const std::vector<Vec3>& angular_velocity)
{
    const int n = cells_.size();
    requireSize(position.size(), n, "cell positions");
    requireSize(velocity.size(), n, "cell velocities");
    requireSize(orientation.size(), n, "cell orientations");
    requireSize(angular_velocity.size(), n, "cell angular velocities");
    cells_.position = position;
    cells_.velocity = velocity;
    cells_.orientation = orientation;
    cells_.angular_velocity = angular_velocity;
    lists_valid_ = forces_valid_ = false;
    rebase_energy_ = true;
}

void DemModel::setCellForces(const std::vector<Vec3>& force, const std::vector<Vec3>& torque)
{
    requireSize(force.size(), cells_.size(), "cell forces");
    requireSize(torque.size(), cells_.size(), "cell torques");
    cells_.force = force;
    cells_.torque = torque;
    forces_valid_ = true;
}

void DemModel::setBondHistory(const BondArrays& history)
{
    const int n = bonds_.size();
    requireSize(history.stage.size(), n, "bond stages");
    requireSize(history.onset_displacement.size(), n, "bond onset displacements");
    requireSize(history.onset_stress.size(), n, "bond onset stresses");
    requireSize(history.rupture_displacement.size(), n, "bond rupture displacements");
    requireSize(history.max_displacement.size(), n, "bond maximum displacements");
    requireSize(history.damage.size(), n, "bond damage");
    bonds_.stage = history.stage;
    std::vector<BondSoftening> per_bond(n);
    for (int b = 0; b < n; ++b) {
        per_bond[b].onset_displacement = history.onset_displacement[b];
        per_bond[b].onset_stress = history.onset_stress[b];
        per_bond[b].rupture_displacement = history.rupture_displacement[b];
        per_bond[b].max_displacement = history.max_displacement[b];
        per_bond[b].damage = history.damage[b];
    }
    setSofteningPerBond(per_bond);
    for (int k = 0; k < interfaces_.size(); ++k) {
        int intact = 0;
        for (int b = interfaces_.bond_offset[k]; b < interfaces_.bond_offset[k + 1]; ++b)
            intact += bonds_.stage[b] != bondBroken;
        interfaces_.intact_bonds[k] = intact;
    }
    forces_valid_ = false;
}

BondArrays DemModel::bonds() const
{
    BondArrays out;
    const int n = bonds_.size();
    out.anchor_i.resize(n);
    out.anchor_j.resize(n);
    for (int k = 0; k < interfaces_.size(); ++k) {
        const Vec3* nodes_i = cells_.anchor_nodes.data() + cells_.anchor_node_offset[interfaces_.cell_i[k]];
        const Vec3* nodes_j = cells_.anchor_nodes.data() + cells_.anchor_node_offset[interfaces_.cell_j[k]];
        for (int b = interfaces_.bond_offset[k]; b < interfaces_.bond_offset[k + 1]; ++b) {
            out.anchor_i[b] = nodes_i[bonds_.node_i[b]];
            out.anchor_j[b] = nodes_j[bonds_.node_j[b]];
        }
    }
    out.stage = bonds_.stage;
    const std::vector<BondSoftening> per_bond = softeningPerBond();
    out.onset_displacement.resize(n);
    out.onset_stress.resize(n);
    out.rupture_displacement.resize(n);
    out.max_displacement.resize(n);
    out.damage.resize(n);
    for (int b = 0; b < n; ++b) {
        out.onset_displacement[b] = per_bond[b].onset_displacement;
        out.onset_stress[b] = per_bond[b].onset_stress;
        out.rupture_displacement[b] = per_bond[b].rupture_displacement;
        out.max_displacement[b] = per_bond[b].max_displacement;
        out.damage[b] = per_bond[b].damage;
    }
    return out;
}

std::vector<BondSoftening> DemModel::softeningPerBond() const
{
    std::vector<BondSoftening> per_bond(bonds_.size());
    for (int k = 0; k < interfaces_.size(); ++k) {
        const int slot = interfaces_.softening_slot[k];
        if (slot < 0) continue;
        const int first = interfaces_.bond_offset[k];
        for (int b = first; b < interfaces_.bond_offset[k + 1]; ++b)
            per_bond[b] = bonds_.softening[slot + (b - first)];
    }
    return per_bond;
}

void DemModel::setSofteningPerBond(const std::vector<BondSoftening>& per_bond)
{
    requireSize(per_bond.size(), bonds_.size(), "bond softening histories");
    // Slots for the interfaces with a bond past its onset, in interface order.
    bonds_.softening.clear();
    for (int k = 0; k < interfaces_.size(); ++k) {
        const int first = interfaces_.bond_offset[k], last = interfaces_.bond_offset[k + 1];
        bool softened = false;
        for (int b = first; b < last; ++b) softened = softened || bonds_.stage[b] != bondElastic;
        interfaces_.softening_slot[k] = softened ? static_cast<int>(bonds_.softening.size()) : -1;
        if (softened)
            bonds_.softening.insert(bonds_.softening.end(), per_bond.begin() + first,
                                    per_bond.begin() + last);
    }
}

void DemModel::claimSofteningSlot(int k)
{
    if (interfaces_.softening_slot[k] >= 0) return;
    interfaces_.softening_slot[k] = static_cast<int>(bonds_.softening.size());
    bonds_.softening.resize(bonds_.softening.size() +
                            (interfaces_.bond_offset[k + 1] - interfaces_.bond_offset[k]));
}

void DemModel::setContactHistory(const ContactPairArrays& pairs, const WallContactArrays& wall_items)
{
    // Only keys and springs matter: the next rebuild carries them into fresh lists.
    pairs_ = pairs;
    if (!parameters_.cell_contact_patch) pairs_.seat.clear();  // point contacts keep no seats
    wall_items_ = wall_items;
    lists_valid_ = forces_valid_ = false;
}

void DemModel::setClock(double time, long steps, const DemEnergies& energies, double initial_balance)
{
    time_ = time;
    counters_.steps = steps;
    energies_ = energies;
    initial_balance_ = initial_balance;
    rebase_energy_ = false;
}

void DemModel::setCellPose(int cell, const Vec3& position, const Quat& orientation)
{
    cells_.position.at(cell) = position;
    cells_.orientation.at(cell) = normalised(orientation);
    lists_valid_ = forces_valid_ = false;  // a jump: GJK margins no longer hold
    rebase_energy_ = true;
}

void DemModel::setCellVelocity(int cell, const Vec3& velocity, const Vec3& angular_velocity_body)
{
    cells_.velocity.at(cell) = velocity;
    cells_.angular_velocity.at(cell) = angular_velocity_body;
    forces_valid_ = false;
    rebase_energy_ = true;
}

std::vector<double> DemModel::cellDamage() const
{
    std::vector<int> broken(cells_.size(), 0);
    for (int k = 0; k < interfaces_.size(); ++k) {
        const int n_broken =
            interfaces_.bond_offset[k + 1] - interfaces_.bond_offset[k] - interfaces_.intact_bonds[k];
        broken[interfaces_.cell_i[k]] += n_broken;
        broken[interfaces_.cell_j[k]] += n_broken;
    }
    std::vector<double> damage(cells_.size(), 0.0);
    for (int c = 0; c < cells_.size(); ++c)
        if (cells_.initial_bond_count[c] > 0) damage[c] = double(broken[c]) / cells_.initial_bond_count[c];
    return damage;
}

Vec3 DemModel::angularMomentum(int c) const
{
    const Vec3 w = cells_.angular_velocity[c], inertia = cells_.principal_inertia[c];
    return rotationMatrix(cells_.orientation[c]) * Vec3{inertia.x * w.x, inertia.y * w.y, inertia.z * w.z};
}

DemMemoryBytes DemModel::memoryUse() const
{
    DemMemoryBytes m;
    const CellArrays& c = cells_;
    m.cells = bytes(c.position) + bytes(c.velocity) + bytes(c.orientation) + bytes(c.angular_velocity) +
              bytes(c.force) + bytes(c.torque) + bytes(c.mass) + bytes(c.principal_inertia) +
              bytes(c.dilation_radius) + bytes(c.bounding_radius) + bytes(c.initial_bond_count) +
              bytes(rotation_) + bytes(angular_velocity_world_) + bytes(position_at_build_);
    m.cores = bytes(c.core_vertex_offset) + bytes(c.core_vertices) + bytes(c.core_edge_offset) +
              bytes(c.core_edges) + bytes(c.core_plane_offset) + bytes(c.core_planes);
    m.anchor_nodes = bytes(c.anchor_node_offset) + bytes(c.anchor_nodes);
    const InterfaceArrays& f = interfaces_;
    m.interfaces = bytes(f.cell_i) + bytes(f.cell_j) + bytes(f.bond_offset) + bytes(f.intact_bonds) +
                   bytes(f.normal_i) + bytes(f.normal_j) + bytes(f.length_i) + bytes(f.length_j) +
                   bytes(f.bond_area) + bytes(f.damping_beta) + bytes(f.strength_scale) +
                   bytes(f.force_on_i) + bytes(f.torque_on_i) + bytes(f.torque_on_j) +
                   bytes(f.softening_slot);
    const BondStorage& b = bonds_;
    m.bonds = bytes(b.node_i) + bytes(b.node_j) + bytes(b.stage);
    m.softening = bytes(b.softening);
    const ContactPairArrays& p = pairs_;
    m.pairs = bytes(p.cell_a) + bytes(p.cell_b) + bytes(p.interface) + bytes(p.tangential_spring) +
              bytes(p.last_normal) + bytes(p.separation_margin) + bytes(p.seat) + bytes(p.force_on_b) +
              bytes(p.point_or_torque) + bytes(p.status) + bytes(p.stiffness);
    const WallContactArrays& w = wall_items_;
    m.wall_items = bytes(w.cell) + bytes(w.wall) + bytes(w.triangle_offset) + bytes(w.triangles) +
                   bytes(w.tangential_spring) + bytes(w.last_normal) + bytes(w.force_on_cell) +
                   bytes(w.torque_on_cell) + bytes(w.elastic_energy) + bytes(w.damping_power) +
                   bytes(w.friction_dissipation) + bytes(w.wall_power) + bytes(w.status) +
                   bytes(w.stiffness) + bytes(contact_frequency2_) + bytes(triangle_vertices_) +
                   bytes(triangle_features_);
    m.lists = bytes(cell_interface_offset_) + bytes(cell_interfaces_) + bytes(cell_pair_offset_) +
              bytes(cell_pairs_) + bytes(cell_wall_item_offset_) + bytes(neighbour_interface_);
    return m;
}

}  // namespace rockfrac
