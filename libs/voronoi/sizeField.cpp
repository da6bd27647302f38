#include "voronoi/sizeField.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.hpp"
#include "core/knownEntries.hpp"

namespace rockfrac {

namespace {

constexpr double pi = 3.14159265358979323846;

std::string mm(double metres)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.4g mm", 1e3 * metres);
    return text;
}

// True if p lies in the box, up to a relative tolerance of its diagonal.
bool inBox(const BoundingBox& box, const Vec3& p)
{
    const double tol = 1e-9 * norm(box.size());
    for (int i = 0; i < 3; ++i)
        if (p[i] < box.lower[i] - tol || p[i] > box.upper[i] + tol) return false;
    return true;
}

// True if the plane through p with unit normal n meets the box (touching counts).
bool planeMeetsBox(const BoundingBox& box, const Vec3& p, const Vec3& n)
{
    const double tol = 1e-9 * norm(box.size());
    double low = std::numeric_limits<double>::max(), high = -low;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 c{corner & 1 ? box.upper.x : box.lower.x, corner & 2 ? box.upper.y : box.lower.y,
                     corner & 4 ? box.upper.z : box.lower.z};
        const double s = dot(c - p, n);
        low = std::min(low, s);
        high = std::max(high, s);
    }
    return low <= tol && high >= -tol;
}

std::string boxText(const BoundingBox& box)
{
    auto v = [](const Vec3& p) {
        return "(" + formatNumber(p.x) + " " + formatNumber(p.y) + " " + formatNumber(p.z) + ")";
    };
    return v(box.lower) + " to " + v(box.upper);
}

Vec3 readDirection(const Dictionary& r, const std::string& key, const std::string& where)
{
    const Vec3 v = r.get<Vec3>(key);
    if (!(norm(v) > 0.0) || !std::isfinite(norm(v)))
        throw UserError(r.location(key).str() + ": " + where + "/" + key +
                        " is zero or not finite; give a non-zero vector, e.g. (0 0 1)");
    return normalised(v);
}

SizeRegion readRegion(const Dictionary& r, const std::string& name, double baseSize, double minimumSize,
                      const BoundingBox& box)
{
    const std::string where = "sizeField/regions/" + name;
    checkKnownEntries(r, sizeRegionEntries());
    SizeRegion region;
    region.name = name;
    const std::string type = r.getWord("type", {"point", "line", "plane"});
    region.kind = type == "point"  ? SizeRegion::Kind::point
                  : type == "line" ? SizeRegion::Kind::line
                                   : SizeRegion::Kind::plane;
    region.point = r.get<Vec3>("point");
    if (region.kind == SizeRegion::Kind::line) region.direction = readDirection(r, "direction", where);
    if (region.kind == SizeRegion::Kind::plane) region.direction = readDirection(r, "normal", where);
    region.size = r.getScalar("size", Bounds::positive());
    if (region.size < minimumSize)
        throw UserError(r.location("size").str() + ": " + where + "/size " + mm(region.size) +
                        " is below the smallest allowed cell, " + mm(minimumSize) + " (" +
                        formatNumber(smallestSizeInDilationRadii) + " x dilationFraction x the base size " +
                        mm(baseSize) +
                        ": finer cells are too small for their dilation radius and the DEM run " +
                        "fails at its first step); give a size of at least " + mm(minimumSize) +
                        " or a smaller dilationFraction");
    if (region.size >= baseSize)
        throw UserError(r.location("size").str() + ": " + where + "/size " + mm(region.size) +
                        " is not below the base size " + mm(baseSize) +
                        " (set by nCells or mesoConstant); a region refines: give a smaller size");
    const bool outside = region.kind == SizeRegion::Kind::plane
                             ? !planeMeetsBox(box, region.point, region.direction)
                             : !inBox(box, region.point);
    if (outside)
        throw UserError(
            r.location("point").str() + ": " + where + ": " +
            (region.kind == SizeRegion::Kind::plane  ? "the plane misses"
             : region.kind == SizeRegion::Kind::line ? "the line's point lies outside"
                                                     : "the point lies outside") +
            " the specimen's bounding box " + boxText(box) +
            " [m]; give coordinates in metres in the specimen's frame (constant/geometryProperties)");
    return region;
}

}  // namespace

double SizeRegion::distance(const Vec3& p) const
{
    const Vec3 d = p - point;
    switch (kind) {
        case Kind::line:
            return norm(cross(d, direction));
        case Kind::plane:
            return std::abs(dot(d, direction));
        case Kind::point:
            break;
    }
    return norm(d);
}

double SizeField::size(const Vec3& p) const
{
    double h = baseSize;
    for (const SizeRegion& r : regions) h = std::min(h, r.size + (grading - 1.0) * r.distance(p));
    return h;
}

double SizeField::smallest() const
{
    double h = baseSize;
    for (const SizeRegion& r : regions) h = std::min(h, r.size);
    return h;
}

const std::vector<std::string>& sizeFieldEntries()
{
    static const std::vector<std::string> entries = {"grading", "regions"};
    return entries;
}

const std::vector<std::string>& sizeRegionEntries()
{
    static const std::vector<std::string> entries = {"type", "point", "direction", "normal", "size"};
    return entries;
}

SizeField readSizeField(const Dictionary& field, double baseSize, double minimumSize, const BoundingBox& box)
{
    checkKnownEntries(field, sizeFieldEntries());
    SizeField f;
    f.baseSize = baseSize;
    f.grading = field.getScalar("grading", Bounds::any());
    if (!(f.grading > 1.0 && f.grading <= 2.0))
        throw UserError(field.location("grading").str() + ": sizeField/grading " + formatNumber(f.grading) +
                        " is not in (1, 2]: it bounds the size ratio of neighbouring cells, so a value " +
                        "of 1 or less never returns to the base size; give e.g. 1.3");
    const Dictionary& regions = field.subDict("regions");
    for (const std::string& name : regions.keys()) {
        if (!regions.isDict(name))
            throw UserError(regions.location(name).str() + ": sizeField/regions/" + name +
                            " is not a dictionary; give " + name + " { type plane; point (x y z); " +
                            "normal (x y z); size <m>; }");
        f.regions.push_back(readRegion(regions.subDict(name), name, baseSize, minimumSize, box));
    }
    if (f.regions.empty())
        throw UserError(regions.endLocation().str() +
                        ": sizeField/regions is empty; give at least one region " +
                        "or remove sizeField for a uniform mesh");
    return f;
}

int gradedCellCount(const Domain& domain, const SizeField& field, double baseCellVolume)
{
    constexpr int n = 64;
    const BoundingBox& box = domain.boundingBox();
    const Vec3 step = box.size() / n;
    double sum = 0.0;
    long inside = 0;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const Vec3 p = box.lower + Vec3{(i + 0.5) * step.x, (j + 0.5) * step.y, (k + 0.5) * step.z};
                if (!domain.contains(p)) continue;
                ++inside;
                const double ratio = field.baseSize / field.size(p);
                sum += ratio * ratio * ratio;
            }
    if (inside == 0) return static_cast<int>(std::round(domain.volume() / baseCellVolume));
    const double count = domain.volume() * (sum / inside) / baseCellVolume;
    if (!(count < std::numeric_limits<int>::max()))
        throw UserError("the size field asks for more than 2^31 cells; give larger region sizes");
    return static_cast<int>(std::round(count));
}

double equivalentDiameter(double volume)
{
    return std::cbrt(6.0 * volume / pi);
}

}  // namespace rockfrac
