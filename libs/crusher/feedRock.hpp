#pragma once
// The feed of a crusher: copies of a bonded Voronoi rock (a voronoiMesh case, one per size
// class), scaled to a drawn size, turned to a random orientation (docs/theory-crusher.md).
//
//   FeedRockTemplate rock = makeFeedRockTemplate(readVoronoiMesh("feedRock"), density);
//   VoronoiMesh big = scaleVoronoiMesh(rock.mesh, 0.075 / rock.sieve_size, {});
//   model.insertCells(big, {position, randomOrientation(seed, k, 0), velocity, {}});
#include <cstdint>
#include <string>
#include <vector>

#include "crusher/linerClearance.hpp"
#include "crusher/machineLoading.hpp"
#include "dem/demModel.hpp"
#include "dem/quat.hpp"
#include "voronoi/voronoiMesh.hpp"

namespace rockfrac {

// The mesh scaled by s about `centre`, which goes to the origin: x' = s (x - centre).
// Lengths (vertices, centroids, seeds, bond points, l_i, l_j, dilation radius and
// pruning distance) scale with s, areas (faces, bond shares A/n) with s^2, volumes
// with s^3 and the second moments of volume with s^5, so the result is the mesh a
// tessellation of the scaled rock would give: masses and bond areas stay consistent
// (bond parameters are stresses and energies per area). UserError for s <= 0.
VoronoiMesh scaleVoronoiMesh(const VoronoiMesh& mesh, double s, const Vec3& centre);

struct FeedRockTemplate {
    VoronoiMesh mesh;         // centred: its centre of volume at the origin
    double volume = 0.0;      // [m^3]
    double sieve_size = 0.0;  // intermediate principal extent (libs/fragments) [m]
    double equivalent_diameter = 0.0;
    double reach = 0.0;  // largest vertex distance from the centre + r_d [m]
    // Per cell: the largest distance of its vertices from its centroid + r_d [m] (a sphere
    // holding the cell, as the model's bounding radius does).
    std::vector<double> cell_reach;
};
// The template rock as one intact fragment; UserError for an empty mesh.
FeedRockTemplate makeFeedRockTemplate(const VoronoiMesh& mesh, double density);

// A uniformly distributed orientation (Shoemake's method) from three draws of the
// counter-based generator: (seed, stream, first_counter .. first_counter + 2).
Quat randomOrientation(std::uint64_t seed, std::uint64_t stream, std::uint64_t first_counter);

// One rock put into the model by the factory.
struct InsertedRock {
    int index = 0;       // rock number (its random stream)
    int feed_class = 0;  // its size class (FeedSpec::classes), whose template it copies
    int first_cell = 0;  // model cells [first_cell, first_cell + mesh.nCells())
    double size = 0.0;   // drawn sieve size [m]
    double mass = 0.0;   // sum of the new cells' masses in the model [kg]
    VoronoiMesh mesh;    // the scaled rock, centred at the origin (mesh frame)
    WallMotion pose;     // where it was put: x = translation + R x_mesh
};

// The feed factory: at each call, rocks are inserted until the fed mass reaches
// mass_rate * t (and at most total_mass), each rock k drawn from its own stream k of
// the counter-based generator under the case seed: size (draw 0, which chooses the size
// class and so the template, feedClassOf), orientation
// (draws 1-3), then per placement attempt a (draws 4 + 3a ..): height, radius and
// azimuth in the feed region. A position is accepted when the bounding sphere of each of
// the rock's cells clears every cell's bounding sphere in the model and, with liners given
// (setLiners), every vertex of the rock's cells lies in the free chamber at least
// linerClearance plus the cells' dilation radius from each liner in its current pose.
// When every attempt fails the rock waits for the next call, which goes on with the next
// `attempts` draws of its stream (the draws are numbered, so the run stays reproducible),
// and the rocks after it wait with it.
class FeedFactory {
public:
    // One template per class of spec.classes, in their order (one template without classes).
    FeedFactory(const FeedSpec& spec, std::vector<FeedRockTemplate> rocks);
    FeedFactory(const FeedSpec& spec, FeedRockTemplate rock);
    // The liners a rock must clear (the crusher's mantle and concave); none: not checked.
    void setLiners(std::vector<RevolvedLiner> liners) { liners_ = std::move(liners); }
    std::vector<InsertedRock> feed(DemModel& model, double time);
    // Whether feed(model, time) would try to place a rock (the mass fed is behind the rate).
    bool feeds(double time) const;
    double massFed() const { return mass_fed_; }
    int rocksFed() const { return rocks_fed_; }
    int rocksFed(int feed_class) const { return rocks_fed_by_class_[feed_class]; }
    const std::vector<int>& rocksFedByClass() const { return rocks_fed_by_class_; }
    // Placement draws already spent on the rock that waits for room (0 when none waits).
    long attemptsSpent() const { return attempts_spent_; }
    // A restart (crusherState.hpp): the counters as the state recorded them; the rocks
    // themselves are put back into the model by the caller. UserError (naming `source`) when
    // the classes do not match this factory's.
    void restoreCounters(double mass_fed, int rocks_fed, const std::vector<int>& rocks_fed_by_class,
                         long attempts_spent, const std::string& source);
    int classes() const { return static_cast<int>(rocks_.size()); }
    const FeedRockTemplate& rock(int feed_class = 0) const { return rocks_[feed_class]; }
    // The template of a class scaled to the smallest size of the class (for the time step).
    VoronoiMesh smallestRock(int feed_class = 0) const;

private:
    bool place(const DemModel& model, int k, const FeedRockTemplate& rock, double s, const Quat& orientation,
               Vec3& centre);
    bool clearOfLiners(const DemModel& model, const FeedRockTemplate& rock, double s, const Mat3& R,
                       const Vec3& centre) const;

    FeedSpec spec_;
    std::vector<FeedRockTemplate> rocks_;
    std::vector<RevolvedLiner> liners_;
    double mass_fed_ = 0.0;
    int rocks_fed_ = 0;
    std::vector<int> rocks_fed_by_class_;
    long attempts_spent_ = 0;  // placement draws already used by the waiting rock rocks_fed_
};

}  // namespace rockfrac
