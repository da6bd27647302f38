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
#include "dem/demFields.hpp"
#include "dem/quat.hpp"

namespace rockfrac {

// The host's arrays; a device backend instantiates the same groups over its own arrays
// (libs/demCuda: DeviceArray), so both walk one field list.
template <class T>
using HostArray = std::vector<T>;

// Each group below lists its arrays once in fields() (demFields.hpp: what the flags mean,
// and forEachField, which every operation over a group's arrays goes through). An array
// added to a group needs its line there; testDemFields checks that none is missing.

// New entries of a resized array are zero (resizeFields): an elastic bond, no contact.
static_assert(bondElastic == 0 && contactNone == 0, "resizeFields value-initialises");

template <template <class> class Array>
struct CellArraysOf {
    static constexpr const char* entity = "cell";
    // Dynamic state (restart).
    Array<Vec3> position;          // centroid [m]
    Array<Vec3> velocity;          // [m/s]
    Array<Quat> orientation;       // body -> world
    Array<Vec3> angular_velocity;  // body frame [rad/s]
    // Derived each step (the state file keeps them, so a continued run is bitwise).
    Array<Vec3> force;   // total force incl. gravity, world [N]
    Array<Vec3> torque;  // about the centroid, world [N m]
    // Constant per cell.
    Array<double> mass;             // [kg]
    Array<Vec3> principal_inertia;  // [kg m^2]
    Array<double> dilation_radius;  // r_d [m]
    Array<double> bounding_radius;  // of the dilated core about the centroid [m]
    Array<int> core_vertex_offset;  // core of cell c: [offset[c], offset[c+1])
    Array<Vec3> core_vertices;      // eroded cell, body frame [m]
    // The core's edges as pairs of its vertex indices (2 bytes per edge: a core has
    // fewer than 256 vertices): cell c's are the entries [core_edge_offset[c],
    // core_edge_offset[c+1]) of core_edges, two per edge.
    Array<int> core_edge_offset;
    Array<std::uint8_t> core_edges;  // 2 per edge
    // The core's face planes, body frame (the cell's face normals, each at the core's
    // support): cell c's are [core_plane_offset[c], core_plane_offset[c+1]). They give the
    // depth of a point inside the core, where GJK has no distance (docs/theory-dem.md §6).
    Array<int> core_plane_offset;
    Array<CorePlane> core_planes;
    // The face nodes the cell's bonds are anchored at, each once (a node is shared by
    // the bonds of up to three faces of the cell), body frame [m]: cell c's are
    // [anchor_node_offset[c], anchor_node_offset[c+1]).
    Array<int> anchor_node_offset;
    Array<Vec3> anchor_nodes;
    Array<int> initial_bond_count;  // bonds the cell started with

    int size() const { return static_cast<int>(mass.size()); }

    template <class Visit, class... Groups>
    static void fields(Visit&& visit, Groups&... g)
    {
        visit(ArrayField<stateField>{"position", "m"}, g.position...);
        visit(ArrayField<stateField>{"velocity", "m/s"}, g.velocity...);
        visit(ArrayField<stateField>{"orientation", "-"}, g.orientation...);
        visit(ArrayField<stateField>{"angularVelocity", "rad/s"}, g.angular_velocity...);
        visit(ArrayField<derivedField | restartField>{"force", "N"}, g.force...);
        visit(ArrayField<derivedField | restartField>{"torque", "N m"}, g.torque...);
        visit(ArrayField<constantField>{"mass", "kg"}, g.mass...);
        visit(ArrayField<constantField>{"principalInertia", "kg m^2"}, g.principal_inertia...);
        visit(ArrayField<constantField>{"dilationRadius", "m"}, g.dilation_radius...);
        visit(ArrayField<constantField>{"boundingRadius", "m"}, g.bounding_radius...);
        visit(ArrayField<constantField | rangedField>{"coreVertices", "m"},
              ranged(g.core_vertex_offset, g.core_vertices)...);
        visit(ArrayField<constantField | rangedField>{"coreEdges", "-"},
              ranged(g.core_edge_offset, g.core_edges)...);
        visit(ArrayField<constantField | rangedField>{"corePlanes", "-"},
              ranged(g.core_plane_offset, g.core_planes)...);
        visit(ArrayField<constantField | rangedField>{"anchorNodes", "m"},
              ranged(g.anchor_node_offset, g.anchor_nodes)...);
        visit(ArrayField<constantField | hostOnlyField>{"initialBondCount", "-"}, g.initial_bond_count...);
    }
};
using CellArrays = CellArraysOf<HostArray>;

// Cell pairs that share a bonded face. Interface k owns bonds [bond_offset[k], bond_offset[k+1]).
template <template <class> class Array>
struct InterfaceArraysOf {
    static constexpr const char* entity = "interface";
    Array<int> cell_i, cell_j;  // cell_i < cell_j
    Array<int> bond_offset;
    Array<int> intact_bonds;           // bonds with D < 1; 0 switches the pair's contact on
    Array<Vec3> normal_i, normal_j;    // outward face normals, each in its cell's body frame
    Array<double> length_i, length_j;  // l_i, l_j [m]
    Array<double> bond_area;           // A/n [m^2]
    Array<double> damping_beta;        // beta of Eqs. 18–19 in seconds after the chosen reading [s]
    // Factor on sigma-bar and C of the interface's bonds (model effects: weakened contact
    // zones, random strengths). Empty = 1 everywhere, so a plain model carries no array.
    Array<double> strength_scale;
    // The softening pool entries of the interface's bonds are [slot, slot + bonds); -1
    // while every bond of the interface is elastic (claimed at the first onset).
    Array<int> softening_slot;
    Array<Vec3> force_on_i, torque_on_i, torque_on_j;  // sums over the interface's bonds

    int size() const { return static_cast<int>(cell_i.size()); }

    template <class Visit, class... Groups>
    static void fields(Visit&& visit, Groups&... g)
    {
        visit(ArrayField<constantField>{"cellI", "-"}, g.cell_i...);
        visit(ArrayField<constantField>{"cellJ", "-"}, g.cell_j...);
        visit(ArrayField<fixedField | childrenField>{"bondOffset", "-"}, g.bond_offset...);
        visit(ArrayField<derivedField>{"intactBonds", "-"}, g.intact_bonds...);
        visit(ArrayField<constantField>{"normalI", "-"}, g.normal_i...);
        visit(ArrayField<constantField>{"normalJ", "-"}, g.normal_j...);
        visit(ArrayField<constantField>{"lengthI", "m"}, g.length_i...);
        visit(ArrayField<constantField>{"lengthJ", "m"}, g.length_j...);
        visit(ArrayField<constantField>{"bondArea", "m^2"}, g.bond_area...);
        visit(ArrayField<constantField>{"dampingBeta", "s"}, g.damping_beta...);
        visit(ArrayField<constantField | optionalField>{"strengthScale", "-", 1.0}, g.strength_scale...);
        visit(ArrayField<migrateField | poolField>{"softeningSlot", "-"}, g.softening_slot...);
        visit(ArrayField<derivedField>{"forceOnI", "N"}, g.force_on_i...);
        visit(ArrayField<derivedField>{"torqueOnI", "N m"}, g.torque_on_i...);
        visit(ArrayField<derivedField>{"torqueOnJ", "N m"}, g.torque_on_j...);
    }
};
using InterfaceArrays = InterfaceArraysOf<HostArray>;

// Bonds as the model stores them: each end names one of its cell's anchor nodes, the
// stage is per bond, and the softening history lives in a pool (InterfaceArrays::
// softening_slot) that only interfaces past an onset use: 5 bytes per intact bond
// instead of 89 (docs/benchmarks.md, memory per cell).
template <template <class> class Array>
struct BondStorageOf {
    static constexpr const char* entity = "bond";
    Array<std::uint16_t> node_i, node_j;  // into the anchor nodes of cell i and of cell j
    Array<unsigned char> stage;           // BondStage
    Array<BondSoftening> softening;       // the pool

    int size() const { return static_cast<int>(stage.size()); }

    template <class Visit, class... Groups>
    static void fields(Visit&& visit, Groups&... g)
    {
        visit(ArrayField<constantField>{"nodeI", "-"}, g.node_i...);
        visit(ArrayField<constantField>{"nodeJ", "-"}, g.node_j...);
        visit(ArrayField<migrateField>{"stage", "-"}, g.stage...);
        visit(ArrayField<migrateField | poolField>{"softening", "-"}, g.softening...);
    }
};
using BondStorage = BondStorageOf<HostArray>;

// Every bond with its anchors and full history, one entry per bond: what restart files,
// VTK output and tests exchange with the model (DemModel::bonds(), setBondHistory()).
struct BondArrays {
    static constexpr const char* entity = "bond";
    std::vector<Vec3> anchor_i, anchor_j;  // anchor points in the body frames of cells i and j [m]
    // Damage history (Algorithm 1); stage: BondStage (elastic = "init" still true).
    std::vector<unsigned char> stage;
    std::vector<double> onset_displacement;    // d_e0 [m]
    std::vector<double> onset_stress;          // sigma_e0 [Pa]
    std::vector<double> rupture_displacement;  // d_f [m]
    std::vector<double> max_displacement;      // d_max [m]
    std::vector<double> damage;                // D

    int size() const { return static_cast<int>(stage.size()); }

    template <class Visit, class... Groups>
    static void fields(Visit&& visit, Groups&... g)
    {
        visit(ArrayField<constantField>{"anchorI", "m"}, g.anchor_i...);
        visit(ArrayField<constantField>{"anchorJ", "m"}, g.anchor_j...);
        visit(ArrayField<stateField>{"stage", "-"}, g.stage...);
        visit(ArrayField<stateField>{"onsetDisplacement", "m"}, g.onset_displacement...);
        visit(ArrayField<stateField>{"onsetStress", "Pa"}, g.onset_stress...);
        visit(ArrayField<stateField>{"ruptureDisplacement", "m"}, g.rupture_displacement...);
        visit(ArrayField<stateField>{"maxDisplacement", "m"}, g.max_displacement...);
        visit(ArrayField<stateField>{"damage", "-"}, g.damage...);
    }
};

// Cell–cell contact candidates of the current neighbour list, sorted by (cell_a, cell_b).
template <template <class> class Array>
struct ContactPairArraysOf {
    static constexpr const char* entity = "pair";
    Array<int> cell_a, cell_b, interface;
    Array<Vec3> tangential_spring, last_normal;  // history, carried across rebuilds by (a, b)
    // GJK skipping (reset at rebuilds): single precision, rounded down, so a stored margin
    // is never larger than the one computed (the skip stays safe and the forces unchanged).
    Array<float> separation_margin;
    // Overlap a face neighbour's contact started at; -1 apart (carried). Patch contacts
    // only: empty when cell contacts are the paper's single point.
    Array<double> seat;
    Array<Vec3> force_on_b;       // on cell b (a gets the opposite) [N]
    Array<Vec3> point_or_torque;  // contact point [m] (point) or torque on b [N m] (patch)
    Array<unsigned char> status;  // ContactStatus (energies: summed per block, not stored)
    Array<float> stiffness;       // normal contact stiffness of the last evaluation [N/m]

    int size() const { return static_cast<int>(cell_a.size()); }

    template <class Visit, class... Groups>
    static void fields(Visit&& visit, Groups&... g)
    {
        visit(ArrayField<stateField | fixedField>{"cellA", "-"}, g.cell_a...);
        visit(ArrayField<stateField | fixedField>{"cellB", "-"}, g.cell_b...);
        visit(ArrayField<stateField | fixedField>{"interface", "-"}, g.interface...);
        visit(ArrayField<stateField | carriedField>{"tangentialSpring", "m"}, g.tangential_spring...);
        visit(ArrayField<stateField | carriedField>{"lastNormal", "-"}, g.last_normal...);
        visit(ArrayField<derivedField>{"separationMargin", "m"}, g.separation_margin...);
        visit(ArrayField<stateField | carriedField | optionalField>{"seat", "m", -1.0}, g.seat...);
        visit(ArrayField<derivedField>{"forceOnB", "N"}, g.force_on_b...);
        visit(ArrayField<derivedField>{"pointOrTorque", "m or N m"}, g.point_or_torque...);
        visit(ArrayField<stateField>{"status", "-"}, g.status...);
        visit(ArrayField<derivedField>{"stiffness", "N/m"}, g.stiffness...);
    }
};
using ContactPairArrays = ContactPairArraysOf<HostArray>;

// Cell–wall contact candidates, sorted by (cell, wall).
template <template <class> class Array>
struct WallContactArraysOf {
    static constexpr const char* entity = "wallItem";
    Array<int> cell, wall;
    Array<int> triangle_offset, triangles;  // candidate triangles (tri surfaces)
    // Where the cell's centre was at the list build in the wall's frame, and its exact distance
    // from the candidate triangles then (tri surfaces; 0 for a plate, or until the next build).
    Array<Vec3> centre_at_build;
    Array<double> clearance_at_build;
    Array<Vec3> tangential_spring, last_normal;  // history, carried by (cell, wall)
    Array<Vec3> force_on_cell, torque_on_cell;
    Array<double> elastic_energy, damping_power, friction_dissipation, wall_power;
    Array<unsigned char> status;
    Array<float> stiffness;  // normal contact stiffness of the last evaluation [N/m]

    int size() const { return static_cast<int>(cell.size()); }

    template <class Visit, class... Groups>
    static void fields(Visit&& visit, Groups&... g)
    {
        visit(ArrayField<stateField | fixedField>{"cell", "-"}, g.cell...);
        visit(ArrayField<stateField | fixedField>{"wall", "-"}, g.wall...);
        visit(ArrayField<fixedField | rangedField>{"triangles", "-"},
              ranged(g.triangle_offset, g.triangles)...);
        visit(ArrayField<fixedField>{"centreAtBuild", "m"}, g.centre_at_build...);
        visit(ArrayField<fixedField>{"clearanceAtBuild", "m"}, g.clearance_at_build...);
        visit(ArrayField<stateField | carriedField>{"tangentialSpring", "m"}, g.tangential_spring...);
        visit(ArrayField<stateField | carriedField>{"lastNormal", "-"}, g.last_normal...);
        visit(ArrayField<derivedField>{"forceOnCell", "N"}, g.force_on_cell...);
        visit(ArrayField<derivedField>{"torqueOnCell", "N m"}, g.torque_on_cell...);
        visit(ArrayField<derivedField>{"elasticEnergy", "J"}, g.elastic_energy...);
        visit(ArrayField<derivedField>{"dampingPower", "W"}, g.damping_power...);
        visit(ArrayField<derivedField>{"frictionDissipation", "J"}, g.friction_dissipation...);
        visit(ArrayField<derivedField>{"wallPower", "W"}, g.wall_power...);
        visit(ArrayField<stateField>{"status", "-"}, g.status...);
        visit(ArrayField<derivedField>{"stiffness", "N/m"}, g.stiffness...);
    }
};
using WallContactArrays = WallContactArraysOf<HostArray>;

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
