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
// With a fracture energy G_F > 0 (crack band, optional) an open crack is not free of
// stress at once: its normal stress softens linearly with the opening over a strain
// set by G_F and the element's width across the crack (crackBandWidth below), so an
// element dissipates G_F per unit crack area whatever its size.
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
    // Crack band (Bazant and Oh 1983): fracture energy G_F [N/m] of each crack; 0 = the
    // crack is complete (no cohesive stress) as soon as it forms, the paper's DFH.
    double fractureEnergy = 0.0;
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
    // Crack band (only with G_F > 0): the largest opening strain each crack has reached
    // and the opening strain at which it carries no normal stress any more.
    double crackOpening[3] = {0, 0, 0};
    double softeningStrain[3] = {0, 0, 0};
    // Not history: the element's shape-function gradients dN_a/dx (12, node-major), for
    // the band width of a crack that forms; nullptr = no geometry (steepest softening).
    const double* elementGradients = nullptr;
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

// ---- Crack band (G_F > 0) -----------------------------------------------------------

// Width of the band over which a crack of normal n is smeared in a linear tet (Oliver
// 1989; Govindjee, Kay and Simo 1995): h = 2 / sum_a |grad N_a . n|, the extent of the
// element's opening strain field along n (a bar of length L gives L).
RF_HD inline double crackBandWidth(const double* gradients, const Vec3& n)
{
    double sum = 0.0;
    for (int a = 0; a < 4; ++a)
        sum += std::abs(gradients[3 * a] * n.x + gradients[3 * a + 1] * n.y + gradients[3 * a + 2] * n.z);
    return sum > 0.0 ? 2.0 / sum : 0.0;
}

// Opening strain at which crack k carries no normal stress: the linear softening
// t = sigma_F (1 - w / w_c) dissipates sigma_F w_c / 2 per unit volume, G_F per unit crack
// area over the band width h when w_c = 2 G_F / (sigma_F h). Never shorter than
// 2 sigma_F / E: the softening stays at most half as steep as the elastic loading (no
// snap-back within an element); an element wider than E G_F / sigma_F^2 then dissipates
// more than G_F, which docs/theory-fem.md states.
RF_HD inline double softeningStrainOf(const KstDfhConstants& c, const KstDfhPointState& s, int k)
{
    const double strength = s.failureStress[k];
    const double steepest = 2.0 * strength / c.elastic.youngsModulus();
    if (!s.elementGradients) return steepest;
    const Vec3 n{s.crackFrame.m[k][0], s.crackFrame.m[k][1], s.crackFrame.m[k][2]};
    const double h = crackBandWidth(s.elementGradients, n);
    const double strain = h > 0.0 ? 2.0 * c.fractureEnergy / (strength * h) : steepest;
    return strain > steepest ? strain : steepest;
}

// Fraction of crack k's strength left after an opening strain w: 1 - max(kappa, w) / w_c,
// at least 0 (the crack's damage is one minus this).
RF_HD inline double remainingStrength(const KstDfhPointState& s, int k, double opening)
{
    const double kappa = opening > s.crackOpening[k] ? opening : s.crackOpening[k];
    const double left = 1.0 - kappa / s.softeningStrain[k];
    return left > 0.0 ? left : 0.0;
}

// The stress of a cracked element back in the global frame: in the crack frame (e, its
// strain) the normal stresses are the volumetric part plus 2 mu (e_i - w_i) with the openings
// w_i, and a shear component between directions i and j keeps the smaller of the two
// cracks' shear factors.
RF_HD inline SymTensor crackFrameStress(const KstDfhPointState& s, const SymTensor& e, double twoMu,
                                        double volumetric, const double opening[3], const double keep[3])
{
    const double r01 = keep[0] < keep[1] ? keep[0] : keep[1];
    const double r12 = keep[1] < keep[2] ? keep[1] : keep[2];
    const double r20 = keep[2] < keep[0] ? keep[2] : keep[0];
    const SymTensor local = {volumetric + twoMu * (e.xx - opening[0]),
                             volumetric + twoMu * (e.yy - opening[1]),
                             volumetric + twoMu * (e.zz - opening[2]),
                             r01 * twoMu * e.xy,
                             r12 * twoMu * e.yz,
                             r20 * twoMu * e.zx};
    return fromFrame(local, s.crackFrame);
}

// Step 2 with a crack band: the open cracks i carry a cohesive normal stress t_i(w_i) of
// their opening strain w_i. Each crack follows one linear branch t = a - b w at a time:
//   closed     w = 0 (full stiffness; compression carried, as without G_F),
//   softening  t = sigma_F (1 - w / w_c) while kappa <= w <= w_c (kappa: largest w so far),
//   reloading  t = sigma_F (1 - kappa / w_c) w / kappa for 0 <= w <= kappa (secant unloading),
//   free       t = 0 beyond w_c (or once kappa >= w_c: the crack of the paper's DFH).
// On a branch the normal-stress conditions lambda (tr e - sum w) + 2 mu (e_i - w_i) = a_i - b_i w_i
// are linear, (2 mu - b_i) w_i + lambda sum w = lambda tr e + 2 mu e_i - a_i, and are solved
// in closed form (diagonal plus rank one, Sherman-Morrison); an active-set loop moves each
// crack to the branch its solution lies on. Shear components coupling to an open crack keep
// the crack's remaining strength fraction of their stiffness (at least crackShearRetention).
RF_HD inline SymTensor crackBandElasticStress(const KstDfhConstants& c, const KstDfhPointState& s,
                                              const SymTensor& elasticStrain, double opening[3])
{
    enum Branch { closed, softening, reloading, free };
    const double lambda = c.elastic.lambda, twoMu = 2.0 * c.elastic.shearModulus;
    const SymTensor e = toFrame(elasticStrain, s.crackFrame);
    const double strainNormal[3] = {e.xx, e.yy, e.zz};
    const double trialTrace = trace(e);
    int branch[3] = {closed, closed, closed};
    for (int i = 0; i < s.crackCount; ++i) {
        const bool spent = s.crackOpening[i] >= s.softeningStrain[i];
        if (s.crackOpening[i] > 0.0) branch[i] = spent ? free : reloading;
    }
    double sumOpening = 0.0;
    for (int iteration = 0; iteration < 16; ++iteration) {
        double d[3] = {1, 1, 1}, r[3] = {0, 0, 0}, sumInverse = 0.0, sumRatio = 0.0;
        for (int i = 0; i < s.crackCount; ++i) {
            if (branch[i] == closed) continue;
            const double strength = s.failureStress[i], wc = s.softeningStrain[i], kappa = s.crackOpening[i];
            double a = 0.0, b = 0.0;
            if (branch[i] == softening) a = strength, b = strength / wc;
            if (branch[i] == reloading) b = -strength * (1.0 - kappa / wc) / kappa;
            d[i] = twoMu - b;
            r[i] = lambda * trialTrace + twoMu * strainNormal[i] - a;
            sumInverse += 1.0 / d[i];
            sumRatio += r[i] / d[i];
        }
        const double lambdaSum = lambda * sumRatio / (1.0 + lambda * sumInverse);  // lambda sum w
        sumOpening = 0.0;
        for (int i = 0; i < 3; ++i) {
            opening[i] = branch[i] == closed ? 0.0 : (r[i] - lambdaSum) / d[i];
            sumOpening += opening[i];
        }
        bool changed = false;
        for (int i = 0; i < s.crackCount; ++i) {
            const double strength = s.failureStress[i], wc = s.softeningStrain[i], kappa = s.crackOpening[i];
            const double w = opening[i];
            const int was = branch[i];
            if (was == closed) {
                const double normalStress = lambda * (trialTrace - sumOpening) + twoMu * strainNormal[i];
                // A crack opens against what it still holds at w = 0: its strength while it
                // has never opened, nothing once it has.
                if (kappa >= wc)
                    branch[i] = normalStress > 0.0 ? free : closed;
                else if (kappa > 0.0)
                    branch[i] = normalStress > 0.0 ? reloading : closed;
                else
                    branch[i] = normalStress > strength ? softening : closed;
            } else if (w < 0.0) {
                branch[i] = closed;
            } else if (was == reloading && w > kappa) {
                branch[i] = softening;
            } else if (was == softening && w > wc) {
                branch[i] = free;
            } else if (was == softening && w < kappa) {
                branch[i] = kappa > 0.0 ? reloading : closed;
            } else if (was == free && w < wc && kappa < wc) {
                branch[i] = w > kappa || kappa <= 0.0 ? softening : reloading;  // no secant before an opening
            }
            changed = changed || branch[i] != was;
        }
        if (!changed) break;
    }
    for (int i = 0; i < 3; ++i)
        if (opening[i] < 0.0) opening[i] = 0.0;
    const double volumetric = lambda * (trialTrace - sumOpening);
    double keep[3] = {1.0, 1.0, 1.0};  // shear stiffness kept by each crack
    for (int i = 0; i < s.crackCount; ++i)
        if (opening[i] > 0.0) {
            const double left = remainingStrength(s, i, opening[i]);
            keep[i] = left > c.crackShearRetention ? left : c.crackShearRetention;
        }
    return crackFrameStress(s, e, twoMu, volumetric, opening, keep);
}

// Step 2: elastic stress with the frozen cracks. In the crack frame, the opening
// strains e_i >= 0 of the open cracks make their normal stresses vanish:
//   (2 mu I + lambda 1 1^T) e = b,  b_i = trial normal stress (Sherman-Morrison solve),
// found by an active set (a crack opens when its trial normal stress is tensile and
// closes again if its opening strain would be negative). Shear components coupling
// to an open crack are multiplied by the retention factor.
RF_HD inline SymTensor crackedElasticStress(const KstDfhConstants& c, const KstDfhPointState& s,
                                            const SymTensor& elasticStrain, double* crackOpening = nullptr)
{
    if (s.crackCount == 0) return c.elastic.stress(elasticStrain);
    if (c.fractureEnergy > 0.0 && crackOpening)
        return crackBandElasticStress(c, s, elasticStrain, crackOpening);
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
    double keep[3];  // shear stiffness kept by each crack: the retention while it is open
    for (int i = 0; i < 3; ++i) keep[i] = open[i] ? c.crackShearRetention : 1.0;
    return crackFrameStress(s, e, twoMu, volumetric, opening, keep);
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
    double opening[3] = {0, 0, 0};  // crack band: the opening strains of this update
    for (int attempt = 0; attempt < 4; ++attempt) {
        double compaction = startCompaction;
        updateCompaction(c, strain - startPlasticStrain, compaction);
        const SymTensor elasticStrain = strain - startPlasticStrain + SymTensor::isotropic(compaction / 3.0);
        const SymTensor trial = crackedElasticStress(c, s, elasticStrain, opening);
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
        // A new crack: its softening length from its normal and the element's width across it.
        if (c.fractureEnergy > 0.0) {
            const int k = s.crackCount - 1;
            s.softeningStrain[k] = softeningStrainOf(c, s, k);
            s.crackOpening[k] = opening[k] = 0.0;
        }
    }
    // The opening reached is history (the secant unloading of a softened crack).
    if (c.fractureEnergy > 0.0)
        for (int i = 0; i < s.crackCount; ++i)
            if (opening[i] > s.crackOpening[i]) s.crackOpening[i] = opening[i];
    if (historyChanged) *historyChanged = changed;
    return stress;
}

}  // namespace kstDfh
}  // namespace rockfrac::fem
