#include "geometry/crusherGeometry.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace rockfrac {

namespace {

constexpr double pi = 3.14159265358979323846;

struct Point2 {
    double r, z;
};
Point2 operator-(Point2 a, Point2 b)
{
    return {a.r - b.r, a.z - b.z};
}
double dot2(Point2 a, Point2 b)
{
    return a.r * b.r + a.z * b.z;
}
double cross2(Point2 a, Point2 b)
{
    return a.r * b.z - a.z * b.r;
}
Point2 toPoint(const ProfilePoint& p)
{
    return {p.r, p.z};
}

// Nearest point of segment [a, b] to p.
Point2 nearestOnSegment(Point2 p, Point2 a, Point2 b)
{
    const Point2 ab = b - a;
    const double len2 = dot2(ab, ab);
    const double s = len2 > 0.0 ? std::clamp(dot2(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return {a.r + s * ab.r, a.z + s * ab.z};
}
double distance2(Point2 a, Point2 b)
{
    return std::hypot(a.r - b.r, a.z - b.z);
}

bool segmentsCross(Point2 a, Point2 b, Point2 c, Point2 d)
{
    const double d1 = cross2(b - a, c - a), d2 = cross2(b - a, d - a);
    const double d3 = cross2(d - c, a - c), d4 = cross2(d - c, b - c);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

// Distance between segments [a0, a1] and [b0, b1]; `onA` receives the nearest point of the first.
double segmentDistance(Point2 a0, Point2 a1, Point2 b0, Point2 b1, Point2& onA)
{
    if (segmentsCross(a0, a1, b0, b1)) {
        onA = a0;
        return 0.0;
    }
    double best = 1e300;
    auto consider = [&](double d, Point2 pa) {
        if (d < best) {
            best = d;
            onA = pa;
        }
    };
    for (Point2 b : {b0, b1}) {
        const Point2 pa = nearestOnSegment(b, a0, a1);
        consider(distance2(pa, b), pa);
    }
    for (Point2 a : {a0, a1}) consider(distance2(a, nearestOnSegment(a, b0, b1)), a);
    return best;
}

// Rodrigues: rotation by |theta| about theta / |theta|.
Mat3 rotationFromVector(const Vec3& theta)
{
    const double angle = norm(theta);
    Mat3 R = Mat3::identity();
    if (angle == 0.0) return R;
    const Vec3 k = theta / angle;
    const double c = std::cos(angle), s = std::sin(angle);
    const double K[3][3] = {{0, -k.z, k.y}, {k.z, 0, -k.x}, {-k.y, k.x, 0}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) R(i, j) = c * (i == j) + s * K[i][j] + (1 - c) * k[i] * k[j];
    return R;
}

Profile shifted(const Profile& p, double dz)
{
    Profile q = p;
    for (auto& point : q) point.z += dz;
    return q;
}

double distanceToProfile(Point2 p, const Profile& profile)
{
    double best = 1e300;
    for (std::size_t i = 0; i + 1 < profile.size(); ++i)
        best =
            std::min(best, distance2(p, nearestOnSegment(p, toPoint(profile[i]), toPoint(profile[i + 1]))));
    return best;
}

// Bisection for an increasing f on [lo, hi] with f(lo) <= 0 <= f(hi).
template <class F>
double bisect(F f, double lo, double hi)
{
    for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++it) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) > 0 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

TriSurface revolveProfile(const Profile& profile, int nSegments, SurfaceFacing facing)
{
    if (profile.size() < 2) throw UserError("a surface of revolution needs a profile of at least 2 points");
    if (nSegments < 3) throw UserError("a surface of revolution needs at least 3 segments around");
    TriSurface s;
    std::vector<int> first(profile.size());
    for (std::size_t p = 0; p < profile.size(); ++p) {
        if (profile[p].r < 0.0)
            throw UserError("profile point " + std::to_string(p) + " has a negative radius");
        if (p > 0 && profile[p].r == 0.0 && profile[p - 1].r == 0.0)
            throw UserError("profile segment " + std::to_string(p - 1) + " lies on the axis");
        first[p] = static_cast<int>(s.points.size());
        if (profile[p].r == 0.0) {
            s.points.push_back({0.0, 0.0, profile[p].z});
            continue;
        }
        for (int k = 0; k < nSegments; ++k) {
            const double a = 2.0 * pi * k / nSegments;
            s.points.push_back({profile[p].r * std::cos(a), profile[p].r * std::sin(a), profile[p].z});
        }
    }
    auto vertex = [&](std::size_t p, int k) {
        return profile[p].r == 0.0 ? first[p] : first[p] + k % nSegments;
    };
    for (std::size_t p = 0; p + 1 < profile.size(); ++p)
        for (int k = 0; k < nSegments; ++k) {
            const int a0 = vertex(p, k), a1 = vertex(p, k + 1), b0 = vertex(p + 1, k),
                      b1 = vertex(p + 1, k + 1);
            if (profile[p + 1].r > 0.0) s.triangles.push_back({a0, b1, b0});
            if (profile[p].r > 0.0) s.triangles.push_back({a0, a1, b1});
        }
    // Orient: the area-weighted radial component of the normals tells which way they face.
    double radial = 0.0;
    for (const auto& t : s.triangles) {
        const Vec3 n = cross(s.points[t[1]] - s.points[t[0]], s.points[t[2]] - s.points[t[0]]);
        const Vec3 c = (s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.0;
        radial += n.x * c.x + n.y * c.y;
    }
    if ((radial > 0.0) != (facing == SurfaceFacing::awayFromAxis))
        for (auto& t : s.triangles) std::swap(t[1], t[2]);
    return s;
}

TriSurface revolveProfileShaped(const Profile& profile, int nSegments, SurfaceFacing facing)
{
    revolveProfile(profile, 3, facing);  // the same checks of the profile
    if (nSegments < 3) throw UserError("a surface of revolution needs at least 3 segments around");
    double r_max = 0.0;
    for (const auto& p : profile) r_max = std::max(r_max, p.r);
    const auto ringCount = [&](double r) {
        if (r <= 0.0) return 1;
        return std::max(3,
                        std::min(nSegments, static_cast<int>(std::ceil(2.0 * nSegments * r / r_max - 1e-9))));
    };
    const auto spacing = [&](double r) {  // target circumferential spacing at r
        return 2.0 * pi * std::max(r, 0.5 * r_max) / nSegments;
    };
    // Refined profile: segment [p, p+1] split where the count of local steps
    // h(s) = 0.87 x the circumferential spacing, N(s) = integral of ds / h, passes an
    // integer (N(end) rounded): rows of near-equilateral triangles of the local size.
    Profile rings;
    for (std::size_t p = 0; p + 1 < profile.size(); ++p) {
        const ProfilePoint a = profile[p], b = profile[p + 1];
        const double length = std::hypot(b.r - a.r, b.z - a.z);
        const int n_sub = 2000;
        std::vector<double> steps(n_sub + 1, 0.0);  // N at t = i / n_sub (midpoint rule)
        for (int i = 0; i < n_sub; ++i) {
            const double t = (i + 0.5) / n_sub;
            steps[i + 1] = steps[i] + length / n_sub / (0.87 * spacing(a.r + t * (b.r - a.r)));
        }
        const int m = std::max(1, static_cast<int>(std::lround(steps[n_sub])));
        int i = 0;
        for (int k = 0; k < m; ++k) {
            const double target = steps[n_sub] * k / m;
            while (i < n_sub && steps[i + 1] < target) ++i;
            const double t =
                (i + (steps[i + 1] > steps[i] ? (target - steps[i]) / (steps[i + 1] - steps[i]) : 0.0)) /
                n_sub;
            rings.push_back({a.r + t * (b.r - a.r), a.z + t * (b.z - a.z)});
        }
    }
    rings.push_back(profile.back());
    TriSurface s;
    std::vector<int> first(rings.size()), count(rings.size());
    for (std::size_t k = 0; k < rings.size(); ++k) {
        first[k] = static_cast<int>(s.points.size());
        count[k] = ringCount(rings[k].r);
        for (int i = 0; i < count[k]; ++i) {  // every other ring turned by half a spacing
            const double a = 2.0 * pi * (i + 0.5 * (k % 2)) / count[k];
            s.points.push_back({rings[k].r * std::cos(a), rings[k].r * std::sin(a), rings[k].z});
        }
    }
    // Zip ring A to ring B: advance on the ring whose next point comes first in angle.
    for (std::size_t k = 0; k + 1 < rings.size(); ++k) {
        const int na = count[k], nb = count[k + 1];
        const double oa = 0.5 * (k % 2), ob = 0.5 * ((k + 1) % 2);
        const auto A = [&](int i) { return first[k] + i % na; };
        const auto B = [&](int j) { return first[k + 1] + j % nb; };
        int i = 0, j = 0;
        while (i < na || j < nb) {
            const double next_a = na > 1 && i < na ? (i + 1 + oa) / na : 2.0;
            const double next_b = nb > 1 && j < nb ? (j + 1 + ob) / nb : 2.0;
            if (next_a <= next_b) {
                s.triangles.push_back({A(i), A(i + 1), B(j)});
                ++i;
            } else {
                s.triangles.push_back({A(i), B(j + 1), B(j)});
                ++j;
            }
            if (na == 1) i = na;  // the axis point: a fan of nb triangles
            if (nb == 1) j = nb;
        }
    }
    // Orient as revolveProfile does.
    double radial = 0.0;
    for (const auto& t : s.triangles) {
        const Vec3 n = cross(s.points[t[1]] - s.points[t[0]], s.points[t[2]] - s.points[t[0]]);
        const Vec3 c = (s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.0;
        radial += n.x * c.x + n.y * c.y;
    }
    if ((radial > 0.0) != (facing == SurfaceFacing::awayFromAxis))
        for (auto& t : s.triangles) std::swap(t[1], t[2]);
    return s;
}

double CrusherKinematics::period() const
{
    return 2.0 * pi / eccentric_speed;
}

double CrusherKinematics::closedSideAzimuth(double t) const
{
    return phase + eccentric_speed * t;
}

MantlePose mantlePose(const CrusherKinematics& k, double t)
{
    // Tilt about the horizontal axis d x z (d: towards the closed side), so points
    // below the pivot move towards d.
    const double phi = k.closedSideAzimuth(t);
    const Vec3 d{std::cos(phi), std::sin(phi), 0.0};
    const Vec3 z{0.0, 0.0, 1.0};
    MantlePose pose;
    pose.rotation_vector = k.eccentric_angle * cross(d, z);
    pose.rotation = rotationFromVector(pose.rotation_vector);
    pose.translation = k.pivot - pose.rotation * k.pivot;
    // R(t) = Rz(Omega t) R(0) Rz(Omega t)^T  =>  dR/dt R^T = Omega (Z - R Z R^T).
    pose.angular_velocity = k.eccentric_speed * (z - pose.rotation * z);
    pose.velocity = -cross(pose.angular_velocity, pose.rotation * k.pivot);
    return pose;
}

MantlePose mantlePose(const CrusherKinematics& k, double t, double spin_angle, double spin_rate)
{
    // x = T + R_g Rz(psi) x0: d/dt = T' + omega_g x (x - T) + R_g (psi' z x Rz x0)
    //   = T' + (omega_g + psi' R_g z) x (x - T); T and T' are the gyration's.
    MantlePose pose = mantlePose(k, t);
    const Vec3 axis = pose.rotation * Vec3{0.0, 0.0, 1.0};
    pose.rotation = pose.rotation * rotationFromVector(Vec3{0.0, 0.0, spin_angle});
    pose.spin_angle = spin_angle;
    pose.angular_velocity = pose.angular_velocity + spin_rate * axis;
    return pose;
}

Profile tiltInMeridian(const Profile& mantle, double pivotZ, double angle)
{
    const double c = std::cos(angle), s = std::sin(angle);
    Profile out;
    for (const auto& p : mantle) {
        const double dz = p.z - pivotZ;
        out.push_back({c * p.r - s * dz, pivotZ + s * p.r + c * dz});
    }
    return out;
}

double profileDistance(const Profile& a, const Profile& b, double* atZ)
{
    double best = 1e300;
    Point2 where{0, 0};
    for (std::size_t i = 0; i + 1 < a.size(); ++i)
        for (std::size_t j = 0; j + 1 < b.size(); ++j) {
            Point2 onA{0, 0};
            const double d =
                segmentDistance(toPoint(a[i]), toPoint(a[i + 1]), toPoint(b[j]), toPoint(b[j + 1]), onA);
            if (d < best) {
                best = d;
                where = onA;
            }
        }
    if (atZ) *atZ = where.z;
    return best;
}

ChamberGaps chamberGaps(const CrusherChamber& chamber, const CrusherKinematics& k)
{
    ChamberGaps g;
    const Profile closed = tiltInMeridian(chamber.mantle, k.pivot.z, k.eccentric_angle);
    const Profile open = tiltInMeridian(chamber.mantle, k.pivot.z, -k.eccentric_angle);
    g.closed = profileDistance(closed, chamber.concave, &g.closed_z);
    g.open = profileDistance(open, chamber.concave, &g.open_z);
    const auto top =
        *std::max_element(chamber.concave.begin(), chamber.concave.end(),
                          [](const ProfilePoint& a, const ProfilePoint& b) { return a.z < b.z; });
    g.feed_closed = distanceToProfile(toPoint(top), closed);
    g.feed_open = distanceToProfile(toPoint(top), open);
    return g;
}

ChamberDesign designChamber(const ChamberSpec& spec)
{
    if (spec.mantle.size() < 2 || spec.concave.size() < 2)
        throw UserError("the mantle and concave profiles need at least 2 points each");
    if (!(spec.closed_side_setting > 0)) throw UserError("closedSideSetting must be positive");
    if (!(spec.eccentric_throw > 0)) throw UserError("throw must be positive");
    if (!(spec.eccentric_speed_rpm > 0)) throw UserError("eccentricSpeed must be positive");
    ChamberDesign d;
    d.discharge_level = std::min_element(spec.mantle.begin(), spec.mantle.end(), [](auto& a, auto& b) {
                            return a.z < b.z;
                        })->z;
    const double arm = spec.pivot_height - d.discharge_level;
    if (!(arm > spec.eccentric_throw))
        throw UserError("pivotHeight must lie well above the mantle's lower rim (z = " +
                        std::to_string(d.discharge_level) + " m)");
    d.axis_offset_angle = std::asin(0.5 * spec.eccentric_throw / arm);
    d.kinematics.pivot = {0.0, 0.0, spec.pivot_height};
    d.kinematics.eccentric_speed = 2.0 * pi * spec.eccentric_speed_rpm / 60.0;
    d.kinematics.phase = spec.phase;
    d.chamber.mantle = spec.mantle;

    // Heights over which the concave may move: the size of the whole chamber.
    double zmin = 1e300, zmax = -1e300;
    for (const Profile* p : {&spec.mantle, &spec.concave})
        for (const auto& q : *p) zmin = std::min(zmin, q.z), zmax = std::max(zmax, q.z);
    const double range = zmax - zmin;

    auto closedGap = [&](double shift, double alpha) {
        return profileDistance(tiltInMeridian(spec.mantle, spec.pivot_height, alpha),
                               shifted(spec.concave, shift));
    };
    // The gap is 1-Lipschitz in the shift, so steps of |gap - CSS| walk from the drawn
    // position to the nearest shift with the setting without jumping over it (far
    // away the concave would pass the mantle and the gap grow again).
    auto solveShift = [&](double alpha) {
        const auto f = [&](double h) { return closedGap(h, alpha) - spec.closed_side_setting; };
        const double direction = f(0.0) > 0 ? -1.0 : 1.0;
        double from = 0.0, value = f(0.0);
        for (int it = 0; it < 100000 && std::abs(from) < range; ++it) {
            const double to = from + direction * std::max(std::abs(value), 1e-5);
            const double next = f(to);
            if ((next > 0) != (value > 0) || next == 0)
                return direction < 0 ? bisect(f, to, from) : bisect(f, from, to);
            from = to;
            value = next;
        }
        throw UserError("the concave cannot be placed at closedSideSetting " +
                        std::to_string(spec.closed_side_setting) +
                        " m: moving it up or down never gives that gap; check the profiles");
    };
    auto throwError = [&](double alpha) {
        CrusherChamber c{spec.mantle, shifted(spec.concave, solveShift(alpha))};
        CrusherKinematics k = d.kinematics;
        k.eccentric_angle = alpha;
        const ChamberGaps g = chamberGaps(c, k);
        return g.open - g.closed - spec.eccentric_throw;
    };

    double alpha = d.axis_offset_angle;
    if (spec.throw_definition == ThrowDefinition::settingDifference) {
        const double hi = std::min(4.0 * d.axis_offset_angle, 0.5);
        if (throwError(hi) < 0)
            throw UserError("no eccentric angle up to " + std::to_string(hi) +
                            " rad gives the requested throw");
        alpha = bisect(throwError, 0.0, hi);
    }
    d.kinematics.eccentric_angle = alpha;
    d.concave_shift = solveShift(alpha);
    d.chamber.concave = shifted(spec.concave, d.concave_shift);
    d.gaps = chamberGaps(d.chamber, d.kinematics);
    return d;
}

}  // namespace rockfrac
