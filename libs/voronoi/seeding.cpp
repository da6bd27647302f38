#include "voronoi/seeding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "voronoi/randomStream.hpp"

namespace rockfrac {

namespace {

// Dart throwing stops when this many throws in a row (inside the domain) land
// too close to an earlier seed: by then the random packing is saturated
// (random sequential addition jams near a sphere volume fraction of 0.38),
// and the count reached is a good estimate of what fits.
constexpr long maxConsecutiveRejections = 100000;

// Bound on the throws inside the domain, so a request just below saturation
// cannot run for hours either: 200 per seed is ample below half of the jamming
// density, where every row of Table 7 lies.
long throwBudget(int nCells)
{
    return 200L * nCells + 1000000L;
}

// Uniform grid over the bounding box with one linked list of seeds per cell,
// so a new point is compared with the seeds of the 27 surrounding cells only.
class SeedGrid {
public:
    SeedGrid(const BoundingBox& box, double cellSize, int capacity) : lower_(box.lower), cellSize_(cellSize)
    {
        for (int i = 0; i < 3; ++i)
            dims_[i] = std::max(1, static_cast<int>(std::ceil(box.size()[i] / cellSize)));
        head_.assign(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2], -1);
        next_.reserve(capacity);
    }

    // True if a point of `points` lies closer than `distance` (<= cell size) to p.
    bool hasPointCloserThan(const Vec3& p, double distance, const std::vector<Vec3>& points) const
    {
        int c[3];
        cellOf(p, c);
        const double distance2 = distance * distance;
        for (int k = std::max(0, c[2] - 1); k <= std::min(dims_[2] - 1, c[2] + 1); ++k)
            for (int j = std::max(0, c[1] - 1); j <= std::min(dims_[1] - 1, c[1] + 1); ++j)
                for (int i = std::max(0, c[0] - 1); i <= std::min(dims_[0] - 1, c[0] + 1); ++i)
                    for (int s = head_[index(i, j, k)]; s >= 0; s = next_[s])
                        if (norm2(points[s] - p) < distance2) return true;
        return false;
    }

    // True if a point s of `points` lies closer than pairDistance(s) to p (pairDistance(s) <=
    // the cell size: the field's local pruning distance of the pair).
    template <class PairDistance>
    bool hasPointCloserThan(const Vec3& p, const std::vector<Vec3>& points, PairDistance pairDistance) const
    {
        int c[3];
        cellOf(p, c);
        for (int k = std::max(0, c[2] - 1); k <= std::min(dims_[2] - 1, c[2] + 1); ++k)
            for (int j = std::max(0, c[1] - 1); j <= std::min(dims_[1] - 1, c[1] + 1); ++j)
                for (int i = std::max(0, c[0] - 1); i <= std::min(dims_[0] - 1, c[0] + 1); ++i)
                    for (int s = head_[index(i, j, k)]; s >= 0; s = next_[s]) {
                        const double d = pairDistance(s);
                        if (norm2(points[s] - p) < d * d) return true;
                    }
        return false;
    }

    // Register points[id] == p (ids must be inserted as 0, 1, 2, ...).
    void insert(int id, const Vec3& p)
    {
        int c[3];
        cellOf(p, c);
        const std::size_t cell = index(c[0], c[1], c[2]);
        next_.push_back(head_[cell]);
        head_[cell] = id;
    }

private:
    void cellOf(const Vec3& p, int c[3]) const
    {
        for (int i = 0; i < 3; ++i)
            c[i] = std::clamp(static_cast<int>((p[i] - lower_[i]) / cellSize_), 0, dims_[i] - 1);
    }
    std::size_t index(int i, int j, int k) const
    {
        return static_cast<std::size_t>(i) + dims_[0] * (static_cast<std::size_t>(j) + dims_[1] * k);
    }

    Vec3 lower_;
    double cellSize_;
    int dims_[3];
    std::vector<int> head_;  // first seed in each grid cell, -1 if none
    std::vector<int> next_;  // next seed in the same grid cell, -1 at the end
};

Vec3 uniformPointInBox(RandomStream& random, const BoundingBox& box)
{
    // Three draws in a fixed order (function arguments have no fixed order).
    const double x = random.uniform(box.lower.x, box.upper.x);
    const double y = random.uniform(box.lower.y, box.upper.y);
    const double z = random.uniform(box.lower.z, box.upper.z);
    return {x, y, z};
}

void checkArguments(int nCells, double pruningDistance)
{
    if (nCells < 2) {
        std::ostringstream msg;
        msg << "cannot mesh with " << nCells << " cells: ask for at least 2 (a bonded mesh needs neighbours)";
        throw UserError(msg.str());
    }
    if (!(pruningDistance >= 0.0) || !std::isfinite(pruningDistance))
        throw UserError("the pruning distance must be a non-negative length in metres");
}

[[noreturn]] void throwDoesNotFit(const Domain& domain, int nCells, double pruningDistance, int placed)
{
    // The count of seeds scales as pd^-3 at a given packing, so pd (placed /
    // nCells)^(1/3) would just saturate; 0.8 of it leaves room for the
    // throws to succeed.
    const double fittingDistance = 0.8 * pruningDistance * std::cbrt(static_cast<double>(placed) / nCells);
    std::ostringstream msg;
    msg.precision(3);
    msg << "cannot place " << nCells << " seeds " << pruningDistance << " m apart in a domain of "
        << domain.volume() << " m^3: at most about " << placed
        << " fit (random placement saturated); ask for at most " << placed
        << " cells or use a pruning distance of at most " << fittingDistance << " m";
    throw UserError(msg.str());
}

}  // namespace

namespace {

// The 21 low bits of v spread to every third bit.
std::uint64_t spreadBits(std::uint64_t v)
{
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
}

}  // namespace

void orderAlongMortonCurve(std::vector<Vec3>& points)
{
    if (points.size() < 2) return;
    Vec3 low = points[0], high = points[0];
    for (const Vec3& p : points) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
    const double extent = std::max({high.x - low.x, high.y - low.y, high.z - low.z, 1e-300});
    const double scale = double((1 << 21) - 1) / extent;
    std::vector<std::pair<std::uint64_t, std::size_t>> keys(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3 q = (points[i] - low) * scale;
        keys[i] = {spreadBits(std::uint64_t(q.x)) | spreadBits(std::uint64_t(q.y)) << 1 |
                       spreadBits(std::uint64_t(q.z)) << 2,
                   i};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<Vec3> ordered(points.size());
    for (std::size_t i = 0; i < keys.size(); ++i) ordered[i] = points[keys[i].second];
    points = std::move(ordered);
}

namespace {

// Random sequential addition: throws uniform in the box, kept inside the domain and, with a
// field, thinned to the density (base / h)^3 (one more draw per throw inside); a throw closer
// than the pruning distance to an earlier seed is rejected. Without a field the draws and tests
// are those of the uniform seeding (meshes reproducible from the seed across versions).
std::vector<Vec3> throwSeeds(const Domain& domain, int nCells, double pruningDistance, std::uint64_t seed,
                             const SizeField* field)
{
    checkArguments(nCells, pruningDistance);
    const BoundingBox& box = domain.boundingBox();

    // Cells at least pd wide so the 27-cell neighbourhood covers pd (with a field every pair's
    // distance is at most pd: sizes never exceed the base), and at least half the mean seed
    // spacing so a tiny pd does not make a huge grid.
    const double meanSpacing = std::cbrt(box.volume() / nCells);
    SeedGrid grid(box, std::max(pruningDistance, 0.5 * meanSpacing), nCells);

    // Throws outside the domain are free; bound them by the volume ratio so a thin slanted
    // domain still terminates. A field keeps a throw with probability (smallest / h)^3 >=
    // (smallest / base)^3: the bound grows by that worst case.
    const double finest = field ? field->smallest() / field->baseSize : 1.0;
    const double insideFraction = std::max(domain.volume() / box.volume(), 1e-6);
    const long maxThrowsInside = throwBudget(nCells);
    double maxThrows = maxThrowsInside / insideFraction * 10.0;
    if (field) maxThrows /= finest * finest * finest;

    RandomStream random(seed);
    std::vector<Vec3> seeds;
    std::vector<double> sizes;  // the field at each seed (with a field)
    seeds.reserve(nCells);
    const double pdPerSize = field ? pruningDistance / field->baseSize : 0.0;
    long rejectedInARow = 0, throwsInside = 0;
    for (double throws = 0; static_cast<int>(seeds.size()) < nCells; throws += 1.0) {
        if (rejectedInARow >= maxConsecutiveRejections || throwsInside >= maxThrowsInside ||
            throws >= maxThrows)
            throwDoesNotFit(domain, nCells, pruningDistance, static_cast<int>(seeds.size()));
        const Vec3 p = uniformPointInBox(random, box);
        if (!domain.contains(p)) continue;
        const double h = field ? field->size(p) : 0.0;
        if (field) {
            const double ratio = field->smallest() / h;
            if (random.uniform() >= ratio * ratio * ratio) continue;  // thinned to (base / h)^3
        }
        ++throwsInside;
        // With a field, the pair's pruning distance is pd at the mean of the two sizes
        // (symmetric; with the grading bound close seeds differ by less than the grading).
        auto pairDistance = [&](int s) { return pdPerSize * 0.5 * (h + sizes[s]); };
        const bool tooClose =
            pruningDistance > 0.0 && (field ? grid.hasPointCloserThan(p, seeds, pairDistance)
                                            : grid.hasPointCloserThan(p, pruningDistance, seeds));
        if (tooClose) {
            ++rejectedInARow;
            continue;
        }
        rejectedInARow = 0;
        grid.insert(static_cast<int>(seeds.size()), p);
        seeds.push_back(p);
        if (field) sizes.push_back(h);
    }
    return seeds;
}

}  // namespace

std::vector<Vec3> placeSeeds(const Domain& domain, int nCells, double pruningDistance, std::uint64_t seed)
{
    return throwSeeds(domain, nCells, pruningDistance, seed, nullptr);
}

std::vector<Vec3> placeSeeds(const Domain& domain, int nCells, double pruningDistance, std::uint64_t seed,
                             const SizeField& field)
{
    return throwSeeds(domain, nCells, pruningDistance, seed, &field);
}

int cellCountFromMesoConstant(double domainVolume, double mesoConstant)
{
    if (!(mesoConstant > 0.0) || !std::isfinite(mesoConstant))
        throw UserError("the meso constant (volume per cell) must be a positive volume in m^3");
    const double count = std::round(domainVolume / mesoConstant);
    if (!(count >= 0.0) || count > std::numeric_limits<int>::max())
        throw UserError("the meso constant gives an unusable cell count; check it is in m^3");
    return static_cast<int>(count);
}

}  // namespace rockfrac
