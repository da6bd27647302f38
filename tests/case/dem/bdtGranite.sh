#!/usr/bin/env bash
# The BDT granite case runs to failure: one peak, then a drop of more than 50 %;
# 1 and 2 threads give bitwise identical plateForce.dat; a run stopped at a
# write time and restarted gives the same plateForce.dat as the uninterrupted run.
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/BDT/granite "$work/base"
cd "$work/base"
# Small size (the sanitized CI pass): 100 cells instead of 300.
caseDict -case . system/voronoiMeshDict -entry nCells -set "$(bySize 300 100)" > /dev/null
runApplication() { "$@" > "log.$1" 2>&1 || fail "$1 failed: $(tail -3 "log.$1")"; }
runApplication meshRock
runApplication voronoiMesh
dat=postProcessing/plateForce/0/plateForce.dat

for threads in 1 2; do
    cp -r "$work/base" "$work/threads$threads"
    (cd "$work/threads$threads" && OMP_NUM_THREADS=$threads runApplication bondedDemFoam)
done
cmp "$work/threads1/$dat" "$work/threads2/$dat" || fail "1 and 2 threads give different $dat"
echo "ok: 1 and 2 threads give identical $dat ($(wc -l < "$work/threads1/$dat") lines)"

# One peak, within 3 % of the calibrated model's (300 cells: 13 393 N, the tutorial's;
# 100 cells at the small size: 13 879 N), then a drop of more than 50 % (the run stops at
# 30 % of the peak). A change of the bond law or its coefficients by more than a few percent fails.
expected=$(bySize 13393 13879)
awk -F'\t' -v expected="$expected" '!/^#/ { f = $3; if (f > peak) { peak = f; tpeak = $1 } last = f }
    END { printf "peak %.1f N at t = %g s, final %.1f N (expected %s N +- 3 %%)\n", peak, tpeak, last, expected;
          if (!(peak > 0.97 * expected && peak < 1.03 * expected)) { print "FAIL: the peak moved"; exit 1 }
          if (!(last < 0.5 * peak)) { print "FAIL: the force did not drop by more than 50 %"; exit 1 } }' \
    "$work/threads1/$dat" || fail "BDT did not fail as expected"
# A single peak: after the maximum, the force never climbs back above 90 % of it
# once it has fallen below 50 %.
awk -F'\t' '!/^#/ { f = $3; if (f > peak) peak = f; if (f < 0.5 * peak) dropped = 1;
                    if (dropped && f > 0.9 * peak) { print "FAIL: second peak at t = " $1; exit 1 } }' \
    "$work/threads1/$dat" || fail "more than one peak"

# Restart: stop at the first write time after 40 % of the run, then continue.
stopTime=$(awk -F'\t' '!/^#/ { t = $1 } END { print t }' "$work/threads1/$dat")
cp -r "$work/base" "$work/restart" && cd "$work/restart"
interval=$(caseDict -case . system/controlDict -entry writeInterval -value)
half=$(awk -v t="$stopTime" -v w="$interval" 'BEGIN { n = int(0.4 * t / w); if (n < 1) n = 1; printf "%.10g", n * w }')
endTime=$(caseDict -case . system/controlDict -entry endTime -value)
caseDict -case . system/controlDict -entry endTime -set "$half" > /dev/null
OMP_NUM_THREADS=2 runApplication bondedDemFoam
[ -d "$half" ] || fail "no time directory $half after the first part"
caseDict -case . system/controlDict -entry endTime -set "$endTime" > /dev/null
OMP_NUM_THREADS=2 bondedDemFoam > log.bondedDemFoam.restart 2>&1 || fail "restart failed: $(tail -3 log.bondedDemFoam.restart)"
grep -q "Restart from time $half" log.bondedDemFoam.restart || fail "the second run did not restart from $half"
cmp "$work/threads2/$dat" "$dat" || fail "restarted run differs from the uninterrupted one"
echo "ok: restart from $half reproduces the uninterrupted $dat"
