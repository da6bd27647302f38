#pragma once
// KST-DFH at one material point: the stress update used by KstDfhMaterial.
//
// Order of one update (total-strain form, small strain):
//  1. compaction (optional): the pressure from the elastic volumetric strain may not
//     exceed the piecewise-linear crush curve P_c(eps_v); the excess becomes
//     irreversible compaction strain;
//  2. elastic predictor with the element's cracks (DFH): in the frozen crack frame an
//     open crack carries no normal stress and a reduced shear stress; a crack closes
//     (full stiffness back) when its normal stress would be compressive;
//  3. KST return: sigma_eq <= sqrt(max(0, a0 + a1 P + a2 P^2)) by scaling the
//     deviator at fixed P (radial return, perfectly plastic); pressures below the
//     tensile cutoff return to the apex P = P_cut;
//  4. DFH: if the next threshold is exceeded, a new crack direction is frozen and
//     the update is redone from step 1 with it (up to three cracks per element).
// All functions are RF_HD (no exceptions, no heap) so a device backend can reuse them.
#include "fem/symTensor.hpp"

namespace rockfrac::fem {

// Constants of the model derived once from MaterialParameters.
struct KstDfhConstants {
    IsotropicElasticity elastic;
    double a0 = 0.0, a1 = 0.0, a2 = 0.0;  // sigma_eq^2 = a0 + a1 P + a2 P^2
    double pressureCutoff = 0.0;          // most tensile admissible pressure (<= 0)
    bool damageEnabled = true;
    double crackShearRetention = 0.0;
    // Compaction curve (compressive volumetric strain, pressure); count 0 = off.
    const double* compactionStrains = nullptr;
    const double* compactionPressures = nullptr;
    int compactionPoints = 0;

    RF_HD double yieldStress(double pressure) const
    {
        const double radicand = a0 + a1 * pressure + a2 * pressure * pressure;
        return radicand > 0.0 ? std::sqrt(radicand) : 0.0;
    }
};

// History of one material point.
struct KstDfhPointState {
    SymTensor plasticStrain;  // deviatoric (KST) and cutoff plastic strain
    double equivalentPlasticStrain = 0.0;
    double compactionStrain = 0.0;        // irreversible compressive volumetric strain (>= 0)
    int crackCount = 0;                   // failed directions: rows 0..crackCount-1 of crackFrame
    Mat3 crackFrame = Mat3::identity();   // orthonormal rows n1, n2, n3
    double failureStress[3] = {0, 0, 0};  // ascending DFH thresholds
};

// Upper root of a0 + a1 P + a2 P^2 = 0 (where the KST surface closes on the tensile
// side), or 0 when there is no real root.
inline double automaticPressureCutoff(double a0, double a1, double a2)
{
    if (a2 == 0.0) return a1 > 0.0 ? -a0 / a1 : 0.0;
    const double discriminant = a1 * a1 - 4.0 * a2 * a0;
    if (discriminant < 0.0) return 0.0;
    const double root = (-a1 + (a2 > 0 ? 1.0 : -1.0) * std::sqrt(discriminant)) / (2.0 * a2);
    return root < 0.0 ? root : 0.0;
}

namespace kstDfh {

// Crush-curve pressure at compressive volumetric strain ev (linear from the origin
// to the first point, last segment extended).
RF_HD inline double compactionPressure(const KstDfhConstants& c, double ev)
{
    double e0 = 0.0, p0 = 0.0;
    for (int k = 0; k < c.compactionPoints; ++k) {
        const double e1 = c.compactionStrains[k], p1 = c.compactionPressures[k];
        if (ev <= e1 || k + 1 == c.compactionPoints) return p0 + (p1 - p0) * (ev - e0) / (e1 - e0);
        e0 = e1, p0 = p1;
    }
    return 0.0;
}

// Step 1: grows the compaction strain when the elastic pressure exceeds the curve.
RF_HD inline void updateCompaction(const KstDfhConstants& c, const SymTensor& strain,
                                   double& compactionStrain)
{
    if (c.compactionPoints == 0) return;
    const double bulk = c.elastic.bulkModulus();
    const double ev = -trace(strain);  // compressive volumetric strain
    const double curvePressure = compactionPressure(c, ev);
    if (bulk * (ev - compactionStrain) > curvePressure) {
        const double compacted = ev - curvePressure / bulk;
        compactionStrain = compacted > compactionStrain ? compacted : compactionStrain;
    }
}

// Step 2: elastic stress with the frozen cracks. In the crack frame, the opening
// strains e_i >= 0 of the open cracks make their normal stresses vanish:
//   (2 mu I + lambda 1 1^T) e = b,  b_i = trial normal stress (Sherman-Morrison solve),
// found by an active set (a crack opens when its trial normal stress is tensile and
// closes again if its opening strain would be negative). Shear components coupling
// to an open crack are multiplied by the retention factor.
RF_HD inline SymTensor crackedElasticStress(const KstDfhConstants& c, const KstDfhPointState& s,
                                            const SymTensor& elasticStrain)
{
    if (s.crackCount == 0) return c.elastic.stress(elasticStrain);
    const double lambda = c.elastic.lambda, twoMu = 2.0 * c.elastic.shearModulus;
    const SymTensor e = toFrame(elasticStrain, s.crackFrame);
    const double strainNormal[3] = {e.xx, e.yy, e.zz};
    const double trialTrace = trace(e);
    bool open[3] = {false, false, false};
    for (int i = 0; i < s.crackCount; ++i) open[i] = lambda * trialTrace + twoMu * strainNormal[i] > 0.0;
    double opening[3] = {0, 0, 0};
    for (int iteration = 0; iteration < 8; ++iteration) {
        int numOpen = 0;
        double sumTrial = 0.0;
        for (int i = 0; i < 3; ++i)
            if (open[i]) ++numOpen, sumTrial += lambda * trialTrace + twoMu * strainNormal[i];
        const double shift = numOpen > 0 ? lambda * sumTrial / (twoMu + numOpen * lambda) : 0.0;
        double sumOpening = 0.0;
        for (int i = 0; i < 3; ++i) {
            opening[i] = open[i] ? (lambda * trialTrace + twoMu * strainNormal[i] - shift) / twoMu : 0.0;
            sumOpening += opening[i];
        }
        bool changed = false;
        for (int i = 0; i < s.crackCount; ++i) {
            const double normalStress =
                lambda * (trialTrace - sumOpening) + twoMu * (strainNormal[i] - opening[i]);
            if (open[i] && opening[i] < 0.0)
                open[i] = false, changed = true;
            else if (!open[i] && normalStress > 0.0)
                open[i] = true, changed = true;
        }
        if (!changed) break;
    }
    double sumOpening = opening[0] + opening[1] + opening[2];
    const double volumetric = lambda * (trialTrace - sumOpening);
    const double r01 = open[0] || open[1] ? c.crackShearRetention : 1.0;
    const double r12 = open[1] || open[2] ? c.crackShearRetention : 1.0;
    const double r20 = open[2] || open[0] ? c.crackShearRetention : 1.0;
    const SymTensor crackFrameStress = {volumetric + twoMu * (strainNormal[0] - opening[0]),
                                        volumetric + twoMu * (strainNormal[1] - opening[1]),
                                        volumetric + twoMu * (strainNormal[2] - opening[2]),
                                        r01 * twoMu * e.xy,
                                        r12 * twoMu * e.yz,
                                        r20 * twoMu * e.zx};
    return fromFrame(crackFrameStress, s.crackFrame);
}

// Step 3: KST return of a trial stress. Returns the admissible stress; `yielded` tells
// whether it differs from the trial (plastic flow or the tensile apex).
RF_HD inline SymTensor kstReturn(const KstDfhConstants& c, const SymTensor& trial, bool& yielded)
{
    yielded = true;
    const double pressure = -trace(trial) / 3.0;
    if (pressure < c.pressureCutoff) return SymTensor::isotropic(-c.pressureCutoff);  // apex
    const SymTensor s = deviator(trial);
    // sigma_eq <= yield compared squared: no square root on the elastic path, which is
    // what almost every element takes at almost every step.
    const double equivalentSquared = 1.5 * doubleContraction(s, s);
    const double radicand = c.a0 + c.a1 * pressure + c.a2 * pressure * pressure;
    const double yieldSquared = radicand > 0.0 ? radicand : 0.0;
    if (equivalentSquared <= yieldSquared) {
        yielded = false;
        return trial;
    }
    const double equivalent = std::sqrt(equivalentSquared), yield = c.yieldStress(pressure);
    return (yield / equivalent) * s - SymTensor::isotropic(pressure);
}
RF_HD inline SymTensor kstReturn(const KstDfhConstants& c, const SymTensor& trial)
{
    bool yielded = false;
    return kstReturn(c, trial, yielded);
}

// Step 4: freezes the next crack direction if its threshold is exceeded.
// Crack 1 is normal to the largest principal stress; crack 2 to the largest normal
// stress within the plane of crack 1; crack 3 completes the frame.
RF_HD inline bool formNextCrack(KstDfhPointState& s, const SymTensor& stress)
{
    if (s.crackCount == 0) {
        if (largestEigenvalueBound(stress) <= s.failureStress[0]) return false;
        const EigenSystem principal = eigenSystem(stress);
        if (principal.values[0] <= s.failureStress[0]) return false;
        const Vec3 n1 = principal.vectors[0], n2 = principal.vectors[1], n3 = cross(n1, n2);
        s.crackFrame = {{{n1.x, n1.y, n1.z}, {n2.x, n2.y, n2.z}, {n3.x, n3.y, n3.z}}};
        s.crackCount = 1;
        return true;
    }
    const SymTensor local = toFrame(stress, s.crackFrame);
    if (s.crackCount == 1) {
        // Largest eigenvalue and direction of the in-plane 2x2 block (yy, yz, zz).
        const double mean = 0.5 * (local.yy + local.zz), half = 0.5 * (local.yy - local.zz);
        const double radius = std::sqrt(half * half + local.yz * local.yz);
        if (mean + radius <= s.failureStress[1]) return false;
        const double angle = 0.5 * std::atan2(local.yz, half);  // rotation of n2 within the plane
        const double ca = std::cos(angle), sa = std::sin(angle);
        Mat3& f = s.crackFrame;
        for (int k = 0; k < 3; ++k) {
            const double n2 = f.m[1][k], n3 = f.m[2][k];
            f.m[1][k] = ca * n2 + sa * n3;
            f.m[2][k] = -sa * n2 + ca * n3;
        }
        s.crackCount = 2;
        return true;
    }
    if (s.crackCount == 2 && local.zz > s.failureStress[2]) {
        s.crackCount = 3;
        return true;
    }
    return false;
}

// Full update of one point for the total strain; returns the stress. `historyChanged`
// (optional) tells whether the plastic strain, its equivalent or the compaction strain
// changed; when it is false the caller need not store them (an elastic step).
RF_HD inline SymTensor updateStress(const KstDfhConstants& c, KstDfhPointState& s, const SymTensor& strain,
                                    bool* historyChanged = nullptr)
{
    const SymTensor startPlasticStrain = s.plasticStrain;
    const double startCompaction = s.compactionStrain;
    SymTensor stress;
    bool changed = false;
    for (int attempt = 0; attempt < 4; ++attempt) {
        double compaction = startCompaction;
        updateCompaction(c, strain - startPlasticStrain, compaction);
        const SymTensor elasticStrain = strain - startPlasticStrain + SymTensor::isotropic(compaction / 3.0);
        const SymTensor trial = crackedElasticStress(c, s, elasticStrain);
        bool yielded = false;
        stress = kstReturn(c, trial, yielded);
        s.compactionStrain = compaction;
        changed = yielded || compaction != startCompaction;
        // Plastic strain that carries the stress correction (isotropic compliance); none
        // on an elastic step (the stress is the trial).
        const SymTensor plasticIncrement = yielded ? c.elastic.strain(trial - stress) : SymTensor{};
        s.plasticStrain = yielded ? startPlasticStrain + plasticIncrement : startPlasticStrain;
        if (!(c.damageEnabled && formNextCrack(s, stress))) {
            if (yielded)
                s.equivalentPlasticStrain +=
                    std::sqrt(2.0 / 3.0 * doubleContraction(plasticIncrement, plasticIncrement));
            break;
        }
    }
    if (historyChanged) *historyChanged = changed;
    return stress;
}

}  // namespace kstDfh
}  // namespace rockfrac::fem
