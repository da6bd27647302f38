// Hertz contact: an elastic sphere pressed on a rigid plate (damage off).
//
// One octant of a sphere of radius R with symmetry planes x = 0, y = 0 and the
// equatorial plane z = 0 held in z: by symmetry this is a sphere squeezed between
// two plates, each contact seeing F = 4/3 E* sqrt(R) delta^1.5 (E* = E / (1 - nu^2))
// with delta the approach of the contact point towards the centre. The mesh is
// refined around the pole with a gmsh distance/threshold size field.
//
// The approach is measured at the pole node relative to the fixed centre plane. Hertz's
// delta is the approach of distant points of a half-space; the centre, at depth R,
// already moves by the Boussinesq far field u = F (1 + nu)(3 - 2 nu) / (2 pi E R)
// (about 1.2 % of delta at delta/R = 3e-4), which is added to the measured approach.
#pragma once
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>

#include "fem/femModel.hpp"
#include "fem/linearElasticMaterial.hpp"
#include "femTestSupport.hpp"

namespace rockfrac::fem::test {

inline TetMesh sphereOctantMesh(const GmshSession& session, double radius, double finestSize,
                                double refinedRadius, double coarsestSize)
{
    gmsh::model::occ::addSphere(0, 0, 0, radius, -1, -M_PI / 2, 0, M_PI / 2);
    gmsh::model::occ::synchronize();
    gmsh::vectorpair poles;
    const double tol = 1e-6 * radius;
    gmsh::model::getEntitiesInBoundingBox(-tol, -tol, -radius - tol, tol, tol, -radius + tol, poles, 0);
    REQUIRE(poles.size() == 1);
    const int distance = gmsh::model::mesh::field::add("Distance");
    gmsh::model::mesh::field::setNumbers(distance, "NodesList", {static_cast<double>(poles[0].second)});
    const int threshold = gmsh::model::mesh::field::add("Threshold");
    gmsh::model::mesh::field::setNumber(threshold, "IField", distance);
    gmsh::model::mesh::field::setNumber(threshold, "LcMin", finestSize);
    gmsh::model::mesh::field::setNumber(threshold, "LcMax", coarsestSize);
    gmsh::model::mesh::field::setNumber(threshold, "DistMin", refinedRadius);
    gmsh::model::mesh::field::setNumber(threshold, "DistMax", 0.6 * radius);
    gmsh::model::mesh::field::setAsBackgroundMesh(threshold);
    gmsh::option::setNumber("Mesh.CharacteristicLengthExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.CharacteristicLengthFromPoints", 0);
    gmsh::option::setNumber("Mesh.CharacteristicLengthFromCurvature", 0);
    return session.generate();
}

inline std::vector<int> nodesOnPlane(const TetMesh& mesh, int axis, double tolerance)
{
    std::vector<int> nodes;
    for (std::size_t i = 0; i < mesh.numNodes(); ++i)
        if (std::abs(mesh.nodes[i][axis]) < tolerance) nodes.push_back(static_cast<int>(i));
    return nodes;
}

struct HertzSettings {
    double approachOverRadius = 3e-4;        // final approach / R
    double finestOverContactRadius = 0.125;  // element size at the pole / final contact radius
    double massScaling = 10.0;               // target step / unscaled stable step
    double loadingPeriods = 10.0;            // ramp duration in lowest periods
    double penaltyScale = 4.0;
};

struct HertzResult {
    std::size_t numTets = 0;
    int samples = 0;
    double worstError = 0.0;  // max |F / F_hertz - 1| along the loading curve
};

inline HertzResult runHertzSphere(const HertzSettings& settings)
{
    const auto start = std::chrono::steady_clock::now();
    GmshSession gmshSession;
    const double radius = 0.01, maxApproach = settings.approachOverRadius * radius;
    const double contactRadius = std::sqrt(radius * maxApproach);
    const TetMesh mesh =
        sphereOctantMesh(gmshSession, radius, settings.finestOverContactRadius * contactRadius,
                         1.5 * contactRadius, 0.2 * radius);
    FemParameters parameters;
    parameters.material = std::make_shared<FemMaterialModelOf<LinearElasticMaterial>>();
    parameters.contactPenaltyScale = settings.penaltyScale;
    parameters.rock.density = 2540.0;
    const double pWaveSpeed = std::sqrt(77e9 * 0.79 / (1.21 * 0.58) / 2540.0);
    const double period = 4.0 * radius / pWaveSpeed;  // of the lowest compressive mode, roughly
    parameters.massDamping = 4.0 * M_PI / period;
    FemModel unscaled(mesh, parameters);
    parameters.massScalingTimeStep = settings.massScaling * unscaled.stableTimeStep();
    FemModel model(mesh, parameters);
    const double tol = 1e-9 * radius;
    model.constrainNodes(nodesOnPlane(mesh, 0, tol), {true, false, false});
    model.constrainNodes(nodesOnPlane(mesh, 1, tol), {false, true, false});
    model.constrainNodes(nodesOnPlane(mesh, 2, tol), {false, false, true});
    RigidPlate plate;
    plate.name = "plate";
    plate.point = {0, 0, -radius};
    plate.normal = {0, 0, 1};
    plate.friction = 0.0;
    model.addPlate(plate);
    int pole = -1;
    for (std::size_t i = 0; i < mesh.numNodes(); ++i)
        if (norm(mesh.nodes[i] - Vec3{0, 0, -radius}) < tol) pole = static_cast<int>(i);
    REQUIRE(pole >= 0);

    // Smooth ramp of the plate over loadingPeriods lowest periods: v = vmax sin^2(pi t / T).
    const double dt = model.stableTimeStep();
    const double loadingTime = settings.loadingPeriods * period;
    const int steps = static_cast<int>(loadingTime / dt);
    const double peakSpeed = 2.0 * maxApproach / loadingTime;
    const double youngsModulus = 77e9, poissonRatio = 0.21;
    const double eStar = youngsModulus / (1.0 - poissonRatio * poissonRatio);
    const double centreCompliance =
        (1.0 + poissonRatio) * (3.0 - 2.0 * poissonRatio) / (2.0 * M_PI * youngsModulus * radius);
    HertzResult result;
    result.numTets = mesh.numTets();
    for (int i = 0; i < steps; ++i) {
        const double s = std::sin(M_PI * (i + 0.5) * dt / loadingTime);
        model.plate(0).velocity = {0, 0, peakSpeed * s * s};
        REQUIRE(model.step(dt).ok);
        // The approach: how far the contact point (pole) moved towards the centre.
        const double poleApproach = model.state().displacements[3 * pole + 2];
        if (poleApproach < 0.3 * maxApproach || (i % 50) != 0) continue;
        const double force = -4.0 * model.plate(0).force.z;  // four octants share the contact
        const double approach = poleApproach + centreCompliance * force;
        const double hertz = 4.0 / 3.0 * eStar * std::sqrt(radius) * std::pow(approach, 1.5);
        result.worstError = std::max(result.worstError, std::abs(force / hertz - 1.0));
        ++result.samples;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "Hertz: %zu tets, %d steps, dt %.3g s, added mass %.3g, penetration/approach %.3g, "
        "kinetic/external %.3g, worst force error %.4f, %.1f s\n",
        mesh.numTets(), steps, dt, model.addedMassFraction(),
        (model.plate(0).displacement.z - model.state().displacements[3 * pole + 2]) /
            model.state().displacements[3 * pole + 2],
        model.kineticEnergy() / model.energy().externalWork, result.worstError, seconds);
    return result;
}

}  // namespace rockfrac::fem::test
