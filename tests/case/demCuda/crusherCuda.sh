#!/usr/bin/env bash
# The CH660 tiny crusher on the CUDA backend (needs a GPU; exit 77 = skipped otherwise):
# rocks are fed and discharged on the host around device steps. The same checks as the
# CPU test (case.crusher.tiny): the mass balance closes to round-off and the mantle draws
# power; and the mean power is within 20 % of the CPU run's (fracture makes the two runs
# two realisations, not the same numbers: docs/benchmarks.md).
source "$(dirname "$0")/../caseTestFunctions"
skipWithoutCudaDevice
export OMP_NUM_THREADS=1
for backend in cpu cuda; do
    copyTutorial tutorials/CH660/tiny "$work/$backend"
    caseDict -case "$work/$backend" system/controlDict -entry backend -add $backend > /dev/null
    (cd "$work/$backend" && ./Allrun > /dev/null) || fail "$backend: Allrun failed: $(tail -3 "$work/$backend"/log.bondedDemFoam*)"
done
grep -q "Backend: cuda" "$work/cuda/log.bondedDemFoam" || fail "the cuda run did not use the CUDA backend"
line=$(grep "^Mass: fed" "$work/cuda/log.bondedDemFoam") || fail "no mass balance line in the cuda log"
fed=$(echo "$line" | awk '{ print $3 }')
imbalance=$(echo "$line" | sed -n 's/.*(imbalance \([^ ]*\) kg).*/\1/p')
awk -v i="$imbalance" -v f="$fed" 'BEGIN { exit !(f > 0 && i != "" && (i < 0 ? -i : i) <= 1e-12 * f) }' ||
    fail "cuda: mass balance: fed $fed kg, imbalance $imbalance kg ($line)"
cpu=$(awk '$1 == "powerMean_W" { print $2 }' "$work/cpu/postProcessing/crusherPost/summary.dat")
gpu=$(awk '$1 == "powerMean_W" { print $2 }' "$work/cuda/postProcessing/crusherPost/summary.dat")
echo "mean power: cpu $cpu W, cuda $gpu W"
awk -v c="$cpu" -v g="$gpu" 'BEGIN { exit !(g > 0 && c > 0 && (g - c < 0 ? c - g : g - c) <= 0.2 * c) }' ||
    fail "the cuda run's mean power $gpu W is not within 20 % of the cpu run's $cpu W"
echo "PASS"
