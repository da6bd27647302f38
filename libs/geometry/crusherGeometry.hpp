#pragma once
// Cone crusher geometry and mantle kinematics (docs/theory-fragments.md, "Crusher").
//
// The mantle (the gyrating cone) and the concave (the fixed bowl liner) are
// surfaces of revolution about the z axis, given by profile polylines (r, z) at
// the mean mantle position. The mantle gyrates without spin: its axis is tilted by
// the eccentric angle alpha about a pivot point on the z axis, towards a direction
// that precesses about z at the eccentric speed. At time t the closed side (where
// the lower mantle comes closest to the concave) is at azimuth phase + Omega t.
//
//   ChamberDesign d = designChamber(mantle, concave, css, throw, pivotHeight, rpm, ...);
//   MantlePose p = mantlePose(d.kinematics, t);   // drives a DEM wall (WallMotion)
//   x_world = p.translation + p.rotation * x_mean;  v(x) = p.velocity + p.angular_velocity x (x -
//   p.translation)
#include <string>
#include <vector>

#include "core/vec3.hpp"
#include "geometry/triSurface.hpp"

namespace rockfrac {

struct ProfilePoint {
    double r = 0.0;  // distance from the z axis [m]
    double z = 0.0;  // height [m]
};
using Profile = std::vector<ProfilePoint>;

// Which way the triangles of a surface of revolution face (their normals):
// away from the axis (a mantle, into the chamber) or towards it (a concave).
enum class SurfaceFacing { awayFromAxis, towardsAxis };

// Surface of revolution of `profile` about z with nSegments around. A profile
// point with r = 0 becomes a single vertex on the axis (the surface is closed
// there, e.g. the top of the mantle); a profile end with r > 0 stays an open rim.
// Vertices: one per axis point, nSegments per other point; triangles: nSegments per
// profile segment touching the axis, 2 nSegments per other segment.
// UserError for fewer than 2 points, nSegments < 3, negative r, or a segment on the axis.
TriSurface revolveProfile(const Profile& profile, int nSegments, SurfaceFacing facing);

// The same surface in well-shaped triangles (what meshCrusher writes): every ring has
// n(r) = max(3, min(nSegments, ceil(2 nSegments r / r_max))) points (nSegments on the
// outer half of the radii, the circumferential spacing h0/2 = pi r_max / nSegments
// inside it, so no fan of slivers closes on the axis), each profile segment is split
// into rows 0.87 x the local circumferential spacing apart, every other ring is turned by
// half its spacing, and neighbouring rings are zipped by angle. Triangles are
// near-equilateral instead of the 0.45 m x 1-4 degree strips of revolveProfile.
// The same UserErrors as revolveProfile.
TriSurface revolveProfileShaped(const Profile& profile, int nSegments, SurfaceFacing facing);

// Mantle kinematics: gyration without spin about `pivot` (on the z axis).
struct CrusherKinematics {
    Vec3 pivot;                    // [m]
    double eccentric_angle = 0.0;  // alpha, tilt of the mantle axis [rad]
    double eccentric_speed = 0.0;  // Omega, precession rate [rad/s]
    double phase = 0.0;            // azimuth of the closed side at t = 0 [rad]

    double period() const;                     // 2 pi / Omega [s]
    double closedSideAzimuth(double t) const;  // phase + Omega t [rad]
};

// Rigid pose of the mantle at time t relative to its mean (untilted) position, in the
// form of DemModel's WallMotion: x = translation + rotation x_mean; rotation_vector
// is the axis-angle of `rotation` (quatFromRotationVector makes the DEM quaternion).
// With spin (free spin, libs/crusher/mantleSpin.hpp) the mantle is first turned by the spin
// angle psi about the z axis (its own axis in the mean position), then gyrated:
// rotation = R_gyration Rz(psi); the translation is unchanged and the angular velocity
// gains psi' times the tilted axis.
struct MantlePose {
    Mat3 rotation;          // R_gyration Rz(spin_angle)
    Vec3 rotation_vector;   // axis-angle of R_gyration (the spin is spin_angle about z, applied first)
    double spin_angle = 0;  // [rad]
    Vec3 translation;       // pivot - R_gyration * pivot [m]
    Vec3 velocity;          // of the point `translation` [m/s]
    Vec3 angular_velocity;  // world frame [rad/s] = Omega (z - R_gyration z) + spin_rate R_gyration z
};
MantlePose mantlePose(const CrusherKinematics& k, double t);
MantlePose mantlePose(const CrusherKinematics& k, double t, double spin_angle, double spin_rate);

// The mantle profile as it lies in the meridian half-plane of the closed side
// (angle = +alpha: points below the pivot move out) or of the open side (-alpha).
// Exact: the tilt plane contains the tilted axis, so it cuts the mantle along its
// meridian profile, rotated in-plane about the pivot.
Profile tiltInMeridian(const Profile& mantle, double pivotZ, double angle);

// Smallest distance between two profile polylines in the (r, z) plane (0 if they
// cross); `atZ` receives the height of the nearest point on `a`.
double profileDistance(const Profile& a, const Profile& b, double* atZ = nullptr);

struct CrusherChamber {
    Profile mantle;   // at the mean position
    Profile concave;  // as placed (setting applied)
};

struct ChamberGaps {
    double closed = 0.0, open = 0.0;      // closed and open side settings [m]
    double closed_z = 0.0, open_z = 0.0;  // where they are measured (on the mantle) [m]
    // Feed opening: distance from the concave's upper rim to the mantle, closed and open side [m].
    double feed_closed = 0.0, feed_open = 0.0;
};
// The gaps of the nutating mantle (the same at every t for an ideal gyration).
ChamberGaps chamberGaps(const CrusherChamber& chamber, const CrusherKinematics& k);

// How `throw` fixes the eccentric angle:
//  settingDifference: OSS - CSS = throw exactly (the industry's definition of throw);
//  axisOffset: the mantle axis moves throw/2 sideways at the discharge level
//              (sin alpha = throw / (2 (z_pivot - z_discharge))), the classic
//              approximation; OSS - CSS then differs from throw for inclined liners.
enum class ThrowDefinition { settingDifference, axisOffset };

struct ChamberSpec {
    Profile mantle, concave;           // concave: the shape; it is moved vertically to set the CSS
    double closed_side_setting = 0.0;  // [m]
    double eccentric_throw = 0.0;      // [m]
    double pivot_height = 0.0;         // z of the pivot [m]
    double eccentric_speed_rpm = 0.0;  // [1/min]
    double phase = 0.0;                // [rad]
    ThrowDefinition throw_definition = ThrowDefinition::settingDifference;
};

// The top-level entries of system/meshCrusherDict (meshCrusher reads ChamberSpec and
// nSegments from it; mantle and concave each hold a profile).
inline const std::vector<std::string>& meshCrusherDictEntries()
{
    static const std::vector<std::string> entries = {
        "mantle",         "concave",           "closedSideSetting", "throw",    "pivotHeight",
        "eccentricSpeed", "closedSideAzimuth", "throwDefinition",   "nSegments"};
    return entries;
}

struct ChamberDesign {
    CrusherChamber chamber;
    CrusherKinematics kinematics;
    double concave_shift = 0.0;      // vertical move of the concave that sets the CSS [m]
    double discharge_level = 0.0;    // z of the mantle's lower rim [m]
    double axis_offset_angle = 0.0;  // the axisOffset angle, for comparison [rad]
    ChamberGaps gaps;
};
// Place the concave (vertical shift) so the closed side setting is met and choose
// alpha by `throw_definition`. UserError naming the entry when the profiles cannot
// give the requested setting (they cross, or never come that close).
ChamberDesign designChamber(const ChamberSpec& spec);

}  // namespace rockfrac
