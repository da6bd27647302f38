#include "demCase/demCase.hpp"

#include <cmath>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/knownEntries.hpp"
#include "core/selector.hpp"
#include "dem/bondLawModel.hpp"
#include "dem/contactLaw.hpp"

namespace rockfrac {

// ---- Parameters ------------------------------------------------------------------

namespace {

// The names of a family's models followed by `others`: the entries a dictionary selecting
// one of them may hold (each model's coefficients in its own sub-dictionary).
std::vector<std::string> withModelNames(std::vector<std::string> others,
                                        const std::vector<std::string>& models)
{
    others.insert(others.end(), models.begin(), models.end());
    return others;
}

void readBond(const Dictionary& bond, DemParameters& p)
{
    requireKnownEntries(bond, withModelNames({"model", "damping", "sizeEffect"}, bondLawNames()),
                        "a bond law's coefficients go in its own sub-dictionary, bond/<model> { ... }; "
                        "docs/models/bond/");
    p.bond_law = bondLaws().select(bond, "model");  // the errors name the file and line
    if (bond.found("sizeEffect")) {
        // Optional: the Weibull size effect of the bond strength (off when absent).
        static const Dimensions area = Dimensions::fromUnits("m^2");
        const Dictionary& size = bond.subDict("sizeEffect");
        requireKnownEntries(size, {"weibullModulus", "referenceArea"});
        p.bond_size_effect_modulus = size.getScalar("weibullModulus", Bounds::positive());
        p.bond_size_effect_reference_area = size.getScalar("referenceArea", Bounds::positive(), &area);
    }
    const Dictionary& damping = bond.subDict("damping");
    requireKnownEntries(damping, {"reading", "beta"});
    p.damping_reading = dampingReadingFromName(damping.getWord("reading", {"absolute", "criticalFraction"}));
    p.bond_damping = damping.getScalar("beta", Bounds::nonNegative());
}

void readContact(const Dictionary& contact, DemParameters& p)
{
    requireKnownEntries(contact,
                        withModelNames({"model", "cellContact", "rockRock", "rockSteel"}, contactLawNames()));
    p.contact_law = contactLaws().select(contact, "model");
    // Optional: how two cells touch (point: the paper's single Hertz point; patch: feature pairs).
    p.cell_contact_patch =
        contact.found("cellContact") && contact.getWord("cellContact", {"point", "patch"}) == "patch";
    const Dictionary& rockRock = contact.subDict("rockRock");
    requireKnownEntries(rockRock, {"friction", "restitution"});
    p.rock_rock_friction = rockRock.getScalar("friction", Bounds::nonNegative());
    p.rock_rock_restitution = rockRock.getScalar("restitution", Bounds::open(0, 1.000001));
    const Dictionary& rockSteel = contact.subDict("rockSteel");
    requireKnownEntries(rockSteel, {"friction", "restitution"});
    p.rock_steel_friction = rockSteel.getScalar("friction", Bounds::nonNegative());
    p.rock_steel_restitution = rockSteel.getScalar("restitution", Bounds::open(0, 1.000001));
}

}  // namespace

const std::vector<std::string>& demRockPropertiesEntries()
{
    static const std::vector<std::string> entries = {"rock", "steel", "bond", "contact"};
    return entries;
}

DemParameters readDemParameters(const Dictionary& d)
{
    static const Dimensions pascal = Dimensions::fromUnits("Pa");
    static const Dimensions density = Dimensions::fromUnits("kg/m^3");

    checkKnownEntries(d, demRockPropertiesEntries());
    DemParameters p;
    const Dictionary& rock = d.subDict("rock");
    requireKnownEntries(rock, {"E", "poissonRatio", "density"});
    p.rock_youngs_modulus = rock.getScalar("E", Bounds::positive(), &pascal);
    p.rock_poisson_ratio = rock.getScalar("poissonRatio", Bounds::closedOpen(0, 0.5));
    p.rock_density = rock.getScalar("density", Bounds::positive(), &density);

    const Dictionary& steel = d.subDict("steel");
    requireKnownEntries(steel, {"E", "poissonRatio"});
    p.steel_youngs_modulus = steel.getScalar("E", Bounds::positive(), &pascal);
    p.steel_poisson_ratio = steel.getScalar("poissonRatio", Bounds::closedOpen(0, 0.5));

    readBond(d.subDict("bond"), p);
    readContact(d.subDict("contact"), p);
    p.validate();
    return p;
}

const std::vector<std::string>& demLoadingEntries()
{
    static const std::vector<std::string> entries = {"plates", "gravity", "settling", "stop"};
    return entries;
}

Loading readLoading(const Dictionary& d)
{
    checkKnownEntries(d, demLoadingEntries());
    checkKnownSubEntries(d, "plates", {"lower", "upper", "startGap"});
    checkKnownSubEntries(d, "settling", {"duration"});
    checkKnownSubEntries(d, "stop", {"forceDropFraction", "maxDisplacement", "minPeakForce"});
    Loading l;
    const Dictionary& plates = d.subDict("plates");
    auto plate = [&](const std::string& name) {
        const Dictionary& p = plates.subDict(name);
        checkKnownEntries(p, {"normal", "velocity"});
        PlateSpec s;
        s.normal = normalised(p.get<Vec3>("normal"));
        s.velocity = p.get<Vec3>("velocity");
        if (norm(s.normal) == 0)
            throw UserError(p.fileName() + ": plates/" + name + "/normal must not be zero");
        return s;
    };
    l.lower = plate("lower");
    l.upper = plate("upper");
    if (!(l.lower.normal.z > 0.99 && l.upper.normal.z < -0.99))
        throw UserError(d.fileName() +
                        ": plates must be horizontal: lower normal (0 0 1), upper normal (0 0 -1)");
    l.startGap = plates.getScalarOrDefault("startGap", 0.0, Bounds::nonNegative());
    l.gravity = d.getOrDefault<Vec3>("gravity", Vec3{0, 0, -9.81});
    if (d.found("settling"))
        l.settlingTime = d.subDict("settling").getScalar("duration", Bounds::nonNegative());
    if (d.found("stop")) {
        const Dictionary& stop = d.subDict("stop");
        l.stopForceFraction = stop.getScalarOrDefault("forceDropFraction", 0.0, Bounds::closedOpen(0, 1));
        l.stopDisplacement = stop.getScalarOrDefault("maxDisplacement", 0.0, Bounds::nonNegative());
        l.minPeakForce = stop.getScalarOrDefault("minPeakForce", 0.0, Bounds::nonNegative());
    }
    const double approachSpeed = dot(l.lower.velocity - l.upper.velocity, Vec3{0, 0, 1});
    if ((l.stopForceFraction > 0 || l.stopDisplacement > 0) && !(approachSpeed > 0))
        throw UserError(
            d.fileName() +
            ": the plates do not approach each other (upper velocity z must be below the lower "
            "one), so the stop criterion can never be met; give the upper plate a downward velocity");
    return l;
}

}  // namespace rockfrac
