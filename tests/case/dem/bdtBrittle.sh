#!/usr/bin/env bash
# The second bond law on the Brazilian disc by changing one keyword: the BDT granite
# tutorial with `bond { model brittleBPM; }` (its brittleBPM sub-dictionary holds the same
# stiffness and strengths as the calibrated voronoiQNSC) runs to failure, 1 and 2 threads
# give bitwise identical plateForce.dat, and against voronoiQNSC on the same mesh: the same
# elastic response before the first bond breaks, and a peak within the band measured for the
# two laws (docs/models/bond/brittleBPM.md).
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/BDT/granite "$work/base"
cd "$work/base"
caseDict -case . system/voronoiMeshDict -entry nCells -set "$(bySize 300 100)" > /dev/null
runApplication() { "$@" > "log.$1" 2>&1 || fail "$1 failed: $(tail -3 "log.$1")"; }
runApplication meshRock
runApplication voronoiMesh
dat=postProcessing/plateForce/0/plateForce.dat

cp -r "$work/base" "$work/qnsc"
(cd "$work/qnsc" && OMP_NUM_THREADS=2 runApplication bondedDemFoam)
for threads in 1 2; do
    cp -r "$work/base" "$work/brittle$threads"
    cd "$work/brittle$threads"
    caseDict -case . constant/rockProperties -entry bond/model -set brittleBPM > /dev/null  # the one keyword
    OMP_NUM_THREADS=$threads runApplication bondedDemFoam
    grep -q "^Bonds: brittleBPM" log.bondedDemFoam || fail "the run did not use brittleBPM: $(grep '^Bonds' log.bondedDemFoam)"
done
cmp "$work/brittle1/$dat" "$work/brittle2/$dat" || fail "1 and 2 threads give different $dat with brittleBPM"
echo "ok: brittleBPM, 1 and 2 threads give identical $dat"

# Columns: time, displacement, force, ..., broken bonds (the header names them).
col() { awk -F'\t' -v name="$2" '/^#/ { for (i = 1; i <= NF; ++i) { h = $i; sub(/^# */, "", h); split(h, w, " "); if (w[1] == name) c = i } next } END { print c + 0 }' "$1"; }
brokenColumn=$(col "$work/qnsc/$dat" brokenBonds)
[ "$brokenColumn" -gt 0 ] || fail "no brokenBonds column in $dat: $(head -1 "$work/qnsc/$dat")"
# Before the first bond breaks the two laws are the same elastic bond: identical rows.
paste <(grep -v '^#' "$work/qnsc/$dat") <(grep -v '^#' "$work/brittle1/$dat") |
awk -F'\t' -v n="$(head -1 "$work/qnsc/$dat" | awk -F'\t' '{ print NF }')" -v b="$brokenColumn" '
    done { next }  # read to the end: an early exit would fail paste (pipefail)
    { if ($b != 0 || $(n + b) != 0) { done = 1; next } rows++
      for (i = 1; i <= n; ++i) if ($i != $(n + i)) { print "FAIL: row " rows " differs before breakage"; bad = 1; done = 1; next } }
    END { if (bad) exit 1; if (rows < 10) { print "FAIL: only " rows " intact rows"; exit 1 } print "ok: " rows " rows identical before the first broken bond" }' ||
    fail "brittleBPM and voronoiQNSC differ before any bond breaks"
peak() { awk -F'\t' '!/^#/ { if ($3 > p) p = $3 } END { printf "%.6g", p }' "$1"; }
qnscPeak=$(peak "$work/qnsc/$dat"); brittlePeak=$(peak "$work/brittle1/$dat")
awk -v q="$qnscPeak" -v b="$brittlePeak" -v small="$caseSize" 'BEGIN {
    r = b / q; printf "peak force: voronoiQNSC %.1f N, brittleBPM %.1f N (ratio %.3f)\n", q, b, r
    if (!(b > 1000)) { print "FAIL: no load built up"; exit 1 }
    if (small != "small" && (r < 0.85 || r > 1.15)) { print "FAIL: the ratio left the measured band [0.85, 1.15]"; exit 1 } }' ||
    fail "brittleBPM peak out of band"
# The force drops after the peak (the stop criterion ends the run at 30 % of it).
awk -F'\t' '!/^#/ { f = $3; if (f > p) p = f; last = f } END { if (!(last < 0.5 * p)) { print "FAIL: no drop"; exit 1 } }' \
    "$work/brittle1/$dat" || fail "the brittleBPM disc did not fail"
echo "ok: brittleBPM breaks the BDT disc"
