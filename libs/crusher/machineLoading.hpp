#pragma once
// constant/loading of a crusher case: the `machine`, `feed`, `choke` and
// `destructor` sections (docs/user-guide-crusher.md lists every entry).
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/vec3.hpp"
#include "crusher/mantleSpin.hpp"
#include "geometry/crusherGeometry.hpp"

namespace rockfrac {

class Dictionary;

struct MachineSpec {
    std::filesystem::path mantle_stl, concave_stl;  // meshCrusher's surfaces
    CrusherKinematics kinematics;                   // from constant/crusherKinematics
    double discharge_level = 0.0;                   // z of the mantle's lower rim [m]
    double closed_side_setting = 0.0;               // [m] (for P80 vs CSS)
};

// A size class of the feed: the rocks of a sieve size above the previous class's up_to and
// at most its own are copies of its template rock.
struct FeedClass {
    std::string name;                 // the keyword under feed/classes; "rock" for feed/rock
    std::filesystem::path rock_case;  // a voronoiMesh case (constant/voronoiMesh)
    double up_to = 0.0;               // [m] the largest sieve size of the class
};

// Rocks copied from a template of their size class, sizes uniform in [size_min, size_max]
// (sieve size), inserted at mass_rate into a cylindrical shell above the chamber.
struct FeedSpec {
    // Sorted by up_to, the last up_to >= size_max; feed/rock gives one class (up to size_max).
    // Empty (a spec built in code): one class, the factory's one template.
    std::vector<FeedClass> classes;
    double size_min = 0.0, size_max = 0.0;
    double mass_rate = 0.0;   // [kg/s]
    double total_mass = 0.0;  // stop feeding after this mass [kg] (0: no limit)
    double z_min = 0.0, z_max = 0.0, r_min = 0.0, r_max = 0.0;  // feed region [m]
    Vec3 velocity;                                              // of the inserted rocks [m/s]
    int attempts = 20;                                          // placement attempts per rock
    double liner_clearance = 0.0;  // least distance of a placed rock from the liners [m]
    double interval = 0.0;         // time between feed events [s]
    std::uint64_t seed = 1;
};

struct ChokeSpec {
    bool enabled = false;
    double level = 0.0;     // z of the plane (normal +z) [m]
    double duration = 0.0;  // it is lowered away at this time [s]
};

struct DestructorSpec {
    double below = 0.0;  // cells whose centroid is below this z leave with their fragment [m]
    long interval = 50;  // steps between checks
};

struct MachineLoading {
    MachineSpec machine;
    FeedSpec feed;
    ChokeSpec choke;
    DestructorSpec destructor;
    Vec3 gravity;
    MantleSpinSpec spin;  // machine/spin: fixed (default) or free with inertia and bearing drag
};

// The size class of a drawn sieve size: the first whose up_to is >= size (the last one
// for a size above every up_to; 0 without classes).
int feedClassOf(const FeedSpec& feed, double size);
// The sieve sizes class i takes: [first, second] within sizeRange.
std::pair<double, double> feedClassSizes(const FeedSpec& feed, int i);
// Reads and checks constant/loading's `feed` section (rock paths relative to caseDir): exactly
// one of `rock` or `classes`, classes sorted by upTo, each one taking some rocks, the last
// upTo >= sizeRange max, every template rock meshed. UserError naming the file and entry.
FeedSpec readFeedSpec(const Dictionary& feed, const std::filesystem::path& caseDir);

// True when constant/loading describes a machine (has a `machine` section).
bool isMachineLoading(const Dictionary& loading);
// Reads and checks every entry; paths are relative to caseDir. UserError naming the entry.
MachineLoading readMachineLoading(const Dictionary& loading, const std::filesystem::path& caseDir);
// The top-level entries of a crusher's constant/loading that readMachineLoading reads.
const std::vector<std::string>& machineLoadingEntries();

// The entries of system/crusherPostDict (read by crusherPost).
inline const std::vector<std::string>& crusherPostDictEntries()
{
    static const std::vector<std::string> entries = {"steadyStart", "pistonArea"};
    return entries;
}

}  // namespace rockfrac
