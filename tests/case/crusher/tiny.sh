#!/usr/bin/env bash
# CH660 tiny: three small rocks beside the mantle in the parallel zone; the mass
# balance closes (fed = inside + discharged) and the mantle draws power (it nips them).
# About a minute on one core (90 cells). One thread: with 90 cells more threads only
# wait on each other (and spin on a loaded machine).
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/CH660/tiny "$work/tiny"
cd "$work/tiny"
export OMP_NUM_THREADS=1
# Small size (the sanitized CI pass): 12.5 ms instead of 0.05 s; the rocks are fed and the
# mantle nips one of them from 11 ms on, nothing is discharged yet (the discharge is
# the unit test test_crusher "[feed]", which the sanitized pass runs in full).
caseDict -case . system/controlDict -entry endTime -set "$(bySize 0.05 0.0125)" > /dev/null
./Allrun > /dev/null || fail "Allrun failed: $(tail -3 log.bondedDemFoam*)"
# The solver's own balance (full precision; the summary's columns are rounded to ~10 digits).
line=$(grep "^Mass: fed" log.bondedDemFoam) || fail "no mass balance line in log.bondedDemFoam"
fed=$(echo "$line" | awk '{ print $3 }')
imbalance=$(echo "$line" | sed -n 's/.*(imbalance \([^ ]*\) kg).*/\1/p')
awk -v i="$imbalance" -v f="$fed" 'BEGIN { exit !(f > 0 && i != "" && (i < 0 ? -i : i) <= 1e-12 * f) }' ||
    fail "mass balance: fed $fed kg, imbalance $imbalance kg ($line)"
power=$(awk '$1 == "powerMean_W" { print $2 }' postProcessing/crusherPost/summary.dat)
awk -v p="$power" 'BEGIN { exit !(p > 0) }' || fail "mean power $power W is not positive"
echo "ok: CH660 tiny, fed $fed kg, imbalance $imbalance kg, power $power W"
