// KST-DFH at one material point: KST return, tensile cutoff, DFH cracking.
#include <catch2/catch.hpp>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/selector.hpp"
#include "fem/elementGeometry.hpp"
#include "fem/kstDfhMaterial.hpp"
#include "femTestSupport.hpp"

using namespace rockfrac;
using namespace rockfrac::fem;

namespace {

double pressureOf(const SymTensor& s)
{
    return -trace(s) / 3.0;
}

SymTensor compressionWithShear(double volumetric, double shear)
{
    SymTensor e = SymTensor::isotropic(-volumetric / 3.0);
    e.xy = shear;
    e.zx = 0.3 * shear;
    return e;
}

// One regular tet of the crack-band model (G_F 30 N/m) whose first threshold is `strength`
// (the others out of reach), without plastic flow or tensile cutoff, driven in uniaxial strain
// along x (u = eps x, no lateral strain).
struct CrackBandElement {
    static constexpr double fractureEnergy = 30.0;  // N/m
    TetMesh mesh;
    ElementGeometry geometry;
    KstDfhMaterial material;
    std::vector<double> u = std::vector<double>(12, 0.0), forces = std::vector<double>(12, 0.0),
                        stress = std::vector<double>(6, 0.0);
    long long lastResult = -1;  // computeElementForces' return of the last stretch

    static KstDfhParameters parameters()
    {
        KstDfhParameters p;
        p.referenceVolume = 1e-9;
        p.fractureEnergy = fractureEnergy;
        p.kstA0 = 1e20;  // no plastic flow and no tensile cutoff in these tests
        p.tensilePressureCutoff = -1e12;
        return p;
    }
    CrackBandElement(double edge, double strength)
        : mesh(test::regularTet(edge)),
          geometry(makeElementGeometry(mesh)),
          material(ElasticParameters{}, parameters())
    {
        material.initialise(geometry);
        KstDfhPointState state = material.pointState(0);
        state.failureStress[0] = strength, state.failureStress[1] = state.failureStress[2] = 1e30;
        material.setPointState(0, state);
    }
    // sigma_xx after straining the element to eps_xx = strain.
    double stressAt(double strain)
    {
        for (int a = 0; a < 4; ++a) u[3 * a] = strain * mesh.nodes[a].x;
        lastResult = material.computeElementForces(geometry, u.data(), stress.data(), forces.data());
        return stress[0];
    }
};

}  // namespace

TEST_CASE("KST: a point driven past the surface returns to it at fixed pressure and stays on it",
          "[fem][kst]")
{
    KstDfhParameters p;
    p.damageEnabled = false;
    const KstDfhMaterial material(ElasticParameters{}, p);
    const KstDfhConstants& c = material.constants();
    KstDfhPointState state;
    const double bulk = c.elastic.bulkModulus();
    int plasticSteps = 0;
    for (int i = 1; i <= 200; ++i) {
        // Pressure grows to about 150 MPa while the shear strain grows beyond yield.
        const double volumetric = 2.0e-5 * i, shear = 2.0e-5 * i;
        const SymTensor strain = compressionWithShear(volumetric, shear);
        const SymTensor trialElastic = c.elastic.stress(strain - state.plasticStrain);
        const double trialEquivalent = vonMises(trialElastic);
        const SymTensor stress = kstDfh::updateStress(c, state, strain);
        const double pressure = pressureOf(stress);
        CHECK(pressure == Approx(bulk * volumetric).epsilon(1e-12));  // return keeps P
        const double yield = c.yieldStress(pressure);
        if (trialEquivalent > yield) {
            ++plasticSteps;
            CHECK(vonMises(stress) == Approx(yield).epsilon(1e-8));
        } else {
            CHECK(vonMises(stress) == Approx(trialEquivalent).epsilon(1e-12));
        }
    }
    CHECK(plasticSteps > 50);  // the path did reach and follow the surface
    CHECK(state.equivalentPlasticStrain > 0.0);
}

TEST_CASE("KST: hydrostatic tension beyond the cutoff returns to the apex", "[fem][kst]")
{
    KstDfhParameters p;
    p.damageEnabled = false;
    const KstDfhMaterial material(ElasticParameters{}, p);
    const KstDfhConstants& c = material.constants();
    // Default cutoff: upper root of 1e16 + 3.1e8 P + 2 P^2, about -46 MPa.
    CHECK(c.pressureCutoff == Approx((-3.1e8 + std::sqrt(3.1e8 * 3.1e8 - 8e16)) / 4.0));
    CHECK(c.yieldStress(-60e6) == 0.0);  // the clamped radicand
    KstDfhPointState state;
    const SymTensor stress = kstDfh::updateStress(c, state, SymTensor::isotropic(1e-3));
    CHECK(pressureOf(stress) == Approx(c.pressureCutoff).epsilon(1e-12));
    CHECK(vonMises(stress) == Approx(0.0).margin(1e-6));
}

TEST_CASE("DFH: uniaxial tension cracks at the first threshold; the crack carries compression only",
          "[fem][dfh]")
{
    KstDfhParameters p;
    p.referenceVolume = 1e-9;
    const KstDfhMaterial material(ElasticParameters{}, p);
    const KstDfhConstants& c = material.constants();
    const double E = ElasticParameters{}.youngsModulus, nu = ElasticParameters{}.poissonRatio;
    KstDfhPointState state;
    state.failureStress[0] = 10e6, state.failureStress[1] = 20e6, state.failureStress[2] = 30e6;
    auto uniaxial = [nu](double e) { return SymTensor{e, -nu * e, -nu * e, 0, 0, 0}; };

    const double breakingStrain = 10e6 / E;
    SymTensor s = kstDfh::updateStress(c, state, uniaxial(0.999 * breakingStrain));
    CHECK(state.crackCount == 0);
    CHECK(s.xx == Approx(0.999 * 10e6).epsilon(1e-10));
    s = kstDfh::updateStress(c, state, uniaxial(1.001 * breakingStrain));
    REQUIRE(state.crackCount == 1);
    CHECK(std::abs(state.crackFrame.m[0][0]) == Approx(1.0));  // crack normal along x
    CHECK(s.xx == Approx(0.0).margin(1e-3));
    s = kstDfh::updateStress(c, state, uniaxial(5 * breakingStrain));  // open: no tension
    CHECK(s.xx == Approx(0.0).margin(1e-3));
    CHECK(state.crackCount == 1);
    s = kstDfh::updateStress(c, state, uniaxial(-2 * breakingStrain));  // closed: full stiffness
    CHECK(s.xx == Approx(-20e6).epsilon(1e-10));
    // The perpendicular direction still carries tension: with the crack open (sigma_xx = 0)
    // and eps_zz = 0 the y direction responds with the plane-stress modulus E / (1 - nu^2).
    const double ey = 1e-4;
    s = kstDfh::updateStress(c, state, SymTensor{5 * breakingStrain, ey, 0, 0, 0, 0});
    CHECK(s.xx == Approx(0.0).margin(1e-3));
    CHECK(s.yy == Approx(E / (1 - nu * nu) * ey).epsilon(1e-10));
    CHECK(state.crackCount == 1);
    // Past the second threshold the second crack forms perpendicular to the first.
    s = kstDfh::updateStress(c, state, SymTensor{5 * breakingStrain, 4 * ey, 0, 0, 0, 0});
    REQUIRE(state.crackCount == 2);
    CHECK(std::abs(state.crackFrame.m[1][1]) == Approx(1.0));
    CHECK(s.yy == Approx(0.0).margin(1e-3));
}

TEST_CASE("DFH: an open crack keeps only the retained fraction of its shear stiffness", "[fem][dfh]")
{
    KstDfhParameters p;
    p.referenceVolume = 1e-9;
    p.crackShearRetention = 0.1;
    const KstDfhMaterial material(ElasticParameters{}, p);
    const KstDfhConstants& c = material.constants();
    KstDfhPointState state;
    state.crackCount = 1;  // crack normal x (identity frame)
    state.failureStress[1] = state.failureStress[2] = 1e30;
    const double mu = c.elastic.shearModulus;
    SymTensor strain{1e-4, 0, 0, 1e-5, 2e-5, 0};
    SymTensor s = kstDfh::updateStress(c, state, strain);
    CHECK(s.xy == Approx(0.1 * 2 * mu * 1e-5));  // plane containing the open normal
    CHECK(s.yz == Approx(2 * mu * 2e-5));        // intact plane
    strain.xx = -1e-4;                           // closed crack: full shear
    s = kstDfh::updateStress(c, state, strain);
    CHECK(s.xy == Approx(2 * mu * 1e-5));
}

TEST_CASE("DFH erosion: an element leaves the model once its set number of directions has failed",
          "[fem][dfh]")
{
    // One regular tet stretched along x past its first threshold, then pressed and finally
    // inverted. Without erosion the cracked element carries the compression; with
    // erodeAfterCracks 1 it carries nothing from the crack on and is never reported inverted.
    const TetMesh mesh = test::regularTet(1e-2);
    const ElementGeometry geometry = makeElementGeometry(mesh);
    auto run = [&](int erodeAfterCracks, double stretch, std::vector<double>& stress) {
        KstDfhParameters p;
        p.referenceVolume = 1e-9;
        p.erodeAfterCracks = erodeAfterCracks;
        KstDfhMaterial material(ElasticParameters{}, p);
        material.initialise(geometry);
        KstDfhPointState state = material.pointState(0);
        state.failureStress[0] = 10e6, state.failureStress[1] = 20e6, state.failureStress[2] = 30e6;
        material.setPointState(0, state);
        std::vector<double> u(12, 0.0), forces(12, 0.0);
        stress.assign(6, 0.0);
        long long bad = -1;
        for (double strain : {2.0 * 10e6 / ElasticParameters{}.youngsModulus, stretch}) {
            for (int a = 0; a < 4; ++a) u[3 * a] = strain * mesh.nodes[a].x;  // u_x = eps x
            bad = material.computeElementForces(geometry, u.data(), stress.data(), forces.data());
        }
        CHECK(material.pointState(0).crackCount == 1);
        return bad;
    };
    std::vector<double> stress;
    CHECK(run(0, -1e-4, stress) == -1);
    CHECK(stress[0] < -1e6);  // the closed crack carries the compression
    CHECK(run(1, -1e-4, stress) == -1);
    for (double component : stress) CHECK(component == 0.0);
    CHECK(run(0, -2.0, stress) == 0);   // inverted (x -> -x): reported
    CHECK(run(1, -2.0, stress) == -1);  // eroded: no longer part of the model
    for (double component : stress) CHECK(component == 0.0);
    KstDfhParameters wrong;
    wrong.erodeAfterCracks = 4;
    CHECK_THROWS_WITH(KstDfhMaterial(ElasticParameters{}, wrong), Catch::Contains("erodeAfterCracks"));
}

TEST_CASE("crack band: the band width is the element's extent across the crack", "[fem][dfh]")
{
    // The corner tet (0,0,0) (L,0,0) (0,L,0) (0,0,L): grad N = (-1,-1,-1)/L, x/L, y/L, z/L.
    const double L = 3e-3;
    TetMesh mesh;
    mesh.nodes = {{0, 0, 0}, {L, 0, 0}, {0, L, 0}, {0, 0, L}};
    mesh.tets = {{0, 1, 2, 3}};
    mesh.tetTags = {0};
    const ElementGeometry geometry = makeElementGeometry(mesh);
    CHECK(kstDfh::crackBandWidth(geometry.gradients.data(), Vec3{1, 0, 0}) == Approx(L));
    // Along the diagonal the element's extent is L / sqrt(3) (from the origin to the face x+y+z = L).
    const double r = 1.0 / std::sqrt(3.0);
    CHECK(kstDfh::crackBandWidth(geometry.gradients.data(), Vec3{r, r, r}) == Approx(L * r));
}

TEST_CASE("crack band: a crack softens linearly and dissipates G_F per unit crack area", "[fem][dfh]")
{
    // One element in uniaxial strain along x (u = eps x, no lateral strain) driven through
    // the whole softening: all the work done goes into the crack, the fracture energy times
    // the crack area V / h, for two element sizes.
    for (double edge : {1e-3, 4e-3}) {
        const double strength = 10e6;
        CrackBandElement element(edge, strength);
        const ElementGeometry& geometry = element.geometry;
        KstDfhMaterial& material = element.material;
        const double M = material.constants().elastic.pWaveModulus();
        const double h = kstDfh::crackBandWidth(geometry.gradients.data(), Vec3{1, 0, 0});
        const double wc = 2.0 * CrackBandElement::fractureEnergy / (strength * h);
        auto stressAt = [&](double strain) {
            const double sxx = element.stressAt(strain);
            REQUIRE(element.lastResult == -1);
            return sxx;
        };
        const double peakStrain = strength / M, endStrain = peakStrain + 1.2 * wc;
        const int steps = 20000;
        double work = 0.0, previousStress = 0.0, previousStrain = 0.0, largest = 0.0;
        for (int i = 1; i <= steps; ++i) {
            const double strain = endStrain * i / steps;
            const double sxx = stressAt(strain);
            work += 0.5 * (sxx + previousStress) * (strain - previousStrain);
            largest = std::max(largest, sxx);
            previousStress = sxx, previousStrain = strain;
            // On the softening branch: t = sigma_F (1 - w / w_c) with w = eps - sigma / M.
            if (strain > peakStrain && strain < wc) {
                const double w = (strain - sxx / M);
                CHECK(sxx == Approx(strength * (1.0 - w / wc)).margin(1e-6 * strength));
            }
        }
        CHECK(largest == Approx(strength).epsilon(1e-3));
        CHECK(previousStress == Approx(0.0).margin(1e-6 * strength));  // fully open: no tension
        CHECK(material.damage(0, 0) == 1.0);
        // Nothing is stored at the end: all the work went into the crack, int t dw = sigma_F w_c / 2.
        const double dissipated = work * geometry.volumes[0];
        INFO("edge " << edge << " h " << h << " wc " << wc << " softening strain "
                     << material.pointState(0).softeningStrain[0]);
        CHECK(dissipated == Approx(CrackBandElement::fractureEnergy * geometry.volumes[0] / h).epsilon(2e-3));
    }
}

TEST_CASE("crack band: a softened crack unloads along its secant and closes in compression", "[fem][dfh]")
{
    const double strength = 10e6;
    CrackBandElement element(2e-3, strength);
    const KstDfhMaterial& material = element.material;
    const double M = material.constants().elastic.pWaveModulus();
    auto stressAt = [&](double strain) { return element.stressAt(strain); };
    double strain = 0.0;
    for (int i = 1; i <= 400; ++i)
        stressAt(strain = 2.0 * strength / M * i / 100.0);  // to 8 x the peak strain
    const KstDfhPointState softened = material.pointState(0);
    REQUIRE(softened.crackCount == 1);
    const double kappa = softened.crackOpening[0], left = 1.0 - kappa / softened.softeningStrain[0];
    REQUIRE(left > 0.1);  // still part-way down the softening branch
    CHECK(material.damage(0, 0) == Approx(1.0 - left));
    const double atTop = stressAt(strain);
    CHECK(atTop == Approx(strength * left).epsilon(1e-6));
    // Half the total strain back: the crack closes along the secant t = (t_kappa / kappa) w.
    const double secant = strength * left / kappa;
    const double half = stressAt(0.5 * strain);
    const double w = 0.5 * strain * M / (M + secant);  // M (eps - w) = secant w
    CHECK(half == Approx(secant * w).epsilon(1e-6));
    CHECK(material.pointState(0).crackOpening[0] == Approx(kappa));  // no new damage on unloading
    // Compression: the crack is closed and the element has its full stiffness.
    CHECK(stressAt(-1e-4) == Approx(-M * 1e-4).epsilon(1e-9));
    KstDfhParameters wrong;
    wrong.fractureEnergy = -1.0;
    CHECK_THROWS_WITH(KstDfhMaterial(ElasticParameters{}, wrong), Catch::Contains("fractureEnergy"));
}

TEST_CASE("unknown material names list the known ones", "[fem]")
{
    const Dictionary empty("kstDfh", "rockProperties");
    CHECK_THROWS_WITH(femMaterials().make("granite", empty),
                      Catch::Contains("linearElastic") && Catch::Contains("kstDfh"));
    CHECK(femMaterials().make("linearElastic", empty)->make(ElasticParameters{})->typeName() ==
          "linearElastic");
    CHECK(defaultFemMaterial()->make(ElasticParameters{})->typeName() == "kstDfh");
}
