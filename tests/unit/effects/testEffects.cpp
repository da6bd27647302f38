// Each model effect does what its page says, against the closed form: the series elements of
// the recorded displacement, the parameter factors, the crumbled layer next to the plates and
// the Weibull scatter of the bond strengths (mean 1, reproducible by its seed).
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>

#include "../dem/boxMeshes.hpp"
#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/selector.hpp"
#include "dem/demModel.hpp"
#include "dem/voronoiQnscBond.hpp"
#include "effects/modelEffect.hpp"

using namespace rockfrac;

namespace {

std::unique_ptr<ModelEffect> effect(const std::string& name, const std::string& coefficients)
{
    const Dictionary d = Dictionary::parse(name + " { " + coefficients + " }\n", "modelEffects");
    return effectSelector().make(name, d.subDict(name));
}

constexpr double cell = 5e-3;

DemModel boxModel(int n)
{
    DemParameters p;
    p.bond_law = std::make_shared<VoronoiQnscBondLaw>(VoronoiQnscBondLaw::Parameters{});
    return DemModel(test::boxBlockMesh(n, n, n, {cell, cell, cell}, 5e-4), p);
}

}  // namespace

TEST_CASE("machineCompliance: the recorded displacement is the approach plus F times the compliance",
          "[effects]")
{
    const auto e = effect("machineCompliance", "compliance 2e-9;");
    CHECK(e->recordedDisplacement(1e-4, 0.0) == 1e-4);
    CHECK(e->recordedDisplacement(1e-4, 5000.0) == Approx(1e-4 + 1e-5).epsilon(1e-14));
    CHECK_THROWS_AS(effect("machineCompliance", "compliance 2e-6;"), UserError);  // above 1e-6 m/N
}

TEST_CASE("seatingOffset: a toe that closes depth (1 - exp(-F / closureForce))", "[effects]")
{
    const auto e = effect("seatingOffset", "depth 5e-5; closureForce 1000;");
    CHECK(e->recordedDisplacement(2e-4, 0.0) == 2e-4);
    CHECK(e->recordedDisplacement(2e-4, -10.0) == 2e-4);
    CHECK(e->recordedDisplacement(2e-4, 1000.0) ==
          Approx(2e-4 + 5e-5 * (1.0 - std::exp(-1.0))).epsilon(1e-14));
    CHECK(e->recordedDisplacement(2e-4, 1e6) == Approx(2e-4 + 5e-5).epsilon(1e-14));
    CHECK(effect("seatingOffset", "depth 0; closureForce 1000;")->recordedDisplacement(2e-4, 500.0) == 2e-4);
}

TEST_CASE("rateDamping and plateFriction multiply their parameter", "[effects]")
{
    DemParameters p;
    p.bond_damping = 0.02;
    p.rock_steel_friction = 0.5;
    effect("rateDamping", "betaFactor 3;")->applyToParameters(p);
    effect("plateFriction", "frictionFactor 0.4;")->applyToParameters(p);
    CHECK(p.bond_damping == Approx(0.06).epsilon(1e-15));
    CHECK(p.rock_steel_friction == Approx(0.2).epsilon(1e-15));
    CHECK(p.rock_rock_friction == DemParameters{}.rock_rock_friction);  // nothing else
}

TEST_CASE("contactCrumbling weakens the interfaces within its depth of a plate, and only those", "[effects]")
{
    // 4 x 4 x 4 cubes between plates at z = 0 and z = 4 h; depth 0.6 h reaches the vertical
    // faces of the bottom and top layers (centres 0.5 h from a plate), not the horizontal
    // faces (h away): 2 x (3 x 4 + 4 x 3) = 48 of the 144 interfaces.
    DemModel model = boxModel(4);
    REQUIRE(model.interfaces().size() == 144);
    effect("contactCrumbling", "strengthLoss 0.3; depth 3e-3;")
        ->applyToModel(model, EffectContext{0.0, 4 * cell});
    const InterfaceArrays& f = model.interfaces();
    REQUIRE(f.strength_scale.size() == 144);
    int weakened = 0;
    for (int k = 0; k < f.size(); ++k) {
        if (f.strength_scale[k] == 1.0) continue;
        CHECK(f.strength_scale[k] == Approx(0.7).epsilon(1e-15));
        ++weakened;
    }
    CHECK(weakened == 48);
    DemModel untouched = boxModel(4);
    effect("contactCrumbling", "strengthLoss 0; depth 3e-3;")
        ->applyToModel(untouched, EffectContext{0.0, 4 * cell});
    CHECK(untouched.interfaces().strength_scale.empty());
}

TEST_CASE("bondStrengthScatter: Weibull factors of mean 1, the same for the same seed", "[effects]")
{
    // Equal interface areas: the factor is W^(1/m) / Gamma(1 + 1/m), W ~ Exp(1), whose mean is 1
    // and whose coefficient of variation is sqrt(Gamma(1 + 2/m) / Gamma(1 + 1/m)^2 - 1).
    const double inv_m = 0.1;
    DemModel a = boxModel(8), b = boxModel(8), c = boxModel(8);
    effect("bondStrengthScatter", "inverseModulus 0.1; seed 3;")->applyToModel(a, {});
    effect("bondStrengthScatter", "inverseModulus 0.1; seed 3;")->applyToModel(b, {});
    effect("bondStrengthScatter", "inverseModulus 0.1; seed 4;")->applyToModel(c, {});
    const std::vector<double>& s = a.interfaces().strength_scale;
    const int n = static_cast<int>(s.size());
    REQUIRE(n == 3 * 7 * 64);
    double mean = 0.0, square = 0.0;
    for (double x : s) {
        mean += x / n;
        square += x * x / n;
    }
    const double cv = std::sqrt(std::tgamma(1 + 2 * inv_m) / std::pow(std::tgamma(1 + inv_m), 2) - 1.0);
    const double sd = std::sqrt(square - mean * mean);
    INFO("mean " << mean << " sd " << sd << " expected cv " << cv);
    CHECK(std::fabs(mean - 1.0) < 4.0 * cv / std::sqrt(double(n)));
    CHECK(sd == Approx(cv).epsilon(0.15));
    CHECK(b.interfaces().strength_scale == s);
    CHECK(c.interfaces().strength_scale != s);
    DemModel off = boxModel(4);
    effect("bondStrengthScatter", "inverseModulus 0; seed 3;")->applyToModel(off, {});
    CHECK(off.interfaces().strength_scale.empty());
}
