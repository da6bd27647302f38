#include "fem/kstDfhMaterial.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/selector.hpp"
#include "fem/elementLoop.hpp"
#include "fem/weibullStrength.hpp"

namespace rockfrac::fem {

namespace {

void checkCompactionCurve(const std::vector<std::pair<double, double>>& curve)
{
    double previousStrain = 0.0;
    for (const auto& [strain, pressure] : curve) {
        if (!(strain > previousStrain))
            throw UserError("kstDfh: the compaction curve strains must be positive and increasing");
        if (!(pressure >= 0.0)) throw UserError("kstDfh: the compaction curve pressures must be >= 0");
        previousStrain = strain;
    }
}

double pressureCutoffOf(const KstDfhParameters& p)
{
    return std::isnan(p.tensilePressureCutoff) ? automaticPressureCutoff(p.kstA0, p.kstA1, p.kstA2)
                                               : p.tensilePressureCutoff;
}

}  // namespace

namespace {

void readKst(const Dictionary& kst, KstDfhParameters& m)
{
    static const Dimensions pascal = Dimensions::fromUnits("Pa");
    static const Dimensions pascalSquared = Dimensions::fromUnits("Pa^2");
    requireKnownEntries(kst, {"a0", "a1", "a2", "tensilePressureCutoff", "compactionCurve"});
    m.kstA0 = kst.getScalar("a0", Bounds::any(), &pascalSquared);
    m.kstA1 = kst.getScalar("a1", Bounds::any(), &pascal);
    m.kstA2 = kst.getScalar("a2", Bounds::any());
    if (kst.found("tensilePressureCutoff"))
        m.tensilePressureCutoff = kst.getScalar("tensilePressureCutoff", Bounds::closed(-1e300, 0), &pascal);
    if (kst.found("compactionCurve"))
        for (const auto& point : kst.get<std::vector<std::vector<double>>>("compactionCurve")) {
            if (point.size() != 2)
                throw UserError(kst.fileName() +
                                ": kstDfh/kst/compactionCurve: each point is (volumetricStrain pressure)");
            m.compactionCurve.emplace_back(point[0], point[1]);
        }
}

void readDfh(const Dictionary& dfh, KstDfhParameters& m)
{
    static const Dimensions pascal = Dimensions::fromUnits("Pa");
    static const Dimensions volume = Dimensions::fromUnits("m^3");
    static const Dimensions energyPerArea = Dimensions::fromUnits("N/m");
    requireKnownEntries(dfh, {"damage", "weibullModulus", "weibullStress", "referenceVolume", "seed",
                              "crackShearRetention", "fractureEnergy", "erodeAfterCracks"});
    m.damageEnabled = dfh.getOrDefault<bool>("damage", true);
    m.weibullModulus = dfh.getScalar("weibullModulus", Bounds::positive());
    m.weibullStress = dfh.getScalar("weibullStress", Bounds::positive(), &pascal);
    m.referenceVolume = dfh.getScalar("referenceVolume", Bounds::positive(), &volume);
    m.seed = dfh.get<std::uint64_t>("seed");
    m.crackShearRetention = dfh.getScalarOrDefault("crackShearRetention", 0.0, Bounds::closed(0, 1));
    m.fractureEnergy = dfh.getScalarOrDefault("fractureEnergy", 0.0, Bounds::nonNegative(), &energyPerArea);
    const double erode = dfh.getScalarOrDefault("erodeAfterCracks", 0.0, Bounds::closed(0, 3));
    if (erode != std::floor(erode)) {
        std::ostringstream message;
        message << dfh.fileName() << ": kstDfh/dfh/erodeAfterCracks is " << erode
                << "; give the number of failed directions that erode an element: 0 (never), 1, 2 or 3";
        throw UserError(message.str());
    }
    m.erodeAfterCracks = static_cast<int>(erode);
}

}  // namespace

KstDfhMaterial::Coefficients KstDfhMaterial::read(const Dictionary& d)
{
    requireKnownEntries(d, {"kst", "dfh"});
    Coefficients c;
    readKst(d.subDict("kst"), c);
    readDfh(d.subDict("dfh"), c);
    return c;
}

std::string KstDfhMaterial::describe(const Coefficients& m)
{
    char buffer[512];
    std::string text;
    std::snprintf(
        buffer, sizeof buffer,
        "; KST a0 %.4g Pa^2 a1 %.4g Pa a2 %.4g; DFH %s m %.3g sigma_w %.4g MPa V_ref %.4g mm^3 seed %llu",
        m.kstA0, m.kstA1, m.kstA2, m.damageEnabled ? "on" : "off", m.weibullModulus, 1e-6 * m.weibullStress,
        1e9 * m.referenceVolume, static_cast<unsigned long long>(m.seed));
    text = buffer;
    if (m.damageEnabled) {
        if (m.fractureEnergy > 0.0) {
            std::snprintf(buffer, sizeof buffer, "; crack band G_F %.4g N/m", m.fractureEnergy);
            text += buffer;
        } else {
            text += "; cracks complete at the threshold";
        }
        if (m.crackShearRetention > 0.0) {
            std::snprintf(buffer, sizeof buffer, "; crack shear retention %.3g", m.crackShearRetention);
            text += buffer;
        }
        if (m.erodeAfterCracks > 0) {
            std::snprintf(buffer, sizeof buffer, "; erosion after %d cracks", m.erodeAfterCracks);
            text += buffer;
        }
    }
    return text;
}

void KstDfhMaterial::check(const Coefficients& p)
{
    checkCompactionCurve(p.compactionCurve);
    if (pressureCutoffOf(p) > 0.0)
        throw UserError("kstDfh: the tensile pressure cutoff must be <= 0 (P is positive in compression)");
    if (!(p.fractureEnergy >= 0.0))
        throw UserError("kstDfh: fractureEnergy must be >= 0 (0: complete failure at the threshold)");
    if (!(p.crackShearRetention >= 0.0 && p.crackShearRetention <= 1.0))
        throw UserError("kstDfh: crackShearRetention must lie in [0, 1]");
    if (p.erodeAfterCracks < 0 || p.erodeAfterCracks > 3)
        throw UserError("kstDfh: erodeAfterCracks must be 0 (no erosion), 1, 2 or 3");
}

KstDfhMaterial::KstDfhMaterial(const ElasticParameters& elastic, const Coefficients& parameters)
    : FemMaterial(elastic), coefficients_(parameters)
{
    check(parameters);
    constants_.elastic = elasticity_;
    constants_.a0 = parameters.kstA0;
    constants_.a1 = parameters.kstA1;
    constants_.a2 = parameters.kstA2;
    constants_.pressureCutoff = pressureCutoffOf(parameters);
    constants_.damageEnabled = parameters.damageEnabled;
    constants_.crackShearRetention = parameters.crackShearRetention;
    constants_.fractureEnergy = parameters.fractureEnergy;
    for (const auto& [strain, pressure] : parameters.compactionCurve) {
        compactionStrains_.push_back(strain);
        compactionPressures_.push_back(pressure);
    }
    constants_.compactionStrains = compactionStrains_.data();
    constants_.compactionPressures = compactionPressures_.data();
    constants_.compactionPoints = static_cast<int>(compactionStrains_.size());
}

void KstDfhMaterial::initialise(const ElementGeometry& geometry)
{
    const std::size_t n = geometry.numElements();
    plasticStrain_.assign(6 * n, 0.0);
    equivalentPlasticStrain_.assign(n, 0.0);
    compactionStrain_.assign(n, 0.0);
    crackCount_.assign(n, 0.0);
    crackFrame_.assign(9 * n, 0.0);
    failureStress_.assign(3 * n, std::numeric_limits<double>::infinity());
    // The crack band's history exists only with a fracture energy (restart files and the
    // memory of the default model are unchanged).
    crackOpening_.assign(coefficients_.fractureEnergy > 0.0 ? 3 * n : 0, 0.0);
    softeningStrain_.assign(coefficients_.fractureEnergy > 0.0 ? 3 * n : 0, 0.0);
    for (std::size_t e = 0; e < n; ++e)
        for (int i = 0; i < 3; ++i) crackFrame_[9 * e + 4 * i] = 1.0;
    if (!coefficients_.damageEnabled) return;
    const WeibullStrength weibull(coefficients_.weibullModulus, coefficients_.weibullStress,
                                  coefficients_.referenceVolume);
    for (std::size_t e = 0; e < n; ++e) {
        const auto thresholds = weibull.elementThresholds(coefficients_.seed, e, geometry.volumes[e]);
        for (int i = 0; i < 3; ++i) failureStress_[3 * e + i] = thresholds[i];
    }
}

KstDfhPointState KstDfhMaterial::pointState(std::size_t e) const
{
    KstDfhPointState s;
    s.plasticStrain = SymTensor::fromArray(&plasticStrain_[6 * e]);
    s.equivalentPlasticStrain = equivalentPlasticStrain_[e];
    s.compactionStrain = compactionStrain_[e];
    s.crackCount = static_cast<int>(crackCount_[e]);
    if (s.crackCount > 0)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) s.crackFrame.m[i][j] = crackFrame_[9 * e + 3 * i + j];
    for (int i = 0; i < 3; ++i) s.failureStress[i] = failureStress_[3 * e + i];
    if (s.crackCount > 0 && !crackOpening_.empty())
        for (int i = 0; i < 3; ++i) {
            s.crackOpening[i] = crackOpening_[3 * e + i];
            s.softeningStrain[i] = softeningStrain_[3 * e + i];
        }
    return s;
}

void KstDfhMaterial::storePlasticHistory(std::size_t e, const KstDfhPointState& s)
{
    s.plasticStrain.toArray(&plasticStrain_[6 * e]);
    equivalentPlasticStrain_[e] = s.equivalentPlasticStrain;
    compactionStrain_[e] = s.compactionStrain;
}

void KstDfhMaterial::storeCracks(std::size_t e, const KstDfhPointState& s)
{
    crackCount_[e] = s.crackCount;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) crackFrame_[9 * e + 3 * i + j] = s.crackFrame.m[i][j];
    storeCrackOpenings(e, s);
}

void KstDfhMaterial::storeCrackOpenings(std::size_t e, const KstDfhPointState& s)
{
    if (crackOpening_.empty()) return;
    for (int i = 0; i < 3; ++i) {
        crackOpening_[3 * e + i] = s.crackOpening[i];
        softeningStrain_[3 * e + i] = s.softeningStrain[i];
    }
}

double KstDfhMaterial::damage(std::size_t e, int direction) const
{
    if (crackCount_[e] <= direction) return 0.0;
    if (crackOpening_.empty()) return 1.0;
    const double fraction = crackOpening_[3 * e + direction] / softeningStrain_[3 * e + direction];
    return fraction < 1.0 ? fraction : 1.0;
}

void KstDfhMaterial::setPointState(std::size_t e, const KstDfhPointState& s)
{
    storePlasticHistory(e, s);
    storeCracks(e, s);
    for (int i = 0; i < 3; ++i) failureStress_[3 * e + i] = s.failureStress[i];
}

Vec3 KstDfhMaterial::crackNormal(std::size_t e, int direction) const
{
    const double* row = &crackFrame_[9 * e + 3 * direction];
    return {row[0], row[1], row[2]};
}

long long KstDfhMaterial::computeElementForces(const ElementGeometry& geometry, const double* displacements,
                                               double* stresses, double* elementForces)
{
    const KstDfhConstants c = constants_;
    const double erodeAt = coefficients_.erodeAfterCracks > 0 ? coefficients_.erodeAfterCracks : 4.0;
    const double* crackCount = crackCount_.data();
    return elementLoop(
        geometry, displacements, stresses, elementForces,
        [this, &c, &geometry, erodeAt](std::size_t e, const SymTensor& strain) {
            // Only what the update can change is written back (the
            // thresholds never change; the frame only when a crack forms).
            // An elastic step leaves the plastic history as it was: not
            // writing it back saves 8 stores per element and step.
            KstDfhPointState state = pointState(e);
            state.elementGradients = &geometry.gradients[12 * e];
            const int cracksBefore = state.crackCount;
            const double openingBefore[3] = {state.crackOpening[0], state.crackOpening[1],
                                             state.crackOpening[2]};
            bool historyChanged = false;
            const SymTensor stress = kstDfh::updateStress(c, state, strain, &historyChanged);
            if (historyChanged) storePlasticHistory(e, state);
            if (state.crackCount != cracksBefore)
                storeCracks(e, state);
            else if (state.crackCount > 0 &&
                     (state.crackOpening[0] != openingBefore[0] ||
                      state.crackOpening[1] != openingBefore[1] || state.crackOpening[2] != openingBefore[2]))
                storeCrackOpenings(e, state);
            // The crack that erodes the element takes its stress at once.
            return state.crackCount >= erodeAt ? SymTensor{} : stress;
        },
        [crackCount, erodeAt](std::size_t e) { return crackCount[e] >= erodeAt; });
}

std::vector<StateField> KstDfhMaterial::stateFields()
{
    std::vector<StateField> fields{{"plasticStrain", 6, &plasticStrain_},
                                   {"equivalentPlasticStrain", 1, &equivalentPlasticStrain_},
                                   {"compactionStrain", 1, &compactionStrain_},
                                   {"crackCount", 1, &crackCount_},
                                   {"crackFrame", 9, &crackFrame_},
                                   {"failureStress", 3, &failureStress_}};
    if (!crackOpening_.empty()) {
        fields.push_back({"crackOpening", 3, &crackOpening_});
        fields.push_back({"softeningStrain", 3, &softeningStrain_});
    }
    return fields;
}

}  // namespace rockfrac::fem
