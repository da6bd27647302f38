// Restart continuity, the virtual extensometer and the failure-load detector.
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "fem/kstDfhMaterial.hpp"
#include "fem/linearElasticMaterial.hpp"
#include "fem/measurements.hpp"
#include "femCase/femCase.hpp"
#include "femTestSupport.hpp"
#include "io/stateFile.hpp"

using namespace rockfrac;
using namespace rockfrac::fem;

namespace {

FemParameters crushingParameters(double contactCrushingPressure = 0.0)
{
    FemParameters parameters;
    parameters.contactCrushingPressure = contactCrushingPressure;
    KstDfhParameters k;
    k.weibullStress = 2e6;
    k.referenceVolume = 1e-9;
    parameters.material = std::make_shared<FemMaterialModelOf<KstDfhMaterial>>(k);
    parameters.massDamping = 1e4;
    return parameters;
}

void addCrushingPlates(FemModel& model, double size)
{
    RigidPlate bottom, top;
    top.point = {0, 0, size};
    top.normal = {0, 0, -1};
    top.velocity = {0.3, 0.0, -2.0};
    model.addPlate(bottom);
    model.addPlate(top);
}

}  // namespace

TEST_CASE("a restarted model continues bit for bit", "[fem][restart]")
{
    // Without and with contact crushing (whose crushed depths are part of the state).
    const double crushingPressure = GENERATE(0.0, 20e6);
    test::GmshSession gmshSession;
    const double size = 0.01;
    const TetMesh mesh = test::boxMesh(gmshSession, size, size, size, 0.25 * size);
    FemModel original(mesh, crushingParameters(crushingPressure));
    addCrushingPlates(original, size);
    const double dt = original.stableTimeStep();
    for (int i = 0; i < 200; ++i) REQUIRE(original.step(dt).ok);

    // What a restart file holds: the FemState and the material's state fields.
    const FemState saved = original.state();
    std::vector<std::vector<double>> savedFields;
    for (const auto& field : original.material().stateFields()) savedFields.push_back(*field.values);

    FemModel restarted(mesh, crushingParameters(crushingPressure));
    addCrushingPlates(restarted, size);
    restarted.setState(saved);
    auto fields = restarted.material().stateFields();
    for (std::size_t k = 0; k < fields.size(); ++k) *fields[k].values = savedFields[k];

    for (int i = 0; i < 100; ++i) {
        REQUIRE(original.step(dt).ok);
        REQUIRE(restarted.step(dt).ok);
    }
    const auto& a = original.state().displacements;
    const auto& b = restarted.state().displacements;
    CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
    CHECK(original.plate(1).force.z == restarted.plate(1).force.z);
    CHECK(original.energy().internalWork == restarted.energy().internalWork);
    CHECK(original.plate(1).crushedDepth == restarted.plate(1).crushedDepth);
    double deepest = 0.0;
    for (double c : original.plate(1).crushedDepth) deepest = std::max(deepest, c);
    CHECK((deepest > 0.0) == (crushingPressure > 0.0));  // the crushing path was exercised
}

TEST_CASE("a state file written before contact crushing existed restarts with no crushed depths",
          "[fem][restart]")
{
    test::GmshSession gmshSession;
    const double size = 0.01;
    const TetMesh mesh = test::boxMesh(gmshSession, size, size, size, 0.25 * size);
    FemModel original(mesh, crushingParameters(20e6));
    addCrushingPlates(original, size);
    const double dt = original.stableTimeStep();
    for (int i = 0; i < 200; ++i) REQUIRE(original.step(dt).ok);
    double deepest = 0.0;
    for (double c : original.plate(1).crushedDepth) deepest = std::max(deepest, c);
    REQUIRE(deepest > 0.0);

    const auto dir =
        std::filesystem::temp_directory_path() / ("rockfrac-old-femState-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    FemRunState run;
    run.step = 200;
    writeFemState(dir / "femState", original, run);
    // The same file as the writer before 2026-12-02: no plateK.crushedDepth arrays.
    StateFile old = StateFile::read(dir / "femState");
    REQUIRE(old.has("plate1.crushedDepth"));
    old.erase("plate0.crushedDepth");
    old.erase("plate1.crushedDepth");
    old.write(dir / "femStateOld");

    FemModel fromOld(mesh, crushingParameters(20e6));
    addCrushingPlates(fromOld, size);
    CHECK(readFemState(dir / "femStateOld", fromOld).step == 200);
    CHECK(fromOld.state().displacements == original.state().displacements);
    for (int k = 0; k < 2; ++k)
        for (double c : fromOld.plate(k).crushedDepth) CHECK(c == 0.0);

    FemModel fromNew(mesh, crushingParameters(20e6));
    addCrushingPlates(fromNew, size);
    readFemState(dir / "femState", fromNew);
    CHECK(fromNew.plate(1).crushedDepth == original.plate(1).crushedDepth);
    std::filesystem::remove_all(dir);
}

TEST_CASE("the virtual extensometer reads the strain along its axis times its length", "[fem][measure]")
{
    test::GmshSession gmshSession;
    const double size = 0.02;
    const TetMesh mesh = test::boxMesh(gmshSession, size, size, size, 0.3 * size);
    FemParameters parameters;
    parameters.material = std::make_shared<FemMaterialModelOf<LinearElasticMaterial>>();
    FemModel model(mesh, parameters);
    // u = G x with G_yy = -1e-3 and shear and rotation parts that do not stretch y.
    std::vector<double> u(3 * mesh.numNodes());
    for (std::size_t i = 0; i < mesh.numNodes(); ++i) {
        const Vec3& x = mesh.nodes[i];
        u[3 * i] = 2e-4 * x.y;
        u[3 * i + 1] = -1e-3 * x.y - 2e-4 * x.x;
        u[3 * i + 2] = 5e-4 * x.x;
    }
    model.setDisplacements(u);
    const double length = 0.01;
    const VirtualExtensometer extensometer(mesh, {0.5 * size, 0.5 * size, 0.5 * size}, {0, 1, 0}, length);
    CHECK(extensometer.elongation(model) == Approx(-1e-3 * length).epsilon(1e-10));
    CHECK_THROWS_AS(VirtualExtensometer(mesh, {0.5 * size, 0.5 * size, 0.5 * size}, {0, 1, 0}, 3 * size),
                    UserError);
}

TEST_CASE("failure load: the running maximum at the first drop beyond the fraction", "[fem][measure]")
{
    FailureLoadDetector detector(0.2);
    for (double force : {1.0, 5.0, 9.0, 8.0, 10.0, 8.5}) CHECK_FALSE(detector.update(force));
    CHECK(detector.update(7.9));  // 21 % below the maximum 10
    CHECK(detector.failureLoad() == 10.0);
    CHECK(detector.update(12.0));  // stays failed with the first peak
    CHECK(detector.failureLoad() == 10.0);
}
