#pragma once
// The cell–cell contact kernel: pairs of dilated cores (GJK narrow phase), as one
// Hertz point (the paper's) or a patch of feature pairs (docs/theory-dem.md §6).
#include <cmath>

#include "dem/contactGeometry.hpp"

namespace rockfrac {

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
    // A decomposed model (dem/demExchange.hpp): only pairs with counted[p] are evaluated (the
    // others are another rank's, their results sent here); null: every pair.
    const unsigned char* counted = nullptr;
};

// Most points of one cell–cell patch; the deepest are kept beyond that.
constexpr int max_pair_patch_points = 32;

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

// Pair p; an active contact adds its energies to sums.
template <class Law>
RF_HD inline void pairKernel(const PairKernelArgs& a, int p, ContactBlockSums& sums)
{
    if (a.counted && !a.counted[p]) return;  // another rank's (dem/demExchange.hpp)
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

}  // namespace rockfrac
