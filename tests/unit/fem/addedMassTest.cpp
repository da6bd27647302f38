// Mass scaling's added mass: the summary (how much, where, how small) and its warning.
#include <catch2/catch.hpp>

#include "fem/addedMass.hpp"
#include "fem/femModel.hpp"
#include "fem/linearElasticMaterial.hpp"
#include "femTestSupport.hpp"

using namespace rockfrac;
using namespace rockfrac::fem;

namespace {

FemParameters elasticParameters(double massScalingTimeStep)
{
    FemParameters p;
    p.material = std::make_shared<FemMaterialModelOf<LinearElasticMaterial>>();
    p.timeStepSafety = 1.0;
    p.massScalingTimeStep = massScalingTimeStep;
    return p;
}

// A sliver (2 mm wide, 1 nm high) at x, y ~ 21 mm, z = 20 mm added to the mesh.
TetMesh withSliver(TetMesh mesh)
{
    const int first = static_cast<int>(mesh.nodes.size());
    mesh.nodes.push_back({20e-3, 20e-3, 20e-3});
    mesh.nodes.push_back({22e-3, 20e-3, 20e-3});
    mesh.nodes.push_back({21e-3, 21.7e-3, 20e-3});
    mesh.nodes.push_back({21e-3, 20.6e-3, 20.000001e-3});
    mesh.tets.push_back({first, first + 1, first + 2, first + 3});
    mesh.tetTags.push_back(0);
    if (!mesh.tetFileTags.empty()) mesh.tetFileTags.push_back(mesh.tetFileTags.back() + 1);
    return mesh;
}

}  // namespace

TEST_CASE("a sliver's added mass is warned about with where it is; a sound mesh is not", "[fem][addedMass]")
{
    test::GmshSession session;
    const TetMesh box = test::boxMesh(session, 10e-3, 10e-3, 10e-3, 2e-3);
    const double density = FemParameters{}.rock.density;
    // The target: half the box's own stable step, so that the box alone needs no scaling
    // (mass scaling also leaves room for the contact springs, 2 / sqrt(5) of the step).
    const double target = 0.5 * FemModel(box, elasticParameters(0.0)).stableTimeStep();

    const FemModel sound(box, elasticParameters(target));
    const AddedMassSummary none = summariseAddedMass(sound, density);
    CHECK(none.fraction < 1e-12);
    CHECK(none.scaledElements == 0);
    CHECK(addedMassWarning(none, target).empty());

    const FemModel sliver(withSliver(box), elasticParameters(target));
    const AddedMassSummary s = summariseAddedMass(sliver, density);
    CHECK(s.fraction > 1.0);  // a single 1 nm sliver outweighs the 10 mm cube
    CHECK(s.scaledElements == 1);
    CHECK(s.elements == box.numTets() + 1);
    CHECK(s.centroid.x == Approx(21.0e-3).epsilon(1e-9));
    CHECK(s.centroid.y == Approx(20.575e-3).epsilon(1e-9));
    CHECK(s.scaledMedianHeight < 2e-9);
    CHECK(s.smallestHeight == s.scaledMedianHeight);
    CHECK(s.medianHeight > 0.3e-3);
    CHECK(s.smallestAt.x == s.centroid.x);
    CHECK(s.surfaceShare == 1.0);  // a lone tet: all its nodes on the surface
    const std::string warning = addedMassWarning(s, target);
    INFO(warning);
    CHECK(warning.rfind("Warning: mass scaling adds ", 0) == 0);
    CHECK(warning.find("1 of " + std::to_string(s.elements) + " elements") != std::string::npos);
    CHECK(warning.find("centred at (21 20.5") != std::string::npos);
    CHECK(warning.find("mm at (21 20.5") != std::string::npos);
    CHECK(warning.find("100 % of the added mass in elements with a face on the surface") !=
          std::string::npos);
    CHECK(warning.find("elementSize in system/feMeshDict") != std::string::npos);
    CHECK(warning.find('\n') == std::string::npos);
    // Below the limit: no warning.
    AddedMassSummary small = s;
    small.fraction = 0.013;  // the SPB tutorial rock's
    CHECK(addedMassWarning(small, target).empty());
}
