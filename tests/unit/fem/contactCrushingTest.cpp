// Plate contact crushing (FemParameters::contactCrushingPressure): nodal contact areas,
// the pressure cap, the irreversible crushed depth, and the baseline left unchanged.
#include <catch2/catch.hpp>
#include <cmath>

#include "fem/femModel.hpp"
#include "fem/linearElasticMaterial.hpp"
#include "femTestSupport.hpp"

using namespace rockfrac;
using namespace rockfrac::fem;

namespace {

constexpr double blockSize = 0.01;

// A linear elastic cube on a fixed plate, pressed by a descending top plate.
struct PressedBlock {
    explicit PressedBlock(const TetMesh& m, double crushingPressure) : mesh(m)
    {
        FemParameters p;
        p.material = std::make_shared<FemMaterialModelOf<LinearElasticMaterial>>();
        p.massDamping = 2e5;
        p.contactCrushingPressure = crushingPressure;
        model = std::make_unique<FemModel>(mesh, p);
        RigidPlate bottom, top;
        bottom.normal = {0, 0, 1};
        top.point = {0, 0, blockSize};
        top.normal = {0, 0, -1};
        top.velocity = {0, 0, -2.0};
        model->addPlate(bottom);
        model->addPlate(top);
    }
    void run(int steps)
    {
        const double dt = model->stableTimeStep();
        for (int i = 0; i < steps; ++i) REQUIRE(model->step(dt).ok);
    }
    // Sum of the contact areas of the top face's nodes.
    double topFaceNodeArea() const
    {
        double area = 0.0;
        const auto& nodes = model->contactNodes();
        for (std::size_t j = 0; j < nodes.size(); ++j)
            if (mesh.nodes[nodes[j]].z > blockSize - 1e-12) area += model->contactAreas(1)[j];
        return area;
    }
    TetMesh mesh;
    std::unique_ptr<FemModel> model;
};

}  // namespace

TEST_CASE("contact areas: the footprint of the faces that face the plate", "[fem][crushing]")
{
    test::GmshSession gmshSession;
    const double lx = 0.02, ly = 0.01, lz = 0.005;
    const TetMesh mesh = test::boxMesh(gmshSession, lx, ly, lz, 0.003);
    FemParameters parameters;
    parameters.material = std::make_shared<FemMaterialModelOf<LinearElasticMaterial>>();
    FemModel model(mesh, parameters);
    RigidPlate bottom, tilted;
    bottom.normal = {0, 0, 1};
    tilted.normal = {1, 0, 1};  // 45 degrees: sees the bottom face and the x = 0 face
    model.addPlate(bottom);
    model.addPlate(tilted);
    double onBottom = 0.0, offBottom = 0.0, onTilted = 0.0;
    const auto& nodes = model.contactNodes();
    for (std::size_t j = 0; j < nodes.size(); ++j) {
        const double a = model.contactAreas(0)[j];
        CHECK(a >= 0.0);
        (mesh.nodes[nodes[j]].z < 1e-12 ? onBottom : offBottom) += a;
        onTilted += model.contactAreas(1)[j];
    }
    CHECK(onBottom == Approx(lx * ly).epsilon(1e-12));  // the bottom face, projected: itself
    CHECK(offBottom == 0.0);                            // no other face looks down
    CHECK(onTilted == Approx((lx * ly + ly * lz) / std::sqrt(2.0)).epsilon(1e-12));
}

TEST_CASE("contact crushing caps each node at p_c A and crushes irreversibly", "[fem][crushing]")
{
    test::GmshSession gmshSession;
    const TetMesh mesh = test::boxMesh(gmshSession, blockSize, blockSize, blockSize, 0.25 * blockSize);
    const double crushingPressure = 30e6;
    PressedBlock block(mesh, crushingPressure);
    block.run(600);  // 2 m/s for ~0.06 ms: the elastic block alone would carry > 300 MPa
    const FemModel& model = *block.model;
    const RigidPlate& top = model.plate(1);
    const auto& nodes = model.contactNodes();
    int crushedTop = 0, topNodes = 0;
    double largestElsewhere = 0.0;
    for (std::size_t j = 0; j < nodes.size(); ++j) {
        if (mesh.nodes[nodes[j]].z > blockSize - 1e-12) {
            ++topNodes;
            crushedTop += top.crushedDepth[j] > 0.0;
        } else {
            largestElsewhere = std::max(largestElsewhere, top.crushedDepth[j]);
        }
    }
    REQUIRE(topNodes > 4);
    CHECK(crushedTop == topNodes);   // the whole face crushes...
    CHECK(largestElsewhere == 0.0);  // ...and nothing the plate does not touch
    // Every top node at its cap: the plate carries exactly p_c over the face's area.
    CHECK(block.topFaceNodeArea() == Approx(blockSize * blockSize).epsilon(1e-12));
    CHECK(top.force.z == Approx(crushingPressure * blockSize * blockSize).epsilon(1e-9));

    // Lift the plate: the force vanishes, the crushed depths stay.
    const std::vector<double> crushed = top.crushedDepth;
    block.model->plate(1).velocity = {0, 0, 2.0};
    block.run(300);
    CHECK(block.model->plate(1).force.z == 0.0);
    CHECK(block.model->plate(1).crushedDepth == crushed);
}

TEST_CASE("contact crushing off: no crushed depth, the force beyond any cap", "[fem][crushing]")
{
    test::GmshSession gmshSession;
    const TetMesh mesh = test::boxMesh(gmshSession, blockSize, blockSize, blockSize, 0.25 * blockSize);
    PressedBlock block(mesh, 0.0);
    block.run(600);
    for (double c : block.model->plate(1).crushedDepth) CHECK(c == 0.0);
    CHECK(block.model->plate(1).force.z > 3.0 * 30e6 * block.topFaceNodeArea());
}
