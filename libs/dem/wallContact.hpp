#pragma once
// The cell–wall contact kernel: dilated cores against rigid plates and triangulated
// surfaces (liners), as patches of Hertz points (docs/theory-dem.md §7).
#include <cmath>

#include "dem/contactGeometry.hpp"

namespace rockfrac {

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

// The prism of a triangle (wall frame): its plane and the three planes through its edges
// normal to it. A point's distance from the plane and from the farthest edge plane it lies
// outside of bound its distance from the triangle from below,
//     d(x, t)^2 >= h^2 + max(0, e_0, e_1, e_2)^2,
// a cheap test before the exact closest point (docs/theory-dem.md §7, "Cost"). Tight beside a
// long sliver of a revolved liner, where a bounding sphere says little. A zero-area triangle
// gets zero normals: a zero bound, always visited.
struct TrianglePrism {
    Vec3 normal;  // unit
    double offset = 0.0;
    Vec3 edge_normal[3];  // unit, in the plane, outward from edge k (corner k to k + 1)
    double edge_offset[3] = {0.0, 0.0, 0.0};

    // The bound's square (a lower bound of d(x, t)^2 up to round-off).
    RF_HD double boundSquared(const Vec3& x) const
    {
        const double h = dot(normal, x) - offset;
        double e = 0.0;
        for (int k = 0; k < 3; ++k) {
            const double ek = dot(edge_normal[k], x) - edge_offset[k];
            if (ek > e) e = ek;
        }
        return h * h + e * e;
    }
};

RF_HD inline TrianglePrism trianglePrism(const Vec3* p)
{
    TrianglePrism t;
    const Vec3 n = cross(p[1] - p[0], p[2] - p[0]);
    const double length = norm(n);
    if (!(length > 0.0)) return t;
    t.normal = (1.0 / length) * n;
    t.offset = dot(t.normal, p[0]);
    for (int k = 0; k < 3; ++k) {
        Vec3 m = cross(p[(k + 1) % 3] - p[k], t.normal);
        const double ml = norm(m);
        if (!(ml > 0.0)) return TrianglePrism{};
        m = (1.0 / ml) * m;
        if (dot(m, p[(k + 2) % 3] - p[k]) > 0.0) m = -1.0 * m;  // outward: away from the third corner
        t.edge_normal[k] = m;
        t.edge_offset[k] = dot(m, p[k]);
    }
    return t;
}

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
    const TrianglePrism* triangle_prisms = nullptr;  // one per triangle; null: no bound test
    // The twin tests' reference: every candidate triangle and every ridge–edge pair evaluated in
    // full, none of the shortcuts (bounds, clearance, pruned pairs).
    bool exhaustive = false;
    const int* item_cell = nullptr;
    const int* item_wall = nullptr;
    const int* item_triangle_offset = nullptr;  // candidate triangles of item i
    const int* item_triangles = nullptr;
    // Per item: the centre at the list build (wall frame) and its distance from the candidate
    // triangles then; null: every item searched.
    const Vec3* item_centre_at_build = nullptr;
    const double* item_clearance_at_build = nullptr;
    ContactItemOutputs items;
    Vec3* force_on_cell = nullptr;
    Vec3* torque_on_cell = nullptr;
    double* wall_power = nullptr;  // force on the cell . wall velocity at the contact [W]
    // A decomposed model (dem/demExchange.hpp): only the items of cells with owned_cell[c]
    // are evaluated (a ghost's are its owner's); null: every item.
    const unsigned char* owned_cell = nullptr;
};

RF_HD inline Vec3 wallPointVelocity(const WallPose& wall, const Vec3& point)
{
    return wall.velocity + cross(wall.angular_velocity, point - wall.origin);
}

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
    // A triangle whose prism keeps it farther than the tolerance beyond the nearest point found
    // so far is left unvisited: the visit would return without touching the sums, so the result
    // is the same bit for bit. margin covers the round-off of the bound (coordinates' 1e-12).
    const TrianglePrism* prisms = a.exhaustive ? nullptr : a.triangle_prisms;
    const double margin =
        1e-3 * tolerance + 1e-12 * (std::fabs(local.x) + std::fabs(local.y) + std::fabs(local.z));
    auto beyond = [&](int t, double& bound) {
        if (prisms == nullptr) return false;
        const double reach = s.distance + tolerance + margin;
        const double b2 = prisms[t].boundSquared(local);
        if (!(b2 > reach * reach)) return false;
        bound = record ? std::sqrt(b2) - margin : reach;
        return true;
    };
    if (culled) {
        // Start from the centre's nearest triangle: a close first bound.
        const double reach = norm(local - cull->centre);
        sums.visit(a.triangle_vertices + 3 * a.item_triangles[begin + cull->nearest], local, tolerance, s);
        for (int e = begin; e < end; ++e) {
            if (e - begin == cull->nearest) continue;
            if (cull->centre_distance[e - begin] - reach > s.distance + tolerance) continue;
            const int t = a.item_triangles[e];
            double bound = 0.0;
            if (beyond(t, bound)) continue;
            sums.visit(a.triangle_vertices + 3 * t, local, tolerance, s);
        }
    } else {
        for (int e = begin; e < end; ++e) {
            const int t = a.item_triangles[e];
            // Recorded for the core's vertices: the exact distance or, for a triangle left
            // unvisited, the bound (below the exact one, so every later cull stays safe).
            double d = 0.0;
            if (!beyond(t, d)) d = sums.visit(a.triangle_vertices + 3 * t, local, tolerance, s);
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

// The core's edges as the ridge pairs see them, once per cell and wall (world frame): each
// edge's unit direction (the one edgeAngleWeight takes), middle and half length. A core with
// more edges than this holds is looked at edge by edge (n = 0).
constexpr int max_wall_patch_edges = 64;
struct CoreEdgeBounds {
    bool filled = false;
    int n = 0;
    Vec3 direction[max_wall_patch_edges], middle[max_wall_patch_edges];
    double half[max_wall_patch_edges];

    RF_HD void fill(const ConvexVertexSet& core, const unsigned char* edges, int n_entries)
    {
        filled = true;
        if (n_entries > 2 * max_wall_patch_edges) return;
        for (int j = 0; j + 1 < n_entries; j += 2) {
            const Vec3 x0 = worldVertex(core, edges[j]), x1 = worldVertex(core, edges[j + 1]);
            direction[j / 2] = normalised(x1 - x0);
            middle[j / 2] = 0.5 * (x0 + x1);
            half[j / 2] = 0.5 * norm(x1 - x0);
        }
        n = n_entries / 2;
    }
};

// The pairs of a ridge (r0, r1) of triangle p with the core's edges (see wallPatch). A core
// edge whose middle is farther from the ridge's line than r_d plus its half length cannot come
// within r_d of the ridge (its overlap would be <= 0): it is passed over without the closest
// points, which leaves every point of the patch as it was (docs/theory-dem.md §7, "Cost").
RF_HD inline void ridgeEdgePairs(const Vec3& r0, const Vec3& r1, const Vec3* p, double side,
                                 const ConvexVertexSet& core, const unsigned char* edges,
                                 const CoreEdgeBounds& bounds, int n_entries, double radius,
                                 PatchPoint* points, int& n, bool& cores_intersect)
{
    const Vec3 ridge = normalised(r1 - r0);
    const double margin = 1e-6 * radius;
    for (int j = 0; j + 1 < n_entries; j += 2) {
        Vec3 along;
        if (bounds.n > 0) {
            const double limit = radius + bounds.half[j / 2] + margin;
            if (norm2(cross(bounds.middle[j / 2] - r0, ridge)) > limit * limit) continue;
            along = bounds.direction[j / 2];
        }
        const Vec3 x0 = worldVertex(core, edges[j]), x1 = worldVertex(core, edges[j + 1]);
        if (bounds.n == 0) along = normalised(x1 - x0);
        EdgeAngleWeight w;  // 0 near parallel: left to the vertex pairs
        if (!edgeAngleWeight(along, ridge, radius, w)) continue;
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
    CoreEdgeBounds core_edges;  // filled at the first ridge within reach
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
                if (n_entries > 0) {
                    if (!core_edges.filled) core_edges.fill(core, edges, a.exhaustive ? 0 : n_edge_entries);
                    ridgeEdgePairs(r0, r1, p, side, core, edges, core_edges, n_entries, radius, points, n,
                                   cores_intersect);
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
    if (a.owned_cell && !a.owned_cell[c]) return;
    const WallPose& wall = a.walls[a.item_wall[item]];
    a.force_on_cell[item] = a.torque_on_cell[item] = Vec3{};
    a.wall_power[item] = 0.0;
    const ConvexVertexSet core = cellCore(a.cells, c);
    const double radius = a.cells.dilation_radius[c];
    PatchPoint points[max_patch_points];
    bool cores_intersect = false;
    double side = 1.0;
    SurfaceCull cull;
    if (wall.kind == wallTriSurface && a.item_clearance_at_build != nullptr && !a.exhaustive) {
        // The centre's distance from the surface now is at least its distance at the list build
        // less how far it has moved in the wall's frame since: when that keeps it beyond the
        // dilated core's reach (plus a round-off margin), the search below would find the same
        // and the item is cleared without it (docs/theory-dem.md §7, "Cost").
        const Vec3 local = transposeTimes(wall.rotation, core.position - wall.origin);
        const double margin = 1e-9 * a.cells.bounding_radius[c] +
                              1e-12 * (std::fabs(local.x) + std::fabs(local.y) + std::fabs(local.z));
        if (a.item_clearance_at_build[item] - norm(local - a.item_centre_at_build[item]) >
            a.cells.bounding_radius[c] + margin)
            return clearItem(a.items, item);
    }
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

}  // namespace rockfrac
