#pragma once
// constant/loading of a crusher case: the `machine`, `feed`, `choke` and
// `destructor` sections (docs/user-guide-crusher.md lists every entry).
#include <cstdint>
#include <filesystem>
#include <string>
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

// Rocks copied from one template, sizes uniform in [size_min, size_max] (sieve size),
// inserted at mass_rate into a cylindrical shell above the chamber.
struct FeedSpec {
    std::filesystem::path rock_case;  // a voronoiMesh case (constant/voronoiMesh)
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
