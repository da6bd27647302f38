#include "femCase/femCase.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/knownEntries.hpp"
#include "core/selector.hpp"
#include "io/stateFile.hpp"
#include "io/vtkOutput.hpp"

namespace rockfrac {

namespace fs = std::filesystem;
using namespace fem;

// ---- Parameters ------------------------------------------------------------------

const std::vector<std::string>& femRockPropertiesEntries()
{
    static const std::vector<std::string> entries = [] {
        std::vector<std::string> e = {"rock", "material"};
        for (const std::string& m : femMaterials().names()) e.push_back(m);
        return e;
    }();
    return entries;
}

FemParameters readFemParameters(const Dictionary& d)
{
    static const Dimensions pascal = Dimensions::fromUnits("Pa");
    static const Dimensions density = Dimensions::fromUnits("kg/m^3");
    FemParameters p;
    const Dictionary& rock = d.subDict("rock");
    requireKnownEntries(rock, {"E", "poissonRatio", "density"});
    p.rock.youngsModulus = rock.getScalar("E", Bounds::positive(), &pascal);
    p.rock.poissonRatio = rock.getScalar("poissonRatio", Bounds::closedOpen(0, 0.5));
    p.rock.density = rock.getScalar("density", Bounds::positive(), &density);
    for (const char* moved : {"kst", "dfh"})
        if (d.found(moved))
            throw UserError(
                d.location(moved).str() + ": '" + moved +
                "' belongs in the material's own sub-dictionary: kstDfh { kst { ... } dfh { ... } } "
                "(docs/models/fem/kstDfh.md)");
    checkKnownEntries(d, femRockPropertiesEntries());
    p.material = femMaterials().select(d, "material");  // the model reads its own sub-dictionary
    return p;
}

const std::vector<std::string>& femControlEntries()
{
    static const std::vector<std::string> entries = {"timeStepSafety", "massScalingTimeStep", "massDamping"};
    return entries;
}

// ---- Loading ---------------------------------------------------------------------

const std::vector<std::string>& femLoadingEntries()
{
    static const std::vector<std::string> entries = {"plates", "arcLoad",     "gravity",     "settling",
                                                     "stop",   "failureLoad", "extensometer"};
    return entries;
}

FemLoading readFemLoading(const Dictionary& d)
{
    static const Dimensions length = Dimensions::fromUnits("m");
    static const Dimensions pressureRate = Dimensions::fromUnits("Pa/s");
    checkKnownEntries(d, femLoadingEntries());
    checkKnownSubEntries(
        d, "plates",
        {"lower", "upper", "startGap", "contactPenaltyScale", "tangentialPenaltyRatio", "crushingPressure"});
    checkKnownSubEntries(d, "arcLoad", {"halfAngle", "pressureRate"});
    checkKnownSubEntries(d, "settling", {"duration"});
    checkKnownSubEntries(d, "stop", {"forceDropFraction", "minPeakForce"});
    checkKnownSubEntries(d, "failureLoad", {"dropFraction"});
    checkKnownSubEntries(d, "extensometer", {"length", "centre"});
    FemLoading l;
    const bool plates = d.found("plates"), arc = d.found("arcLoad");
    if (plates == arc)
        throw UserError(d.fileName() +
                        ": give either 'plates { lower {...} upper {...} }' or "
                        "'arcLoad { halfAngle; pressureRate; }', not both or neither");
    if (plates) {
        const Dictionary& p = d.subDict("plates");
        auto plate = [&](const std::string& name) {
            const Dictionary& s = p.subDict(name);
            checkKnownEntries(s, {"velocity", "friction"});
            FemPlateSpec spec;
            spec.velocity = s.get<Vec3>("velocity");
            spec.friction = s.getScalarOrDefault("friction", 0.6, Bounds::nonNegative());
            return spec;
        };
        l.lower = plate("lower");
        l.upper = plate("upper");
        l.startGap = p.getScalarOrDefault("startGap", 0.0, Bounds::nonNegative(), &length);
        l.contactPenaltyScale = p.getScalarOrDefault("contactPenaltyScale", 1.0, Bounds::positive());
        l.tangentialPenaltyRatio = p.getScalarOrDefault("tangentialPenaltyRatio", 1.0, Bounds::nonNegative());
        static const Dimensions pascal = Dimensions::fromUnits("Pa");
        l.contactCrushingPressure =
            p.getScalarOrDefault("crushingPressure", 0.0, Bounds::nonNegative(), &pascal);
        if (!(l.approachSpeed() > 0))
            throw UserError(
                d.fileName() +
                ": the plates do not approach each other (upper velocity z must be below the lower "
                "one); give the upper plate a downward velocity");
    } else {
        const Dictionary& a = d.subDict("arcLoad");
        l.kind = FemLoading::Kind::arcLoad;
        l.arc.halfAngle = a.getScalar("halfAngle", Bounds::open(0, 90)) * M_PI / 180.0;
        l.arc.pressureRate = a.getScalar("pressureRate", Bounds::positive(), &pressureRate);
    }
    l.gravity = d.getOrDefault<Vec3>("gravity", Vec3{0, 0, 0});
    if (d.found("settling"))
        l.settlingTime = d.subDict("settling").getScalar("duration", Bounds::nonNegative());
    if (d.found("stop")) {
        const Dictionary& stop = d.subDict("stop");
        l.stopForceFraction = stop.getScalarOrDefault("forceDropFraction", 0.0, Bounds::closedOpen(0, 1));
        l.minPeakForce = stop.getScalarOrDefault("minPeakForce", 0.0, Bounds::nonNegative());
    }
    if (d.found("failureLoad"))
        l.failureDropFraction =
            d.subDict("failureLoad").getScalarOrDefault("dropFraction", 0.2, Bounds::open(0, 1));
    if (d.found("extensometer")) {
        const Dictionary& e = d.subDict("extensometer");
        l.extensometerLength = e.getScalarOrDefault("length", 20e-3, Bounds::positive(), &length);
        if (e.found("centre")) l.extensometerCentre = e.get<Vec3>("centre");
    }
    return l;
}

std::vector<double> arcLoadUnitForces(const TetMesh& mesh, const Vec3& centre, double halfAngle,
                                      double& topForce)
{
    const std::vector<std::array<int, 4>> faces = boundaryFaces(mesh);  // (a, b, c, opposite)
    std::vector<double> forces(3 * mesh.numNodes(), 0.0);
    const double cosLimit = std::cos(halfAngle);
    // The arcs are integrated exactly, not facet by facet: with a few facets across an
    // arc, taking whole facets whose centroid lies on it loads a discrete arc that can be
    // 15 % narrower on one side than on the other, and the self-equilibrating correction
    // below then moves the resultant away from the one reported (measured on the 2 mm BDT
    // mesh: 4.62e-5 N/Pa on the upper arc and 4.10e-5 N/Pa on the lower, 5.4e-5 nominal).
    // Each curved facet is cut into n^2 congruent sub-triangles; a sub-triangle whose
    // centroid lies within the arc adds its share of the pressure, lumped to the facet's
    // nodes with the linear shape functions at that centroid (consistent nodal forces of
    // the pressure on the exact arc, up to h/n along its edges).
    constexpr int n = 24;
    for (const auto& f : faces) {
        const Vec3 &a = mesh.nodes[f[0]], &b = mesh.nodes[f[1]], &c = mesh.nodes[f[2]];
        Vec3 areaNormal = 0.5 * cross(b - a, c - a);  // |.| = area
        const Vec3 centroid = (a + b + c) / 3.0;
        if (dot(areaNormal, centroid - mesh.nodes[f[3]]) < 0) areaNormal = -1.0 * areaNormal;
        const double area = norm(areaNormal);
        const Vec3 radial{centroid.x - centre.x, 0.0, centroid.z - centre.z};
        // Curved surface only: the outward normal lies in the x-z plane, not along the axis.
        if (std::abs(areaNormal.y) > 0.5 * area || !(norm(radial) > 0)) continue;
        // Pressure acts against the outward normal, towards the centre.
        const Vec3 subForce = (-1.0 / (n * n)) * areaNormal;
        // Sub-triangle centroids in barycentric coordinates (i + 1/3, j + 1/3)/n (upright)
        // and (i + 2/3, j + 2/3)/n (inverted): n^2 triangles of equal area.
        for (int i = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j)
                for (int inverted = 0; inverted < (i + j < n - 1 ? 2 : 1); ++inverted) {
                    const double shift = inverted ? 2.0 / 3.0 : 1.0 / 3.0;
                    const double wb = (i + shift) / n, wc = (j + shift) / n, wa = 1.0 - wb - wc;
                    const Vec3 point = wa * a + wb * b + wc * c;
                    const double rx = point.x - centre.x, rz = point.z - centre.z;
                    if (std::abs(rz) < cosLimit * std::hypot(rx, rz)) continue;
                    const double weights[3] = {wa, wb, wc};
                    for (int k = 0; k < 3; ++k)
                        for (int d = 0; d < 3; ++d) forces[3 * f[k] + d] += weights[k] * subForce[d];
                }
    }
    // The facets of the two arcs differ slightly (an unstructured mesh): remove the net
    // force, spread evenly over the loaded nodes, so the load is self-equilibrated and
    // does not drive a slow rigid drift of the free disc.
    Vec3 net;
    std::vector<int> loaded;
    for (std::size_t i = 0; i < mesh.numNodes(); ++i) {
        const Vec3 f{forces[3 * i], forces[3 * i + 1], forces[3 * i + 2]};
        if (norm(f) > 0) loaded.push_back(static_cast<int>(i)), net += f;
    }
    for (int i : loaded)
        for (int j = 0; j < 3; ++j) forces[3 * i + j] -= net[j] / static_cast<double>(loaded.size());
    // The resultant reported is the one applied: the downward force on the upper arc
    // after the correction.
    topForce = 0.0;
    for (int i : loaded)
        if (mesh.nodes[i].z > centre.z) topForce -= forces[3 * i + 2];
    return forces;
}

// ---- Whole state -------------------------------------------------------------------

void writeFemState(const fs::path& file, FemModel& model, const FemRunState& run)
{
    const FemState& s = model.state();
    StateFile f;
    f.putScalar("time", s.time);
    f.put("stepCount", std::vector<std::int64_t>{s.stepCount});
    f.putScalar("previousTimeStep", s.previousTimeStep);
    f.put("displacements", s.displacements);
    f.put("velocities", s.velocities);
    f.put("netForces", s.netForces);
    f.put("internalForces", s.internalForces);
    f.put("externalForces", s.externalForces);
    f.put("elementStresses", s.elementStresses);
    f.put("energy", std::vector<double>{s.energy.internalWork, s.energy.externalWork, s.energy.dampingWork});
    for (std::size_t k = 0; k < s.plates.size(); ++k) {
        const RigidPlate& p = s.plates[k];
        const std::string name = "plate" + std::to_string(k) + ".";
        f.put(name + "motion",
              std::vector<double>{p.velocity.x, p.velocity.y, p.velocity.z, p.displacement.x,
                                  p.displacement.y, p.displacement.z, p.force.x, p.force.y, p.force.z});
        f.put(name + "tangentialForces", p.tangentialForces);
        f.put(name + "crushedDepth", p.crushedDepth);
    }
    for (const StateField& field : model.material().stateFields())
        f.put("material." + field.name, *field.values);
    f.put("run.step", std::vector<std::int64_t>{run.step});
    f.put("run.peak", std::vector<double>{run.peakForce, run.peakTime, run.peakGap, run.peakElongation,
                                          run.kineticRatioAtPeak});
    f.put("run.detectorMaximum", run.detectorMaximum);
    f.put("run.detectorFailed", run.detectorFailed);
    f.put("run.detectorTime", run.detectorTime);
    f.write(file);
}

FemRunState readFemState(const fs::path& file, FemModel& model)
{
    const StateFile f = StateFile::read(file);
    const long nodes3 = static_cast<long>(3 * model.mesh().numNodes());
    const long elements = static_cast<long>(model.mesh().numTets());
    FemState s = model.state();
    s.time = f.scalar("time");
    s.stepCount = f.integers("stepCount", 1)[0];
    s.previousTimeStep = f.scalar("previousTimeStep");
    s.displacements = f.doubles("displacements", nodes3);
    s.velocities = f.doubles("velocities", nodes3);
    s.netForces = f.doubles("netForces", nodes3);
    s.internalForces = f.doubles("internalForces", nodes3);
    s.externalForces = f.doubles("externalForces", nodes3);
    s.elementStresses = f.doubles("elementStresses", 6 * elements);
    const auto& energy = f.doubles("energy", 3);
    s.energy = {energy[0], energy[1], energy[2]};
    for (std::size_t k = 0; k < s.plates.size(); ++k) {
        RigidPlate& p = s.plates[k];
        const std::string name = "plate" + std::to_string(k) + ".";
        const auto& m = f.doubles(name + "motion", 9);
        p.velocity = {m[0], m[1], m[2]};
        p.displacement = {m[3], m[4], m[5]};
        p.force = {m[6], m[7], m[8]};
        p.tangentialForces =
            f.doubles(name + "tangentialForces", static_cast<long>(p.tangentialForces.size()));
        // States written before contact crushing existed have no crushed depths: none.
        if (f.has(name + "crushedDepth"))
            p.crushedDepth = f.doubles(name + "crushedDepth", static_cast<long>(p.crushedDepth.size()));
    }
    model.setState(s);
    for (const StateField& field : model.material().stateFields())
        *field.values = f.doubles("material." + field.name, static_cast<long>(field.components) * elements);
    FemRunState run;
    run.step = f.integers("run.step", 1)[0];
    const auto& peak = f.doubles("run.peak", 5);
    run.peakForce = peak[0], run.peakTime = peak[1], run.peakGap = peak[2], run.peakElongation = peak[3];
    run.kineticRatioAtPeak = peak[4];
    run.detectorMaximum = f.doubles("run.detectorMaximum");
    const long detectors = static_cast<long>(run.detectorMaximum.size());
    run.detectorFailed = f.doubles("run.detectorFailed", detectors);
    run.detectorTime = f.doubles("run.detectorTime", detectors);
    return run;
}

// ---- VTK ---------------------------------------------------------------------------

void writeFemVtk(const fs::path& caseDir, long index, const FemModel& model, bool restarted)
{
    const ElementOutput out = model.elementOutput();
    const std::size_t n = model.mesh().numTets();
    std::vector<double> sigma[3];
    for (int k = 0; k < 3; ++k) {
        sigma[k].resize(n);
        for (std::size_t e = 0; e < n; ++e) sigma[k][e] = out.principalStresses[3 * e + k];
    }
    const auto& u = model.state().displacements;
    std::vector<Vec3> displacement(model.mesh().numNodes());
    for (std::size_t i = 0; i < displacement.size(); ++i)
        displacement[i] = {u[3 * i], u[3 * i + 1], u[3 * i + 2]};
    const std::string name = "fem_" + std::to_string(index) + ".vtu";
    const fs::path vtk = caseDir / "VTK";
    writeTetsVtu(vtk / name, model.mesh().nodes, model.mesh().tets,
                 {Field::scalar("D1", out.damage[0]), Field::scalar("D2", out.damage[1]),
                  Field::scalar("D3", out.damage[2]),
                  Field::scalar("equivalentPlasticStrain", out.equivalentPlasticStrain),
                  Field::scalar("sigma1", sigma[0]), Field::scalar("sigma2", sigma[1]),
                  Field::scalar("sigma3", sigma[2])},
                 {Field::vector("displacement", displacement)}, model.time());
    SeriesFile series(vtk / "fem.vtu.series");
    if (!restarted && index == 0) series.truncateFrom(-1.0);
    series.truncateFrom(model.time());  // entries of a longer earlier run at or after this time go
    series.add(name, model.time());
    series.write();
}

}  // namespace rockfrac
