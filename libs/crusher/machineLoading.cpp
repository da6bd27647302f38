#include "crusher/machineLoading.hpp"

#include <cmath>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/knownEntries.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

bool isMachineLoading(const Dictionary& loading)
{
    return loading.found("machine");
}

namespace {

std::pair<double, double> range(const Dictionary& d, const std::string& key)
{
    const auto v = d.get<std::vector<double>>(key);
    if (v.size() != 2 || !(v[0] <= v[1]))
        throw UserError(d.fileName() + ": " + key + " must be (min max) with min <= max");
    return {v[0], v[1]};
}

fs::path casePath(const fs::path& caseDir, const std::string& entry)
{
    const fs::path p(entry);
    return p.is_absolute() ? p : caseDir / p;
}

void readMachine(const Dictionary& d, const fs::path& caseDir, MachineSpec& m, MantleSpinSpec& spin)
{
    checkKnownEntries(d, {"mantle", "concave", "kinematics", "spin", "spinInertia", "bearingDamping"});
    m.mantle_stl = casePath(caseDir, d.getOrDefault<std::string>("mantle", "constant/triSurface/mantle.stl"));
    m.concave_stl =
        casePath(caseDir, d.getOrDefault<std::string>("concave", "constant/triSurface/concave.stl"));
    const fs::path kinematics =
        casePath(caseDir, d.getOrDefault<std::string>("kinematics", "constant/crusherKinematics"));
    for (const fs::path& p : {m.mantle_stl, m.concave_stl, kinematics})
        if (!fs::exists(p))
            throw UserError("missing " + p.string() + "; run meshCrusher to make the crusher surfaces");
    // Free spin needs the mantle's inertia about its axis and the bearing drag: no defaults,
    // both depend on the machine (docs/user-guide-crusher.md gives the CH660 estimate).
    spin.free = d.found("spin") && d.getWord("spin", {"fixed", "free"}) == "free";
    if (spin.free) {
        static const Dimensions inertia = Dimensions::fromUnits("kg m^2");
        static const Dimensions torquePerRate = Dimensions::fromUnits("N m s");
        if (!d.found("spinInertia") || !d.found("bearingDamping"))
            throw UserError(d.fileName() +
                            ": machine/spin free needs spinInertia [kg m^2] (the mantle's moment of "
                            "inertia about its axis) and bearingDamping [N m s] (the bearing's drag)");
        spin.inertia = d.getScalar("spinInertia", Bounds::positive(), &inertia);
        spin.bearing_damping = d.getScalar("bearingDamping", Bounds::nonNegative(), &torquePerRate);
    }
    const Dictionary k = Dictionary::readFile(kinematics);
    m.kinematics.pivot = k.get<Vec3>("pivot");
    m.kinematics.eccentric_angle = k.getScalar("eccentricAngle", Bounds::nonNegative());
    m.kinematics.eccentric_speed = k.getScalar("eccentricSpeed", Bounds::nonNegative());
    m.kinematics.phase = k.getScalarOrDefault("closedSideAzimuth", 0.0, Bounds::any());
    m.discharge_level = k.getScalar("dischargeLevel", Bounds::any());
    m.closed_side_setting = k.getScalar("closedSideSetting", Bounds::positive());
    // The spin turns the mantle about the z axis of its mean position (mantlePose), which
    // must then pass through the pivot (meshCrusher writes it so).
    if (spin.free && std::hypot(m.kinematics.pivot.x, m.kinematics.pivot.y) > 1e-12)
        throw UserError(kinematics.string() +
                        ": pivot must lie on the z axis (0 0 z) for machine/spin free: the mantle turns "
                        "about the axis of its mean position");
}

void readFeed(const Dictionary& d, const fs::path& caseDir, FeedSpec& f)
{
    checkKnownEntries(d, {"rock", "sizeRange", "massRate", "totalMass", "region", "velocity", "attempts",
                          "linerClearance", "interval", "seed"});
    checkKnownSubEntries(d, "region", {"zRange", "rRange"});
    f.rock_case = casePath(caseDir, d.get<std::string>("rock"));
    if (!fs::exists(f.rock_case / "constant/voronoiMesh/meshInfo"))
        throw UserError(d.fileName() + ": feed/rock: " + (f.rock_case / "constant/voronoiMesh").string() +
                        " is missing; mesh the feed rock (meshRock, voronoiMesh) first");
    std::tie(f.size_min, f.size_max) = range(d, "sizeRange");
    if (!(f.size_min > 0)) throw UserError(d.fileName() + ": feed/sizeRange must be positive");
    f.mass_rate = d.getScalar("massRate", Bounds::nonNegative());
    f.total_mass = d.getScalarOrDefault("totalMass", 0.0, Bounds::nonNegative());
    const Dictionary& region = d.subDict("region");
    std::tie(f.z_min, f.z_max) = range(region, "zRange");
    std::tie(f.r_min, f.r_max) = range(region, "rRange");
    if (f.r_min < 0) throw UserError(region.fileName() + ": feed/region/rRange must not be negative");
    f.velocity = d.getOrDefault<Vec3>("velocity", Vec3{});
    f.attempts = d.getOrDefault<int>("attempts", 20);
    if (f.attempts < 1) throw UserError(d.fileName() + ": feed/attempts must be at least 1");
    // Every placed rock clears the liners; this adds a margin (e.g. so a rock put into the
    // chamber does not touch the mantle within its first steps).
    f.liner_clearance = d.getScalarOrDefault("linerClearance", 0.0, Bounds::nonNegative());
    f.interval = d.getScalar("interval", Bounds::positive());
    f.seed = static_cast<std::uint64_t>(d.getOrDefault<long>("seed", 1));
}

}  // namespace

const std::vector<std::string>& machineLoadingEntries()
{
    static const std::vector<std::string> entries = {"machine", "feed", "choke", "destructor", "gravity"};
    return entries;
}

MachineLoading readMachineLoading(const Dictionary& d, const fs::path& caseDir)
{
    checkKnownEntries(d, machineLoadingEntries());
    checkKnownSubEntries(d, "choke", {"level", "duration"});
    checkKnownSubEntries(d, "destructor", {"below", "interval"});
    MachineLoading l;
    readMachine(d.subDict("machine"), caseDir, l.machine, l.spin);
    readFeed(d.subDict("feed"), caseDir, l.feed);
    if (d.found("choke")) {
        const Dictionary& c = d.subDict("choke");
        l.choke.enabled = true;
        l.choke.level = c.getScalar("level", Bounds::any());
        l.choke.duration = c.getScalar("duration", Bounds::nonNegative());
    }
    const Dictionary& destructor = d.subDict("destructor");
    l.destructor.below = destructor.getScalar("below", Bounds::any());
    l.destructor.interval = destructor.getOrDefault<long>("interval", 50);
    if (l.destructor.interval < 1) throw UserError(d.fileName() + ": destructor/interval must be >= 1 step");
    if (!(l.destructor.below < l.machine.discharge_level))
        throw UserError(d.fileName() + ": destructor/below must lie below the discharge level " +
                        std::to_string(l.machine.discharge_level) + " m");
    if (!(l.feed.z_min > l.destructor.below))
        throw UserError(d.fileName() + ": feed/region lies below the destructor");
    l.gravity = d.getOrDefault<Vec3>("gravity", Vec3{0, 0, -9.81});
    return l;
}

}  // namespace rockfrac
