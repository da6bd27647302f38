#!/usr/bin/env bash
# CH660 tiny: a few rocks through the lower chamber; the mass balance closes
# (fed = inside + discharged) and the mantle draws power.
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/CH660/tiny "$work/tiny"
cd "$work/tiny"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}
./Allrun > /dev/null || fail "Allrun failed: $(tail -3 log.bondedDemFoam*)"
imbalance=$(awk '$1 == "massImbalance_kg" { print $2 }' postProcessing/crusherPost/summary.dat)
fed=$(awk '$1 == "massFed_kg" { print $2 }' postProcessing/crusherPost/summary.dat)
awk -v i="$imbalance" -v f="$fed" 'BEGIN { exit !(f > 0 && (i < 0 ? -i : i) <= 1e-12 * f) }' ||
    fail "mass balance: fed $fed kg, imbalance $imbalance kg"
power=$(awk '$1 == "powerMean_W" { print $2 }' postProcessing/crusherPost/summary.dat)
awk -v p="$power" 'BEGIN { exit !(p > 0) }' || fail "mean power $power W is not positive"
echo "ok: CH660 tiny, fed $fed kg, imbalance $imbalance kg, power $power W"
