#!/usr/bin/env bash
# explainGap on twin data: the 60-cell disc of tutorials/explainGap makes
# "measured" curves (24 specimens on other Voronoi seeds, noise on every sample)
# with one effect hidden, or none; explainGap must name the hidden effect and
# shrink the held-out gap by >= 30 %, raise no alarm without one, and report two
# effects that the data cannot tell apart as such. All scenarios share the
# baseline and sensitivity runs (explainGapDict 'simulations').
source "$(dirname "$0")/../caseTestFunctions"
export OMP_NUM_THREADS=1
copyTutorial tutorials/explainGap "$work/tutorial"
cd "$work/tutorial"
smallSizePlates bdt

# The neutral effects file is the baseline bit for bit.
cp -r bdt neutral
cat > neutral/constant/modelEffects <<'DICT'
FoamFile { format ascii; class dictionary; object modelEffects; }
contactCrumbling    { strengthLoss 0; depth 8e-3; }
machineCompliance   { compliance 0; }
seatingOffset       { depth 0; closureForce 1500; }
bondStrengthScatter { inverseModulus 0; seed 3; }
rateDamping         { betaFactor 1; }
plateFriction       { frictionFactor 1; }
DICT
for c in bdt neutral; do
    (cd $c && meshRock > log.meshRock 2>&1 && voronoiMesh > log.voronoiMesh 2>&1 &&
        bondedDemFoam > log.bondedDemFoam 2>&1) || fail "$c: the run failed"
done
cut -f1-11 bdt/postProcessing/plateForce/0/plateForce.dat > a.dat
cut -f1-11 neutral/postProcessing/plateForce/0/plateForce.dat > b.dat
cmp -s a.dat b.dat || fail "constant/modelEffects with every effect neutral changed plateForce.dat"
echo "neutral effects: plateForce.dat identical to the baseline's"
# Every effect switched on at once: each effect's code runs in one simulation (at the small
# size, under the sanitizers, the scenarios below screen two effects only).
cp -r neutral allOn
rm -rf allOn/[0-9]* allOn/postProcessing allOn/VTK
cat > allOn/constant/modelEffects <<'DICT'
FoamFile { format ascii; class dictionary; object modelEffects; }
contactCrumbling    { strengthLoss 0.5; depth 8e-3; }
machineCompliance   { compliance 3e-9; }
seatingOffset       { depth 0.03e-3; closureForce 1500; }
bondStrengthScatter { inverseModulus 0.4; seed 3; }
rateDamping         { betaFactor 3; }
plateFriction       { frictionFactor 0.5; }
DICT
(cd allOn && bondedDemFoam > log.bondedDemFoam 2>&1) || fail "allOn: the run with every effect on failed: $(tail -1 allOn/log.bondedDemFoam)"
peakOf() { awk -F'\t' '!/^#/ { if ($3 > f) f = $3 } END { printf "%.6g", f }' "$1/postProcessing/plateForce/0/plateForce.dat"; }
basePeak=$(peakOf bdt)
allPeak=$(peakOf allOn)
awk -v a="$basePeak" -v b="$allPeak" 'BEGIN { exit !(b > 0 && (b - a) * (b - a) > 1e-6 * a * a) }' ||
    fail "allOn: every effect on left the peak force at $allPeak N (baseline $basePeak N)"
echo "every effect on: peak force $allPeak N against the baseline's $basePeak N"
rm -rf neutral allOn bdt/[0-9]* bdt/postProcessing bdt/VTK bdt/constant/voronoiMesh

source "$(dirname "$0")/scenarioFunctions"

if [ "$caseSize" = small ]; then  # the fixed-baseline fit and the features option
    export EFFECTS="seatingOffset machineCompliance"  # the two in play (all of them: allOn above)
    FIXED_BASELINE=1 scenario fixedBaseline "seatingOffset { depth 0.03e-3; closureForce 1500; }" explained seatingOffset
    scenario ambiguous  "seatingOffset { depth 0.15e-3; closureForce 1500; }" indistinguishable \
        "seatingOffset machineCompliance" "peakForce peakForceSpread peakDisplacement"
    echo "PASS (small size)"
    exit 0
fi
scenario none       ""                                                    noGapBeyondScatter ""
# On discs the plate friction has no signature: listed as not testable, never screened.
if grep -q "^plateFriction" none/study/screening.dat; then
    awk -F'\t' '$1 == "plateFriction" { found = 1; if ($2 != "notTestable") exit 1 } END { exit !found }' \
        none/study/screening.dat || fail "none: plateFriction not reported as notTestable on discs"
    echo "none: plateFriction listed as not testable on discs"
fi
scenario seating    "seatingOffset { depth 0.03e-3; closureForce 1500; }" explained seatingOffset
scenario compliance "machineCompliance { compliance 5e-9; }"              explained machineCompliance
# Crumbling under the plates and a compliant frame both soften the disc's contact: on this
# 60-cell disc the two can fit the same data about equally well (docs/explainGap.md). The
# hidden crumbling must be named, or reported as indistinguishable from compliance; never
# compliance alone (since the failure peak is the first notable drop, 2026-12-02, crumbling
# is named: compliance falls short of the held-out test).
scenario crumbling  "contactCrumbling { strengthLoss 0.8; depth 8e-3; }"      "explained|indistinguishable" \
    "contactCrumbling machineCompliance"
# Bond scatter 1/m = 0.6 sits at the detection limit of 12 + 12 discs (p 0.02 against the
# 0.01 significance with the single force evaluation per step, found at p < 0.01 before):
# the case test hides a clearly detectable 0.8; the limits are in docs/validation.md.
scenario scatter    "bondStrengthScatter { inverseModulus 0.8; seed 5; }"   explained bondStrengthScatter
# The case as calibrated (baseline { }): the effect alone is fitted.
FIXED_BASELINE=1 scenario fixedBaseline "seatingOffset { depth 0.03e-3; closureForce 1500; }" explained seatingOffset
# Displacement at failure but no curves: seating and compliance both only add to it.
scenario ambiguous  "seatingOffset { depth 0.15e-3; closureForce 1500; }" indistinguishable \
    "seatingOffset machineCompliance" "peakForce peakForceSpread peakDisplacement"
grep -q "full force-displacement curves" ambiguous/study/explainGap.result ||
    fail "ambiguous: the separating measurement should be full curves: $(grep separating ambiguous/study/explainGap.result)"
echo "PASS"
