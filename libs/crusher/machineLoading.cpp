#include "crusher/machineLoading.hpp"

#include <algorithm>
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

// The template rock of a class, which must be meshed; `entry` names it in messages.
fs::path meshedRock(const Dictionary& d, const std::string& key, const std::string& entry,
                    const fs::path& caseDir)
{
    const fs::path rock = casePath(caseDir, d.get<std::string>(key));
    if (!fs::exists(rock / "constant/voronoiMesh/meshInfo"))
        throw UserError(d.location(key).str() + ": " + entry + ": " +
                        (rock / "constant/voronoiMesh").string() +
                        " is missing; mesh the feed rock (meshRock, voronoiMesh) first");
    return rock;
}

// feed/classes: one sub-dictionary { rock "<case>"; upTo <m>; } per class, by increasing upTo.
std::vector<FeedClass> readFeedClasses(const Dictionary& feed, const fs::path& caseDir, double size_min,
                                       double size_max)
{
    const Dictionary& d = feed.subDict("classes");
    std::vector<FeedClass> classes;
    for (const Entry& e : d.entries()) {
        const std::string entry = "feed/classes/" + e.keyword;
        if (!e.isDict())
            throw UserError(e.keywordLocation.str() + ": " + entry +
                            " must be a sub-dictionary { rock \"<case>\"; upTo <m>; }");
        checkKnownEntries(*e.dict, {"rock", "upTo"});
        FeedClass c;
        c.name = e.keyword;
        c.rock_case = meshedRock(*e.dict, "rock", entry + "/rock", caseDir);
        c.up_to = e.dict->getScalar("upTo", Bounds::positive());
        const std::string at =
            e.dict->location("upTo").str() + ": " + entry + "/upTo " + formatNumber(c.up_to);
        if (!classes.empty() && !(c.up_to > classes.back().up_to))
            throw UserError(at + " is not above the previous class's (" + classes.back().name + ", " +
                            formatNumber(classes.back().up_to) + "); list the classes by increasing upTo");
        if (!classes.empty() && !(classes.back().up_to < size_max))
            throw UserError(at +
                            ": no rock would be of this class, the previous class already takes every size "
                            "up to sizeRange max " +
                            formatNumber(size_max) + "; remove it or lower the previous upTo");
        if (c.up_to < size_min)
            throw UserError(at + " is below sizeRange min " + formatNumber(size_min) +
                            ": no rock would be of this class; remove it or raise its upTo");
        classes.push_back(std::move(c));
    }
    if (classes.empty())
        throw UserError(feed.location("classes").str() +
                        ": feed/classes has no class; give one { rock \"<case>\"; upTo <m>; } "
                        "per size class");
    const FeedClass& last = classes.back();
    if (last.up_to < size_max)
        throw UserError(d.subDict(last.name).location("upTo").str() + ": feed/classes/" + last.name +
                        "/upTo " + formatNumber(last.up_to) + " is below sizeRange max " +
                        formatNumber(size_max) +
                        ": the largest rocks would have no class; raise it to at least the max");
    return classes;
}

}  // namespace

int feedClassOf(const FeedSpec& feed, double size)
{
    const int n = static_cast<int>(feed.classes.size());
    for (int i = 0; i + 1 < n; ++i)
        if (size <= feed.classes[i].up_to) return i;
    return std::max(0, n - 1);
}

std::pair<double, double> feedClassSizes(const FeedSpec& feed, int i)
{
    if (feed.classes.empty()) return {feed.size_min, feed.size_max};
    const double lo = i == 0 ? feed.size_min : std::max(feed.size_min, feed.classes[i - 1].up_to);
    const double hi = i + 1 == static_cast<int>(feed.classes.size())
                          ? feed.size_max
                          : std::min(feed.size_max, feed.classes[i].up_to);
    return {lo, hi};
}

FeedSpec readFeedSpec(const Dictionary& d, const fs::path& caseDir)
{
    checkKnownEntries(d, {"rock", "classes", "sizeRange", "massRate", "totalMass", "region", "velocity",
                          "attempts", "linerClearance", "interval", "seed"});
    checkKnownSubEntries(d, "region", {"zRange", "rRange"});
    FeedSpec f;
    std::tie(f.size_min, f.size_max) = range(d, "sizeRange");
    if (!(f.size_min > 0)) throw UserError(d.fileName() + ": feed/sizeRange must be positive");
    // One template (rock) or one per size class (classes), never both.
    if (d.found("rock") && d.found("classes"))
        throw UserError(d.location("classes").str() +
                        ": feed has both rock and classes; give either rock (one template for every size) or "
                        "classes (one template per size class)");
    if (d.found("rock")) {
        f.classes.push_back({"rock", meshedRock(d, "rock", "feed/rock", caseDir), f.size_max});
    } else if (d.found("classes")) {
        if (!d.isDict("classes"))
            throw UserError(
                d.location("classes").str() +
                ": feed/classes must be a sub-dictionary of classes { rock \"<case>\"; upTo <m>; }");
        f.classes = readFeedClasses(d, caseDir, f.size_min, f.size_max);
    } else {
        throw UserError(d.fileName() +
                        ": feed has neither rock nor classes; give rock \"<case>\" (one template "
                        "rock) or classes { <name> { rock \"<case>\"; upTo <m>; } ... }");
    }
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
    return f;
}

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
    l.feed = readFeedSpec(d.subDict("feed"), caseDir);
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
