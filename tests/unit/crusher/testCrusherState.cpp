// The crusher's restart (crusher/crusherState.hpp): a fed run with discharges, written at a
// step after a discharge (demState + crusherState), rebuilt from the files into a fresh model
// and continued, goes on bitwise as the uninterrupted run; a record that does not fit the
// feed is refused naming the file.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "crusher/crusherState.hpp"
#include "crusher/destructor.hpp"
#include "crusher/feedRock.hpp"
#include "dem/demModel.hpp"
#include "dem/voronoiQnscBond.hpp"
#include "funnelFeed.hpp"
#include "voronoi/tessellation.hpp"

using namespace rockfrac;

namespace crusherStateTest {

namespace fs = std::filesystem;

DemParameters parameters()
{
    DemParameters p;
    p.damping_reading = DampingReading::criticalFraction;
    p.bond_damping = 0.05;
    p.gravity = {0.0, 0.0, -200.0};
    VoronoiQnscBondLaw::Parameters q;
    q.youngs_modulus = 4.6e9;
    p.bond_law = std::make_shared<VoronoiQnscBondLaw>(q);
    p.rock_youngs_modulus = 7.7e9;
    return p;
}

FeedSpec feedSpec()
{
    return funnelFeedSpec(3);
}

FeedRockTemplate rockTemplate()
{
    static const FeedRockTemplate rock = makeFeedRockTemplate(
        generateVoronoiMesh(Domain::box({0.0, 0.0, 0.0}, {0.03, 0.02, 0.012}), 20, 2.5e-3, 5),
        parameters().rock_density);
    return rock;
}

// A fed run as CrusherRun keeps it: the model, the factory, the record and the shapes.
struct Run {
    FeedFactory factory{feedSpec(), rockTemplate()};
    DemModel model{parameters()};
    FeedRecord fed;
    CellShapes shapes;
    double discharged = 0.0;
    int fragments = 0;
    double dt = 0.0;
    long feedEvery = 1;
    Run()
    {
        model.addPlate({-0.05, 0, 0}, {1, 0, 0.5});
        model.addPlate({0.05, 0, 0}, {-1, 0, 0.5});
        dt = 0.5 * DemModel(factory.smallestRock(), parameters()).criticalTimeStep().value;
        feedEvery = std::lround(feedSpec().interval / dt);
    }
    void steps(long from, long to)
    {
        for (long step = from; step < to; ++step) {
            if (step % feedEvery == 0)
                for (const InsertedRock& rock : factory.feed(model, model.time())) {
                    appendShapes(shapes, rock, model);
                    fed.add(rock);
                }
            model.step(dt);
            REQUIRE(model.status().ok());
            if ((step + 1) % 50 == 0) {
                const DestructorResult r = destroyBelow(model, -0.03);
                if (r.fragments.empty()) continue;
                compactShapes(shapes, r.new_index);
                fed.compact(r.new_index);
                discharged += r.mass;
                fragments += static_cast<int>(r.fragments.size());
            }
        }
    }
    CrusherState state(long step) const
    {
        CrusherState c;
        c.step = step;
        c.time = model.time();
        c.fed = fed;
        c.mass_fed = factory.massFed();
        c.rocks_fed = factory.rocksFed();
        c.rocks_fed_by_class = factory.rocksFedByClass();
        c.attempts_spent = factory.attemptsSpent();
        c.mass_discharged = discharged;
        c.fragments_discharged = fragments;
        for (int k = 0; k < model.nWalls(); ++k) c.wall_work.push_back(model.wallWork(k));
        return c;
    }
};

bool same(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

struct ScratchDir {
    fs::path path = fs::temp_directory_path() / ("rockfracCrusherState" + std::to_string(::getpid()));
    ScratchDir() { fs::create_directories(path); }
    ~ScratchDir() { fs::remove_all(path); }
};

}  // namespace crusherStateTest

using namespace crusherStateTest;

TEST_CASE("a crusher state after a discharge, rebuilt and continued, goes on bitwise", "[crusher][restart]")
{
    Run uninterrupted;
    long step = 0;
    // Until a fragment has left (cells removed from the record) and a few rocks are inside.
    while (uninterrupted.fragments == 0 && step < 20000) {
        uninterrupted.steps(step, step + 500);
        step += 500;
    }
    REQUIRE(uninterrupted.fragments > 0);
    REQUIRE(uninterrupted.model.cells().size() > 0);
    REQUIRE(uninterrupted.fed.cell_rock.size() ==
            static_cast<std::size_t>(uninterrupted.model.cells().size()));
    const ScratchDir dir;
    writeDemState(dir.path / "demState", uninterrupted.model, step, 0.0, false);
    writeCrusherState(dir.path / "crusherState", uninterrupted.state(step));

    Run restarted;
    const CrusherState c = readCrusherState(dir.path / "crusherState");
    CHECK(c.step == step);
    CHECK(c.fed.rocks.size() == uninterrupted.fed.rocks.size());
    CHECK(c.fed.cell_rock == uninterrupted.fed.cell_rock);
    CHECK(c.fed.cell_local == uninterrupted.fed.cell_local);
    CHECK(c.mass_discharged == uninterrupted.discharged);
    rebuildCrusherModel(c.fed, restarted.factory, restarted.model, restarted.shapes,
                        dir.path / "crusherState");
    for (int k = 0; k < restarted.model.nWalls(); ++k) {
        WallState w = restarted.model.wall(k);
        w.work = c.wall_work[k];
        restarted.model.setWallState(k, w);
    }
    readDemState(dir.path / "demState", restarted.model);
    restarted.fed = c.fed;
    restarted.factory.restoreCounters(c.mass_fed, c.rocks_fed, c.rocks_fed_by_class, c.attempts_spent,
                                      "test");
    restarted.discharged = c.mass_discharged;
    restarted.fragments = c.fragments_discharged;
    CHECK(same(restarted.model.cells().position, uninterrupted.model.cells().position));
    CHECK(same(restarted.shapes.bodyVertices, uninterrupted.shapes.bodyVertices));
    CHECK(restarted.shapes.faceVertices == uninterrupted.shapes.faceVertices);
    CHECK(restarted.model.nBonds() == uninterrupted.model.nBonds());

    uninterrupted.steps(step, step + 3000);
    restarted.steps(step, step + 3000);
    INFO("rocks fed " << uninterrupted.factory.rocksFed() << ", fragments out " << uninterrupted.fragments);
    CHECK(same(restarted.model.cells().position, uninterrupted.model.cells().position));
    CHECK(same(restarted.model.cells().velocity, uninterrupted.model.cells().velocity));
    CHECK(restarted.model.energies().balance() == uninterrupted.model.energies().balance());
    CHECK(restarted.factory.massFed() == uninterrupted.factory.massFed());
    CHECK(restarted.discharged == uninterrupted.discharged);
    CHECK(restarted.fed.cell_rock == uninterrupted.fed.cell_rock);
    CHECK(restarted.model.wallWork(0) == uninterrupted.model.wallWork(0));

    // A record that does not fit the feed's template.
    FeedRecord wrong = c.fed;
    wrong.rocks[0].n_cells += 1;
    Run other;
    CHECK_THROWS_AS(
        rebuildCrusherModel(wrong, other.factory, other.model, other.shapes, dir.path / "crusherState"),
        UserError);
}
