#pragma once
// Distance and closest points between two convex polytopes given by their
// vertices (Gilbert–Johnson–Keerthi), for the narrow phase between the cores
// of two dilated cells and between a core and a wall triangle.
//
// Written as plain RF_HD functions over raw vertex arrays: no allocation, no
// exceptions, fixed iteration bound, so the same code runs in a CUDA kernel.
#include "core/vec3.hpp"

namespace rockfrac {

// A convex polytope: the hull of vertices[0..n_vertices) given in a local frame,
// placed in the world by x_world = position + rotation * x_local.
struct ConvexVertexSet {
    const Vec3* vertices = nullptr;
    int n_vertices = 0;
    Vec3 position;
    Mat3 rotation = Mat3::identity();
};

// A supporting plane of a polytope in its local frame: every point x of it has
// dot(normal, x) <= offset. The planes of a core's faces give the depth of a point inside
// it (a point's signed distance is the largest dot(normal, x) - offset over the facets).
// Single precision (16 bytes a facet; about 8 facets a cell): the depth it gives is of
// the plane as stored, and the force uses the same numbers, so the contact stays the
// gradient of one energy; the offset is rounded outward so the core stays inside.
struct CorePlane {
    float normal_x = 0.0f, normal_y = 0.0f, normal_z = 0.0f;  // outward unit normal
    float offset = 0.0f;

    RF_HD Vec3 normal() const { return {normal_x, normal_y, normal_z}; }
};

// Index of the vertex furthest along the world direction.
RF_HD inline int supportIndex(const ConvexVertexSet& s, const Vec3& direction)
{
    const Mat3& R = s.rotation;  // local direction = R^T direction
    const Vec3 local{R.m[0][0] * direction.x + R.m[1][0] * direction.y + R.m[2][0] * direction.z,
                     R.m[0][1] * direction.x + R.m[1][1] * direction.y + R.m[2][1] * direction.z,
                     R.m[0][2] * direction.x + R.m[1][2] * direction.y + R.m[2][2] * direction.z};
    int best = 0;
    double best_value = dot(s.vertices[0], local);
    for (int v = 1; v < s.n_vertices; ++v) {
        const double value = dot(s.vertices[v], local);
        if (value > best_value) {
            best_value = value;
            best = v;
        }
    }
    return best;
}

RF_HD inline Vec3 worldVertex(const ConvexVertexSet& s, int v)
{
    return s.position + s.rotation * s.vertices[v];
}

RF_HD inline Vec3 supportPoint(const ConvexVertexSet& s, const Vec3& direction)
{
    return worldVertex(s, supportIndex(s, direction));
}

struct GjkResult {
    double distance = 0.0;  // 0 when the polytopes intersect
    Vec3 point_a;           // closest point on A (a witness point when intersecting)
    Vec3 point_b;           // closest point on B
    bool intersecting = false;
    int iterations = 0;
};

namespace gjk_detail {

// One vertex of the simplex in the Minkowski difference A - B.
struct SimplexVertex {
    Vec3 w, a, b;
    int index_a = -1, index_b = -1;
};

struct Simplex {
    SimplexVertex v[4];
    double weight[4] = {0, 0, 0, 0};  // barycentric weights of the closest point
    int size = 0;
};

RF_HD inline void keep(Simplex& s, int i0, double l0)
{
    s.v[0] = s.v[i0];
    s.weight[0] = l0;
    s.size = 1;
}
RF_HD inline void keep(Simplex& s, int i0, int i1, double l0, double l1)
{
    const SimplexVertex a = s.v[i0], b = s.v[i1];
    s.v[0] = a;
    s.v[1] = b;
    s.weight[0] = l0;
    s.weight[1] = l1;
    s.size = 2;
}
RF_HD inline void keep(Simplex& s, int i0, int i1, int i2, double l0, double l1, double l2)
{
    const SimplexVertex a = s.v[i0], b = s.v[i1], c = s.v[i2];
    s.v[0] = a;
    s.v[1] = b;
    s.v[2] = c;
    s.weight[0] = l0;
    s.weight[1] = l1;
    s.weight[2] = l2;
    s.size = 3;
}

// Closest point to the origin on the segment (i0, i1); reduces the simplex to the
// supporting feature.
RF_HD inline void closestOnSegment(Simplex& s, int i0, int i1)
{
    const Vec3 a = s.v[i0].w, ab = s.v[i1].w - s.v[i0].w;
    const double denom = norm2(ab);
    const double t = denom > 0.0 ? -dot(a, ab) / denom : 0.0;
    if (t <= 0.0)
        keep(s, i0, 1.0);
    else if (t >= 1.0)
        keep(s, i1, 1.0);
    else
        keep(s, i0, i1, 1.0 - t, t);
}

// Closest point to the origin on triangle (i0, i1, i2) by its Voronoi regions
// (Ericson, Real-Time Collision Detection, 5.1.5) with P = origin.
RF_HD inline void closestOnTriangle(Simplex& s, int i0, int i1, int i2)
{
    const Vec3 a = s.v[i0].w, b = s.v[i1].w, c = s.v[i2].w;
    const Vec3 ab = b - a, ac = c - a, ap = -a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return keep(s, i0, 1.0);
    const Vec3 bp = -b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return keep(s, i1, 1.0);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double t = d1 / (d1 - d3);
        return keep(s, i0, i1, 1.0 - t, t);
    }
    const Vec3 cp = -c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return keep(s, i2, 1.0);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double t = d2 / (d2 - d6);
        return keep(s, i0, i2, 1.0 - t, t);
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return keep(s, i1, i2, 1.0 - t, t);
    }
    const double denom = va + vb + vc;
    if (!(denom > 0.0)) return closestOnSegment(s, i0, i1);  // degenerate (collinear) triangle
    const double v = vb / denom, w = vc / denom;
    keep(s, i0, i1, i2, 1.0 - v - w, v, w);
}

// True when the origin and vertex d lie on opposite sides of plane (a, b, c), or
// the tetrahedron is flat (then every face is a candidate).
RF_HD inline bool originOutsideFace(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
    const Vec3 normal = cross(b - a, c - a);
    const double side_origin = -dot(a, normal);
    const double side_d = dot(d - a, normal);
    const double scale = norm2(normal) * (norm2(b - a) + norm2(c - a) + norm2(d - a)) + 1e-300;
    if (side_d * side_d <= 1e-24 * scale) return true;
    return side_origin * side_d < 0.0;
}

// Closest point on the tetrahedron; returns false when the origin is inside.
RF_HD inline bool closestOnTetrahedron(Simplex& s)
{
    const int faces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
    double best = 1e300;
    Simplex best_simplex;
    bool outside_any = false;
    for (const auto& f : faces) {
        if (!originOutsideFace(s.v[f[0]].w, s.v[f[1]].w, s.v[f[2]].w, s.v[f[3]].w)) continue;
        outside_any = true;
        Simplex candidate = s;
        closestOnTriangle(candidate, f[0], f[1], f[2]);
        Vec3 point;
        for (int i = 0; i < candidate.size; ++i) point += candidate.weight[i] * candidate.v[i].w;
        if (norm2(point) < best) {
            best = norm2(point);
            best_simplex = candidate;
        }
    }
    if (!outside_any) return false;
    s = best_simplex;
    return true;
}

RF_HD inline Vec3 simplexPoint(const Simplex& s)
{
    Vec3 point;
    for (int i = 0; i < s.size; ++i) point += s.weight[i] * s.v[i].w;
    return point;
}

}  // namespace gjk_detail

// Distance between the hulls of A and B. initial_direction: any guess of
// (point of A - point of B), e.g. the previous result or the centre difference.
RF_HD inline GjkResult gjkDistance(const ConvexVertexSet& A, const ConvexVertexSet& B, Vec3 initial_direction,
                                   int max_iterations = 64)
{
    using namespace gjk_detail;
    GjkResult result;
    Simplex simplex;
    Vec3 v = norm2(initial_direction) > 0.0 ? initial_direction : Vec3{1.0, 0.0, 0.0};
    double v2 = 1e300;
    bool first = true;
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
        result.iterations = iteration + 1;
        SimplexVertex sv;
        sv.index_a = supportIndex(A, -v);
        sv.index_b = supportIndex(B, v);
        sv.a = worldVertex(A, sv.index_a);
        sv.b = worldVertex(B, sv.index_b);
        sv.w = sv.a - sv.b;
        if (!first) {
            // Converged: the support point gains nothing along -v (relative tolerance).
            if (v2 - dot(v, sv.w) <= 1e-12 * v2) break;
            bool repeated = false;
            for (int i = 0; i < simplex.size; ++i)
                repeated =
                    repeated || (simplex.v[i].index_a == sv.index_a && simplex.v[i].index_b == sv.index_b);
            if (repeated) break;
        }
        first = false;
        const Simplex previous = simplex;
        simplex.v[simplex.size++] = sv;
        bool inside = false;
        if (simplex.size == 1)
            simplex.weight[0] = 1.0;
        else if (simplex.size == 2)
            closestOnSegment(simplex, 0, 1);
        else if (simplex.size == 3)
            closestOnTriangle(simplex, 0, 1, 2);
        else
            inside = !closestOnTetrahedron(simplex);
        if (inside) {
            result.intersecting = true;
            break;
        }
        const Vec3 next = simplexPoint(simplex);
        const double next2 = norm2(next);
        if (next2 >= v2) {  // no progress: the round-off floor is reached
            if (next2 > v2) simplex = previous;
            break;
        }
        v = next;
        v2 = next2;
        if (v2 <= 1e-300) {
            result.intersecting = true;
            break;
        }
    }
    Vec3 pa, pb;
    for (int i = 0; i < simplex.size; ++i) {
        pa += simplex.weight[i] * simplex.v[i].a;
        pb += simplex.weight[i] * simplex.v[i].b;
    }
    result.point_a = pa;
    result.point_b = pb;
    result.distance = result.intersecting ? 0.0 : std::sqrt(v2);
    return result;
}

}  // namespace rockfrac
