#include "crusher/feedRock.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/counterRandom.hpp"
#include "core/error.hpp"
#include "fragments/fragments.hpp"

namespace rockfrac {

namespace {
constexpr double pi = 3.14159265358979323846;
}

VoronoiMesh scaleVoronoiMesh(const VoronoiMesh& mesh, double s, const Vec3& centre)
{
    if (!(s > 0.0)) throw UserError("scaleVoronoiMesh: the scale factor must be positive");
    const double s2 = s * s, s3 = s2 * s, s5 = s3 * s2;
    VoronoiMesh m = mesh;
    auto place = [&](const Vec3& x) { return s * (x - centre); };
    for (Vec3& x : m.seeds) x = place(x);
    for (Vec3& x : m.centroids) x = place(x);
    for (Vec3& x : m.vertices) x = place(x);
    for (double& v : m.volumes) v *= s3;
    for (Mat3& J : m.inertia)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) J(i, j) *= s5;
    for (double& a : m.faceArea) a *= s2;
    for (VoronoiBond& b : m.bonds) {
        b.point = place(b.point);
        b.lI *= s;
        b.lJ *= s;
        b.area *= s2;
    }
    m.pruningDistance *= s;
    m.domainVolume *= s3;
    m.dilationRadius *= s;
    return m;
}

FeedRockTemplate makeFeedRockTemplate(const VoronoiMesh& mesh, double density)
{
    if (mesh.nCells() == 0) throw UserError("the feed rock has no cells; run voronoiMesh on it first");
    Vec3 centre;
    double volume = 0.0;
    for (int c = 0; c < mesh.nCells(); ++c) {
        centre += mesh.volumes[c] * mesh.centroids[c];
        volume += mesh.volumes[c];
    }
    centre = (1.0 / volume) * centre;
    FeedRockTemplate t;
    t.mesh = scaleVoronoiMesh(mesh, 1.0, centre);
    t.volume = volume;
    // The whole rock is one intact fragment: its sizes as fragmentPSD measures them.
    CellPoses poses;
    poses.position = t.mesh.centroids;
    poses.orientation = initialCellOrientations(t.mesh, density);
    const FragmentAnalysis a =
        analyseFragments(t.mesh, demBondCells(t.mesh), std::vector<std::uint8_t>(t.mesh.nBonds(), 0), poses,
                         poses.orientation, density);
    if (a.fragments.size() != 1)
        throw UserError("the feed rock is not one bonded piece (" + std::to_string(a.fragments.size()) +
                        " fragments); mesh a single rock");
    t.sieve_size = a.fragments[0].sieve_size;
    t.equivalent_diameter = a.fragments[0].equivalent_diameter;
    for (const Vec3& v : t.mesh.vertices) t.reach = std::max(t.reach, norm(v));
    t.reach += t.mesh.dilationRadius;
    t.cell_reach.assign(t.mesh.nCells(), 0.0);
    for (int c = 0; c < t.mesh.nCells(); ++c) {
        for (int v = t.mesh.cellVertexOffset[c]; v < t.mesh.cellVertexOffset[c + 1]; ++v)
            t.cell_reach[c] = std::max(t.cell_reach[c], norm(t.mesh.vertices[v] - t.mesh.centroids[c]));
        t.cell_reach[c] += t.mesh.dilationRadius;
    }
    return t;
}

Quat randomOrientation(std::uint64_t seed, std::uint64_t stream, std::uint64_t first_counter)
{
    const double u1 = uniform01(seed, stream, first_counter);
    const double u2 = uniform01(seed, stream, first_counter + 1);
    const double u3 = uniform01(seed, stream, first_counter + 2);
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    return normalised(Quat{b * std::cos(2 * pi * u3), a * std::sin(2 * pi * u2), a * std::cos(2 * pi * u2),
                           b * std::sin(2 * pi * u3)});
}

}  // namespace rockfrac

namespace rockfrac {

FeedFactory::FeedFactory(const FeedSpec& spec, std::vector<FeedRockTemplate> rocks)
    : spec_(spec), rocks_(std::move(rocks)), rocks_fed_by_class_(rocks_.size(), 0)
{
    const std::size_t classes = std::max<std::size_t>(1, spec_.classes.size());
    if (rocks_.size() != classes)
        throw std::logic_error("FeedFactory: " + std::to_string(rocks_.size()) + " template rocks for " +
                               std::to_string(classes) + " size classes");
}

FeedFactory::FeedFactory(const FeedSpec& spec, FeedRockTemplate rock)
    : FeedFactory(spec, std::vector<FeedRockTemplate>{std::move(rock)})
{
}

VoronoiMesh FeedFactory::smallestRock(int feed_class) const
{
    const FeedRockTemplate& rock = rocks_[feed_class];
    return scaleVoronoiMesh(rock.mesh, feedClassSizes(spec_, feed_class).first / rock.sieve_size, {});
}

bool FeedFactory::clearOfLiners(const DemModel& model, const FeedRockTemplate& rock, double s, const Mat3& R,
                                const Vec3& centre) const
{
    const double margin = spec_.liner_clearance + s * rock.mesh.dilationRadius;
    for (const RevolvedLiner& liner : liners_) {
        const WallState& wall = model.wall(liner.wall);
        for (const Vec3& v : rock.mesh.vertices)
            if (linerClearance(liner, wall, centre + R * (s * v)) < margin) return false;
    }
    return true;
}

bool FeedFactory::place(const DemModel& model, int k, const FeedRockTemplate& rock, double s,
                        const Quat& orientation, Vec3& centre)
{
    const CellArrays& cells = model.cells();
    const double reach = s * rock.reach;
    const Mat3 R = rotationMatrix(orientation);
    std::vector<Vec3> cellCentre(rock.mesh.nCells());
    for (long a = attempts_spent_; a < attempts_spent_ + spec_.attempts; ++a) {
        const std::uint64_t first = 4 + 3 * static_cast<std::uint64_t>(a);
        const double z = spec_.z_min + (spec_.z_max - spec_.z_min) * uniform01(spec_.seed, k, first);
        const double r2 =
            spec_.r_min * spec_.r_min +
            (spec_.r_max * spec_.r_max - spec_.r_min * spec_.r_min) * uniform01(spec_.seed, k, first + 1);
        const double phi = 2.0 * pi * uniform01(spec_.seed, k, first + 2);
        centre = {std::sqrt(r2) * std::cos(phi), std::sqrt(r2) * std::sin(phi), z};
        for (int i = 0; i < rock.mesh.nCells(); ++i)
            cellCentre[i] = centre + R * (s * rock.mesh.centroids[i]);
        // Cell spheres against cell spheres, after the rock's sphere as a quick filter.
        bool clear = true;
        for (int c = 0; c < cells.size() && clear; ++c) {
            const double gap = reach + cells.bounding_radius[c];
            if (norm2(cells.position[c] - centre) > gap * gap) continue;
            for (int i = 0; i < rock.mesh.nCells() && clear; ++i) {
                const double g = s * rock.cell_reach[i] + cells.bounding_radius[c];
                clear = norm2(cells.position[c] - cellCentre[i]) > g * g;
            }
        }
        if (clear && clearOfLiners(model, rock, s, R, centre)) {
            attempts_spent_ = 0;
            return true;
        }
    }
    attempts_spent_ += spec_.attempts;
    return false;
}

void FeedFactory::restoreCounters(double mass_fed, int rocks_fed, const std::vector<int>& rocks_fed_by_class,
                                  long attempts_spent, const std::string& source)
{
    if (rocks_fed_by_class.size() != rocks_.size() || rocks_fed < 0 || attempts_spent < 0)
        throw UserError(source + ": the feed counters are for " + std::to_string(rocks_fed_by_class.size()) +
                        " size classes, the case has " + std::to_string(rocks_.size()) +
                        "; the state does not belong to this case's feed");
    mass_fed_ = mass_fed;
    rocks_fed_ = rocks_fed;
    rocks_fed_by_class_ = rocks_fed_by_class;
    attempts_spent_ = attempts_spent;
}

bool FeedFactory::feeds(double time) const
{
    double target = spec_.mass_rate * time;
    if (spec_.total_mass > 0.0) target = std::min(target, spec_.total_mass);
    return mass_fed_ < target;
}

std::vector<InsertedRock> FeedFactory::feed(DemModel& model, double time)
{
    std::vector<InsertedRock> inserted;
    while (feeds(time)) {
        const int k = rocks_fed_;
        const double u = uniform01(spec_.seed, k, 0);
        const double size = spec_.size_min + (spec_.size_max - spec_.size_min) * u;
        const int feed_class = feedClassOf(spec_, size);
        const FeedRockTemplate& from = rocks_[feed_class];
        const double s = size / from.sieve_size;
        const Quat orientation = randomOrientation(spec_.seed, k, 1);
        Vec3 centre;
        if (!place(model, k, from, s, orientation, centre)) break;
        InsertedRock rock;
        rock.index = k;
        rock.feed_class = feed_class;
        rock.size = size;
        rock.mesh = scaleVoronoiMesh(from.mesh, s, {});
        rock.pose.translation = centre;
        rock.pose.orientation = orientation;
        rock.pose.velocity = spec_.velocity;
        rock.first_cell = model.insertCells(rock.mesh, rock.pose);
        for (int c = rock.first_cell; c < model.cells().size(); ++c) rock.mass += model.cells().mass[c];
        mass_fed_ += rock.mass;
        ++rocks_fed_;
        ++rocks_fed_by_class_[feed_class];
        inserted.push_back(std::move(rock));
    }
    return inserted;
}

}  // namespace rockfrac
