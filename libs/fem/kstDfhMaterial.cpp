#include "fem/kstDfhMaterial.hpp"

#include <cmath>
#include <limits>

#include "core/error.hpp"
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

}  // namespace

KstDfhMaterial::KstDfhMaterial(const MaterialParameters& parameters) : FemMaterial(parameters)
{
    checkCompactionCurve(parameters.compactionCurve);
    constants_.elastic = elasticity_;
    constants_.a0 = parameters.kstA0;
    constants_.a1 = parameters.kstA1;
    constants_.a2 = parameters.kstA2;
    constants_.pressureCutoff =
        std::isnan(parameters.tensilePressureCutoff)
            ? automaticPressureCutoff(parameters.kstA0, parameters.kstA1, parameters.kstA2)
            : parameters.tensilePressureCutoff;
    if (constants_.pressureCutoff > 0.0)
        throw UserError("kstDfh: the tensile pressure cutoff must be <= 0 (P is positive in compression)");
    constants_.damageEnabled = parameters.damageEnabled;
    constants_.crackShearRetention = parameters.crackShearRetention;
    constants_.fractureEnergy = parameters.fractureEnergy;
    if (!(parameters.fractureEnergy >= 0.0))
        throw UserError("kstDfh: fractureEnergy must be >= 0 (0: complete failure at the threshold)");
    if (!(parameters.crackShearRetention >= 0.0 && parameters.crackShearRetention <= 1.0))
        throw UserError("kstDfh: crackShearRetention must lie in [0, 1]");
    if (parameters.erodeAfterCracks < 0 || parameters.erodeAfterCracks > 3)
        throw UserError("kstDfh: erodeAfterCracks must be 0 (no erosion), 1, 2 or 3");
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
    crackOpening_.assign(parameters_.fractureEnergy > 0.0 ? 3 * n : 0, 0.0);
    softeningStrain_.assign(parameters_.fractureEnergy > 0.0 ? 3 * n : 0, 0.0);
    for (std::size_t e = 0; e < n; ++e)
        for (int i = 0; i < 3; ++i) crackFrame_[9 * e + 4 * i] = 1.0;
    if (!parameters_.damageEnabled) return;
    const WeibullStrength weibull(parameters_.weibullModulus, parameters_.weibullStress,
                                  parameters_.referenceVolume);
    for (std::size_t e = 0; e < n; ++e) {
        const auto thresholds = weibull.elementThresholds(parameters_.seed, e, geometry.volumes[e]);
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
    const double erodeAt = parameters_.erodeAfterCracks > 0 ? parameters_.erodeAfterCracks : 4.0;
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
