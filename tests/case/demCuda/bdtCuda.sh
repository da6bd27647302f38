#!/usr/bin/env bash
# The BDT granite case on the CUDA backend against the CPU backend, with the bond law
# ${BOND_LAW:-voronoiQNSC} (needs a GPU;
# exit 77 = skipped otherwise). Tolerance (docs/benchmarks.md): before the first bond
# breaks the two force curves agree to 1e-6 of the peak force; the peak force agrees
# to 2 % (fracture amplifies the round-off of a different summation order).
source "$(dirname "$0")/../caseTestFunctions"
skipWithoutCudaDevice
copyTutorial tutorials/BDT/granite "$work/base"
cd "$work/base"
runApplication() { "$@" > "log.$1" 2>&1 || fail "$1 failed: $(tail -3 "log.$1")"; }
runApplication meshRock
runApplication voronoiMesh
# BOND_LAW: the bond law of the run (gpu.demCuda.bdtBrittle runs brittleBPM).
caseDict -case . constant/rockProperties -entry bond/model -set "${BOND_LAW:-voronoiQNSC}" > /dev/null
dat=postProcessing/plateForce/0/plateForce.dat
for backend in cpu cuda; do
    cp -r "$work/base" "$work/$backend"
    caseDict -case "$work/$backend" system/controlDict -entry backend -add $backend > /dev/null
    (cd "$work/$backend" && runApplication bondedDemFoam)
done
grep -q "Backend: cuda" "$work/cuda/log.bondedDemFoam" || fail "the cuda run did not use the CUDA backend"
paste <(grep -v '^#' "$work/cpu/$dat" | cut -f1,3,5) <(grep -v '^#' "$work/cuda/$dat" | cut -f1,3,5) |
awk -F'\t' '{ if ($2 > peak_cpu) peak_cpu = $2; if ($5 > peak_gpu) peak_gpu = $5
              if ($3 == 0 && $6 == 0 && $1 == $4) { d = $2 - $5; if (d < 0) d = -d; if (d > intact) intact = d } }
    END { printf "peak force: cpu %.6g N, cuda %.6g N; largest difference before breakage %.3g N\n",
                 peak_cpu, peak_gpu, intact
          if (intact > 1e-6 * peak_cpu) { print "FAIL: the curves differ before the first bond breaks"; exit 1 }
          r = peak_gpu / peak_cpu; if (r < 0.98 || r > 1.02) { print "FAIL: peak forces differ by more than 2 %"; exit 1 } }' ||
    fail "the CUDA backend's BDT force curve is outside the tolerance"
echo "ok: the BDT force curve on the CUDA backend agrees with the CPU"
