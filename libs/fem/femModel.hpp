#pragma once
// Explicit dynamics of a tetrahedral rock with rigid plates: the FEM solver core.
//
// Central differences with lumped mass (docs/theory.md, FEM section):
//   v(n+1/2) = [(1 - a h/2) v(n-1/2) + h F(n)/m] / (1 + a h/2),  h = (dt(n-1) + dt(n))/2
//   u(n+1)   = u(n) + dt(n) v(n+1/2)
//   F(n+1)   = f_ext(u(n+1)) - f_int(u(n+1))
// with mass-proportional damping a. Element forces are computed per element into
// separate slots and each node sums its elements in a fixed order, so results are
// bitwise identical for any OpenMP thread count. All state is reachable for restarts.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "fem/elementGeometry.hpp"
#include "fem/femMaterial.hpp"
#include "fem/tetMesh.hpp"

namespace rockfrac::fem {

struct FemParameters {
    ElasticParameters rock;  // elasticity and density (rock { } of constant/rockProperties)
    // The material with its coefficients (`material <keyword>;` and its sub-dictionary);
    // kstDfh with the documented defaults unless set.
    std::shared_ptr<const FemMaterialModel> material = defaultFemMaterial();
    // Fraction of the critical step used by stableTimeStep().
    double timeStepSafety = 0.9;
    // Target step for mass scaling (s); 0 = off. Elements whose stable step is smaller
    // get a larger density so that stableTimeStep() >= this value.
    double massScalingTimeStep = 0.0;
    // Mass-proportional damping coefficient a (1/s): force -a m v. 0 = undamped.
    double massDamping = 0.0;
    Vec3 gravity{0.0, 0.0, 0.0};  // m/s^2, applied with the physical (unscaled) mass
    // Plate contact penalty kappa: k_node = (kappa/4) m_node min omega_e^2 over the node's
    // elements, i.e. about kappa times the largest eigen-stiffness of an adjacent element.
    double contactPenaltyScale = 1.0;
    // Tangential (stick) penalty as a fraction of the normal penalty.
    double tangentialPenaltyRatio = 1.0;
    // Contact crushing (Pa); 0 = off, the paper's model. The plate pressure on a contact
    // node may not exceed this value over the node's share of the boundary area: beyond
    // it the rock under the plate crushes, the node's crushed depth grows (irreversibly)
    // and the contact spreads to the neighbouring nodes instead of concentrating.
    double contactCrushingPressure = 0.0;
};

// A rigid plane. The rock lies on the side the normal points to; nodes behind the
// plane are pushed out along the normal by a penalty force, with Coulomb friction.
struct RigidPlate {
    std::string name;
    Vec3 point;                  // a point of the plane at zero displacement
    Vec3 normal{0.0, 0.0, 1.0};  // unit normal pointing into the rock
    Vec3 velocity;               // prescribed velocity (m/s); the caller may change it
    Vec3 displacement;           // accumulated displacement (m)
    double friction = 0.6;       // Coulomb coefficient (paper: mu = 0.6)
    Vec3 force;                  // force of the rock on the plate (N), at the current time
    // Stick-slip history: tangential force on each contact candidate node (3 per node).
    std::vector<double> tangentialForces;
    // Contact crushing history: depth of rock crushed away under this plate at each
    // contact candidate node (m, >= 0; zero unless crushing is or was on in this run).
    std::vector<double> crushedDepth;
};

// Energy bookkeeping (J). Balance: kinetic + internalWork + dampingWork = externalWork.
struct EnergyBalance {
    double internalWork = 0.0;  // work of the stresses: strain energy + plastic + fracture dissipation
    double externalWork = 0.0;  // work of plates, gravity and prescribed-velocity supports on the rock
    double dampingWork = 0.0;   // energy removed by the mass-proportional damping
};

// Everything needed to continue a run bit for bit (plus the material's stateFields()).
struct FemState {
    double time = 0.0;
    long long stepCount = 0;
    double previousTimeStep = 0.0;
    std::vector<double> displacements;    // 3 per node, at time
    std::vector<double> velocities;       // 3 per node, at time - previousTimeStep/2 (initial: at time)
    std::vector<double> netForces;        // 3 per node, f_ext - f_int at time
    std::vector<double> internalForces;   // 3 per node
    std::vector<double> externalForces;   // 3 per node (contact, gravity, support reactions)
    std::vector<double> elementStresses;  // 6 per element (xx yy zz xy yz zx)
    std::vector<RigidPlate> plates;
    EnergyBalance energy;
};

struct StepStatus {
    bool ok = true;
    long long element = -1;  // offending element when !ok
    std::string message;     // names the element
};

// Per-element output fields.
struct ElementOutput {
    std::vector<double> damage[3];  // D1, D2, D3: 0 intact, 1 failed
    std::vector<double> equivalentPlasticStrain;
    std::vector<double> principalStresses;  // 3 per element, descending
};

class FemModel {
public:
    FemModel(const TetMesh& mesh, const FemParameters& parameters);

    // ---- set-up -----------------------------------------------------------------
    // Adds a plate; returns its index. Its friction history is sized here.
    int addPlate(const RigidPlate& plate);
    // Prescribes velocity components (x, y, z selected by `components`) of nodes.
    void constrainNodes(const std::vector<int>& nodes, const std::array<bool, 3>& components,
                        const Vec3& velocity = {});
    // Applied nodal forces (3 per node, N), e.g. a distributed pressure lumped to the
    // nodes: part of f_ext (and W_ext) from the next force evaluation on. The caller
    // sets the load of time t + dt before step(dt) for a time-dependent load (the forces
    // of the current time are not re-evaluated); not part of the state.
    void setAppliedForces(const std::vector<double>& forces);
    void setVelocities(const std::vector<double>& velocities);
    void setDisplacements(const std::vector<double>& displacements);

    // ---- time stepping ----------------------------------------------------------
    // timeStepSafety * 2 / max_e omega_e: omega_e is the exact highest eigenfrequency of
    // element e with lumped mass (~ 2.9 c_p / h_e for a regular tet, c_p = sqrt((lambda+2mu)/rho)),
    // reduced by 2/sqrt(4 + kappa) when plates are present (contact springs).
    double stableTimeStep() const;
    // Added mass / physical mass from mass scaling (0 when off).
    double addedMassFraction() const { return addedMassFraction_; }
    // Each element's density after mass scaling (kg/m^3; the rock's where not scaled).
    const std::vector<double>& elementDensities() const { return elementDensity_; }
    StepStatus step(double dt);

    // ---- state --------------------------------------------------------------------
    const FemState& state() const { return state_; }
    // Restores a state written earlier (sizes are checked; UserError on mismatch).
    void setState(const FemState& state);
    FemMaterial& material() { return *material_; }
    const FemMaterial& material() const { return *material_; }
    RigidPlate& plate(int index) { return state_.plates.at(index); }
    const RigidPlate& plate(int index) const { return state_.plates.at(index); }
    int numPlates() const { return static_cast<int>(state_.plates.size()); }
    double time() const { return state_.time; }

    // ---- measurements -------------------------------------------------------------
    // Kinetic energy at the current time (velocities advanced by half a step).
    double kineticEnergy() const;
    const EnergyBalance& energy() const { return state_.energy; }
    // Recoverable elastic energy sum V sigma : C^-1 : sigma / 2 (isotropic compliance).
    double strainEnergy() const;
    ElementOutput elementOutput() const;
    Vec3 nodePosition(int node) const;
    const TetMesh& mesh() const { return mesh_; }
    const ElementGeometry& geometry() const { return geometry_; }
    const std::vector<double>& nodalMasses() const { return nodalMass_; }
    const std::vector<int>& contactNodes() const { return contactNodes_; }
    // Each contact node's contact area on plate `plate` (m^2): a third of each of its
    // boundary faces that face the plate, projected on the plate. Their sum over a flat
    // face lying on the plate is that face's area.
    const std::vector<double>& contactAreas(int plate) const { return plateContactAreas_.at(plate); }

private:
    void buildNodeElementLists();
    void computeMasses();
    void computeContactStiffness();
    void collectBoundaryFaces();
    std::vector<double> projectedContactAreas(const Vec3& plateNormal) const;
    double elementFrequencySquared(std::size_t element, double density) const;
    double contactStepFactor() const;
    // Forces at the current displacements; returns the first bad element or -1.
    long long computeForces(const std::vector<double>& displacementIncrement, double dt);
    void gatherInternalForces();
    void addContactForces(const std::vector<double>& displacementIncrement, double dt);
    void applyConstraintsAndGravity();
    void checkStateSizes(const FemState& state) const;

    TetMesh mesh_;
    FemParameters parameters_;
    ElementGeometry geometry_;
    std::unique_ptr<FemMaterial> material_;
    std::vector<double> elementForces_;          // 12 per element: internal force on each of its nodes
    std::vector<int> nodeElementStart_;          // CSR over nodes
    std::vector<int> nodeElementSlot_;           // 4 e + a: node a of element e
    std::vector<double> elementDensity_;         // after mass scaling
    std::vector<double> elementEigenstiffness_;  // lambda_max(K_e) per element
    std::vector<double> nodalMass_, physicalNodalMass_;
    double addedMassFraction_ = 0.0;
    std::vector<int> contactNodes_;         // boundary nodes (contact candidates)
    std::vector<double> contactStiffness_;  // normal penalty per contact node
    struct BoundaryFace {
        std::array<int, 3> nodes;  // contact-candidate indices
        Vec3 thirdAreaVector;      // outward normal times a third of the area
    };
    std::vector<BoundaryFace> boundaryFaces_;
    std::vector<std::vector<double>> plateContactAreas_;  // per plate, per contact node (crushing)
    std::vector<unsigned char> constrained_;              // bit k: component k prescribed
    std::vector<double> prescribedVelocity_;              // 3 per node
    std::vector<double> appliedForces_;                   // 3 per node, empty = none
    bool forcesCurrent_ = false;
    FemState state_;
    // Scratch of step(), kept between steps so a step allocates nothing: the displacement
    // increment and the forces of the previous step (swapped in, not copied).
    std::vector<double> stepIncrement_, previousInternal_, previousExternal_;
};

}  // namespace rockfrac::fem
