#pragma once
// The bonded Voronoi DEM (physics.md §3, docs/theory-dem.md): rigid dilated
// polyhedral cells glued at their shared faces by the bonds of Eqs. 5–20, Hertz–
// Mindlin contact once the bonds of a face are gone, rigid walls, and an explicit
// integrator (velocity Verlet for translation, forward Euler on SO(3) for rotation).
//
// Typical use (the bondedDemFoam application):
//     DemModel model(mesh, parameters);
//     int bottom = model.addPlate({0, 0, 0}, {0, 0, 1});
//     int top = model.addPlate({0, 0, h}, {0, 0, -1}, {0, 0, -0.25});
//     double dt = 0.02 * model.rayleighTimeStep();
//     while (...) { model.step(dt); if (!model.status().ok()) fail(model.status().message()); }
//
// Kernels (bond, contact pair, wall item, gather, integration) are RF_HD
// functions over raw arrays; per-item forces are summed per cell in a fixed order,
// so results are bitwise independent of the OpenMP thread count.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dem/bondLaw.hpp"
#include "dem/cellKernels.hpp"
#include "dem/contactKernels.hpp"
#include "dem/demParameters.hpp"
#include "dem/demState.hpp"
#include "dem/neighbourSearch.hpp"
#include "voronoi/voronoiMesh.hpp"

namespace rockfrac {

enum class DemStatusCode { ok, nonFiniteState, energyGrowth };

// What the last step found; the caller turns it into a message naming the step.
struct DemStatus {
    DemStatusCode code = DemStatusCode::ok;
    long step = 0;  // step index at which it was found
    double time = 0.0;
    double energy_error = 0.0;  // balance minus its initial value [J]
    double energy_scale = 0.0;  // the largest energy of the run so far [J]
    int cell = -1;              // a cell with a non-finite state

    bool ok() const { return code == DemStatusCode::ok; }
    std::string message() const;
};

struct DemCounters {
    long steps = 0;
    long neighbour_rebuilds = 0;
    int bonds = 0;
    int bonds_broken = 0;
    int interfaces_open = 0;       // cell pairs whose every bond is broken
    int interfaces_cracked = 0;    // cell pairs with at least one broken bond (their contact is on)
    int contact_pairs_listed = 0;  // current neighbour list
    int contacts_active = 0;       // cell–cell contacts with overlap
    int wall_contacts_active = 0;
    int core_intersections = 0;       // contacts this step whose cores are cut (pairs and walls)
    int pair_core_intersections = 0;  // of these, cell–cell pairs
    int shrunk_cores = 0;             // cells whose erosion failed (shrink fallback)
    int own_radius_cells = 0;         // cells too thin for r_d: their own radius (dilatedCellCore)
    // The step check (DemModel::setStepLimit): steps of the caller split into substeps
    // because contacts had stiffened a cell beyond the step, and the substeps they took.
    long split_steps = 0;
    long substeps = 0;
    int most_substeps = 0;  // of one step
};

// One line for a solver log: how many steps the step check split (DemModel::setStepLimit).
std::string stepCheckSummary(const DemCounters& counters);

// What the model's arrays hold, by part [bytes] (bench/, docs/benchmarks.md).
struct DemMemoryBytes {
    std::size_t cells = 0;         // state, constants and per-step caches per cell
    std::size_t cores = 0;         // eroded core vertices, edges and planes (contact geometry)
    std::size_t anchor_nodes = 0;  // bond anchor nodes per cell
    std::size_t interfaces = 0;    // per bonded cell pair, incl. its force/torque sums
    std::size_t bonds = 0;         // per bond: two node indices and the stage
    std::size_t softening = 0;     // the softening pool (bonds past their onset)
    std::size_t pairs = 0;         // contact candidates with their histories
    std::size_t wall_items = 0;    // cell–wall candidates, the walls, their triangles, features and grids
    std::size_t lists = 0;         // per-cell gather and neighbour lists, per-block partial sums

    std::size_t total() const
    {
        return cells + cores + anchor_nodes + interfaces + bonds + softening + pairs + wall_items + lists;
    }
};

// The explicit stability limit of the current model (docs/theory-dem.md §2).
struct CriticalTimeStep {
    double value = 0.0;                   // the smaller of bond and contact [s]
    double bond = 0.0;                    // 2 (sqrt(1 + zeta^2) - zeta) / omega of the bonds [s]
    double bond_frequency = 0.0;          // omega: highest frequency of the linearised bonds [rad/s]
    double bond_damping_ratio = 0.0;      // zeta of that mode (stiffness-proportional dashpots)
    double bond_translation_bound = 0.0;  // Gershgorin, translation blocks only [s] (undamped)
    double bond_rotation_bound = 0.0;     // Gershgorin, rotation blocks only [s] (undamped)
    double contact = 0.0;                 // Hertz estimate at an overlap of 0.1 r_d [s]
};

// Rigid motion of a triangulated wall: x_world = translation + R(orientation) x_wall,
// velocity field v(x) = velocity + angular_velocity x (x - translation).
struct WallMotion {
    Vec3 translation;
    Quat orientation;
    Vec3 velocity;
    Vec3 angular_velocity;
};

class CudaDemModel;  // libs/demCuda: steps this model's state on a GPU
class DemExchange;   // dem/demExchange.hpp: the other ranks of a decomposed run

class DemModel {
public:
    DemModel(const VoronoiMesh& mesh, const DemParameters& parameters);
    // A model without cells (a crusher filled by a feed): cells come by insertCells().
    explicit DemModel(const DemParameters& parameters);

    // ---- Cells entering and leaving (feed and discharge) ---------------------
    // Append the cells and bonds of `mesh`, placed rigidly: x = pose.translation +
    // R(pose.orientation) x_mesh, moving with v(x) = pose.velocity + pose.angular_velocity
    // x (x - pose.translation). New cells take indices [returned, cells().size()); the
    // indices of existing cells, interfaces, bonds and contact histories are unchanged.
    // The kinetic energy brought in is booked in energies().exchanged.
    int insertCells(const VoronoiMesh& mesh, const WallMotion& pose);
    // Remove the cells with remove[c] != 0 (size cells().size()) and everything that
    // names them: interfaces and their bonds, contact pairs and wall items; the rest is
    // compacted in order (old index -> new index returned, -1 for removed cells), so
    // the state equals that of a model built from the remaining cells. Forces are
    // re-evaluated; the energy leaving (kinetic + strain) is booked in energies().exchanged.
    std::vector<int> removeCells(const std::vector<char>& remove);
    // The same without the evaluation (forces, energies and lists as they were, the lists
    // stale): cutting a whole model down to one rank's share (decompose).
    std::vector<int> removeCellsOnly(const std::vector<char>& remove);

    // ---- Bond strengths ----------------------------------------------------
    // Multiply sigma-bar and C of every bond of interface k by factor (> 0); a model
    // effect (libs/effects) sets these before the first step. Without a call every
    // factor is 1 and the model carries no array for them.
    void scaleInterfaceStrength(int interface, double factor);

    // ---- Walls -------------------------------------------------------------
    // A rigid plane through point, normal pointing into the domain, moving with velocity.
    int addPlate(const Vec3& point, const Vec3& normal_into_domain, const Vec3& velocity = {});
    // Triangles (vertex indices) over vertices given in the wall's own frame.
    int addTriSurface(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 3>>& triangles,
                      const WallMotion& motion = {});
    void setWallVelocity(int wall, const Vec3& velocity, const Vec3& angular_velocity = {});
    // Pose and velocities at the current time (e.g. a gyrating mantle); the pose then
    // advances with the velocities during each step until set again.
    void setWallMotion(int wall, const WallMotion& motion);
    int nWalls() const { return static_cast<int>(walls_.size()); }
    const WallState& wall(int w) const { return walls_[w]; }
    WallPose wallPose(const WallState& wall) const;  // as the contact kernels see it
    Vec3 wallDisplacement(int w) const { return walls_[w].origin - walls_[w].initial_origin; }
    Vec3 wallReaction(int w) const { return walls_[w].reaction; }
    // Torque of the cells' forces on wall w about its origin, and the power the wall
    // delivers to the cells (sum of contact force . wall velocity at the contact), this step.
    Vec3 wallReactionTorque(int w) const { return walls_[w].reaction_torque; }
    double wallPower(int w) const { return walls_[w].power; }
    // Work wall w has done on the cells since the start [J] (booked half a step at a time
    // with the forces of each half kick, as energies().wall_work).
    double wallWork(int w) const { return walls_[w].work; }
    // Powers of the last force evaluation that the next step books over its first half
    // kick (restart files keep them, so that a continued run books what an uninterrupted
    // one does).
    const DemForceRates& forceRates() const { return force_rates_; }
    void setForceRates(const DemForceRates& rates) { force_rates_ = rates; }

    // ---- Time stepping -----------------------------------------------------
    // pi R sqrt(rho/G) / (0.1631 nu + 0.8766), R the smallest volume-equivalent radius.
    double rayleighTimeStep() const { return rayleigh_time_step_; }
    // The largest stable step of the intact bonds (highest mode of the linearised
    // bond system by power iteration, with its damping ratio) and of the contacts.
    CriticalTimeStep criticalTimeStep() const;
    // One explicit step; returns the new time. Check status() afterwards.
    // With a step limit set, a step longer than `fraction` of currentCriticalStep() is
    // taken as equal substeps short enough (counters().split_steps).
    double step(double dt);
    // The step check (docs/theory-dem.md §2): a run's step is chosen at the start from the
    // bonds and a one-point contact estimate; a cell pressed into many contact points can be
    // far stiffer. Each step compares dt with fraction x 2 (sqrt(1 + z^2) - z) / omega,
    // omega the larger of bond_frequency and the largest contact bound of any cell
    // (gatherCellForces), z the damping ratio of whichever is larger, and splits the step
    // into as many equal substeps as that needs (at most max_substeps). fraction 0 (the
    // default) switches the check off.
    void setStepLimit(double fraction, double bond_frequency, double bond_damping_ratio);
    static constexpr int max_substeps = 1000;
    // The critical step with the contacts of the last force evaluation [s] (1e300 without
    // a step limit set).
    double currentCriticalStep() const;
    // The stiffest cell's contact bound of the last evaluation [rad^2/s^2], which decides
    // the next step's split; a restart sets it back (with setCellForces, no re-evaluation).
    double contactFrequencyBound() const { return max_contact_frequency2_; }
    void setContactFrequencyBound(double omega2) { max_contact_frequency2_ = omega2; }
    // Forces at the current state without moving anything (histories advance as in a
    // step of length dt). For imposed-kinematics studies and after setting a state.
    void evaluateForces(double dt);
    const DemStatus& status() const { return status_; }
    double time() const { return time_; }

    // ---- State (read for output and restart; write back for restart) --------
    const CellArrays& cells() const { return cells_; }
    // Every bond with its anchors and history, assembled from the compact storage
    // (O(bonds): for output, restart and tests, not for a loop).
    BondArrays bonds() const;
    int nBonds() const { return bonds_.size(); }
    const BondStorage& bondStorage() const { return bonds_; }  // the compact form bonds() expands
    const InterfaceArrays& interfaces() const { return interfaces_; }
    const ContactPairArrays& contactPairs() const { return pairs_; }
    const WallContactArrays& wallContacts() const { return wall_items_; }
    // Of the whole model: in a decomposed run, the sums over every rank.
    const DemEnergies& energies() const { return exchange_ ? global_energies_ : energies_; }
    const DemCounters& counters() const { return exchange_ ? global_counters_ : counters_; }
    const DemParameters& parameters() const { return parameters_; }
    const std::vector<Vec3>& triangleVertices() const { return triangle_vertices_; }
    const std::vector<std::uint16_t>& triangleFeatures() const { return triangle_features_; }

    // Restart: the kinematic state, the bond histories, the contact histories (keys
    // and springs), the walls, time, step count and the energy accumulators. Sizes
    // must match this model (UserError otherwise); lists are rebuilt and histories
    // carried by their keys. Order: cell state, bond and contact histories, walls,
    // clock, and setCellForces last (the other setters mark the forces stale).
    void setCellState(const std::vector<Vec3>& position, const std::vector<Vec3>& velocity,
                      const std::vector<Quat>& orientation, const std::vector<Vec3>& angular_velocity);
    // The total force and torque of the last step: with them the next step continues
    // bitwise as if never interrupted (else forces are recomputed at the restart state,
    // with the dashpots seeing end-of-step instead of mid-step velocities).
    void setCellForces(const std::vector<Vec3>& force, const std::vector<Vec3>& torque);
    // The same from the restart arrays of `state` (demState.hpp): setCellState takes the
    // kinematic state, setCellForces the derived ones (force and torque) and does nothing
    // when they are all empty (a state file written before they were kept).
    void setCellState(const CellArrays& state);
    void setCellForces(const CellArrays& state);
    void setBondHistory(const BondArrays& history);  // anchors are kept; stages and histories replaced
    void setContactHistory(const ContactPairArrays& pairs, const WallContactArrays& wall_items);
    void setWallState(int wall, const WallState& state);
    void setClock(double time, long steps, const DemEnergies& energies, double initial_balance);
    double initialBalance() const { return initial_balance_; }

    // Imposed kinematics (tests, studies): move a cell; forces are stale until the
    // next evaluateForces() or step(), which also restart the energy balance there
    // (a state set from outside is an energy input the balance cannot see).
    void setCellPose(int cell, const Vec3& position, const Quat& orientation);
    void setCellVelocity(int cell, const Vec3& velocity, const Vec3& angular_velocity_body);

    // ---- Decomposed runs (dem/demExchange.hpp) ---------------------------------
    // This model now holds one rank's cells (owned[c] != 0) and their ghosts, and takes every
    // decision with the other ranks through `exchange` (kept, not owned). Items are counted
    // where their first cell is owned; energies() and counters() become the sums over the
    // ranks. `whole` is the whole model before it was cut down (removeCells): its energies,
    // counters and force rates at this moment; the cumulative parts stay with rank 0. The
    // lists are rebuilt at the next force evaluation, where the whole model would build them.
    void decompose(DemExchange* exchange, const std::vector<char>& owned, const DemEnergies& whole_energies,
                   const DemCounters& whole_counters, const DemForceRates& whole_rates);
    bool decomposed() const { return exchange_ != nullptr; }
    bool ownsCell(int c) const { return !exchange_ || owned_cell_[c]; }
    // The neighbour lists' skin: pairs within the two bounding radii plus this are listed [m].
    double skin() const { return skin_; }
    // The decomposition's weights: per cell 1 + the items it takes part in as last listed
    // (bond ends, contact pairs, wall triangles within reach; a plate counts 1).
    std::vector<double> cellCosts() const;
    // The counters as they are over all the ranks (a decomposed run's whole model, gathered).
    void setCounters(const DemCounters& counters) { counters_ = counters; }

    // ---- Derived outputs ---------------------------------------------------
    // Fraction of the cell's initial bonds that are broken (0 for a cell without bonds).
    std::vector<double> cellDamage() const;
    // Angular momentum of cell c about its centroid, world frame.
    Vec3 angularMomentum(int c) const;
    // Memory of the state arrays [bytes] (capacities), by part, and in all.
    DemMemoryBytes memoryUse() const;
    std::size_t memoryBytes() const { return memoryUse().total(); }

    // ---- Lists and flags a device backend reads --------------------------------
    // The per-cell gather lists (CSR per cell; entry = 2 * item + side, side 1 = the
    // item's second cell; wall items are sorted by cell, so a range per cell).
    struct GatherLists {
        const std::vector<int>& interface_offset;
        const std::vector<int>& interfaces;
        const std::vector<int>& pair_offset;
        const std::vector<int>& pairs;
        const std::vector<int>& wall_item_offset;
    };
    GatherLists gatherLists() const
    {
        return {cell_interface_offset_, cell_interfaces_, cell_pair_offset_, cell_pairs_,
                cell_wall_item_offset_};
    }
    bool listsValid() const { return lists_valid_; }
    bool forcesValid() const { return forces_valid_; }
    // One entry per bond (elastic bonds: zeros), from the softening pool.
    std::vector<BondSoftening> softeningPerBond() const;

    // ---- Device backends ---------------------------------------------------
    // The CUDA backend (libs/demCuda) steps this model's arrays on a device and leaves to
    // this model what stays on the host (walls, neighbour-list rebuilds, bookkeeping).
    // Beyond the public interface it may use DeviceSide only, which only it can get.
    class DeviceKey {
        friend class CudaDemModel;
        DeviceKey() {}  // user-provided: no aggregate initialisation around it
    };
    class DeviceSide;
    DeviceSide deviceSide(DeviceKey);

private:
    void setUpLaws();
    // Append the cells of mesh (placed by pose unless identity) and their bonds; the
    // body frames relative to the mesh frame are returned for the bonds' anchors.
    std::vector<Quat> appendCells(const VoronoiMesh& mesh, const WallMotion& pose, bool identity);
    void appendBonds(const VoronoiMesh& mesh, int first_cell, const std::vector<Quat>& mesh_orientation);
    void buildIncidence();
    void shrinkToFit();
    void refreshKinematicCaches();
    void refreshWallPoses();
    bool neighbourListsStale() const;
    bool neighbourListsStale(double cell_move) const;
    void rebuildNeighbourLists();
    void buildWallItems();
    void computeForces(double dt);
    void measureCells(double sync_dt);
    void finishMeasurement(double kinetic_translation, double kinetic_rotation, int non_finite_cell);
    void updateStatus(int non_finite_cell);
    // Decomposed: the energies and counters summed over the ranks; the first non-finite cell.
    int reduceOverRanks(int non_finite_cell);
    double ownedCost() const;  // cellCosts summed over this rank's cells
    void countPairs();
    void countInterfaces();
    void sumWallReactionsOverRanks();
    bool counted(const std::vector<unsigned char>& mask, int i) const { return mask.empty() || mask[i]; }
    void runBondKernel(double dt);
    void runContactKernels(double dt);
    void gatherForces();
    void kickDrift(double dt);
    void bookFirstHalfKick(double dt);
    void kick(double dt);
    void moveWalls(double dt);
    void singleStep(double dt);
    int substepsNeeded(double dt) const;
    double contactDampingRatio() const;
    // The split of step(): `single` advances by a given length (CPU or CUDA); the number of
    // parts is fixed at the start of the step from the forces of the last evaluation
    // (deterministic), and walls keep the velocities the caller gave them for the whole step.
    template <class SingleStep>
    double stepInParts(double dt, SingleStep&& single)
    {
        const int parts = substepsNeeded(dt);
        const double start = time_;
        for (int i = 0; i < parts; ++i) single(dt / parts);
        time_ = start + dt;  // as singleStep's own time_ += dt when there is one part
        if (parts > 1) {
            ++counters_.split_steps;
            counters_.substeps += parts;
            counters_.most_substeps = parts > counters_.most_substeps ? parts : counters_.most_substeps;
        }
        return time_;
    }
    BondKernelArgs bondArgs();
    // The softening history from one entry per bond (softeningPerBond): slots are claimed
    // for every interface with a bond past its onset.
    void setSofteningPerBond(const std::vector<BondSoftening>& per_bond);
    void claimSofteningSlot(int interface);
    GatherArgs gatherArgs();
    IntegrationArgs integrationArgs();
    CellContactView cellView() const;

    DemParameters parameters_;
    ContactConstants rock_rock_, rock_steel_;
    double rayleigh_time_step_ = 0.0;
    double smallest_radius_ = 1e300;  // smallest volume-equivalent radius of any cell so far
    double skin_ = 0.0;
    double last_dt_ = 0.0;
    struct StepLimit {
        double fraction = 0.0;  // 0: no check
        double bond_frequency2 = 0.0, bond_damping_ratio = 0.0, contact_damping_ratio = 0.0;
    } step_limit_;
    // Per cell, the contacts' squared frequency of the last evaluation (gatherCellForces);
    // the CUDA backend keeps its own on the device and puts its largest value here.
    std::vector<float> contact_frequency2_;
    double max_contact_frequency2_ = 0.0;

    CellArrays cells_;
    InterfaceArrays interfaces_;
    BondStorage bonds_;
    ContactPairArrays pairs_;
    WallContactArrays wall_items_;
    std::vector<WallState> walls_;
    std::vector<Vec3> triangle_vertices_;           // 3 per triangle, each wall's own frame
    std::vector<std::uint16_t> triangle_features_;  // ridges and convex corners (surfaceFeatures.hpp)
    std::vector<TrianglePrism> triangle_prisms_;    // distance bounds, each wall's own frame
    std::vector<TriangleGrid> triangle_grids_;      // per wall (empty for plates)

    // Per-step caches.
    std::vector<Mat3> rotation_;
    std::vector<Vec3> angular_velocity_world_;
    std::vector<WallPose> wall_poses_;
    // Gather lists (CSR per cell; entry = 2 * item + side, side 1 = the item's second cell).
    std::vector<int> cell_interface_offset_, cell_interfaces_;
    std::vector<int> cell_pair_offset_, cell_pairs_;
    std::vector<int> cell_wall_item_offset_;
    // Interfaces of each cell sorted by neighbour (the ranges of cell_interface_offset_),
    // for the pair -> interface lookup.
    std::vector<int> neighbour_interface_;
    // Neighbour-list validity.
    std::vector<Vec3> position_at_build_;
    std::vector<Vec3> wall_origin_at_build_;
    std::vector<double> wall_extent_;  // per wall: largest |vertex| in its frame (0 for plates)
    std::vector<Quat> wall_orientation_at_build_;
    int interfaces_cracked_at_build_ = 0;
    bool lists_valid_ = false;
    bool forces_valid_ = false;
    bool rebase_energy_ = false;  // the caller changed the state: restart the balance

    // Deterministic block sums.
    std::vector<BondBlockSums> bond_block_sums_;
    std::vector<ContactBlockSums> pair_block_sums_;
    struct CellBlockSums {
        double kinetic_translation = 0.0, kinetic_rotation = 0.0, gravity_work = 0.0;
        double max_displacement2 = 0.0;
        int non_finite_cell = -1;
    };
    std::vector<CellBlockSums> cell_block_sums_;

    double time_ = 0.0;
    DemEnergies energies_;
    DemForceRates force_rates_;
    double initial_balance_ = 0.0;
    double energy_scale_ = 0.0;
    double energy_floor_ = 0.0;  // fracture energy of one average bond: the check's noise floor
    DemCounters counters_;
    DemStatus status_;

    // Decomposed runs: the exchange, which cells are this rank's, which interfaces and pairs
    // it counts (empty when not decomposed), and the sums over the ranks.
    DemExchange* exchange_ = nullptr;
    std::vector<unsigned char> owned_cell_, counted_interface_, counted_pair_;
    DemEnergies global_energies_;
    DemCounters global_counters_;
};

// What a device backend may do to a DemModel besides its public interface: mirror the
// array groups (upload them, download into them) and run the host's share of a step it
// takes on the device (cudaDemModel.hpp says what runs where).
class DemModel::DeviceSide {
public:
    // The arrays the device mirrors, and the per-cell kinematic caches.
    CellArrays& cells() { return m_.cells_; }
    InterfaceArrays& interfaces() { return m_.interfaces_; }
    BondStorage& bonds() { return m_.bonds_; }
    ContactPairArrays& pairs() { return m_.pairs_; }
    WallContactArrays& wallItems() { return m_.wall_items_; }
    std::vector<Mat3>& rotation() { return m_.rotation_; }
    std::vector<Vec3>& angularVelocityWorld() { return m_.angular_velocity_world_; }
    const std::vector<Vec3>& positionAtBuild() const { return m_.position_at_build_; }
    void setSofteningPerBond(const std::vector<BondSoftening>& per_bond) { m_.setSofteningPerBond(per_bond); }

    // The laws' constants, as the CPU kernels get them.
    const ContactConstants& rockRock() const { return m_.rock_rock_; }
    const ContactConstants& rockSteel() const { return m_.rock_steel_; }

    // Where the device's sums are booked.
    DemEnergies& energies() { return m_.energies_; }
    DemForceRates& forceRates() { return m_.force_rates_; }
    DemCounters& counters() { return m_.counters_; }
    WallState& wall(int w) { return m_.walls_[w]; }

    // The host's share of a force evaluation and of a step.
    const std::vector<WallPose>& refreshWallPoses()
    {
        m_.refreshWallPoses();
        return m_.wall_poses_;
    }
    // After the bond forces, the lists are rebuilt when stale after cell_move (the largest
    // cell displacement since the build) or when an interface has cracked since
    // (DemModel::computeForces' test).
    bool listsStale(double cell_move) const { return m_.neighbourListsStale(cell_move); }
    bool crackedSinceListBuild() const
    {
        return m_.counters_.interfaces_cracked != m_.interfaces_cracked_at_build_;
    }
    void rebuildLists() { m_.rebuildNeighbourLists(); }
    void forcesComputed() { m_.forces_valid_ = true; }
    void finishMeasurement(double kinetic_translation, double kinetic_rotation, int non_finite_cell)
    {
        m_.finishMeasurement(kinetic_translation, kinetic_rotation, non_finite_cell);
    }
    template <class SingleStep>
    double stepInParts(double dt, SingleStep&& single)
    {
        return m_.stepInParts(dt, single);
    }
    void beginStep(double dt)  // DemModel::singleStep before the first half kick
    {
        m_.last_dt_ = dt;
        m_.bookFirstHalfKick(dt);
    }
    void moveWalls(double dt) { m_.moveWalls(dt); }
    void endStep(double dt)  // after the second half kick
    {
        m_.time_ += dt;
        ++m_.counters_.steps;
    }

private:
    friend class DemModel;
    explicit DeviceSide(DemModel& model) : m_(model) {}
    DemModel& m_;
};

inline DemModel::DeviceSide DemModel::deviceSide(DeviceKey)
{
    return DeviceSide(*this);
}

}  // namespace rockfrac
