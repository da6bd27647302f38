#include "voronoi/domain.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "voronoi/polyhedron.hpp"

namespace rockfrac {

namespace {

constexpr double pi = 3.14159265358979323846;

// A convex polyhedron as a list of face polygons, each counter-clockwise seen
// from outside. Only used to find the vertices and volume of a plane domain.
using Polygon = std::vector<Vec3>;
using FaceList = std::vector<Polygon>;

FaceList boxFaces(const Vec3& lo, const Vec3& hi)
{
    const Vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                       {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    return {{c[0], c[3], c[2], c[1]}, {c[4], c[5], c[6], c[7]}, {c[0], c[1], c[5], c[4]},
            {c[2], c[3], c[7], c[6]}, {c[0], c[4], c[7], c[3]}, {c[1], c[2], c[6], c[5]}};
}

// Two unit vectors u, w with u x w = n, spanning the plane normal to n.
void planeBasis(const Vec3& n, Vec3& u, Vec3& w)
{
    const Vec3 helper = std::fabs(n.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    u = normalised(cross(helper, n));
    w = cross(n, u);
}

// The points on the cutting plane, ordered counter-clockwise around the
// outward normal, with near-duplicates (the same edge crossing seen from the
// two faces sharing the edge) merged.
Polygon capPolygon(std::vector<Vec3> points, const Vec3& normal, double mergeDistance)
{
    Polygon cap;
    for (const Vec3& p : points) {
        const bool seen =
            std::any_of(cap.begin(), cap.end(), [&](const Vec3& q) { return norm(p - q) <= mergeDistance; });
        if (!seen) cap.push_back(p);
    }
    if (cap.size() < 3) return {};
    Vec3 centre;
    for (const Vec3& p : cap) centre += p;
    centre /= static_cast<double>(cap.size());
    Vec3 u, w;
    planeBasis(normal, u, w);
    auto angle = [&](const Vec3& p) { return std::atan2(dot(p - centre, w), dot(p - centre, u)); };
    std::sort(cap.begin(), cap.end(), [&](const Vec3& a, const Vec3& b) { return angle(a) < angle(b); });
    return cap;
}

// Keep the part of a convex polyhedron where plane.signedDistance <= 0
// (Sutherland-Hodgman on every face, then a new face on the plane). Vertices
// within `tolerance` of the plane count as on it.
FaceList clip(const FaceList& faces, const HalfSpace& plane, double tolerance)
{
    // A plane that cuts nothing off (redundant, touching, or repeating a face
    // already made) must not add a second face on the plane.
    const bool cutsSomething = std::any_of(faces.begin(), faces.end(), [&](const Polygon& face) {
        return std::any_of(face.begin(), face.end(),
                           [&](const Vec3& p) { return plane.signedDistance(p) > tolerance; });
    });
    if (!cutsSomething) return faces;

    FaceList result;
    std::vector<Vec3> onPlane;
    for (const Polygon& face : faces) {
        Polygon kept;
        const std::size_t n = face.size();
        for (std::size_t k = 0; k < n; ++k) {
            const Vec3& p = face[k];
            const Vec3& q = face[(k + 1) % n];
            const double dp = plane.signedDistance(p), dq = plane.signedDistance(q);
            if (dp <= tolerance) kept.push_back(p);
            if (std::fabs(dp) <= tolerance) onPlane.push_back(p);
            if ((dp < -tolerance && dq > tolerance) || (dp > tolerance && dq < -tolerance)) {
                const Vec3 crossing = p + (dp / (dp - dq)) * (q - p);
                kept.push_back(crossing);
                onPlane.push_back(crossing);
            }
        }
        if (kept.size() >= 3) result.push_back(std::move(kept));
    }
    Polygon cap = capPolygon(std::move(onPlane), plane.normal, 1e3 * tolerance);
    if (!cap.empty()) result.push_back(std::move(cap));
    return result;
}

FaceList clipAll(FaceList faces, const std::vector<HalfSpace>& planes, double tolerance)
{
    for (const HalfSpace& plane : planes) {
        faces = clip(faces, plane, tolerance);
        if (faces.empty()) break;
    }
    return faces;
}

BoundingBox boundsOf(const FaceList& faces)
{
    BoundingBox box{faces.front().front(), faces.front().front()};
    for (const Polygon& face : faces)
        for (const Vec3& p : face)
            for (int i = 0; i < 3; ++i) {
                box.lower[i] = std::min(box.lower[i], p[i]);
                box.upper[i] = std::max(box.upper[i], p[i]);
            }
    return box;
}

double volumeOf(const FaceList& faces)
{
    std::vector<Vec3> vertices;
    std::vector<int> offsets{0}, indices;
    for (const Polygon& face : faces) {
        for (const Vec3& p : face) {
            indices.push_back(static_cast<int>(vertices.size()));
            vertices.push_back(p);
        }
        offsets.push_back(static_cast<int>(indices.size()));
    }
    const PolyhedronView view{vertices.data(), offsets.data(), indices.data(),
                              static_cast<int>(faces.size())};
    return massProperties(view).volume;
}

double largestSide(const BoundingBox& box)
{
    const Vec3 s = box.size();
    return std::max({s.x, s.y, s.z});
}

bool isFinite(const Vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

const char* planesAdvice = "give the outward facets of a closed convex body (e.g. its convex hull)";

std::vector<HalfSpace> normalisedPlanes(std::vector<HalfSpace> planes)
{
    for (std::size_t i = 0; i < planes.size(); ++i) {
        HalfSpace& h = planes[i];
        const double length = norm(h.normal);
        if (!isFinite(h.normal) || !std::isfinite(h.offset) || !(length > 0.0)) {
            std::ostringstream msg;
            msg << "domain plane " << i << " has a zero or non-finite normal or offset; " << planesAdvice;
            throw UserError(msg.str());
        }
        h.normal /= length;
        h.offset /= length;
    }
    return planes;
}

}  // namespace

double Cylinder::distanceFromAxis(const Vec3& p) const
{
    const Vec3 d = p - axisPoint;
    return norm(d - dot(d, axisDirection) * axisDirection);
}

double BoundingBox::volume() const
{
    const Vec3 s = size();
    return s.x * s.y * s.z;
}

// The polytope is found in two passes of clipping a box by every plane: first
// a huge box (to find where the body is, and to detect an unbounded set of
// planes), then a box just around the body so the round-off is relative to the
// body's own size.
Domain Domain::fromPlanes(std::vector<HalfSpace> planes)
{
    planes = normalisedPlanes(std::move(planes));
    if (planes.size() < 4)
        throw UserError("a plane domain needs at least 4 planes; " + std::string(planesAdvice));

    double reach = 0.0;
    for (const HalfSpace& h : planes) reach = std::max(reach, std::fabs(h.offset));
    if (!(reach > 0.0))
        throw UserError("the domain planes all pass through the origin; " + std::string(planesAdvice));

    const double hugeSide = 1e4 * reach;
    const FaceList rough =
        clipAll(boxFaces(Vec3{-hugeSide, -hugeSide, -hugeSide}, Vec3{hugeSide, hugeSide, hugeSide}), planes,
                1e-12 * hugeSide);
    if (rough.empty()) throw UserError("the domain planes enclose no volume; " + std::string(planesAdvice));
    const BoundingBox roughBox = boundsOf(rough);
    for (int i = 0; i < 3; ++i)
        if (roughBox.upper[i] > 0.5 * hugeSide || roughBox.lower[i] < -0.5 * hugeSide)
            throw UserError("the domain planes do not enclose a bounded volume; " +
                            std::string(planesAdvice));

    const double margin = 0.01 * largestSide(roughBox) + 1e-9 * reach;
    const Vec3 pad{margin, margin, margin};
    const FaceList exact =
        clipAll(boxFaces(roughBox.lower - pad, roughBox.upper + pad), planes, 1e-13 * largestSide(roughBox));
    const double volume = exact.empty() ? 0.0 : volumeOf(exact);
    if (!(volume > 1e-12 * std::pow(largestSide(roughBox), 3)))
        throw UserError("the domain planes enclose no volume; " + std::string(planesAdvice));

    Domain domain;
    domain.planes_ = std::move(planes);
    domain.boundingBox_ = boundsOf(exact);
    domain.volume_ = volume;
    return domain;
}

Domain Domain::box(const Vec3& lower, const Vec3& upper)
{
    return fromPlanes({{{1, 0, 0}, upper.x},
                       {{-1, 0, 0}, -lower.x},
                       {{0, 1, 0}, upper.y},
                       {{0, -1, 0}, -lower.y},
                       {{0, 0, 1}, upper.z},
                       {{0, 0, -1}, -lower.z}});
}

Domain Domain::disc(const Vec3& centre, const Vec3& axis, double diameter, double thickness)
{
    if (!isFinite(centre) || !isFinite(axis) || !(norm(axis) > 0.0))
        throw UserError("disc domain: the centre and axis must be finite and the axis non-zero");
    if (!(diameter > 0.0) || !(thickness > 0.0) || !std::isfinite(diameter) || !std::isfinite(thickness))
        throw UserError("disc domain: the diameter and thickness must be positive numbers [m]");

    const Vec3 n = normalised(axis);
    const double radius = 0.5 * diameter;
    const double halfThickness = 0.5 * thickness;

    Domain domain;
    domain.planes_ = {{n, dot(n, centre) + halfThickness}, {-n, -dot(n, centre) + halfThickness}};
    domain.cylinder_ = Cylinder{centre, n, radius};
    // Extent along coordinate i: the rim circle reaches r sqrt(1 - n_i^2), the
    // faces add t/2 |n_i|.
    for (int i = 0; i < 3; ++i) {
        const double halfExtent =
            radius * std::sqrt(std::max(0.0, 1.0 - n[i] * n[i])) + halfThickness * std::fabs(n[i]);
        domain.boundingBox_.lower[i] = centre[i] - halfExtent;
        domain.boundingBox_.upper[i] = centre[i] + halfExtent;
    }
    domain.volume_ = pi * radius * radius * thickness;
    return domain;
}

bool Domain::contains(const Vec3& p) const
{
    for (const HalfSpace& h : planes_)
        if (h.signedDistance(p) > 0.0) return false;
    return !cylinder_ || cylinder_->distanceFromAxis(p) <= cylinder_->radius;
}

}  // namespace rockfrac
