#pragma once
// Contact geometry shared by the cell–cell and cell–wall kernels: the cells as the
// kernels see them (cores, dilation), closest points by GJK and of triangles and segments,
// patch bookkeeping, and the per-item outputs both kernels write.
#include <cfloat>
#include <cmath>

#include "core/parallel.hpp"
#include "core/vec3.hpp"
#include "dem/contactLaw.hpp"
#include "dem/gjk.hpp"
#include "dem/quat.hpp"

namespace rockfrac {

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

}  // namespace rockfrac
