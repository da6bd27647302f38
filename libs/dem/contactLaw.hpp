#pragma once
// The contact law interface: what one contact point between a cell and another cell or
// a wall sees and returns (contactKernels.hpp applies a law to every pair and wall item).
//
// A law is a struct with one static RF_HD function
//     ContactOutput evaluate(const ContactConstants&, const ContactInput&, Vec3& tangential_spring)
// A new law is a new file pair (the struct and its ContactLawModel, see
// hertzMindlinContact.*) plus one line in contactLawTable.cpp.
#include <memory>
#include <string>
#include <vector>

#include "core/parallel.hpp"
#include "core/vec3.hpp"

namespace rockfrac {

// Constants of one material pairing (rock–rock or rock–steel).
struct ContactConstants {
    double effective_modulus = 0.0;        // E*: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 [Pa]
    double effective_shear_modulus = 0.0;  // G*: 1/G* = (2-nu1)/G1 + (2-nu2)/G2 [Pa]
    double friction = 0.0;                 // Coulomb coefficient mu [-]
    double restitution_beta = 0.0;         // beta_e = ln e / sqrt(ln^2 e + pi^2) (< 0) [-]
};

struct ContactInput {
    double overlap = 0.0;           // delta > 0 [m]
    Vec3 normal;                    // unit, from body A (or the wall) to body B (the cell)
    Vec3 relative_velocity;         // velocity of B minus that of A at the contact point [m/s]
    double effective_radius = 0.0;  // R* [m]
    double effective_mass = 0.0;    // m* [kg]
    double dt = 0.0;                // time step, for the tangential spring increment [s]
};

struct ContactOutput {
    Vec3 force_on_b;                    // A receives the opposite force [N]
    double elastic_energy = 0.0;        // stored in the normal and tangential springs [J]
    double damping_power = 0.0;         // viscous dissipation rate, >= 0 [W]
    double friction_dissipation = 0.0;  // energy lost by sliding in this call [J]
    // Normal stiffness dF/d(overlap) at this overlap, what the step check adds to the
    // cell's bonds (DemModel::step, docs/theory-dem.md §Integration) [N/m].
    double stiffness = 0.0;
};

// One point of a contact patch: the sphere of one core vertex against a wall
// (docs/theory-dem.md §7). Every point carries a normal spring of its own.
struct PatchPoint {
    Vec3 point;              // contact point (middle of the overlap) [m]
    Vec3 normal;             // unit, from the wall into the cell
    Vec3 relative_velocity;  // cell minus wall at the point [m/s]
    double overlap = 0.0;    // > 0 [m]
    // Torque on the cell per newton of the point's normal force besides that of the force
    // at the point: from an overlap that depends on the cell's orientation itself (the
    // angle weight of a ridge–edge pair, see wallPatch) [m].
    Vec3 torque_per_force;
};

// Most points of one patch; the kernel keeps the deepest ones beyond that.
constexpr int max_patch_points = 64;

// A patch of points of one cell against one wall, sharing one tangential spring.
struct ContactPatchInput {
    const PatchPoint* points = nullptr;
    int n_points = 0;
    Vec3 centre;                    // the cell's centroid: torques are about it [m]
    double effective_radius = 0.0;  // R* of every point [m]
    double effective_mass = 0.0;    // m* of the cell [kg]
    double dt = 0.0;
};

struct ContactPatchOutput {
    Vec3 force;   // on the cell [N]
    Vec3 torque;  // on the cell about centre [N m]
    double elastic_energy = 0.0;
    double damping_power = 0.0;
    double friction_dissipation = 0.0;
    double stiffness = 0.0;  // sum of the points' normal stiffnesses [N/m] (ContactOutput)
};

// Contact status of a pair or wall item after a kernel call.
enum ContactStatus : unsigned char { contactNone = 0, contactActive = 1, contactCoresIntersect = 2 };

struct PairKernelArgs;
struct WallKernelArgs;

// The host side of a contact law: the object `contact { model <keyword>; }` selects. The
// pairings' friction and restitution (contact/rockRock, contact/rockSteel) and the cell
// contact's form (contact/cellContact point | patch) are the same for every law (they make
// the ContactConstants and the kernels' arguments); a law with coefficients of its own
// reads them from contact/<keyword>.
class ContactLawModel {
public:
    virtual ~ContactLawModel() = default;
    virtual const char* type() const = 0;
    // The law over every cell–cell pair and every cell–wall item (OpenMP, deterministic).
    virtual void runPairs(const PairKernelArgs& args) const = 0;
    virtual void runWalls(const WallKernelArgs& args) const = 0;
};

class Dictionary;
template <class Base, class... Args>
class Selector;

// The table of contact laws (contactLawTable.cpp).
const Selector<ContactLawModel>& contactLaws();
std::vector<std::string> contactLawNames();
// Hertz–Mindlin, the paper's (what DemParameters starts from).
std::shared_ptr<const ContactLawModel> defaultContactLaw();

}  // namespace rockfrac
