// meshCrusher: the mantle and concave of a cone crusher as triangulated surfaces.
//
// Reads  system/meshCrusherDict           profiles (r z) of mantle and concave, setting,
//                                         throw, eccentric speed, pivot height
// Writes constant/triSurface/mantle.stl   mantle at its mean (untilted) position
//        constant/triSurface/concave.stl  concave, moved vertically to give the CSS
//        constant/crusherKinematics       pivot, eccentric angle and speed (for the DEM walls)
//        VTK/mantle.vtp, VTK/concave.vtp  the surfaces for ParaView
//
// Triangulation (revolveProfileShaped): nSegments points per ring on the outer half of the
// radii, fewer towards the axis, each profile segment split so that the triangles are
// near-equilateral (no long strips, no fan of slivers at the mantle top).
//
// The mantle gyrates without spin about the pivot (libs/geometry/crusherGeometry.hpp);
// the gaps at the closed and open sides are computed from the tilted mantle in the
// meridian plane of each side and printed (docs/theory-fragments.md, "Crusher").
#include <cmath>
#include <cstdio>

#include "core/application.hpp"
#include "core/atomicFile.hpp"
#include "core/dictionary.hpp"
#include "core/knownEntries.hpp"
#include "core/memoryLimit.hpp"
#include "geometry/crusherGeometry.hpp"
#include "io/foamFile.hpp"
#include "io/vtkOutput.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

namespace {

constexpr double pi = 3.14159265358979323846;

const AppInfo info{
    "meshCrusher",
    "Makes the mantle and concave of a cone crusher from (r z) profiles in system/meshCrusherDict:\n"
    "surfaces of revolution about z, the concave moved vertically so that the nutating mantle\n"
    "gives the closed side setting, the eccentric angle chosen to give the throw. Writes STL and\n"
    "VTK surfaces and constant/crusherKinematics, and prints CSS, OSS and the feed opening.",
    "[options]",
    {"meshCrusher -case tutorials/CH660/geometry", "meshCrusher -case tutorials/CH660/geometry -dry-run"},
    {},
};

Profile readProfile(const Dictionary& d, const std::string& key)
{
    Profile profile;
    for (const auto& point : d.get<std::vector<std::vector<double>>>(key)) {
        if (point.size() != 2)
            throw UserError(d.fileName() + ": " + key + ": each profile point is (r z), got " +
                            std::to_string(point.size()) + " values");
        profile.push_back({point[0], point[1]});
    }
    if (profile.size() < 2) throw UserError(d.fileName() + ": " + key + " needs at least 2 points (r z)");
    return profile;
}

ChamberSpec readSpec(const Dictionary& d)
{
    checkKnownEntries(d, meshCrusherDictEntries());
    checkKnownSubEntries(d, "mantle", {"profile"});
    checkKnownSubEntries(d, "concave", {"profile"});
    static const Dimensions metre = Dimensions::fromUnits("m");
    ChamberSpec s;
    s.mantle = readProfile(d, "mantle/profile");
    s.concave = readProfile(d, "concave/profile");
    s.closed_side_setting = d.getScalar("closedSideSetting", Bounds::positive(), &metre);
    s.eccentric_throw = d.getScalar("throw", Bounds::positive(), &metre);
    s.pivot_height = d.getScalar("pivotHeight", Bounds::any(), &metre);
    s.eccentric_speed_rpm = d.getScalar("eccentricSpeed", Bounds::positive());
    s.phase = pi / 180.0 * d.getScalarOrDefault("closedSideAzimuth", 0.0, Bounds::any());
    const std::string definition = d.found("throwDefinition")
                                       ? d.getWord("throwDefinition", {"settingDifference", "axisOffset"})
                                       : "settingDifference";
    s.throw_definition =
        definition == "axisOffset" ? ThrowDefinition::axisOffset : ThrowDefinition::settingDifference;
    return s;
}

std::string kinematicsText(const ChamberDesign& d, const ChamberSpec& s)
{
    auto entry = [](const std::string& key, const std::string& value, const std::string& comment) {
        std::string line = entryLine(key, value);
        line.pop_back();
        return line + "  // " + comment + "\n";
    };
    std::string t = foamFileHeader("crusherKinematics", "written by meshCrusher from system/meshCrusherDict");
    t += "// The mantle gyrates without spin: x = pivot + R(t) (x_mean - pivot), R(t) the tilt by\n"
         "// eccentricAngle about the horizontal axis d(t) x z, d(t) = (cos a, sin a, 0) the closed side,\n"
         "// a = closedSideAzimuth + eccentricSpeed t (libs/geometry/crusherGeometry.hpp: mantlePose).\n";
    t += entry("pivot", vectorText(d.kinematics.pivot), "[m]");
    t += entry("eccentricAngle", numberText(d.kinematics.eccentric_angle), "[rad]");
    t += entry("eccentricSpeed", numberText(d.kinematics.eccentric_speed), "[rad/s]");
    t += entry("closedSideAzimuth", numberText(d.kinematics.phase), "[rad] at t = 0");
    t += entry("closedSideSetting", numberText(d.gaps.closed), "[m] computed");
    t += entry("openSideSetting", numberText(d.gaps.open), "[m] computed");
    t += entry("concaveShift", numberText(d.concave_shift), "[m] applied to concave.stl");
    t += entry("dischargeLevel", numberText(d.discharge_level), "[m] lower rim of the mantle");
    t += entry("requestedThrow", numberText(s.eccentric_throw), "[m]");
    return t;
}

// Triangles of revolveProfileShaped, from above: rows of near-equilateral triangles whose
// circumferential spacing is 2 pi max(r, r_max/2) / nSegments, so each profile segment of
// length L gets at most L nSegments / (0.87 pi r_max) + 1 rows of 2 nSegments triangles.
double revolvedTriangles(const Profile& profile, int nSegments)
{
    double rMax = 0.0, rows = 0.0;
    for (const auto& p : profile) rMax = std::max(rMax, p.r);
    for (std::size_t p = 0; p + 1 < profile.size(); ++p)
        rows += std::hypot(profile[p + 1].r - profile[p].r, profile[p + 1].z - profile[p].z) * nSegments /
                    (0.87 * pi * rMax) +
                1.0;
    return 2.0 * nSegments * rows;
}

// Refuse liners that cannot fit before they are made. Measured peaks (docs/reliability.md):
// 176 018 triangles 28 MB, 17 650 242 triangles 1.05 GB (59 bytes each, with the output).
// Returns the -dry-run line.
std::string checkLinerMemory(const Dictionary& dict, const ChamberDesign& design, int nSegments)
{
    const double triangles = revolvedTriangles(design.chamber.mantle, nSegments) +
                             revolvedTriangles(design.chamber.concave, nSegments);
    const auto bytes = static_cast<std::uint64_t>(30e6 + 80.0 * std::min(triangles, 1e15));
    const std::string counts = "about " + formatNumber(std::round(triangles)) + " liner triangles";
    const std::string where = dict.found("nSegments") ? dict.location("nSegments").str() : dict.fileName();
    checkMemoryFits(bytes, where + ": nSegments " + std::to_string(nSegments) + ", " + counts,
                    "use fewer nSegments (360 is one degree)");
    return estimateLine(bytes, counts);
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, [](Application& app) {
        const Dictionary dict = Dictionary::readFile(app.path("system/meshCrusherDict"));
        const int n_segments = dict.getOrDefault<int>("nSegments", 360);
        if (n_segments < 3)
            throw UserError(dict.fileName() + ": nSegments must be at least 3, got " +
                            std::to_string(n_segments));
        const ChamberSpec spec = readSpec(dict);
        ChamberDesign design;
        try {
            design = designChamber(spec);
        } catch (const UserError& e) {
            throw UserError(dict.fileName() + ": " + e.what());
        }
        const std::string estimate = checkLinerMemory(dict, design, n_segments);
        const TriSurface mantle =
            revolveProfileShaped(design.chamber.mantle, n_segments, SurfaceFacing::awayFromAxis);
        const TriSurface concave =
            revolveProfileShaped(design.chamber.concave, n_segments, SurfaceFacing::towardsAxis);

        const CrusherKinematics& k = design.kinematics;
        const ChamberGaps& g = design.gaps;
        std::printf("Mantle: %zu points, %zu triangles; concave: %zu points, %zu triangles (%d segments)\n",
                    mantle.points.size(), mantle.triangles.size(), concave.points.size(),
                    concave.triangles.size(), n_segments);
        std::printf(
            "Pivot at z = %.4g m, discharge level z = %.4g m; concave moved by %+.2f mm for the CSS\n",
            k.pivot.z, design.discharge_level, 1e3 * design.concave_shift);
        std::printf(
            "Eccentric angle %.4f deg (axis offset throw/2 at the discharge would be %.4f deg), "
            "%.4g rpm, period %.5g s\n",
            180 / pi * k.eccentric_angle, 180 / pi * design.axis_offset_angle, spec.eccentric_speed_rpm,
            k.period());
        std::printf(
            "Closed side setting %.2f mm at z = %.1f mm; open side setting %.2f mm at z = %.1f mm; "
            "throw %.2f mm\n",
            1e3 * g.closed, 1e3 * g.closed_z, 1e3 * g.open, 1e3 * g.open_z, 1e3 * (g.open - g.closed));
        std::printf("Feed opening (upper rim of the concave): closed side %.1f mm, open side %.1f mm\n",
                    1e3 * g.feed_closed, 1e3 * g.feed_open);
        if (app.dryRun()) {
            std::printf("%s\nDry run: nothing written.\n", estimate.c_str());
            return 0;
        }
        writeStl(app.path("constant/triSurface/mantle.stl"), mantle, "mantle");
        writeStl(app.path("constant/triSurface/concave.stl"), concave, "concave");
        writeFileAtomically(app.path("constant/crusherKinematics"),
                            [&](std::ostream& out) { out << kinematicsText(design, spec); });
        writeTrianglesVtp(app.path("VTK/mantle.vtp"), mantle.points, mantle.triangles, 0.0);
        writeTrianglesVtp(app.path("VTK/concave.vtp"), concave.points, concave.triangles, 0.0);
        std::printf(
            "End: written constant/triSurface/{mantle,concave}.stl, constant/crusherKinematics, "
            "VTK/{mantle,concave}.vtp\n");
        return 0;
    });
}
