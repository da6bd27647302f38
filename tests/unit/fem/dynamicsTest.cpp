// Explicit dynamics: patch test, stable step, energy conservation, thread independence.
#include <omp.h>

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cstring>
#include <limits>

#include "core/counterRandom.hpp"
#include "fem/femModel.hpp"
#include "fem/kstDfhMaterial.hpp"
#include "fem/linearElasticMaterial.hpp"
#include "femTestSupport.hpp"

using namespace rockfrac;
using namespace rockfrac::fem;

namespace {

FemParameters elasticParameters()
{
    FemParameters p;
    p.material = std::make_shared<FemMaterialModelOf<LinearElasticMaterial>>();
    return p;
}

bool isInterior(const Vec3& x, double size)
{
    const double tol = 1e-9;
    for (int k = 0; k < 3; ++k)
        if (x[k] < tol || x[k] > size - tol) return false;
    return true;
}

// u = G x: a uniform strain sym(G) plus a small rotation.
Vec3 linearField(const Vec3& x)
{
    const Mat3 g{{{1.0e-3, 2.0e-4, -3.0e-4}, {-1.0e-4, -5.0e-4, 4.0e-4}, {2.5e-4, 1.5e-4, 7.0e-4}}};
    return g * x;
}

}  // namespace

TEST_CASE("patch test: a uniform strain imposed on the boundary is reproduced exactly", "[fem][patch]")
{
    test::GmshSession gmshSession;
    const double size = 0.01;
    const TetMesh mesh = test::boxMesh(gmshSession, size, size, size, 0.3 * size);
    REQUIRE(mesh.numTets() > 100);
    FemParameters parameters = elasticParameters();
    parameters.massDamping = 2.0e5;  // dynamic relaxation towards the static solution
    FemModel model(mesh, parameters);

    // Boundary nodes follow the linear field; interior nodes start off it by noise.
    std::vector<double> u(3 * mesh.numNodes());
    std::vector<int> boundary, interior;
    for (std::size_t i = 0; i < mesh.numNodes(); ++i) {
        const Vec3 exact = linearField(mesh.nodes[i]);
        const bool inside = isInterior(mesh.nodes[i], size);
        (inside ? interior : boundary).push_back(static_cast<int>(i));
        for (int k = 0; k < 3; ++k)
            u[3 * i + k] = exact[k] + (inside ? 2e-6 * (uniform01(1, i, k) - 0.5) : 0.0);
    }
    REQUIRE(interior.size() > 5);
    model.setDisplacements(u);
    model.constrainNodes(boundary, {true, true, true});
    const double dt = model.stableTimeStep();
    for (int i = 0; i < 6000; ++i) REQUIRE(model.step(dt).ok);

    const ElasticParameters& m = parameters.rock;
    const IsotropicElasticity elastic =
        IsotropicElasticity::fromYoungPoisson(m.youngsModulus, m.poissonRatio);
    const SymTensor expected = elastic.stress(symmetricPart(
        Mat3{{{1.0e-3, 2.0e-4, -3.0e-4}, {-1.0e-4, -5.0e-4, 4.0e-4}, {2.5e-4, 1.5e-4, 7.0e-4}}}));
    const double scale = std::abs(expected.xx);
    double worstStress = 0.0;
    for (std::size_t e = 0; e < mesh.numTets(); ++e) {
        const SymTensor s = SymTensor::fromArray(&model.state().elementStresses[6 * e]);
        const SymTensor d = s - expected;
        worstStress = std::max(worstStress, std::sqrt(doubleContraction(d, d)) / scale);
    }
    CHECK(worstStress < 1e-9);
    // Interior nodes are in equilibrium: internal force ~ 0 against an element force.
    const double forceScale = scale * size * size;
    double worstForce = 0.0;
    for (int i : interior)
        for (int k = 0; k < 3; ++k)
            worstForce = std::max(worstForce, std::abs(model.state().internalForces[3 * i + k]) / forceScale);
    CHECK(worstForce < 1e-9);
}

namespace {

// Largest displacement after n undamped steps of a single tet from a random start.
double amplitudeAfter(FemModel& model, double dt, int steps)
{
    std::vector<double> u(12);
    for (int k = 0; k < 12; ++k) u[k] = 1e-9 * (uniform01(3, 0, k) - 0.5);
    model.setDisplacements(u);
    for (int i = 0; i < steps; ++i) model.step(dt);
    double largest = 0.0;
    for (double x : model.state().displacements) {
        if (!std::isfinite(x)) return std::numeric_limits<double>::infinity();
        largest = std::max(largest, std::abs(x));
    }
    return largest;
}

}  // namespace

TEST_CASE("stable time step of a single regular tet is the exact limit 2 / omega_max", "[fem][timestep]")
{
    const double a = 1e-3;
    FemParameters parameters = elasticParameters();
    parameters.timeStepSafety = 1.0;
    const TetMesh mesh = test::regularTet(a);
    FemModel model(mesh, parameters);

    // Highest eigenfrequency of the lumped-mass tet from its assembled stiffness matrix.
    Eigen::MatrixXd stiffness(12, 12);
    std::vector<double> stresses(6), forces(12);
    for (int column = 0; column < 12; ++column) {
        std::vector<double> unit(12, 0.0);
        unit[column] = 1e-9;
        model.material().computeElementForces(model.geometry(), unit.data(), stresses.data(), forces.data());
        for (int row = 0; row < 12; ++row) stiffness(row, column) = forces[row] / 1e-9;
    }
    const double nodalMass = model.nodalMasses()[0];
    const double omegaMax = std::sqrt(
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(stiffness / nodalMass).eigenvalues().maxCoeff());
    const double critical = 2.0 / omegaMax;
    CHECK(model.stableTimeStep() == Approx(critical).epsilon(1e-9));

    // It scales as h / c_p with the smallest height h = a sqrt(2/3) and c_p = sqrt((lambda+2mu)/rho);
    // for the regular tet 2/omega_max = 0.70 h / c_p (h / c_p alone would be unstable).
    const double pWaveSpeed =
        std::sqrt(model.material().elasticity().pWaveModulus() / parameters.rock.density);
    const double heightStep = a * std::sqrt(2.0 / 3.0) / pWaveSpeed;
    CHECK(critical / heightStep == Approx(0.70).margin(0.01));

    // Central differences are stable just below the limit and unstable just above it.
    FemModel below(mesh, parameters), above(mesh, parameters);
    CHECK(amplitudeAfter(below, 0.99 * critical, 2000) < 1e-8);
    CHECK(amplitudeAfter(above, 1.02 * critical, 2000) > 1e-6);
}

TEST_CASE("undamped elastic vibration conserves energy", "[fem][energy]")
{
    test::GmshSession gmshSession;
    const double length = 0.02;
    const TetMesh mesh = test::boxMesh(gmshSession, length, 0.5 * length, 0.5 * length, 0.2 * length);
    FemModel model(mesh, elasticParameters());
    std::vector<double> v(3 * mesh.numNodes());
    for (std::size_t i = 0; i < mesh.numNodes(); ++i) {
        const Vec3& x = mesh.nodes[i];
        v[3 * i] = 0.5 * std::cos(M_PI * x.x / length);  // first longitudinal mode, no net momentum
    }
    model.setVelocities(v);
    const double initial = model.kineticEnergy();
    const double dt = model.stableTimeStep();
    double largestDrift = 0.0, largestStrainWork = 0.0;
    for (int i = 0; i < 3000; ++i) {
        REQUIRE(model.step(dt).ok);
        const double total = model.kineticEnergy() + model.energy().internalWork;
        largestDrift = std::max(largestDrift, std::abs(total - initial) / initial);
        largestStrainWork = std::max(largestStrainWork, model.energy().internalWork);
    }
    CHECK(largestStrainWork > 0.3 * initial);  // energy really went back and forth
    CHECK(largestDrift < 0.01);
    CHECK(model.strainEnergy() == Approx(model.energy().internalWork).epsilon(1e-6));
}

namespace {

// Compression of a KST-DFH block between two plates with friction, weak enough to crack.
std::vector<double> crushBlock(int threads, int& cracks)
{
    omp_set_num_threads(threads);
    test::GmshSession gmshSession;
    const double size = 0.01;
    const TetMesh mesh = test::boxMesh(gmshSession, size, size, size, 0.2 * size);
    FemParameters parameters;
    KstDfhParameters k;
    k.weibullStress = 2e6;
    k.referenceVolume = 1e-9;
    k.seed = 5;
    parameters.material = std::make_shared<FemMaterialModelOf<KstDfhMaterial>>(k);
    parameters.massDamping = 1e4;
    FemModel model(mesh, parameters);
    RigidPlate bottom, top;
    bottom.normal = {0, 0, 1};
    top.point = {0, 0, size};
    top.normal = {0, 0, -1};
    top.velocity = {0.3, 0.0, -2.0};  // sliding and pressing
    model.addPlate(bottom);
    model.addPlate(top);
    const double dt = model.stableTimeStep();
    REQUIRE(omp_get_max_threads() == threads);  // gmsh must not have changed it
    for (int i = 0; i < 400; ++i) REQUIRE(model.step(dt).ok);
    cracks = 0;
    for (double d : model.elementOutput().damage[0]) cracks += d > 0.5;
    std::vector<double> result = model.state().displacements;
    result.push_back(model.plate(1).force.z);
    return result;
}

}  // namespace

TEST_CASE("1 and 2 OpenMP threads give bitwise identical results", "[fem][threads]")
{
    int cracksOne = 0, cracksTwo = 0;
    const std::vector<double> one = crushBlock(1, cracksOne);
    const std::vector<double> two = crushBlock(2, cracksTwo);
    omp_set_num_threads(2);
    CHECK(cracksOne > 0);  // the damage path was exercised
    CHECK(cracksOne == cracksTwo);
    REQUIRE(one.size() == two.size());
    CHECK(std::memcmp(one.data(), two.data(), one.size() * sizeof(double)) == 0);
    CHECK(one.back() > 0.0);  // the rock pushes the top plate up
}
