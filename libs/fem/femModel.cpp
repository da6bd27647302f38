// Explicit central-difference dynamics of linear tetrahedra (see femModel.hpp).
#include "fem/femModel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "fem/deterministicSum.hpp"
#include "fem/elementStiffnessScale.hpp"

namespace rockfrac::fem {

FemModel::FemModel(const TetMesh& mesh, const FemParameters& parameters)
    : mesh_(mesh),
      parameters_(parameters),
      geometry_(makeElementGeometry(mesh)),
      material_(parameters.material->make(parameters.rock))
{
    if (!(parameters.timeStepSafety > 0.0 && parameters.timeStepSafety <= 1.0))
        throw UserError("FEM: timeStepSafety must lie in (0, 1]");
    if (!(parameters.massDamping >= 0.0)) throw UserError("FEM: massDamping must be >= 0");
    if (!(parameters.contactPenaltyScale > 0.0)) throw UserError("FEM: contactPenaltyScale must be > 0");
    if (!(parameters.contactCrushingPressure >= 0.0))
        throw UserError("FEM: the contact crushing pressure must be >= 0 (0 = off)");
    material_->initialise(geometry_);
    const std::size_t n = mesh.numNodes();
    elementForces_.assign(12 * geometry_.numElements(), 0.0);
    for (auto* v : {&state_.displacements, &state_.velocities, &state_.netForces, &state_.internalForces,
                    &state_.externalForces})
        v->assign(3 * n, 0.0);
    state_.elementStresses.assign(6 * geometry_.numElements(), 0.0);
    constrained_.assign(n, 0);
    prescribedVelocity_.assign(3 * n, 0.0);
    buildNodeElementLists();
    elementEigenstiffness_ = largestElementEigenstiffness(geometry_, material_->elasticity());
    computeMasses();
    contactNodes_ = boundaryNodes(mesh);
    computeContactStiffness();
    collectBoundaryFaces();
}

// Boundary faces as (three contact-candidate indices, outward area vector / 3): what a
// plate's projected contact areas are summed from.
void FemModel::collectBoundaryFaces()
{
    std::vector<int> candidate(mesh_.numNodes(), -1);
    for (std::size_t j = 0; j < contactNodes_.size(); ++j) candidate[contactNodes_[j]] = static_cast<int>(j);
    for (const auto& f : boundaryFaces(mesh_)) {
        const Vec3 &a = mesh_.nodes[f[0]], &b = mesh_.nodes[f[1]], &c = mesh_.nodes[f[2]];
        Vec3 areaVector = 0.5 * cross(b - a, c - a);
        if (dot(areaVector, mesh_.nodes[f[3]] - a) > 0.0) areaVector = -1.0 * areaVector;  // outward
        boundaryFaces_.push_back(
            {{candidate[f[0]], candidate[f[1]], candidate[f[2]]}, (1.0 / 3.0) * areaVector});
    }
}

// A node's contact area against a plate: a third of each of its boundary faces' areas
// projected on the plate, for the faces that face it (outward normal against the plate
// normal), i.e. its share of the rock's footprint on the plate. The crushing pressure
// limit acts on it.
std::vector<double> FemModel::projectedContactAreas(const Vec3& plateNormal) const
{
    std::vector<double> area(contactNodes_.size(), 0.0);
    for (const BoundaryFace& f : boundaryFaces_) {
        const double facing = -dot(f.thirdAreaVector, plateNormal);
        if (facing > 0.0)
            for (int j : f.nodes) area[j] += facing;
    }
    return area;
}

// Node -> (element, local node) lists in increasing element order: the fixed
// summation order that makes the force gather independent of the thread count.
void FemModel::buildNodeElementLists()
{
    const std::size_t n = mesh_.numNodes();
    nodeElementStart_.assign(n + 1, 0);
    for (int id : geometry_.nodeIds) ++nodeElementStart_[id + 1];
    for (std::size_t i = 0; i < n; ++i) nodeElementStart_[i + 1] += nodeElementStart_[i];
    nodeElementSlot_.resize(geometry_.nodeIds.size());
    std::vector<int> next(nodeElementStart_.begin(), nodeElementStart_.end() - 1);
    for (std::size_t slot = 0; slot < geometry_.nodeIds.size(); ++slot)
        nodeElementSlot_[next[geometry_.nodeIds[slot]]++] = static_cast<int>(slot);
}

// Lumped mass: a quarter of each element's mass on each of its nodes. With mass
// scaling, an element whose stable step 2/omega_e is below the target gets the density
// that brings it to the target (omega_e^2 = 4 lambda_max(K_e) / (rho_e V_e)).
void FemModel::computeMasses()
{
    const double density = parameters_.rock.density;
    const double target = parameters_.massScalingTimeStep;
    const double reach = parameters_.timeStepSafety * contactStepFactor();
    elementDensity_.assign(geometry_.numElements(), density);
    if (target > 0.0)
        for (std::size_t e = 0; e < geometry_.numElements(); ++e) {
            const double required =
                elementEigenstiffness_[e] * target * target / (geometry_.volumes[e] * reach * reach);
            elementDensity_[e] = std::max(density, required);
        }
    nodalMass_.assign(mesh_.numNodes(), 0.0);
    physicalNodalMass_.assign(mesh_.numNodes(), 0.0);
    double physical = 0.0, scaled = 0.0;
    for (std::size_t e = 0; e < geometry_.numElements(); ++e) {
        const double volume = geometry_.volumes[e];
        for (int a = 0; a < 4; ++a) {
            nodalMass_[geometry_.nodeIds[4 * e + a]] += 0.25 * elementDensity_[e] * volume;
            physicalNodalMass_[geometry_.nodeIds[4 * e + a]] += 0.25 * density * volume;
        }
        physical += density * volume;
        scaled += elementDensity_[e] * volume;
    }
    addedMassFraction_ = (scaled - physical) / physical;
}

double FemModel::elementFrequencySquared(std::size_t e, double density) const
{
    return 4.0 * elementEigenstiffness_[e] / (density * geometry_.volumes[e]);
}

// The contact springs raise a node's highest frequency: with k <= (kappa/4) m omega_e^2
// (below) the bound becomes (1 + kappa/4) omega_max^2, hence the factor 2/sqrt(4 + kappa),
// kappa taken as the larger of the normal and tangential penalty scales.
double FemModel::contactStepFactor() const
{
    return 2.0 / std::sqrt(4.0 + parameters_.contactPenaltyScale *
                                     std::max(1.0, parameters_.tangentialPenaltyRatio));
}

// Penalty of a node against a plate, on the scale of its own elements' stiffness:
// k_i = (kappa / 4) m_i min_{e at i} omega_e^2 with the physical mass and frequencies
// (about kappa lambda_max(K_e) V_i / V_e), so k_i / m_i <= (kappa/4) omega_max^2 also
// after mass scaling, and the penalty does not grow with added mass.
void FemModel::computeContactStiffness()
{
    const double density = parameters_.rock.density;
    std::vector<double> lowestFrequencySquared(mesh_.numNodes(), std::numeric_limits<double>::infinity());
    for (std::size_t e = 0; e < geometry_.numElements(); ++e)
        for (int a = 0; a < 4; ++a) {
            double& lowest = lowestFrequencySquared[geometry_.nodeIds[4 * e + a]];
            lowest = std::min(lowest, elementFrequencySquared(e, density));
        }
    contactStiffness_.resize(contactNodes_.size());
    for (std::size_t j = 0; j < contactNodes_.size(); ++j) {
        const int node = contactNodes_[j];
        contactStiffness_[j] =
            0.25 * parameters_.contactPenaltyScale * physicalNodalMass_[node] * lowestFrequencySquared[node];
    }
}

int FemModel::addPlate(const RigidPlate& plate)
{
    RigidPlate p = plate;
    if (!(norm(p.normal) > 0.0)) throw UserError("plate '" + p.name + "': the normal must not be zero");
    if (!(p.friction >= 0.0)) throw UserError("plate '" + p.name + "': friction must be >= 0");
    p.normal = normalised(p.normal);
    p.tangentialForces.assign(3 * contactNodes_.size(), 0.0);
    p.crushedDepth.assign(contactNodes_.size(), 0.0);
    plateContactAreas_.push_back(projectedContactAreas(p.normal));
    state_.plates.push_back(std::move(p));
    forcesCurrent_ = false;
    return numPlates() - 1;
}

void FemModel::constrainNodes(const std::vector<int>& nodes, const std::array<bool, 3>& components,
                              const Vec3& velocity)
{
    for (int node : nodes) {
        if (node < 0 || static_cast<std::size_t>(node) >= mesh_.numNodes())
            throw UserError("constrainNodes: node " + std::to_string(node) + " does not exist");
        for (int k = 0; k < 3; ++k)
            if (components[k]) {
                constrained_[node] |= static_cast<unsigned char>(1u << k);
                prescribedVelocity_[3 * node + k] = velocity[k];
                state_.velocities[3 * node + k] = velocity[k];
            }
    }
    forcesCurrent_ = false;
}

void FemModel::setAppliedForces(const std::vector<double>& forces)
{
    if (!forces.empty() && forces.size() != state_.displacements.size())
        throw UserError("setAppliedForces: wrong size");
    appliedForces_ = forces;  // no re-evaluation: the forces at the current time stay as they are
}

void FemModel::setVelocities(const std::vector<double>& velocities)
{
    if (velocities.size() != state_.velocities.size()) throw UserError("setVelocities: wrong size");
    state_.velocities = velocities;
}

void FemModel::setDisplacements(const std::vector<double>& displacements)
{
    if (displacements.size() != state_.displacements.size()) throw UserError("setDisplacements: wrong size");
    state_.displacements = displacements;
    forcesCurrent_ = false;
}

double FemModel::stableTimeStep() const
{
    double highest = 0.0;
    for (std::size_t e = 0; e < geometry_.numElements(); ++e)
        highest = std::max(highest, elementFrequencySquared(e, elementDensity_[e]));
    const double contactFactor = state_.plates.empty() ? 1.0 : contactStepFactor();
    return parameters_.timeStepSafety * contactFactor * 2.0 / std::sqrt(highest);
}

void FemModel::gatherInternalForces()
{
    const long long n = static_cast<long long>(mesh_.numNodes());
    double* internal = state_.internalForces.data();
#pragma omp parallel for schedule(static)
    for (long long i = 0; i < n; ++i) {
        double f[3] = {0.0, 0.0, 0.0};
        for (int k = nodeElementStart_[i]; k < nodeElementStart_[i + 1]; ++k) {
            const double* slot = &elementForces_[3 * static_cast<std::size_t>(nodeElementSlot_[k])];
            f[0] += slot[0], f[1] += slot[1], f[2] += slot[2];
        }
        for (int c = 0; c < 3; ++c) internal[3 * i + c] = f[c];
    }
}

// Node-to-plane penalty contact with regularised Coulomb friction. The tangential
// force is an elastic stick spring (stiffness ratio * k) updated with the relative
// tangential motion of the step and capped at mu * normal force (slip). Serial over
// the contact candidates so the plate forces are summed in a fixed order.
// Contact crushing (when the pressure p_c > 0): a node's normal force is at most
// p_c A_node, A_node its projected contact area on this plate. A penetration beyond p_c A_node / k is crushed
// rock, not elastic overlap: it is added to the node's crushed depth c (which never shrinks), and the node's
// contact surface lies c behind the plate from then on, F_n = k (delta - c). Unloading is elastic; the work
// of the capped force over the crushed depth is dissipated in the crushed layer, outside the rock's own
// energy balance.
void FemModel::addContactForces(const std::vector<double>& displacementIncrement, double dt)
{
    for (std::size_t k = 0; k < state_.plates.size(); ++k) {
        RigidPlate& plate = state_.plates[k];
        const std::vector<double>& contactArea = plateContactAreas_[k];
        plate.force = {};
        const Vec3 planePoint = plate.point + plate.displacement;
        const Vec3 plateStep = dt * plate.velocity;
        for (std::size_t j = 0; j < contactNodes_.size(); ++j) {
            const int node = contactNodes_[j];
            double* tangential = &plate.tangentialForces[3 * j];
            const double stiffness = contactStiffness_[j];
            double& crushed = plate.crushedDepth[j];
            double overlap = -dot(nodePosition(node) - planePoint, plate.normal) - crushed;
            const double crushingForce = parameters_.contactCrushingPressure * contactArea[j];
            if (crushingForce > 0.0 && stiffness * overlap > crushingForce) {
                crushed += overlap - crushingForce / stiffness;
                overlap = crushingForce / stiffness;
            }
            if (overlap <= 0.0) {
                tangential[0] = tangential[1] = tangential[2] = 0.0;
                continue;
            }
            const double normalForce = stiffness * overlap;
            const Vec3 nodeStep{displacementIncrement[3 * node], displacementIncrement[3 * node + 1],
                                displacementIncrement[3 * node + 2]};
            Vec3 slip = nodeStep - plateStep;
            slip -= dot(slip, plate.normal) * plate.normal;
            Vec3 friction{tangential[0], tangential[1], tangential[2]};
            friction -= dot(friction, plate.normal) * plate.normal;  // plate may have rotated the frame
            friction -= parameters_.tangentialPenaltyRatio * stiffness * slip;
            const double limit = plate.friction * normalForce;
            if (norm(friction) > limit) friction *= limit / norm(friction);
            tangential[0] = friction.x, tangential[1] = friction.y, tangential[2] = friction.z;
            const Vec3 force = normalForce * plate.normal + friction;
            for (int c = 0; c < 3; ++c) state_.externalForces[3 * node + c] += force[c];
            plate.force -= force;
        }
    }
}

// Gravity on the physical mass; prescribed components carry whatever reaction keeps
// them on their prescribed velocity (external force = internal force there).
void FemModel::applyConstraintsAndGravity()
{
    const Vec3 g = parameters_.gravity;
    for (std::size_t i = 0; i < mesh_.numNodes(); ++i)
        for (int c = 0; c < 3; ++c) {
            double& external = state_.externalForces[3 * i + c];
            external += physicalNodalMass_[i] * g[c];
            if (!appliedForces_.empty()) external += appliedForces_[3 * i + c];
            if (constrained_[i] & (1u << c)) external = state_.internalForces[3 * i + c];
            state_.netForces[3 * i + c] = external - state_.internalForces[3 * i + c];
        }
}

long long FemModel::computeForces(const std::vector<double>& displacementIncrement, double dt)
{
    const long long bad = material_->computeElementForces(
        geometry_, state_.displacements.data(), state_.elementStresses.data(), elementForces_.data());
    gatherInternalForces();
    std::fill(state_.externalForces.begin(), state_.externalForces.end(), 0.0);
    addContactForces(displacementIncrement, dt);
    applyConstraintsAndGravity();
    forcesCurrent_ = true;
    return bad;
}

StepStatus FemModel::step(double dt)
{
    const long long n3 = static_cast<long long>(3 * mesh_.numNodes());
    if (!forcesCurrent_) computeForces(std::vector<double>(n3, 0.0), 0.0);
    // Velocity interval: half a step at the start (initial velocities are at time 0).
    const double h = state_.previousTimeStep > 0.0 ? 0.5 * (state_.previousTimeStep + dt) : 0.5 * dt;
    const double c = 0.5 * parameters_.massDamping * h;
    std::vector<double>& increment = stepIncrement_;
    increment.resize(n3);
    double* v = state_.velocities.data();
    double* u = state_.displacements.data();
    const double* force = state_.netForces.data();
    const double alpha = parameters_.massDamping;
    const double dampingWork = deterministicSum(n3, [&](long long k) {
        const long long node = k / 3;
        const double oldVelocity = v[k];
        if (constrained_[node] & (1u << (k % 3)))
            v[k] = prescribedVelocity_[k];
        else
            v[k] = ((1.0 - c) * v[k] + h * force[k] / nodalMass_[node]) / (1.0 + c);
        increment[k] = dt * v[k];
        u[k] += increment[k];
        const double meanVelocity = 0.5 * (oldVelocity + v[k]);
        return alpha * nodalMass_[node] * meanVelocity * meanVelocity * h;
    });
    for (auto& plate : state_.plates) plate.displacement += dt * plate.velocity;

    // The forces of the step's start move to the scratch buffers; computeForces rewrites
    // every entry of the state's (gather and fill), so the swap costs no copy.
    previousInternal_.resize(n3), previousExternal_.resize(n3);
    previousInternal_.swap(state_.internalForces);
    previousExternal_.swap(state_.externalForces);
    const std::vector<double>& oldInternal = previousInternal_;
    const std::vector<double>& oldExternal = previousExternal_;
    const long long bad = computeForces(increment, dt);

    // Trapezoidal work of internal and external forces over the step.
    state_.energy.internalWork += deterministicSum(
        n3, [&](long long k) { return 0.5 * (oldInternal[k] + state_.internalForces[k]) * increment[k]; });
    state_.energy.externalWork += deterministicSum(
        n3, [&](long long k) { return 0.5 * (oldExternal[k] + state_.externalForces[k]) * increment[k]; });
    state_.energy.dampingWork += dampingWork;
    state_.time += dt;
    state_.previousTimeStep = dt;
    ++state_.stepCount;

    StepStatus status;
    if (bad >= 0) {
        status.ok = false;
        status.element = bad;
        std::ostringstream s;
        s << "at time " << state_.time << " s (step " << state_.stepCount << "), "
          << mesh_.describeTet(static_cast<std::size_t>(bad))
          << " is inverted or its displacements are not finite; reduce the time step or check the loading";
        status.message = s.str();
    }
    return status;
}

Vec3 FemModel::nodePosition(int node) const
{
    const double* u = &state_.displacements[3 * static_cast<std::size_t>(node)];
    return mesh_.nodes[node] + Vec3{u[0], u[1], u[2]};
}

double FemModel::kineticEnergy() const
{
    const double half = 0.5 * state_.previousTimeStep;
    return deterministicSum(static_cast<long long>(3 * mesh_.numNodes()), [&](long long k) {
        const long long node = k / 3;
        double v = state_.velocities[k];
        if (!(constrained_[node] & (1u << (k % 3)))) v += half * state_.netForces[k] / nodalMass_[node];
        return 0.5 * nodalMass_[node] * v * v;
    });
}

double FemModel::strainEnergy() const
{
    const IsotropicElasticity elastic = material_->elasticity();
    return deterministicSum(static_cast<long long>(geometry_.numElements()), [&](long long e) {
        const SymTensor stress = SymTensor::fromArray(&state_.elementStresses[6 * e]);
        return 0.5 * geometry_.volumes[e] * doubleContraction(stress, elastic.strain(stress));
    });
}

ElementOutput FemModel::elementOutput() const
{
    const long long n = static_cast<long long>(geometry_.numElements());
    ElementOutput out;
    for (auto& d : out.damage) d.resize(n);
    out.equivalentPlasticStrain.resize(n);
    out.principalStresses.resize(3 * n);
#pragma omp parallel for schedule(static)
    for (long long e = 0; e < n; ++e) {
        for (int k = 0; k < 3; ++k) out.damage[k][e] = material_->damage(e, k);
        out.equivalentPlasticStrain[e] = material_->equivalentPlasticStrain(e);
        const EigenSystem principal = eigenSystem(SymTensor::fromArray(&state_.elementStresses[6 * e]));
        for (int k = 0; k < 3; ++k) out.principalStresses[3 * e + k] = principal.values[k];
    }
    return out;
}

void FemModel::checkStateSizes(const FemState& s) const
{
    const std::size_t n3 = 3 * mesh_.numNodes();
    for (const auto* v :
         {&s.displacements, &s.velocities, &s.netForces, &s.internalForces, &s.externalForces})
        if (v->size() != n3) throw UserError("FEM restart: nodal arrays do not match the mesh");
    if (s.elementStresses.size() != 6 * geometry_.numElements())
        throw UserError("FEM restart: element stresses do not match the mesh");
    if (s.plates.size() != state_.plates.size()) throw UserError("FEM restart: the number of plates differs");
    for (const auto& p : s.plates)
        if (p.tangentialForces.size() != 3 * contactNodes_.size() ||
            p.crushedDepth.size() != contactNodes_.size())
            throw UserError("FEM restart: plate '" + p.name + "' contact history does not match the mesh");
}

void FemModel::setState(const FemState& state)
{
    checkStateSizes(state);
    state_ = state;
    forcesCurrent_ = true;  // the stored forces belong to the stored displacements
}

}  // namespace rockfrac::fem
