// A size-resolved feed (constant/loading feed/classes): the class of a drawn size, the checks
// of the classes as read, one class the same feed as `rock`, and every rock a copy of its
// own class's template, with the draws of a one-template feed.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <tuple>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "crusher/feedRock.hpp"
#include "crusher/machineLoading.hpp"
#include "dem/demModel.hpp"
#include "voronoi/tessellation.hpp"

using namespace rockfrac;
using Catch::Matchers::Contains;

namespace fs = std::filesystem;

namespace {

// A case directory with two "meshed" rocks a and b (readFeedSpec checks only that their
// constant/voronoiMesh/meshInfo exists).
struct CaseWithRocks {
    fs::path dir = fs::temp_directory_path() / ("rockfracFeedClasses" + std::to_string(::getpid()));
    CaseWithRocks()
    {
        for (const char* rock : {"a", "b"}) {
            fs::create_directories(dir / rock / "constant/voronoiMesh");
            std::ofstream(dir / rock / "constant/voronoiMesh/meshInfo") << "\n";
        }
    }
    ~CaseWithRocks() { fs::remove_all(dir); }
};

const fs::path& caseWithRocks()
{
    static const CaseWithRocks c;
    return c.dir;
}

// constant/loading's feed section with `body` added to the entries every feed has.
FeedSpec readFeed(const std::string& body)
{
    const Dictionary loading = Dictionary::parse(
        "feed { sizeRange (0.06 0.09); massRate 10; region { zRange (0 1); rRange (0 1); } interval 1e-3; " +
            body + " }",
        "constant/loading");
    return readFeedSpec(loading.subDict("feed"), caseWithRocks());
}

FeedSpec twoClasses(double fine, double coarse)
{
    FeedSpec f;
    f.size_min = 0.06;
    f.size_max = 0.09;
    f.classes = {{"fine", "a", fine}, {"coarse", "b", coarse}};
    return f;
}

}  // namespace

TEST_CASE("a drawn size goes to the first class whose upTo it does not exceed", "[crusher][feed]")
{
    const FeedSpec f = twoClasses(0.07, 0.09);
    CHECK(feedClassOf(f, 0.06) == 0);
    CHECK(feedClassOf(f, 0.07) == 0);  // upTo belongs to its class
    CHECK(feedClassOf(f, std::nextafter(0.07, 1.0)) == 1);
    CHECK(feedClassOf(f, 0.09) == 1);
    CHECK(feedClassOf(f, 0.095) == 1);  // above every upTo (round-off): the last class
    CHECK(feedClassSizes(f, 0) == std::pair<double, double>{0.06, 0.07});
    CHECK(feedClassSizes(f, 1) == std::pair<double, double>{0.07, 0.09});
    const FeedSpec wide = twoClasses(0.07, 0.2);  // the last upTo beyond the range: the range's max
    CHECK(feedClassSizes(wide, 1) == std::pair<double, double>{0.07, 0.09});
    FeedSpec none;  // built in code, no classes: one class, the whole range
    none.size_min = 0.01;
    none.size_max = 0.02;
    CHECK(feedClassOf(none, 0.015) == 0);
    CHECK(feedClassSizes(none, 0) == std::pair<double, double>{0.01, 0.02});
}

TEST_CASE("feed/rock or feed/classes read: one class for rock, classes in order", "[crusher][feed]")
{
    const FeedSpec one = readFeed("rock \"a\";");
    REQUIRE(one.classes.size() == 1);
    CHECK(one.classes[0].name == "rock");
    CHECK(one.classes[0].rock_case == caseWithRocks() / "a");
    CHECK(one.classes[0].up_to == 0.09);
    const FeedSpec two =
        readFeed("classes { fine { rock \"a\"; upTo 0.07; } coarse { rock \"b\"; upTo 0.1; } }");
    REQUIRE(two.classes.size() == 2);
    CHECK(two.classes[0].name == "fine");
    CHECK(two.classes[1].rock_case == caseWithRocks() / "b");
    CHECK(two.classes[1].up_to == 0.1);
}

TEST_CASE("bad feed classes: each one UserError naming the file and the entry", "[crusher][feed][badInput]")
{
    const std::vector<std::tuple<std::string, std::string, std::string>> bad = {
        {"rock \"a\"; classes { c { rock \"a\"; upTo 0.09; } }", "feed has both rock and classes", ""},
        {"", "feed has neither rock nor classes", ""},
        {"classes { }", "feed/classes has no class", ""},
        {"classes 0.09;", "feed/classes must be a sub-dictionary", ""},
        {"classes { fine \"a\"; }", "feed/classes/fine must be a sub-dictionary", ""},
        {"classes { fine { rock \"a\"; upTo 0.08; } coarse { rock \"b\"; upTo 0.07; } }",
         "feed/classes/coarse/upTo 0.07", "increasing upTo"},
        {"classes { fine { rock \"a\"; upTo 0.08; } coarse { rock \"b\"; upTo 0.08; } }",
         "feed/classes/coarse/upTo 0.08", "increasing upTo"},
        {"classes { fine { rock \"a\"; upTo 0.07; } coarse { rock \"b\"; upTo 0.085; } }",
         "feed/classes/coarse/upTo 0.085", "below sizeRange max"},
        {"classes { fine { rock \"a\"; upTo 0.05; } coarse { rock \"b\"; upTo 0.09; } }",
         "feed/classes/fine/upTo 0.05", "below sizeRange min"},
        {"classes { fine { rock \"a\"; upTo 0.09; } coarse { rock \"b\"; upTo 0.1; } }",
         "feed/classes/coarse/upTo 0.1", "no rock would be of this class"},
        {"classes { fine { rock \"c\"; upTo 0.09; } }", "feed/classes/fine/rock", "mesh the feed rock"},
        {"rock \"c\";", "feed/rock", "mesh the feed rock"},
        {"classes { fine { rock \"a\"; } }", "upTo", ""},
        {"classes { fine { rock \"a\"; upTo -0.09; } }", "upTo", ""},
    };
    for (const auto& [body, entry, what] : bad) {
        INFO(body);
        CHECK_THROWS_AS(readFeed(body), UserError);
        CHECK_THROWS_WITH(readFeed(body), Contains("constant/loading") && Contains(entry) && Contains(what));
    }
}

namespace {

const VoronoiMesh& rockMesh(int cells)
{
    static const VoronoiMesh coarse =
        generateVoronoiMesh(Domain::box({0.0, 0.0, 0.0}, {0.03, 0.02, 0.012}), 20, 2.5e-3, 5);
    static const VoronoiMesh fine =
        generateVoronoiMesh(Domain::box({0.0, 0.0, 0.0}, {0.03, 0.02, 0.012}), 60, 1.5e-3, 6);
    return cells == 20 ? coarse : fine;
}

FeedSpec openFeed(FeedSpec f)
{
    // Sizes of 15-25 mm, ~20 rocks at once into a roomy cylinder (no liners).
    std::tie(f.size_min, f.size_max, f.mass_rate, f.total_mass) = std::make_tuple(0.015, 0.025, 1e6, 0.25);
    std::tie(f.z_min, f.z_max, f.r_min, f.r_max) = std::make_tuple(0.0, 1.0, 0.0, 0.5);
    std::tie(f.interval, f.seed) = std::make_tuple(1e-3, std::uint64_t{3});
    return f;
}

}  // namespace

TEST_CASE("a one-class feed is the feed of rock; two classes copy each class's template", "[crusher][feed]")
{
    DemParameters p;
    p.gravity = {0.0, 0.0, 0.0};
    const FeedRockTemplate coarse = makeFeedRockTemplate(rockMesh(20), p.rock_density);
    const FeedRockTemplate fine = makeFeedRockTemplate(rockMesh(60), p.rock_density);
    REQUIRE(fine.mesh.nCells() > coarse.mesh.nCells());
    FeedSpec asRock = readFeed("rock \"a\";"),
             asClass = readFeed("classes { only { rock \"a\"; upTo 0.09; } }");
    asRock = openFeed(asRock);
    asClass = openFeed(asClass);
    auto run = [&](const FeedSpec& spec, std::vector<FeedRockTemplate> rocks, DemModel& model) {
        FeedFactory factory(spec, std::move(rocks));
        std::vector<InsertedRock> fed = factory.feed(model, 1.0);
        REQUIRE(static_cast<int>(fed.size()) == factory.rocksFed());
        int sum = 0;
        for (int i = 0; i < factory.classes(); ++i) sum += factory.rocksFed(i);
        CHECK(sum == factory.rocksFed());
        return fed;
    };
    DemModel one(p), same(p), two(p);
    const std::vector<InsertedRock> a = run(asRock, {coarse}, one);
    const std::vector<InsertedRock> b = run(asClass, {coarse}, same);
    REQUIRE(a.size() >= 10);
    REQUIRE(a.size() == b.size());
    const CellArrays &ca = one.cells(), &cb = same.cells();
    REQUIRE(ca.size() == cb.size());
    CHECK(std::memcmp(ca.position.data(), cb.position.data(), ca.size() * sizeof(Vec3)) == 0);
    CHECK(std::memcmp(ca.mass.data(), cb.mass.data(), ca.size() * sizeof(double)) == 0);

    // Two classes, the finer template above 20 mm: each rock copies its class's template at
    // the drawn size, with the same size and orientation draws as the one-template feed.
    FeedSpec classes = openFeed(twoClasses(0.02, 0.025));
    const std::vector<InsertedRock> c = run(classes, {coarse, fine}, two);
    int nCoarse = 0, nFine = 0;
    for (std::size_t k = 0; k < std::min(a.size(), c.size()); ++k) {
        CHECK(c[k].index == a[k].index);
        CHECK(c[k].size == a[k].size);
        CHECK(std::memcmp(&c[k].pose.orientation, &a[k].pose.orientation, sizeof(Quat)) == 0);
        CHECK(c[k].feed_class == (c[k].size <= 0.02 ? 0 : 1));
        const FeedRockTemplate& t = c[k].feed_class == 0 ? coarse : fine;
        CHECK(c[k].mesh.nCells() == t.mesh.nCells());
        CHECK(c[k].mesh.dilationRadius == Approx(t.mesh.dilationRadius * c[k].size / t.sieve_size));
        ++(c[k].feed_class == 0 ? nCoarse : nFine);
    }
    CHECK(nCoarse > 0);
    CHECK(nFine > 0);
    // The time step's probe: each class's template at the class's smallest size.
    FeedFactory factory(classes, {coarse, fine});
    CHECK(factory.smallestRock(0).dilationRadius ==
          Approx(coarse.mesh.dilationRadius * 0.015 / coarse.sieve_size));
    CHECK(factory.smallestRock(1).dilationRadius ==
          Approx(fine.mesh.dilationRadius * 0.02 / fine.sieve_size));
    CHECK_THROWS_AS(FeedFactory(classes, {coarse}), std::logic_error);
}
