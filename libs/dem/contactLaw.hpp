#pragma once
// The contact law interface and the two contact kernels that use it: cell–cell
// pairs (between the dilated cores, GJK narrow phase) and cell–wall items
// (plates and triangulated surfaces).
//
// A law is a struct with one static RF_HD function
//     ContactOutput evaluate(const ContactConstants&, const ContactInput&, Vec3& tangential_spring)
// A new law is a new file (the struct and its two runners, see hertzMindlinContact.*)
// plus one line in contactLawTable.cpp.
#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include "core/parallel.hpp"
#include "core/vec3.hpp"
#include "dem/gjk.hpp"
#include "dem/quat.hpp"

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

// Cell data the contact kernels read.
struct CellContactView {
    const Vec3* position = nullptr;
    const Vec3* velocity = nullptr;
    const Vec3* angular_velocity_world = nullptr;
    const Mat3* rotation = nullptr;
    const double* mass = nullptr;
    const double* dilation_radius = nullptr;
    const double* bounding_radius = nullptr;  // of the dilated core about the centroid
    const int* core_vertex_offset = nullptr;
    const Vec3* core_vertices = nullptr;        // body frame
    const int* core_edge_offset = nullptr;      // entries of core_edges, two per edge
    const unsigned char* core_edges = nullptr;  // vertex index pairs of the core's edges
    const int* core_plane_offset = nullptr;     // entries of core_planes
    const CorePlane* core_planes = nullptr;     // the core's face planes, body frame
};

// Signed distance of a world point x from the surface of cell c's core where x is inside or
// on it (negative inside): the largest signed distance to the core's face planes (the
// nearest facet; planes that are no facet lie outside and never decide). normal receives
// that facet's outward normal (world): the depth's gradient.
RF_HD inline double coreDepthDistance(const CellContactView& cells, int c, const Vec3& x, Vec3& normal)
{
    const Mat3& R = cells.rotation[c];
    const Vec3 local = transposeTimes(R, x - cells.position[c]);
    double largest = -1e300;
    int facet = cells.core_plane_offset[c];
    for (int f = cells.core_plane_offset[c]; f < cells.core_plane_offset[c + 1]; ++f) {
        const double d = dot(cells.core_planes[f].normal(), local) - cells.core_planes[f].offset;
        if (d > largest) {
            largest = d;
            facet = f;
        }
    }
    normal = R * cells.core_planes[facet].normal();
    return largest;
}

RF_HD inline ConvexVertexSet cellCore(const CellContactView& cells, int c)
{
    ConvexVertexSet core;
    core.vertices = cells.core_vertices + cells.core_vertex_offset[c];
    core.n_vertices = cells.core_vertex_offset[c + 1] - cells.core_vertex_offset[c];
    core.position = cells.position[c];
    core.rotation = cells.rotation[c];
    return core;
}

// A pair's separation margin as stored: single precision, never above the double it
// comes from. The margin is a lower bound on the gap between the two cells; rounded up,
// it could skip a pair that touches, rounded down it only skips less often.
RF_HD inline float storedMarginBelow(double margin)
{
    float stored = static_cast<float>(margin);
    if (static_cast<double>(stored) > margin) stored = nextafterf(stored, -FLT_MAX);
    return stored;
}

RF_HD inline Vec3 pointVelocity(const CellContactView& cells, int c, const Vec3& point)
{
    return cells.velocity[c] + cross(cells.angular_velocity_world[c], point - cells.position[c]);
}

// Per-item outputs shared by pairs and wall items. The energy slots are optional:
// contact pairs (many) leave them null and add their energies to block sums instead
// (24 bytes less per pair); wall items (few, and each wall's power is wanted) keep them.
struct ContactItemOutputs {
    Vec3* tangential_spring = nullptr;  // history, world frame
    Vec3* last_normal = nullptr;        // history, for intersecting cores
    double* elastic_energy = nullptr;
    double* damping_power = nullptr;
    double* friction_dissipation = nullptr;
    unsigned char* status = nullptr;
    float* stiffness = nullptr;  // ContactOutput::stiffness, 0 when inactive (the step check)
};

// Energies and counts of a block of contact items, summed in item order.
struct ContactBlockSums {
    double elastic_energy = 0.0;
    double damping_power = 0.0;
    double friction_dissipation = 0.0;
    int active = 0;
    int cores_intersect = 0;

    RF_HD void add(const ContactOutput& out, unsigned char status)
    {
        elastic_energy += out.elastic_energy;
        damping_power += out.damping_power;
        friction_dissipation += out.friction_dissipation;
        ++active;
        cores_intersect += status == contactCoresIntersect;
    }
};

RF_HD inline void clearItem(const ContactItemOutputs& o, int item)
{
    o.tangential_spring[item] = Vec3{};
    if (o.elastic_energy) {
        o.elastic_energy[item] = 0.0;
        o.damping_power[item] = 0.0;
        o.friction_dissipation[item] = 0.0;
    }
    o.status[item] = contactNone;
    o.stiffness[item] = 0.0f;
}

RF_HD inline void storeItem(const ContactItemOutputs& o, int item, const ContactOutput& out,
                            unsigned char status)
{
    if (o.elastic_energy) {
        o.elastic_energy[item] = out.elastic_energy;
        o.damping_power[item] = out.damping_power;
        o.friction_dissipation[item] = out.friction_dissipation;
    }
    o.status[item] = status;
    o.stiffness[item] = static_cast<float>(out.stiffness);
}

struct PairKernelArgs {
    ContactConstants constants;  // rock–rock
    double dt = 0.0;
    int n_pairs = 0;
    CellContactView cells;
    const int* intact_bonds = nullptr;  // per interface
    const int* bond_offset = nullptr;   // per interface: its bonds are [offset[k], offset[k + 1])
    const int* cell_a = nullptr;
    const int* cell_b = nullptr;
    const int* interface = nullptr;  // -1 when the pair shares no face
    // Gap between the dilated surfaces at the last GJK call, less a bound on the
    // approach since: while positive the pair cannot touch and GJK is skipped.
    float* separation_margin = nullptr;  // rounded down when stored (storedMarginBelow)
    // The overlap a face neighbour's contact started at (its bonds' compression then),
    // taken off every point's overlap; -1 while the pair is apart (docs/theory-dem.md §6).
    // Patch contacts only (null otherwise).
    double* seat = nullptr;
    ContactItemOutputs items;
    // The patch contact (true) or the single GJK point (false, the paper's contact).
    bool patch = false;
    Vec3* force_on_b = nullptr;
    // Point contact: where the force acts; patch: the torque on b about its centroid. The
    // gather forms the two cells' torques from it (GatherArgs::pair_torques).
    Vec3* point_or_torque = nullptr;
    int block_size = 512;
    ContactBlockSums* block_sums = nullptr;  // one per block of block_size pairs (CPU runner)
};

// Where two dilated bodies touch: normal from A to B, overlap, contact point.
struct ContactGeometry {
    Vec3 normal, point;
    Vec3 point_a, point_b;  // the cores' closest points (separated cores)
    double overlap = 0.0;
    bool cores_intersect = false;
};

// Overlap along a fixed normal from the support points of the two cores: used
// when the cores themselves intersect and GJK has no separating direction.
RF_HD inline ContactGeometry supportGeometry(const ConvexVertexSet& A, const ConvexVertexSet& B,
                                             const Vec3& normal, double radius_a, double radius_b)
{
    ContactGeometry g;
    const Vec3 point_a = supportPoint(A, normal);
    const Vec3 point_b = supportPoint(B, -normal);
    g.normal = normal;
    g.overlap = radius_a + radius_b - dot(point_b - point_a, normal);
    g.point = 0.5 * (point_a + radius_a * normal + point_b - radius_b * normal);
    g.cores_intersect = true;
    return g;
}

// Closest points of the cores by GJK; the dilated surfaces are r_d outside them.
RF_HD inline ContactGeometry coreGeometry(const ConvexVertexSet& A, const ConvexVertexSet& B, double radius_a,
                                          double radius_b, const Vec3& fallback_normal)
{
    const GjkResult gjk = gjkDistance(A, B, A.position - B.position);
    const double scale = radius_a + radius_b;
    if (gjk.intersecting || gjk.distance <= 1e-9 * scale)
        return supportGeometry(A, B, fallback_normal, radius_a, radius_b);
    ContactGeometry g;
    g.normal = (gjk.point_b - gjk.point_a) / gjk.distance;
    g.point_a = gjk.point_a;
    g.point_b = gjk.point_b;
    g.overlap = scale - gjk.distance;
    g.point = 0.5 * (gjk.point_a + radius_a * g.normal + gjk.point_b - radius_b * g.normal);
    return g;
}

// Most points of one cell–cell patch; the deepest are kept beyond that.
constexpr int max_pair_patch_points = 32;

RF_HD inline int pairPatch(const CellContactView& cells, int ca, int cb, const ContactGeometry& g, double ra,
                           double rb, PatchPoint* points);

// Pair p; an active contact adds its energies to sums.
template <class Law>
RF_HD inline void pairKernel(const PairKernelArgs& a, int p, ContactBlockSums& sums)
{
    const int ca = a.cell_a[p], cb = a.cell_b[p];
    a.force_on_b[p] = a.point_or_torque[p] = Vec3{};
    const CellContactView& cells = a.cells;
    const int iface = a.interface[p];
    // A pair whose bonds are all intact gets no contact force. The contact starts at the
    // first broken bond: a cracked face can close where its bonds are gone (the cells hinge
    // on the bonds left), and a contact switched on only at the last bond would start with
    // whatever overlap that hinging made, its Hertz energy out of nothing (docs/theory-dem.md §6).
    const bool bonded =
        iface >= 0 && a.intact_bonds[iface] == a.bond_offset[iface + 1] - a.bond_offset[iface];
    const Vec3 between = cells.position[cb] - cells.position[ca];
    const double reach = cells.bounding_radius[ca] + cells.bounding_radius[cb];
    // A pair apart: no contact, and a patch is unseated.
    const auto apart = [&] {
        if (a.patch) a.seat[p] = -1.0;
        clearItem(a.items, p);
    };
    if (bonded || norm2(between) > reach * reach) return apart();
    // Largest approach of the two surfaces during this step (x 1.25 for the change of
    // the velocities within the step): translation plus rotation of the far points.
    const double approach = 1.25 * a.dt *
                            (norm(cells.velocity[ca]) + norm(cells.velocity[cb]) +
                             norm(cells.angular_velocity_world[ca]) * cells.bounding_radius[ca] +
                             norm(cells.angular_velocity_world[cb]) * cells.bounding_radius[cb]);
    const double margin = a.separation_margin[p] - approach;
    a.separation_margin[p] = storedMarginBelow(margin);
    if (margin > 0.0) return apart();
    const double ra = cells.dilation_radius[ca], rb = cells.dilation_radius[cb];
    const Vec3 previous = a.items.last_normal[p];
    const Vec3 fallback = norm2(previous) > 0.0 ? previous : normalised(between);
    const ContactGeometry g = coreGeometry(cellCore(cells, ca), cellCore(cells, cb), ra, rb, fallback);
    a.separation_margin[p] = storedMarginBelow(g.overlap < 0.0 ? -g.overlap : 0.0);
    if (!(g.overlap > 0.0)) return apart();
    a.items.last_normal[p] = g.normal;
    // The seat. A face neighbour's contact starts at its first broken bond, when its faces
    // are pressed together by what the bonds carry (microns): the patch's Hertz springs
    // would hold energy at once that nothing put in (with tens of points on a face, +1.0 J
    // in the main split of a 25 J crushing test, +0.1 J seated). So its overlaps are counted
    // from the overlap at the start; the contact takes up what the face closes from then on
    // (the compression the broken bonds carried is released with them, booked as fracture).
    // While the faces open, the seat follows the overlap down, with every point's spring at
    // zero: no energy jumps. Other pairs come into contact from apart and start at zero.
    double seat = 0.0;  // point contacts: the paper's unseated start
    if (a.patch) {
        if (a.seat[p] < 0.0)
            a.seat[p] = iface >= 0 ? g.overlap : 0.0;
        else if (g.overlap < a.seat[p])
            a.seat[p] = g.overlap;
        seat = a.seat[p];
    }
    const unsigned char status = g.cores_intersect ? contactCoresIntersect : contactActive;
    PatchPoint points[max_pair_patch_points];
    int n_points = a.patch ? pairPatch(cells, ca, cb, g, ra, rb, points) : 0;
    if (n_points > 0) {
        int kept = 0;
        for (int i = 0; i < n_points; ++i) {
            points[i].overlap -= seat;
            if (points[i].overlap > 0.0) points[kept++] = points[i];
        }
        if (kept == 0) return clearItem(a.items, p);  // seated, not pressed further yet
        n_points = kept;
    }
    if (n_points > 0) {  // the patch of feature pairs (docs/theory-dem.md §6), as against a wall
        for (int i = 0; i < n_points; ++i)
            points[i].relative_velocity =
                pointVelocity(cells, cb, points[i].point) - pointVelocity(cells, ca, points[i].point);
        ContactPatchInput in;
        in.points = points;
        in.n_points = n_points;
        in.centre = cells.position[cb];
        in.effective_radius = ra * rb / (ra + rb);
        in.effective_mass = cells.mass[ca] * cells.mass[cb] / (cells.mass[ca] + cells.mass[cb]);
        in.dt = a.dt;
        const ContactPatchOutput patch = Law::evaluatePatch(a.constants, in, a.items.tangential_spring[p]);
        ContactOutput out;
        out.force_on_b = patch.force;
        out.elastic_energy = patch.elastic_energy;
        out.damping_power = patch.damping_power;
        out.friction_dissipation = patch.friction_dissipation;
        out.stiffness = patch.stiffness;
        storeItem(a.items, p, out, status);
        sums.add(out, status);
        a.force_on_b[p] = patch.force;
        a.point_or_torque[p] = patch.torque;
        return;
    }
    // The point contact, or a patch without a feature pair within reach (round-off at the edge
    // of reach): GJK's single point; where the cores are cut, along the last normal (the depth
    // is not resolved: the patch resolves it).
    if (a.patch && !(g.overlap - seat > 0.0)) return clearItem(a.items, p);
    ContactInput in;
    in.overlap = g.overlap - seat;
    in.normal = g.normal;
    in.relative_velocity = pointVelocity(cells, cb, g.point) - pointVelocity(cells, ca, g.point);
    in.effective_radius = ra * rb / (ra + rb);
    in.effective_mass = cells.mass[ca] * cells.mass[cb] / (cells.mass[ca] + cells.mass[cb]);
    in.dt = a.dt;
    const ContactOutput out = Law::evaluate(a.constants, in, a.items.tangential_spring[p]);
    storeItem(a.items, p, out, status);
    sums.add(out, status);
    a.force_on_b[p] = out.force_on_b;
    a.point_or_torque[p] = a.patch ? cross(g.point - cells.position[cb], out.force_on_b) : g.point;
}

// A wall's pose at the current time: x_world = origin + rotation * x_local, and
// its rigid velocity field v(x) = velocity + angular_velocity x (x - origin).
enum WallKind : int { wallPlate = 0, wallTriSurface = 1 };
struct WallPose {
    int kind = wallPlate;
    Vec3 origin;
    Mat3 rotation = Mat3::identity();
    Vec3 velocity;
    Vec3 angular_velocity;
    Vec3 normal;             // plates: unit normal into the domain (world)
    int first_triangle = 0;  // tri surfaces: triangles [first, first + n) of the vertex array
    int n_triangles = 0;
};

struct WallKernelArgs {
    ContactConstants constants;  // rock–steel
    double dt = 0.0;
    int n_items = 0;
    CellContactView cells;
    const WallPose* walls = nullptr;
    const Vec3* triangle_vertices = nullptr;  // 3 per triangle, wall frame
    // Per triangle: which of its edges and corners are convex features of the surface
    // (ridges and convex vertices, see ridgeBit), each flagged on one owning triangle only.
    const unsigned short* triangle_features = nullptr;
    const int* item_cell = nullptr;
    const int* item_wall = nullptr;
    const int* item_triangle_offset = nullptr;  // candidate triangles of item i
    const int* item_triangles = nullptr;
    ContactItemOutputs items;
    Vec3* force_on_cell = nullptr;
    Vec3* torque_on_cell = nullptr;
    double* wall_power = nullptr;  // force on the cell . wall velocity at the contact [W]
};

// Add a point to a patch of at most `capacity` points; when full, the shallowest point gives
// way to a deeper one.
RF_HD inline void addPatchPoint(PatchPoint* points, int& n, const PatchPoint& p,
                                int capacity = max_patch_points)
{
    if (n < capacity) {
        points[n++] = p;
        return;
    }
    int shallowest = 0;
    for (int i = 1; i < n; ++i)
        if (points[i].overlap < points[shallowest].overlap) shallowest = i;
    if (p.overlap > points[shallowest].overlap) points[shallowest] = p;
}

RF_HD inline Vec3 wallPointVelocity(const WallPose& wall, const Vec3& point)
{
    return wall.velocity + cross(wall.angular_velocity, point - wall.origin);
}

// Which part of a triangle holds the closest point.
enum TriangleFeature : int { featureFace = 0, featureEdge = 1, featureVertex = 2 };

// Closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection 5.1.5);
// feature receives where it lies, vertex the corner (0, 1, 2) for featureVertex. A
// degenerate (zero-area) triangle gives the nearest point of its edges.
RF_HD inline Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                         int& feature, int& vertex)
{
    feature = featureVertex;
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return vertex = 0, a;
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return vertex = 1, b;
    feature = featureEdge;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return feature = featureVertex, vertex = 2, c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) {  // zero area: nearest point of the three edges
        auto onSegment = [&](const Vec3& s0, const Vec3& s1) {
            const Vec3 d = s1 - s0;
            const double l2 = norm2(d);
            double t = l2 > 0.0 ? dot(p - s0, d) / l2 : 0.0;
            t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
            return s0 + t * d;
        };
        Vec3 best = onSegment(a, b);
        const Vec3 q1 = onSegment(b, c), q2 = onSegment(c, a);
        if (norm2(q1 - p) < norm2(best - p)) best = q1;
        if (norm2(q2 - p) < norm2(best - p)) best = q2;
        return best;
    }
    feature = featureFace;
    const double denominator = 1.0 / sum;
    return a + (vb * denominator) * ab + (vc * denominator) * ac;
}

RF_HD inline Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    int feature = 0, vertex = 0;
    return closestPointOnTriangle(p, a, b, c, feature, vertex);
}

// Closest points of segments [p1, q1] and [p2, q2] (Ericson, Real-Time Collision
// Detection 5.1.9): c1 on the first, c2 on the second. Parallel segments take s = 0 (any
// pair of the overlap is closest; a configuration of measure zero).
RF_HD inline void closestPointsOfSegments(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2,
                                          Vec3& c1, Vec3& c2)
{
    const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = norm2(d1), e = norm2(d2), f = dot(d2, r);
    double s = 0.0, t = 0.0;
    if (!(a > 0.0) && !(e > 0.0)) {
        c1 = p1, c2 = p2;
        return;
    }
    auto clamp01 = [](double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); };
    if (!(a > 0.0)) {
        t = clamp01(f / e);
    } else {
        const double c = dot(d1, r);
        if (!(e > 0.0)) {
            s = clamp01(-c / a);
        } else {
            const double b = dot(d1, d2), denominator = a * e - b * b;
            s = denominator > 1e-14 * a * e ? clamp01((b * f - c * e) / denominator) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = clamp01(-c / a);
            } else if (t > 1.0) {
                t = 1.0;
                s = clamp01((b - c) / a);
            }
        }
    }
    c1 = p1 + s * d1;
    c2 = p2 + t * d2;
}

// Ridge–edge pairs within 10 degrees of parallel are left to the vertex pairs at their
// ends (a line contact); the pair's reach grows smoothly to r_d at 20 degrees.
constexpr double ridge_parallel_begin = 10.0 * 3.14159265358979323846 / 180.0;
constexpr double ridge_parallel_full = 20.0 * 3.14159265358979323846 / 180.0;
constexpr double cos_ridge_parallel_begin = 0.98480775301220805936;  // cos 10 degrees
constexpr double cos_ridge_parallel_full = 0.93969262078590838405;   // cos 20 degrees

// The angle weight w(theta) of an edge pair: a core edge (unit `along`) against a wall's
// ridge or another core's edge (unit `ridge`). 0 within ridge_parallel_begin of parallel
// (returns false: such a pair is left to the vertex pairs at its ends), 1 beyond
// ridge_parallel_full, smooth between. The pair's reach is weighted by w, so its overlap
// depends on the edges' angle: d(overlap)/d(rotation of along's body) = reach w'(theta)
// dtheta/dphi, and with cos theta = sigma a.b, dtheta/dphi = -sigma (a x b) / sin theta; the
// torque on that body is then F reach w' sigma (a x b) / |a x b| (torque_per_force, per
// newton of the pair's force; zero outside the ramp).
struct EdgeAngleWeight {
    double weight = 1.0;
    Vec3 torque_per_force;
};

RF_HD inline bool edgeAngleWeight(const Vec3& along, const Vec3& ridge, double reach, EdgeAngleWeight& w)
{
    const double cosine = dot(along, ridge);
    const double abs_cosine = cosine < 0.0 ? -cosine : cosine;
    if (!(abs_cosine < cos_ridge_parallel_begin)) return false;
    w.weight = 1.0;
    w.torque_per_force = Vec3{};
    if (abs_cosine > cos_ridge_parallel_full) {  // the angle needed only in the ramp
        const Vec3 binormal = cross(along, ridge);
        const double angle = std::atan2(norm(binormal), abs_cosine);
        const double width = ridge_parallel_full - ridge_parallel_begin;
        double u = (angle - ridge_parallel_begin) / width;
        u = u < 0.0 ? 0.0 : u;
        w.weight = u * u * (3.0 - 2.0 * u);
        const double slope = 6.0 * u * (1.0 - u) / width;
        if (slope > 0.0)
            w.torque_per_force = (reach * slope * (cosine < 0.0 ? -1.0 : 1.0) / norm(binormal)) * binormal;
    }
    return true;
}

// Most core edges of one cell that a pair patch looks at (those within reach of the other
// core), and most core vertices of a cell with a pair patch (larger cores: the GJK point).
constexpr int max_pair_patch_edges = 48;
constexpr int max_pair_patch_vertices = 96;

// A core edge within reach of the other core of a pair: its ends (indices into the world
// vertices), unit direction and half length.
struct NearEdge {
    int end0 = 0, end1 = 0;
    Vec3 direction;
    double half_length = 0.0;
};

// The edges of a core (vertex index pairs, world vertices) with an end less than `reach`
// beyond the other core's supporting plane (`beyond` per vertex): the plane bound is linear
// along an edge, so the others are out of reach. Returns how many (at most max_pair_patch_edges).
RF_HD inline int nearEdges(const unsigned char* edges, int n_edges, const Vec3* world, const double* beyond,
                           double reach, NearEdge* near)
{
    int n = 0;
    for (int e = 0; e < n_edges && n < max_pair_patch_edges; ++e) {
        const int i0 = edges[2 * e], i1 = edges[2 * e + 1];
        if ((beyond[i0] < beyond[i1] ? beyond[i0] : beyond[i1]) >= reach) continue;
        const Vec3 along = world[i1] - world[i0];
        near[n].end0 = i0;
        near[n].end1 = i1;
        near[n].direction = normalised(along);
        near[n].half_length = 0.5 * norm(along);
        ++n;
    }
    return n;
}

// A triangle's normal on its winding side, its length twice the area.
RF_HD inline Vec3 areaNormal(const Vec3* p)
{
    return cross(p[1] - p[0], p[2] - p[0]);
}

// Whether edge a of core A and edge b of core B can have passed through each other: the
// closest points of the segments (on_a, on_b) lie inside both segments, where they are the
// closest points of the two lines, and the lines' common normal c points out of A at a and
// into B at b (judged by outward_a, from A's centroid to edge a, and outward_b): the two
// edges face each other, as two edges of faces pressed on each other do. Then normal
// receives c oriented out of A, along which the lines' signed distance passes through zero.
RF_HD inline bool crossingNormal(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1,
                                 const Vec3& on_a, const Vec3& on_b, const Vec3& outward_a,
                                 const Vec3& outward_b, Vec3& normal)
{
    const Vec3 da = a1 - a0, db = b1 - b0;
    const double s = dot(on_a - a0, da) / norm2(da), t = dot(on_b - b0, db) / norm2(db);
    const double inside = 1e-12;
    if (!(s > inside && s < 1.0 - inside && t > inside && t < 1.0 - inside)) return false;
    const Vec3 c = cross(da, db);
    const double out_of_a = dot(c, outward_a), out_of_b = dot(c, outward_b);
    if (!(out_of_a * out_of_b < 0.0)) return false;
    normal = (out_of_a < 0.0 ? -1.0 / norm(c) : 1.0 / norm(c)) * c;
    return true;
}

// The contact of two dilated cells as a patch of Hertz points (docs/theory-dem.md §6), the
// cell–cell form of the wall patch: one point per pair of features within r_a + r_b,
//  - every core vertex of either cell and the other core: the vertex's distance to that
//    core (GJK of a point), normal from the nearest point to the vertex;
//  - every core edge of A and core edge of B: the distance of the two segments, with the
//    reach weighted by w(theta) of the angle between them (0 within 10 degrees of parallel,
//    1 beyond 20, smooth between) exactly as a core edge against a ridge of a wall, the
//    weight's own torque in torque_per_force (on B).
// Each overlap is a continuous function of the two poses, zero when the pair comes into
// reach, so the elastic forces derive from one potential and two faces lying on each other
// are held at the corners of their common area, as a face on a plate: their torque follows
// the tilt smoothly. A single GJK point (the contact before 2026-12-03) jumps from corner
// to corner between two parallel faces, and a loaded face contact that rocks by a hair then
// pumps energy into the pair (docs/theory-dem.md §6). Features are culled by the separating
// plane GJK found between the cores: B lies beyond the plane through its closest point p_b
// normal to n, A behind the one through p_a, so a feature of A farther than r_a + r_b
// behind p_b's plane (or of B beyond p_a's) is out of reach. Normals point from A to B; the
// torques the patch law forms are on B about its centroid. Returns the number of points.
RF_HD inline int pairPatch(const CellContactView& cells, int ca, int cb, const ContactGeometry& g, double ra,
                           double rb, PatchPoint* points)
{
    const bool cut = g.cores_intersect;
    const double reach = ra + rb;
    const double tolerance = 1e-9 * reach;
    const ConvexVertexSet core_a = cellCore(cells, ca), core_b = cellCore(cells, cb);
    if (core_a.n_vertices > max_pair_patch_vertices || core_b.n_vertices > max_pair_patch_vertices) return 0;
    // World vertices and their distance beyond the other core's supporting plane (the
    // separating planes above), a lower bound of their distance from that core.
    Vec3 world_a[max_pair_patch_vertices], world_b[max_pair_patch_vertices];
    double beyond_a[max_pair_patch_vertices], beyond_b[max_pair_patch_vertices];
    // Cut cores have no separating plane: nothing is culled.
    const double plane_b = dot(g.point_b, g.normal), plane_a = dot(g.point_a, g.normal);
    for (int v = 0; v < core_a.n_vertices; ++v) {
        world_a[v] = worldVertex(core_a, v);
        beyond_a[v] = cut ? -reach : plane_b - dot(world_a[v], g.normal);
    }
    for (int v = 0; v < core_b.n_vertices; ++v) {
        world_b[v] = worldVertex(core_b, v);
        beyond_b[v] = cut ? -reach : dot(world_b[v], g.normal) - plane_a;
    }
    int n = 0;
    // Vertices of each core against the other.
    for (int side = 0; side < 2; ++side) {
        const ConvexVertexSet& own = side == 0 ? core_a : core_b;
        const ConvexVertexSet& other = side == 0 ? core_b : core_a;
        const Vec3* world = side == 0 ? world_a : world_b;
        const double* beyond = side == 0 ? beyond_a : beyond_b;
        for (int v = 0; v < own.n_vertices; ++v) {
            if (beyond[v] >= reach) continue;
            const Vec3 x = world[v];
            const Vec3 origin{};
            ConvexVertexSet vertex;
            vertex.vertices = &origin;
            vertex.n_vertices = 1;
            vertex.position = x;
            const GjkResult gjk = gjkDistance(vertex, other, x - other.position);
            PatchPoint pt;
            if (gjk.intersecting || !(gjk.distance > tolerance)) {
                // Inside the other core (only where the cores are cut): its depth below the
                // nearest facet continues the distance through zero, so the overlap keeps
                // growing smoothly and the force still derives from the one potential.
                Vec3 facet;
                const double depth = coreDepthDistance(cells, side == 0 ? cb : ca, x, facet);
                pt.overlap = reach - depth;
                pt.normal = side == 0 ? -1.0 * facet : facet;
                const Vec3 on_a = side == 0 ? x : x - depth * facet;
                pt.point = on_a + (0.5 * (ra + depth - rb)) * pt.normal;
                addPatchPoint(points, n, pt, max_pair_patch_points);
                continue;
            }
            pt.overlap = reach - gjk.distance;
            if (!(pt.overlap > 0.0)) continue;
            const Vec3 towards_other = (gjk.point_b - gjk.point_a) / gjk.distance;
            pt.normal = side == 0 ? towards_other : -1.0 * towards_other;
            const Vec3 on_a = side == 0 ? x : gjk.point_b;
            pt.point = on_a + (0.5 * (ra + gjk.distance - rb)) * pt.normal;
            addPatchPoint(points, n, pt, max_pair_patch_points);
        }
    }
    // Edge pairs among the edges of each core within reach of the other core.
    NearEdge near_a[max_pair_patch_edges], near_b[max_pair_patch_edges];
    const int n_near_a = nearEdges(cells.core_edges + cells.core_edge_offset[ca],
                                   (cells.core_edge_offset[ca + 1] - cells.core_edge_offset[ca]) / 2, world_a,
                                   beyond_a, reach, near_a);
    const int n_near_b = nearEdges(cells.core_edges + cells.core_edge_offset[cb],
                                   (cells.core_edge_offset[cb + 1] - cells.core_edge_offset[cb]) / 2, world_b,
                                   beyond_b, reach, near_b);
    for (int i = 0; i < n_near_a; ++i) {
        const Vec3 a0 = world_a[near_a[i].end0], a1 = world_a[near_a[i].end1];
        const Vec3 middle_a = 0.5 * (a0 + a1);
        for (int j = 0; j < n_near_b; ++j) {
            const Vec3 b0 = world_b[near_b[j].end0], b1 = world_b[near_b[j].end1];
            // The segments' bounding spheres apart by the reach: out of reach.
            const double apart =
                norm(0.5 * (b0 + b1) - middle_a) - near_a[i].half_length - near_b[j].half_length;
            if (apart >= reach) continue;
            // A's edge plays the wall's ridge, B's the core edge: the weight's torque is on B.
            EdgeAngleWeight w;
            if (!edgeAngleWeight(near_b[j].direction, near_a[i].direction, reach, w)) continue;
            Vec3 on_a, on_b;
            closestPointsOfSegments(a0, a1, b0, b1, on_a, on_b);
            const Vec3 gap = on_b - on_a;
            double distance = norm(gap);
            PatchPoint pt;
            Vec3 crossing;
            if (cut && distance < reach &&
                crossingNormal(a0, a1, b0, b1, on_a, on_b, middle_a - cells.position[ca],
                               0.5 * (b0 + b1) - cells.position[cb], crossing)) {
                // Where the cores are cut, two edges facing each other can pass through each
                // other (two pressed faces sink into each other, their edges crossing): the
                // distance of their lines, signed positive outside A, continues through zero
                // and the overlap keeps growing, up to 2 (r_a + r_b) (beyond, the edges are
                // far apart on the lines' two sides, not crossed; crossed closest points are
                // inside both segments, so their distance is the lines').
                distance = dot(gap, crossing);
                pt.normal = crossing;
            } else {
                if (!(distance > tolerance)) continue;
                pt.normal = gap / distance;
            }
            pt.overlap = w.weight * reach - distance;
            if (!(pt.overlap > 0.0)) continue;
            pt.torque_per_force = w.torque_per_force;
            pt.point = on_a + (0.5 * (ra + distance - rb)) * pt.normal;
            addPatchPoint(points, n, pt, max_pair_patch_points);
        }
    }
    return n;
}

// Bits of triangle_features: edge k (from corner k to corner k+1) is a ridge seen from
// the winding side (+1) or the other side (-1); corner k is a convex vertex seen from
// either side. A triangle carries the bits of the features it owns (the lowest-numbered
// triangle of an edge or vertex), so that each feature is visited once.
RF_HD inline unsigned short ridgeBit(int k, double side)
{
    return (unsigned short)(1u << (k + (side > 0.0 ? 0 : 3)));
}
RF_HD inline unsigned short convexCornerBit(int k, double side)
{
    return (unsigned short)(1u << (k + (side > 0.0 ? 6 : 9)));
}

// The nearest point of a triangulated surface (the candidate triangles of an item) to x,
// with the pseudo-normal of the feature it lies on (Baerentzen & Aanaes 2005): the face
// normal for a face point, the sum of the two face normals for an edge, the angle-weighted
// sum for a vertex, all from the triangles' winding (a consistently oriented surface).
// boundary: the point lies on an edge of one triangle only or a vertex whose angles do
// not close around it (an open rim), where the surface has no inside.
struct SurfaceNearest {
    Vec3 point;
    Vec3 pseudo_normal;  // unnormalised, winding orientation
    double distance = 1e300;
    bool boundary = false;
};

// What the search for the cell centre leaves for the searches of the core's vertices
// (docs/theory-dem.md §7, "Cost"): the distance of the centre from each candidate
// triangle, so that a triangle whose distance from a vertex x cannot come within the
// tolerance of the best one found (d(x, t) >= d(c, t) - |x - c|) is not visited, and the
// nearest triangle to start from. Items with more candidates than it holds are searched
// in full.
constexpr int max_culled_triangles = 192;
struct SurfaceCull {
    Vec3 centre;  // wall frame
    double centre_distance[max_culled_triangles];
    double least = 1e300;  // distance of the centre from the surface
    int nearest = -1;      // entry (into the item's candidates) of the nearest triangle
    bool valid = false;
};

// Accumulates the pseudo-normal of the nearest feature over the triangles that hold it
// (within the tolerance), in the wall frame.
struct NearestSums {
    Vec3 face, edges, corners;
    int n_faces = 0, n_edges = 0, n_corners = 0;
    double corner_angle = 0.0;

    // Visits triangle p (3 corners) and returns its distance from x.
    RF_HD double visit(const Vec3* p, const Vec3& x, double tolerance, SurfaceNearest& s)
    {
        int feature = 0, vertex = 0;
        const Vec3 q = closestPointOnTriangle(x, p[0], p[1], p[2], feature, vertex);
        const double distance = norm(x - q);
        if (distance > s.distance + tolerance) return distance;
        if (distance < s.distance - tolerance) {  // a new nearest feature: restart the sums
            face = edges = corners = Vec3{};
            n_faces = n_edges = n_corners = 0;
            corner_angle = 0.0;
        }
        if (distance < s.distance) {
            s.distance = distance;
            s.point = q;
        }
        const Vec3 area_normal = areaNormal(p);
        if (!(norm2(area_normal) > 0.0)) return distance;  // zero area: no normal of its own
        const Vec3 n = normalised(area_normal);
        if (feature == featureFace) {
            face += n;
            ++n_faces;
        } else if (feature == featureEdge) {
            edges += n;
            ++n_edges;
        } else {
            const Vec3 u = p[(vertex + 1) % 3] - p[vertex], v = p[(vertex + 2) % 3] - p[vertex];
            const double angle = std::atan2(norm(cross(u, v)), dot(u, v));
            corners += angle * n;
            corner_angle += angle;
            ++n_corners;
        }
        return distance;
    }
    // The pseudo-normal and boundary flag of the nearest feature (wall frame).
    RF_HD void finish(SurfaceNearest& s) const
    {
        constexpr double pi = 3.14159265358979323846;
        if (n_faces > 0) {
            s.pseudo_normal = face;
        } else if (n_corners > 0) {
            s.pseudo_normal = corners;
            s.boundary = corner_angle < 1.5 * pi;
        } else {
            s.pseudo_normal = edges;
            s.boundary = n_edges < 2;
        }
    }
};

// The nearest point of a triangulated surface (the candidate triangles of an item) to x,
// with the pseudo-normal of the feature it lies on (Baerentzen & Aanaes 2005): the face
// normal for a face point, the sum of the two face normals for an edge, the angle-weighted
// sum for a vertex, all from the triangles' winding (a consistently oriented surface).
// boundary: the point lies on an edge of one triangle only or a vertex whose angles do
// not close around it (an open rim), where the surface has no inside.
// The search runs in the wall's frame (x taken there once, the point and normal brought
// back), so the triangles are not moved for every query. With `cull` filled by the search
// for the centre (cull->valid), triangles that cannot hold the nearest point are skipped;
// without it (nullptr) and cull not yet valid, every candidate is visited and, when cull is
// given, the centre's distances are recorded in it.
RF_HD inline SurfaceNearest nearestOnSurface(const WallKernelArgs& a, const WallPose& wall, int item,
                                             const Vec3& x, double tolerance, SurfaceCull* cull = nullptr)
{
    SurfaceNearest s;
    NearestSums sums;
    const Vec3 local = transposeTimes(wall.rotation, x - wall.origin);
    const int begin = a.item_triangle_offset[item], end = a.item_triangle_offset[item + 1];
    const bool record = cull != nullptr && !cull->valid && end - begin <= max_culled_triangles;
    const bool culled = cull != nullptr && cull->valid;
    if (culled) {
        // Start from the centre's nearest triangle: a close first bound.
        const double reach = norm(local - cull->centre);
        sums.visit(a.triangle_vertices + 3 * a.item_triangles[begin + cull->nearest], local, tolerance, s);
        for (int e = begin; e < end; ++e) {
            if (e - begin == cull->nearest) continue;
            if (cull->centre_distance[e - begin] - reach > s.distance + tolerance) continue;
            sums.visit(a.triangle_vertices + 3 * a.item_triangles[e], local, tolerance, s);
        }
    } else {
        for (int e = begin; e < end; ++e) {
            const double d = sums.visit(a.triangle_vertices + 3 * a.item_triangles[e], local, tolerance, s);
            if (record) {
                cull->centre_distance[e - begin] = d;
                if (d < cull->least) cull->least = d, cull->nearest = e - begin;
            }
        }
        if (record) {
            cull->centre = local;
            cull->valid = cull->nearest >= 0;
        }
    }
    sums.finish(s);
    s.point = wall.origin + wall.rotation * s.point;
    s.pseudo_normal = wall.rotation * s.pseudo_normal;
    return s;
}

// The patch of a cell against a wall: one point per pair of features of the core and
// the wall that come within r_d of each other (docs/theory-dem.md §7).
// Plate: every core vertex, overlap r_d - signed distance of the vertex.
// Triangulated surface, three kinds of pairs, each a Hertz point of its own:
//  - a core vertex and the surface: the signed distance of the vertex to the surface, from
//    its nearest point over all candidate triangles and the pseudo-normal there (so a
//    vertex over a shared edge counts once, and a vertex beside a triangle is never judged
//    by that triangle's infinite plane). side (+1/-1, see wallKernel) tells which side of
//    the winding the cell is on. A vertex behind the surface (its nearest point on a face
//    or an inner edge or vertex) overlaps by r_d + distance, pushed back towards that
//    point; at an open rim the surface has no inside and the rim is an edge seen from both
//    sides;
//  - a ridge of the surface (a convex edge seen from the cell's side, or a rim) and a core
//    edge: their closest points. A ridge lying across a core face is held at the two points
//    where it passes under the face's edges, each moving smoothly with the cell;
//  - a convex vertex of the surface and the core: the vertex's closest point on the core.
//    These two kinds use the unsigned distance: a ridge or corner that has gone deeper
//    than r_d into the core (the core cut; a broken run) is flagged, not pushed back.
// Every pair's overlap is a continuous function of the cell's pose that is zero when the
// pair comes into reach, so the elastic force derives from one potential and a cell rocking
// over ridges keeps its energy (the former single GJK contact, used only while no core
// vertex was in reach, jumped whenever a corner arrived). Concave and flat surface edges
// never hold the nearest point of a convex core, so they need no pairs of their own; a core
// face on a flat region is held by its corners alone, as on a plate.
// Returns the number of points; sets cores_intersect when a feature is behind the surface.
// cull: the centre's search (nearestOnSurface), or nullptr. With it, a core vertex x with
// d(c) - |x - c| > r_d is out of reach in front of the surface (every surface point is
// farther than r_d from it; a vertex reaching behind a liner round its rim, farther than
// r_d from the steel, is not looked for), and a triangle farther from the centre than the
// dilated core reaches holds no ridge or corner pair.
RF_HD inline int wallPatch(const WallKernelArgs& a, const ConvexVertexSet& core, int c, double radius,
                           double side, const WallPose& wall, int item, PatchPoint* points,
                           bool& cores_intersect, SurfaceCull* cull = nullptr)
{
    int n = 0;
    cores_intersect = false;
    const double tolerance = 1e-7 * radius;
    for (int v = 0; v < core.n_vertices; ++v) {
        const Vec3 x = worldVertex(core, v);
        PatchPoint p;
        bool behind = false;
        if (wall.kind == wallPlate) {
            p.normal = wall.normal;
            p.overlap = radius - dot(x - wall.origin, wall.normal);
        } else {
            if (cull != nullptr && cull->valid && cull->least - norm(x - core.position) > radius + tolerance)
                continue;
            const SurfaceNearest s = nearestOnSurface(a, wall, item, x, tolerance, cull);
            const Vec3 gap = x - s.point;
            behind = !s.boundary && side * dot(gap, s.pseudo_normal) < 0.0;
            p.overlap = behind ? radius + s.distance : radius - s.distance;
            if (s.distance > 1e-9 * radius)
                p.normal = (behind ? -1.0 : 1.0) / s.distance * gap;
            else
                p.normal = side * normalised(s.pseudo_normal);
        }
        if (!(p.overlap > 0.0)) continue;
        if (behind) cores_intersect = true;
        p.point = x - (radius - 0.5 * p.overlap) * p.normal;
        addPatchPoint(points, n, p);
    }
    if (wall.kind != wallTriSurface || a.triangle_features == nullptr) return n;

    const double reach = a.cells.bounding_radius[c];  // of the dilated core about its centre
    const unsigned char* edges = a.cells.core_edges + a.cells.core_edge_offset[c];
    const int n_edge_entries = a.cells.core_edge_offset[c + 1] - a.cells.core_edge_offset[c];
    for (int e = a.item_triangle_offset[item]; e < a.item_triangle_offset[item + 1]; ++e) {
        const int t = a.item_triangles[e];
        const unsigned short flags = a.triangle_features[t];
        if (flags == 0) continue;
        if (cull != nullptr && cull->valid &&
            cull->centre_distance[e - a.item_triangle_offset[item]] >= reach)
            continue;
        const Vec3* local = a.triangle_vertices + 3 * t;
        const Vec3 p[3] = {wall.origin + wall.rotation * local[0], wall.origin + wall.rotation * local[1],
                           wall.origin + wall.rotation * local[2]};
        for (int k = 0; k < 3; ++k) {
            if (flags & ridgeBit(k, side)) {
                const Vec3 r0 = p[k], r1 = p[(k + 1) % 3];
                Vec3 on_ridge, unused;
                closestPointsOfSegments(r0, r1, core.position, core.position, on_ridge, unused);
                const int n_entries = norm(on_ridge - core.position) < reach ? n_edge_entries : 0;
                const Vec3 ridge = n_entries > 0 ? normalised(r1 - r0) : Vec3{};
                for (int j = 0; j + 1 < n_entries; j += 2) {
                    const Vec3 x0 = worldVertex(core, edges[j]), x1 = worldVertex(core, edges[j + 1]);
                    EdgeAngleWeight w;  // 0 near parallel: left to the vertex pairs
                    if (!edgeAngleWeight(normalised(x1 - x0), ridge, radius, w)) continue;
                    Vec3 on_surface, on_core;
                    closestPointsOfSegments(r0, r1, x0, x1, on_surface, on_core);
                    const Vec3 gap = on_core - on_surface;
                    double distance = norm(gap);
                    PatchPoint pt;
                    // Only a pair nearer than r_d can have crossed within reach (its closest
                    // points then lie inside both segments and their distance is the lines'):
                    // the far pairs of this hot loop skip the test.
                    Vec3 crossing;
                    if (distance < radius &&
                        crossingNormal(r0, r1, x0, x1, on_surface, on_core, side * areaNormal(p),
                                       0.5 * (x0 + x1) - core.position, crossing) &&
                        !(dot(gap, crossing) > 0.0)) {
                        // The ridge has passed through the core edge (the core is r_d deep):
                        // the lines' signed distance continues through zero, so the overlap
                        // keeps growing (up to 2 r_d) and still derives from the potential.
                        distance = dot(gap, crossing);
                        pt.normal = crossing;
                        cores_intersect = true;
                    } else if (distance > 1e-9 * radius) {
                        pt.normal = gap / distance;
                    } else {  // the ridge cuts the core edge where their lines cannot cross
                        pt.normal = normalised(core.position - on_surface);
                        cores_intersect = true;
                    }
                    pt.overlap = w.weight * radius - distance;
                    if (!(pt.overlap > 0.0)) continue;
                    pt.torque_per_force = w.torque_per_force;  // the weight's own torque
                    pt.point = on_core - (radius - 0.5 * pt.overlap) * pt.normal;
                    addPatchPoint(points, n, pt);
                }
            }
            if ((flags & convexCornerBit(k, side)) && norm(p[k] - core.position) < reach) {
                const Vec3 origin{};
                ConvexVertexSet vertex;
                vertex.vertices = &origin;
                vertex.n_vertices = 1;
                vertex.position = p[k];
                const GjkResult gjk = gjkDistance(vertex, core, core.position - p[k]);
                PatchPoint pt;
                if (gjk.intersecting || !(gjk.distance > 1e-9 * radius)) {
                    // The surface's corner is inside the core: its depth below the core's
                    // nearest facet continues the distance through zero (one potential).
                    Vec3 facet;
                    const double depth = coreDepthDistance(a.cells, c, p[k], facet);
                    pt.overlap = radius - depth;
                    pt.normal = -1.0 * facet;
                    cores_intersect = true;
                    pt.point = p[k] - depth * facet - (radius - 0.5 * pt.overlap) * pt.normal;
                } else {
                    pt.overlap = radius - gjk.distance;
                    if (!(pt.overlap > 0.0)) continue;
                    pt.normal = (gjk.point_b - gjk.point_a) / gjk.distance;
                    pt.point = gjk.point_b - (radius - 0.5 * pt.overlap) * pt.normal;
                }
                addPatchPoint(points, n, pt);
            }
        }
    }
    return n;
}

template <class Law>
RF_HD inline void wallKernel(const WallKernelArgs& a, int item)
{
    const int c = a.item_cell[item];
    const WallPose& wall = a.walls[a.item_wall[item]];
    a.force_on_cell[item] = a.torque_on_cell[item] = Vec3{};
    a.wall_power[item] = 0.0;
    const ConvexVertexSet core = cellCore(a.cells, c);
    const double radius = a.cells.dilation_radius[c];
    PatchPoint points[max_patch_points];
    bool cores_intersect = false;
    double side = 1.0;
    SurfaceCull cull;
    if (wall.kind == wallTriSurface) {
        // The nearest point of the surface to the centre gives the cell's side; when it is
        // farther than the dilated core reaches (bounding radius), nothing can touch.
        const SurfaceNearest s = nearestOnSurface(a, wall, item, core.position, 1e-7 * radius, &cull);
        if (s.distance > a.cells.bounding_radius[c]) return clearItem(a.items, item);
        side = dot(core.position - s.point, s.pseudo_normal) < 0.0 ? -1.0 : 1.0;
    }
    const int n = wallPatch(a, core, c, radius, side, wall, item, points, cores_intersect, &cull);
    if (n == 0) return clearItem(a.items, item);
    for (int i = 0; i < n; ++i)
        points[i].relative_velocity =
            pointVelocity(a.cells, c, points[i].point) - wallPointVelocity(wall, points[i].point);
    a.items.last_normal[item] = points[0].normal;
    ContactPatchInput in;
    in.points = points;
    in.n_points = n;
    in.centre = a.cells.position[c];
    in.effective_radius = radius;  // R* = r_d against a wall (R = infinity)
    in.effective_mass = a.cells.mass[c];
    in.dt = a.dt;
    const ContactPatchOutput out = Law::evaluatePatch(a.constants, in, a.items.tangential_spring[item]);
    a.items.elastic_energy[item] = out.elastic_energy;
    a.items.damping_power[item] = out.damping_power;
    a.items.friction_dissipation[item] = out.friction_dissipation;
    a.items.status[item] = cores_intersect ? contactCoresIntersect : contactActive;
    a.items.stiffness[item] = static_cast<float>(out.stiffness);
    a.force_on_cell[item] = out.force;
    a.torque_on_cell[item] = out.torque;
    // Power of the force system on the wall's rigid velocity field, about the centroid.
    a.wall_power[item] =
        dot(out.force, wallPointVelocity(wall, in.centre)) + dot(wall.angular_velocity, out.torque);
}

// Blocks of pairs, each summed in pair order (static schedule: the sums do not
// depend on the thread count).
template <class Law>
void runPairKernel(const PairKernelArgs& a)
{
    const int n_blocks = (a.n_pairs + a.block_size - 1) / a.block_size;
#pragma omp parallel for schedule(static) if (n_blocks > 1)
    for (int block = 0; block < n_blocks; ++block) {
        ContactBlockSums sums;
        const int end = a.n_pairs < (block + 1) * a.block_size ? a.n_pairs : (block + 1) * a.block_size;
        for (int p = block * a.block_size; p < end; ++p) pairKernel<Law>(a, p, sums);
        a.block_sums[block] = sums;
    }
}

// An item against a triangulated liner searches tens to hundreds of candidate triangles per
// core vertex, against one plane for a plate: the work is the candidate count, not the item
// count (a few hundred cells on the liners of a crusher already fill two threads), and it is
// uneven (an item out of reach returns after the centre's search), so the items are dealt
// out dynamically. Each item writes its own slots: the result does not depend on the order.
template <class Law>
void runWallKernel(const WallKernelArgs& a)
{
    const long work = a.n_items > 0 ? a.n_items + a.item_triangle_offset[a.n_items] : 0;
#pragma omp parallel for schedule(dynamic, 8) if (work >= parallelMinimumItems())
    for (int item = 0; item < a.n_items; ++item) wallKernel<Law>(a, item);
}

struct ContactLawRunners {
    void (*pairs)(const PairKernelArgs&) = nullptr;
    void (*walls)(const WallKernelArgs&) = nullptr;
};

// The law registered under name; a UserError listing the known names otherwise.
ContactLawRunners contactLawRunners(const std::string& name);
std::vector<std::string> contactLawNames();

}  // namespace rockfrac
