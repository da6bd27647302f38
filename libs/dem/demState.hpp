#pragma once
// The whole state of a bonded DEM run as structure-of-arrays: what the kernels
// read and write, what a restart file must hold, and what VTK output shows.
//
// Frames: "body" is the cell's principal frame (origin at the centroid, axes the
// principal axes of inertia); x_world = position + R(orientation) x_body.
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "dem/bondLaw.hpp"
#include "dem/contactKernels.hpp"
#include "dem/quat.hpp"

namespace rockfrac {

struct CellArrays {
    // Dynamic state (restart).
    std::vector<Vec3> position;          // centroid [m]
    std::vector<Vec3> velocity;          // [m/s]
    std::vector<Quat> orientation;       // body -> world
    std::vector<Vec3> angular_velocity;  // body frame [rad/s]
    // Derived each step.
    std::vector<Vec3> force;   // total force incl. gravity, world [N]
    std::vector<Vec3> torque;  // about the centroid, world [N m]
    // Constant per cell.
    std::vector<double> mass;             // [kg]
    std::vector<Vec3> principal_inertia;  // [kg m^2]
    std::vector<double> dilation_radius;  // r_d [m]
    std::vector<double> bounding_radius;  // of the dilated core about the centroid [m]
    std::vector<int> core_vertex_offset;  // core of cell c: [offset[c], offset[c+1])
    std::vector<Vec3> core_vertices;      // eroded cell, body frame [m]
    // The core's edges as pairs of its vertex indices (2 bytes per edge: a core has
    // fewer than 256 vertices): cell c's are the entries [core_edge_offset[c],
    // core_edge_offset[c+1]) of core_edges, two per edge.
    std::vector<int> core_edge_offset;
    std::vector<std::uint8_t> core_edges;  // 2 per edge
    // The core's face planes, body frame (the cell's face normals, each at the core's
    // support): cell c's are [core_plane_offset[c], core_plane_offset[c+1]). They give the
    // depth of a point inside the core, where GJK has no distance (docs/theory-dem.md §6).
    std::vector<int> core_plane_offset;
    std::vector<CorePlane> core_planes;
    // The face nodes the cell's bonds are anchored at, each once (a node is shared by
    // the bonds of up to three faces of the cell), body frame [m]: cell c's are
    // [anchor_node_offset[c], anchor_node_offset[c+1]).
    std::vector<int> anchor_node_offset;
    std::vector<Vec3> anchor_nodes;
    std::vector<int> initial_bond_count;  // bonds the cell started with

    int size() const { return static_cast<int>(mass.size()); }
};

// Cell pairs that share a bonded face. Interface k owns bonds [bond_offset[k], bond_offset[k+1]).
struct InterfaceArrays {
    std::vector<int> cell_i, cell_j;  // cell_i < cell_j
    std::vector<int> bond_offset;
    std::vector<int> intact_bonds;           // bonds with D < 1; 0 switches the pair's contact on
    std::vector<Vec3> normal_i, normal_j;    // outward face normals, each in its cell's body frame
    std::vector<double> length_i, length_j;  // l_i, l_j [m]
    std::vector<double> bond_area;           // A/n [m^2]
    std::vector<double> damping_beta;        // beta of Eqs. 18–19 in seconds after the chosen reading [s]
    // Factor on sigma-bar and C of the interface's bonds (model effects: weakened contact
    // zones, random strengths). Empty = 1 everywhere, so a plain model carries no array.
    std::vector<double> strength_scale;
    // The softening pool entries of the interface's bonds are [slot, slot + bonds); -1
    // while every bond of the interface is elastic (claimed at the first onset).
    std::vector<int> softening_slot;
    std::vector<Vec3> force_on_i, torque_on_i, torque_on_j;  // sums over the interface's bonds

    int size() const { return static_cast<int>(cell_i.size()); }
};

// Bonds as the model stores them: each end names one of its cell's anchor nodes, the
// stage is per bond, and the softening history lives in a pool (InterfaceArrays::
// softening_slot) that only interfaces past an onset use: 5 bytes per intact bond
// instead of 89 (docs/benchmarks.md, memory per cell).
struct BondStorage {
    std::vector<std::uint16_t> node_i, node_j;  // into the anchor nodes of cell i and of cell j
    std::vector<unsigned char> stage;           // BondStage
    std::vector<BondSoftening> softening;       // the pool

    int size() const { return static_cast<int>(stage.size()); }
};

// Every bond with its anchors and full history, one entry per bond: what restart files,
// VTK output and tests exchange with the model (DemModel::bonds(), setBondHistory()).
struct BondArrays {
    std::vector<Vec3> anchor_i, anchor_j;  // anchor points in the body frames of cells i and j [m]
    // Damage history (Algorithm 1); stage: BondStage (elastic = "init" still true).
    std::vector<unsigned char> stage;
    std::vector<double> onset_displacement;    // d_e0 [m]
    std::vector<double> onset_stress;          // sigma_e0 [Pa]
    std::vector<double> rupture_displacement;  // d_f [m]
    std::vector<double> max_displacement;      // d_max [m]
    std::vector<double> damage;                // D

    int size() const { return static_cast<int>(stage.size()); }
};

// Cell–cell contact candidates of the current neighbour list, sorted by (cell_a, cell_b).
struct ContactPairArrays {
    std::vector<int> cell_a, cell_b, interface;
    std::vector<Vec3> tangential_spring, last_normal;  // history, carried across rebuilds by (a, b)
    // GJK skipping (reset at rebuilds): single precision, rounded down, so a stored margin
    // is never larger than the one computed (the skip stays safe and the forces unchanged).
    std::vector<float> separation_margin;
    // Overlap a face neighbour's contact started at; -1 apart (carried). Patch contacts
    // only: empty when cell contacts are the paper's single point.
    std::vector<double> seat;
    std::vector<Vec3> force_on_b;       // on cell b (a gets the opposite) [N]
    std::vector<Vec3> point_or_torque;  // contact point [m] (point) or torque on b [N m] (patch)
    std::vector<unsigned char> status;  // ContactStatus (energies: summed per block, not stored)
    std::vector<float> stiffness;       // normal contact stiffness of the last evaluation [N/m]

    int size() const { return static_cast<int>(cell_a.size()); }
};

// Cell–wall contact candidates, sorted by (cell, wall).
struct WallContactArrays {
    std::vector<int> cell, wall;
    std::vector<int> triangle_offset, triangles;       // candidate triangles (tri surfaces)
    std::vector<Vec3> tangential_spring, last_normal;  // history, carried by (cell, wall)
    std::vector<Vec3> force_on_cell, torque_on_cell;
    std::vector<double> elastic_energy, damping_power, friction_dissipation, wall_power;
    std::vector<unsigned char> status;
    std::vector<float> stiffness;  // normal contact stiffness of the last evaluation [N/m]

    int size() const { return static_cast<int>(cell.size()); }
};

// Energy bookkeeping [J]. Balance: kinetic + stored + dissipated + exchanged - external work = constant.
struct DemEnergies {
    double kinetic_translation = 0.0;
    double kinetic_rotation = 0.0;
    double bond_strain = 0.0;      // recoverable elastic energy of the bonds
    double contact_elastic = 0.0;  // Hertz normal + tangential springs
    double bond_damping = 0.0;     // cumulative dashpot dissipation of the bonds
    double contact_damping = 0.0;  // cumulative restitution damping of the contacts
    double friction = 0.0;         // cumulative Coulomb sliding
    double fracture = 0.0;         // cumulative damage dissipation (-> G_f A/n per broken bond)
    double wall_work = 0.0;        // cumulative work done on the cells by the walls
    double gravity_work = 0.0;     // cumulative work done on the cells by gravity
    // Cumulative energy carried out of the model by removed cells (their kinetic energy
    // and the strain of their bonds and contacts) minus that brought in by inserted cells.
    double exchanged = 0.0;

    double kinetic() const { return kinetic_translation + kinetic_rotation; }
    double stored() const { return bond_strain + contact_elastic; }
    double dissipated() const { return bond_damping + contact_damping + friction + fracture; }
    double externalWork() const { return wall_work + gravity_work; }
    // Should stay at its initial value (zero for a run started at rest and unloaded).
    double balance() const { return kinetic() + stored() + dissipated() + exchanged - externalWork(); }
};

// Powers of the velocity-dependent forces of the last evaluation [W], booked over the
// half kicks those forces act in (DemModel::step).
struct DemForceRates {
    double bond_damping = 0.0;
    double contact_damping = 0.0;
};

struct WallState {
    int kind = wallPlate;
    Vec3 origin;             // plate point / surface pivot, world [m]
    Quat orientation;        // surface frame -> world
    Vec3 velocity;           // of the origin [m/s]
    Vec3 angular_velocity;   // world, about the origin [rad/s]
    Vec3 normal;             // plates: unit normal into the domain
    Vec3 initial_origin;     // displacement = origin - initial_origin
    Vec3 reaction;           // force the cells exert on the wall, this step [N]
    Vec3 reaction_torque;    // torque of those forces about origin, this step [N m]
    double power = 0.0;      // power the wall delivers to the cells, this step [W]
    double work = 0.0;       // work it has done on the cells since the start [J]
    int first_triangle = 0;  // into DemModel's triangle vertex array (3 per triangle)
    int n_triangles = 0;
};

}  // namespace rockfrac
