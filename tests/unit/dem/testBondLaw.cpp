// One bond between two box cells under imposed kinematics (no dynamics): the
// traction–separation law of Eqs. 5–20 and Algorithm 1, checked bond by bond.
#include <catch2/catch.hpp>
#include <cmath>

#include "boxMeshes.hpp"
#include "core/error.hpp"
#include "core/selector.hpp"
#include "dem/brittleBpmBond.hpp"
#include "dem/demModel.hpp"
#include "dem/voronoiQnscBond.hpp"
#include "demBackend.hpp"

using namespace rockfrac;

namespace {

constexpr double cell_size = 5e-3;         // [m]
constexpr double dilation = 5e-4;          // [m]
constexpr double bond_area = 25e-6 / 4.0;  // A/n of a 5 mm square face with 4 bonds
constexpr double reference_length = 5e-3;  // l_i + l_j

// Two cubes side by side along x, glued by the single bond at one corner of the shared face.
VoronoiMesh oneBondMesh()
{
    VoronoiMesh mesh = test::boxBlockMesh(2, 1, 1, {cell_size, cell_size, cell_size}, dilation);
    mesh.bonds.resize(1);
    return mesh;
}

// The paper's law with G_I = G_II = 100 N/m (d_f > d_e0, see theory-dem.md).
VoronoiQnscBondLaw::Parameters quietQnsc()
{
    VoronoiQnscBondLaw::Parameters q;
    q.fracture_energy_I = q.fracture_energy_II = 100.0;
    return q;
}

DemParameters quietParameters(const VoronoiQnscBondLaw::Parameters& q = quietQnsc())
{
    DemParameters p;
    p.gravity = {0.0, 0.0, 0.0};
    p.bond_damping = 0.0;
    p.bond_law = std::make_shared<VoronoiQnscBondLaw>(q);
    return p;
}

// The coefficients of the case's voronoiQNSC law.
const VoronoiQnscBondLaw::Parameters& qnscOf(const DemParameters& p)
{
    return dynamic_cast<const VoronoiQnscBondLaw&>(*p.bond_law).parameters();
}

double normalModulus(const DemParameters& p)
{
    const double E = qnscOf(p).youngs_modulus, nu = qnscOf(p).poisson_ratio;
    return E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
}
double shearModulus(const DemParameters& p)
{
    return qnscOf(p).youngs_modulus / (2.0 * (1.0 + qnscOf(p).poisson_ratio));
}

// Cell 1 displaced by d from its place (cell 0 fixed), forces evaluated; returns the force on cell 0.
struct ImposedBond {
    DemModel model;
    Vec3 rest;
    Quat orientation;
    explicit ImposedBond(const DemParameters& p)
        : model(oneBondMesh(), p), rest(model.cells().position[1]), orientation(model.cells().orientation[1])
    {
    }
    Vec3 forceAt(const Vec3& opening, const Vec3& velocity = {})
    {
        model.setCellPose(1, rest + opening, orientation);
        model.setCellVelocity(1, velocity, {});
        test::evaluateForces(model, 0.0);
        return model.cells().force[0];
    }
    BondArrays bonds() const { return model.bonds(); }
};

double qnsc(const DemParameters& p, double sigma, double tau)
{
    const double tensile = std::max(sigma, 0.0) / qnscOf(p).tensile_strength;
    const double shear = tau / (qnscOf(p).cohesion - qnscOf(p).friction * sigma);
    return tensile * tensile + shear * shear;
}

}  // namespace

TEST_CASE("one bond under imposed opening: linear, linear softening, work = G_f A/n", "[dem][bond]")
{
    const DemParameters p = quietParameters();
    ImposedBond bond(p);
    const double kn = normalModulus(p);
    const double onset = qnscOf(p).tensile_strength * reference_length / kn;                // d_e0
    const double rupture = 2.0 * qnscOf(p).fracture_energy_I / qnscOf(p).tensile_strength;  // d_f
    REQUIRE(rupture > onset);
    const int n_increments = 4000;
    const double last = 1.2 * rupture;
    double work = 0.0, previous_force = 0.0, peak = 0.0;
    for (int i = 1; i <= n_increments; ++i) {
        const double opening = last * i / n_increments;
        const double force = bond.forceAt({opening, 0.0, 0.0}).x;
        work += 0.5 * (force + previous_force) * (last / n_increments);
        previous_force = force;
        peak = std::max(peak, force);
        // The analytic law: elastic, then linear softening to zero at d_f.
        const double expected = opening <= onset    ? kn * opening / reference_length * bond_area
                                : opening < rupture ? qnscOf(p).tensile_strength * bond_area *
                                                          (rupture - opening) / (rupture - onset)
                                                    : 0.0;
        REQUIRE(force == Approx(expected).margin(1e-9 * qnscOf(p).tensile_strength * bond_area));
    }
    const double separation_energy = qnscOf(p).fracture_energy_I * bond_area;
    CHECK(peak == Approx(qnscOf(p).tensile_strength * bond_area).epsilon(1e-3));
    CHECK(work == Approx(separation_energy).epsilon(0.01));
    CHECK(bond.model.energies().fracture == Approx(separation_energy).epsilon(0.01));
    CHECK(bond.bonds().stage[0] == bondBroken);
    CHECK(bond.model.counters().bonds_broken == 1);
    CHECK(bond.model.cellDamage()[0] == 1.0);
}

TEST_CASE("bond size effect: an interface of area A opens at sigma-bar (A_ref/A)^(1/m), and shears at C x it",
          "[dem][bond][sizeEffect]")
{
    // The one-bond mesh keeps a single bond of the face: its interface area is A/n.
    DemParameters p = quietParameters();
    p.bond_size_effect_modulus = 7.0;
    p.bond_size_effect_reference_area = 4.0 * bond_area;  // this interface is 4 x smaller: stronger
    const double factor = std::pow(4.0, 1.0 / 7.0);
    CHECK(p.bondSizeFactor(bond_area) == Approx(factor).epsilon(1e-14));
    CHECK(p.bondSizeFactor(4.0 * bond_area) == 1.0);
    const double kn = normalModulus(p), kt = shearModulus(p);
    for (const Vec3 direction : {Vec3{1.0, 0.0, 0.0}, Vec3{0.0, 1.0, 0.0}}) {
        // Opening (tension, onset at sigma-bar) or sliding (pure shear, onset at C).
        const bool tension = direction.x > 0.0;
        const double expected = factor * (tension ? qnscOf(p).tensile_strength : qnscOf(p).cohesion);
        const double step = 1e-4 * expected * reference_length / (tension ? kn : kt);
        ImposedBond bond(p);
        REQUIRE(bond.model.interfaces().strength_scale.size() == 1);
        CHECK(bond.model.interfaces().strength_scale[0] == Approx(factor).epsilon(1e-14));
        double d = 0.0;
        while (bond.bonds().stage[0] == bondElastic &&
               d < 2.0 * expected * reference_length / (tension ? kn : kt)) {
            d += step;
            bond.forceAt(d * direction);
        }
        INFO((tension ? "tension" : "shear"));
        REQUIRE(bond.bonds().stage[0] != bondElastic);
        CHECK(bond.bonds().onset_stress[0] == Approx(expected).epsilon(2e-3));
    }
    // Off (m = 0): the paper's model exactly; a reference area is then not needed.
    p.bond_size_effect_modulus = 0.0;
    p.bond_size_effect_reference_area = 0.0;
    CHECK(p.bondSizeFactor(bond_area) == 1.0);
    CHECK_NOTHROW(p.validate());
    p.bond_size_effect_modulus = 7.0;
    CHECK_THROWS_AS(p.validate(), UserError);
}

TEST_CASE("pure shear onset at tau-bar = C - mu sigma, compression raising the strength", "[dem][bond]")
{
    const DemParameters p = quietParameters();
    const double kn = normalModulus(p), kt = shearModulus(p);
    for (double sigma : {0.0, -10e6, -40e6, -80e6}) {
        ImposedBond bond(p);
        const double normal_opening = sigma * reference_length / kn;
        const double expected = qnscOf(p).cohesion - qnscOf(p).friction * sigma;
        const double step = 1e-4 * expected * reference_length / kt;
        double shear = 0.0;
        while (bond.bonds().stage[0] == bondElastic && shear < 2.0 * expected * reference_length / kt) {
            shear += step;
            bond.forceAt({normal_opening, shear, 0.0});
        }
        INFO("sigma = " << sigma);
        REQUIRE(bond.bonds().stage[0] != bondElastic);
        // Before the onset the shear stress stayed below tau-bar; at it, sigma_e0 = tau-bar.
        CHECK(kt * (shear - step) / reference_length < expected);
        CHECK(bond.bonds().onset_stress[0] == Approx(expected).epsilon(2e-3));
    }
}

TEST_CASE("mixed-mode onset lies on the QNSC ellipse; G_f from Benzeggagh-Kenane", "[dem][bond]")
{
    VoronoiQnscBondLaw::Parameters q = quietQnsc();
    q.fracture_energy_I = 100.0;
    q.fracture_energy_II = 300.0;
    q.bk_exponent = 2.0;
    const DemParameters p = quietParameters(q);
    const double kn = normalModulus(p), kt = shearModulus(p);
    for (double angle_degrees : {10.0, 30.0, 45.0, 60.0, 80.0}) {
        ImposedBond bond(p);
        const double angle = angle_degrees * M_PI / 180.0;
        const Vec3 direction{std::cos(angle), std::sin(angle), 0.0};
        double amount = 0.0;
        while (bond.bonds().stage[0] == bondElastic && amount < 1e-3) {
            amount += 1e-8;
            bond.forceAt(amount * direction);
        }
        INFO("angle = " << angle_degrees);
        REQUIRE(bond.bonds().stage[0] != bondElastic);
        // Proportional loading: d_e = amount, so the onset stresses follow from d_e0.
        const double d0 = bond.bonds().onset_displacement[0];
        const double sigma0 = kn * d0 * std::cos(angle) / reference_length;
        const double tau0 = kt * d0 * std::sin(angle) / reference_length;
        CHECK(qnsc(p, sigma0, tau0) == Approx(1.0).epsilon(1e-9));
        CHECK(bond.bonds().onset_stress[0] == Approx(std::hypot(sigma0, tau0)).epsilon(1e-9));
        const double mixity = tau0 * tau0 / (sigma0 * sigma0 + tau0 * tau0);
        const double fracture_energy =
            qnscOf(p).fracture_energy_I +
            (qnscOf(p).fracture_energy_II - qnscOf(p).fracture_energy_I) * mixity * mixity;
        CHECK(bond.bonds().rupture_displacement[0] ==
              Approx(2.0 * fracture_energy / bond.bonds().onset_stress[0]).epsilon(1e-12));
    }
}

TEST_CASE("compression never damages a bond", "[dem][bond]")
{
    const DemParameters p = quietParameters();
    ImposedBond bond(p);
    const double kn = normalModulus(p);
    const double onset = qnscOf(p).tensile_strength * reference_length / kn;
    for (int i = 1; i <= 100; ++i) {
        const double opening = -50.0 * onset * i / 100.0;
        const double force = bond.forceAt({opening, 0.0, 0.0}).x;
        REQUIRE(force == Approx(kn * opening / reference_length * bond_area).epsilon(1e-12));
        REQUIRE(bond.bonds().stage[0] == bondElastic);
        REQUIRE(bond.bonds().damage[0] == 0.0);
    }
}

TEST_CASE("damage never decreases on unloading and reloading", "[dem][bond]")
{
    const DemParameters p = quietParameters();
    ImposedBond bond(p);
    const double kn = normalModulus(p);
    const double onset = qnscOf(p).tensile_strength * reference_length / kn;
    const double rupture = 2.0 * qnscOf(p).fracture_energy_I / qnscOf(p).tensile_strength;
    const double peak_opening = onset + 0.5 * (rupture - onset);
    for (int i = 1; i <= 200; ++i) bond.forceAt({peak_opening * i / 200.0, 0.0, 0.0});
    const double damage = bond.bonds().damage[0];
    REQUIRE(damage > 0.3);
    // Unload to zero and into compression: D stays, the tensile stiffness is the secant one.
    for (int i = 199; i >= -100; --i) {
        const double opening = peak_opening * i / 200.0;
        const double force = bond.forceAt({opening, 0.0, 0.0}).x;
        REQUIRE(bond.bonds().damage[0] == damage);
        const double stiffness = opening < 0.0 ? kn : (1.0 - damage) * kn;
        REQUIRE(force == Approx(stiffness * opening / reference_length * bond_area).margin(1e-12));
    }
    // Reload to the previous maximum: still D; beyond it D grows.
    for (int i = 1; i <= 200; ++i) bond.forceAt({peak_opening * i / 200.0, 0.0, 0.0});
    CHECK(bond.bonds().damage[0] == damage);
    bond.forceAt({1.1 * peak_opening, 0.0, 0.0});
    CHECK(bond.bonds().damage[0] > damage);
}

TEST_CASE("bond damping: beta k eps-dot A/n (absolute) and 2 zeta sqrt(m*/k) (criticalFraction)",
          "[dem][bond]")
{
    DemParameters p = quietParameters();
    const double kn = normalModulus(p), kt = shearModulus(p);
    const double speed = 0.01;  // [m/s]
    SECTION("absolute: beta in seconds")
    {
        p.bond_damping = 1e-6;
        p.damping_reading = DampingReading::absolute;
        ImposedBond bond(p);
        const Vec3 normal_force = bond.forceAt({}, {speed, 0.0, 0.0});
        CHECK(normal_force.x ==
              Approx(p.bond_damping * kn * (speed / reference_length) * bond_area).epsilon(1e-12));
        const Vec3 shear_force = bond.forceAt({}, {0.0, speed, 0.0});
        CHECK(shear_force.y ==
              Approx(p.bond_damping * kt * (speed / reference_length) * bond_area).epsilon(1e-12));
        CHECK(std::fabs(shear_force.x) < 1e-12 * std::fabs(shear_force.y));
    }
    SECTION("criticalFraction: beta = zeta of the bond's critical damping")
    {
        p.bond_damping = 0.1;
        p.damping_reading = DampingReading::criticalFraction;
        ImposedBond bond(p);
        const double mass = p.rock_density * cell_size * cell_size * cell_size;
        const double reduced_mass = 0.5 * mass;
        const double stiffness = kn * bond_area / reference_length;
        const double beta = 2.0 * p.bond_damping * std::sqrt(reduced_mass / stiffness);
        CHECK(bond.model.interfaces().damping_beta[0] == Approx(beta).epsilon(1e-12));
        // The dashpot is c = 2 zeta sqrt(k m*) on the relative anchor velocity.
        const Vec3 force = bond.forceAt({}, {speed, 0.0, 0.0});
        CHECK(force.x ==
              Approx(2.0 * p.bond_damping * std::sqrt(stiffness * reduced_mass) * speed).epsilon(1e-12));
    }
}

TEST_CASE("unknown law names are user errors listing the known ones", "[dem][registry]")
{
    const Dictionary empty("bond", "rockProperties");
    CHECK_THROWS_WITH(bondLaws().make("timoshenkoBeam", empty),
                      Catch::Contains("voronoiQNSC") && Catch::Contains("brittleBPM"));
    CHECK_THROWS_WITH(contactLaws().make("linearSpring", empty), Catch::Contains("hertzMindlin"));
    CHECK_THROWS_AS(dampingReadingFromName("seconds"), UserError);
    DemParameters p = quietParameters();
    p.bond_law = nullptr;
    CHECK_THROWS_AS(DemModel(oneBondMesh(), p), UserError);
}

TEST_CASE("a bond broken in shear under compression books its compressive energy as fracture",
          "[dem][bond][energy]")
{
    VoronoiQnscLaw::Coefficients m;
    m.normal_modulus = 55e9;
    m.shear_modulus = 18e9;
    m.tensile_strength = 28e6;
    m.cohesion = 42e6;
    m.friction = 0.8;
    m.fracture_energy_I = m.fracture_energy_II = 1e-3;  // brittle: breaks right at onset
    m.rupture_tolerance = 1e-6;
    BondInput in;
    in.normal = {1.0, 0.0, 0.0};
    in.reference_length = reference_length;
    in.bond_area = bond_area;
    const double dn = -1e-6;  // compression: sigma = -11 MPa
    BondHistory h;
    double fracture = 0.0, strain_before = 0.0;
    for (int i = 1; i <= 4000 && h.stage != bondBroken; ++i) {
        in.opening = {dn, 1e-8 * i, 0.0};
        const BondOutput out = VoronoiQnscLaw::evaluate(m, in, h);
        fracture += out.fracture_dissipation;
        if (h.stage != bondBroken) strain_before = out.strain_energy;
    }
    REQUIRE(h.stage == bondBroken);
    // Everything the bond stored (shear and compression) is released into fracture.
    const double compressive = 0.5 * bond_area * m.normal_modulus * dn * dn / reference_length;
    INFO("fracture " << fracture << " stored before " << strain_before << " compressive part "
                     << compressive);
    CHECK(fracture > compressive);
    CHECK(fracture == Approx(strain_before).epsilon(0.02));
}

// ---- brittleBPM: the bonded-particle model's brittle bond ---------------------------

namespace {

DemParameters brittleParameters(const BrittleBpmBondLaw::Parameters& b = {})
{
    DemParameters p = quietParameters();
    p.bond_law = std::make_shared<BrittleBpmBondLaw>(b);
    return p;
}

}  // namespace

TEST_CASE(
    "brittleBPM under imposed opening: linear to sigma-bar A/n, then nothing; dissipates the stored energy",
    "[dem][bond][brittle]")
{
    const BrittleBpmBondLaw::Parameters b;
    const DemParameters p = brittleParameters(b);
    ImposedBond bond(p);
    const double kn = normalModulus(quietParameters());  // the same E and nu: the same k_n
    REQUIRE(p.bond_law->normalModulus() == kn);
    const double onset = b.tensile_strength * reference_length / kn;  // where sigma = sigma-bar
    const int n = 2000;
    const double last = 2.0 * onset;
    double work = 0.0, previous = 0.0, peak = 0.0;
    for (int i = 1; i <= n; ++i) {
        const double opening = last * i / n;
        const double force = bond.forceAt({opening, 0.0, 0.0}).x;
        work += 0.5 * (force + previous) * (last / n);
        previous = force;
        peak = std::max(peak, force);
        const double expected =
            opening < onset * (1.0 - 1e-12) ? kn * opening / reference_length * bond_area : 0.0;
        REQUIRE(force == Approx(expected).margin(1e-9 * b.tensile_strength * bond_area));
    }
    // The largest force is the last sample below the strength; the bond broke at the first at or above it.
    CHECK(peak < b.tensile_strength * bond_area);
    CHECK(peak >= (1.0 - 1.01 * 2.0 / n) * b.tensile_strength * bond_area);  // within one sample
    const BondArrays bonds = bond.bonds();
    CHECK(bonds.stage[0] == bondBroken);
    CHECK(bonds.damage[0] == 1.0);
    CHECK(bond.model.counters().bonds_broken == 1);
    // Dissipated: the strain energy the bond held at the step it broke, 1/2 sigma^2 A l / k_n at that
    // step's opening (one sample past sigma-bar), and the work of the sampled curve up to there.
    const double broke_at = std::ceil(onset / (last / n) - 1e-9) * (last / n);
    const double stored = 0.5 * kn * broke_at * broke_at / reference_length * bond_area;
    CHECK(bond.model.energies().fracture == Approx(stored).epsilon(1e-9));
    CHECK(bond.model.energies().fracture ==
          Approx(0.5 * b.tensile_strength * b.tensile_strength * bond_area * reference_length / kn)
              .epsilon(2.0 * 2.0 / n));
    CHECK(work == Approx(0.5 * b.tensile_strength * b.tensile_strength * bond_area * reference_length / kn)
                      .epsilon(2.0 * 2.0 / n));
}

TEST_CASE("brittleBPM fails in shear at tau-bar = C - mu sigma, compression raising it",
          "[dem][bond][brittle]")
{
    const BrittleBpmBondLaw::Parameters b;
    const DemParameters p = brittleParameters(b);
    const double kn = p.bond_law->normalModulus(), kt = p.bond_law->shearModulus();
    for (double sigma : {0.0, -10e6, -40e6}) {
        ImposedBond bond(p);
        const double normal_opening = sigma * reference_length / kn;
        const double expected = b.cohesion - b.friction * sigma;
        const double step = 1e-4 * expected * reference_length / kt;
        double shear = 0.0;
        while (bond.bonds().stage[0] == bondElastic && shear < 2.0 * expected * reference_length / kt) {
            shear += step;
            bond.forceAt({normal_opening, shear, 0.0});
        }
        INFO("sigma = " << sigma);
        REQUIRE(bond.bonds().stage[0] == bondBroken);  // no softening stage: broken at once
        CHECK(kt * (shear - step) / reference_length < expected);
        CHECK(kt * shear / reference_length >= expected);
        CHECK(bond.bonds().onset_stress[0] == Approx(expected).epsilon(2e-4));
    }
}

TEST_CASE("brittleBPM tests tension and shear each on its own, where the QNSC ellipse has failed",
          "[dem][bond][brittle]")
{
    BrittleBpmLaw::Coefficients m;
    m.normal_modulus = 55e9;
    m.shear_modulus = 18e9;
    m.tensile_strength = 28e6;
    m.cohesion = 42e6;
    m.friction = 0.8;
    const double sigma = 0.9 * m.tensile_strength;
    const double tau = 0.9 * (m.cohesion - m.friction * sigma);
    CHECK_FALSE(BrittleBpmLaw::fails(m, sigma, tau * tau));  // 0.81 + 0.81 > 1 on the QNSC ellipse
    CHECK(BrittleBpmLaw::fails(m, m.tensile_strength, 0.0));
    CHECK(BrittleBpmLaw::fails(m, 0.0, m.cohesion * m.cohesion));
    CHECK(BrittleBpmLaw::fails(m, m.cohesion / m.friction, 0.0));  // C - mu sigma <= 0
    CHECK_FALSE(BrittleBpmLaw::fails(
        m, -1e9, 0.99 * 0.99 * (m.cohesion + m.friction * 1e9) * (m.cohesion + m.friction * 1e9)));
    // The same state through the law: intact, force and energy of the elastic bond.
    BondInput in;
    in.normal = {1.0, 0.0, 0.0};
    in.reference_length = reference_length;
    in.bond_area = bond_area;
    in.opening = {sigma * reference_length / m.normal_modulus, tau * reference_length / m.shear_modulus, 0.0};
    BondHistory h;
    const BondOutput out = BrittleBpmLaw::evaluate(m, in, h);
    CHECK(h.stage == bondElastic);
    CHECK(out.force_on_i.x == Approx(sigma * bond_area).epsilon(1e-12));
    CHECK(out.force_on_i.y == Approx(tau * bond_area).epsilon(1e-12));
    CHECK(out.fracture_dissipation == 0.0);
    // Past the cut-off: broken, no force, and the strain energy it held dissipated.
    in.opening.x *= 1.2;
    const double stored =
        0.5 * bond_area / reference_length *
        (m.normal_modulus * in.opening.x * in.opening.x + m.shear_modulus * in.opening.y * in.opening.y);
    const BondOutput broken = BrittleBpmLaw::evaluate(m, in, h);
    CHECK(h.stage == bondBroken);
    CHECK(h.damage == 1.0);
    CHECK(norm(broken.force_on_i) == 0.0);
    CHECK(broken.strain_energy == 0.0);
    CHECK(broken.fracture_dissipation == Approx(stored).epsilon(1e-12));
    CHECK(norm(BrittleBpmLaw::evaluate(m, in, h).force_on_i) == 0.0);  // and stays broken
}

TEST_CASE("bond laws are selected by keyword and read their own sub-dictionary", "[dem][registry]")
{
    const Dictionary bond = Dictionary::parse(R"(
        model brittleBPM;
        voronoiQNSC { E 46e9; poissonRatio 0.25; tensileStrength 28e6; cohesion 42e6;
                      frictionCoefficient 0.8; GI 10; GII 10; }
        brittleBPM  { E 40e9; poissonRatio 0.2; tensileStrength 20e6; cohesion 30e6; frictionCoefficient 0.5; }
    )",
                                              "rockProperties");
    const std::shared_ptr<BondLawModel> law = bondLaws().select(bond, "model");
    CHECK(std::string(law->type()) == "brittleBPM");
    const auto& b = dynamic_cast<const BrittleBpmBondLaw&>(*law).parameters();
    CHECK(b.youngs_modulus == 40e9);
    CHECK(b.tensile_strength == 20e6);
    CHECK(law->shearModulus() == Approx(40e9 / 2.4).epsilon(1e-15));
    // An entry the law does not know is refused at its line, naming the known ones.
    const Dictionary typo = Dictionary::parse(
        "model brittleBPM;\nbrittleBPM { E 40e9; poissonRatio 0.2; tensileStrength 20e6; cohesion 30e6;\n"
        "frictionCoefficient 0.5; GI 10; }\n",
        "rockProperties");
    CHECK_THROWS_WITH(bondLaws().select(typo, "model"), Catch::Contains("rockProperties:3") &&
                                                            Catch::Contains("unknown entry 'GI'") &&
                                                            Catch::Contains("frictionCoefficient"));
    // The law's sub-dictionary is required.
    const Dictionary missing = Dictionary::parse("model voronoiQNSC;\n", "rockProperties");
    CHECK_THROWS_WITH(bondLaws().select(missing, "model"), Catch::Contains("voronoiQNSC"));
    // An unknown model: the line of the keyword, the known names.
    const Dictionary unknown = Dictionary::parse("model beam;\n", "rockProperties");
    CHECK_THROWS_WITH(bondLaws().select(unknown, "model"),
                      Catch::Contains("rockProperties:1") && Catch::Contains("voronoiQNSC, brittleBPM"));
}
