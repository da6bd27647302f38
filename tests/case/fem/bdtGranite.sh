#!/usr/bin/env bash
# The BDT granite FEM case (coarser 2 mm mesh) runs to failure with a single main crack
# along the loaded diameter: a peak, a drop of more than 25 % (with the tutorial's crack
# band the split halves still carry about two thirds of the peak; the run stops once the
# force is below 70 % of it), and most of the cracked volume (D1 = 1) within |x| < D/8 of
# the vertical mid-plane. A run on 2 threads, stopped
# at a write time and restarted, gives bitwise the plateForce.dat of the uninterrupted run
# on 1 thread: thread-count independence and restart exactness in one comparison (one
# solver run fewer than checking them apart; if it fails, run the two checks apart to
# see which one broke).
source "$(dirname "$0")/../caseTestFunctions"
export OMP_WAIT_POLICY=passive  # 2 threads on shared cores: do not spin
copyTutorial tutorials/BDT/graniteFEM "$work/base"
cd "$work/base"
# Small size (sanitized CI pass): 4 mm elements, too coarse to localise one crack.
caseDict -case . system/feMeshDict -entry elementSize -set "$(bySize 2.0e-3 4.0e-3)" > /dev/null
caseDict -case . system/controlDict -entry writeInterval -set 2.5e-4 > /dev/null
meshRock > log.meshRock 2>&1 || fail "meshRock: $(tail -3 log.meshRock)"
dat=postProcessing/plateForce/0/plateForce.dat
run() { "$@" > "log.$1" 2>&1 || fail "$1 failed: $(tail -3 "log.$1")"; }

cp -r "$work/base" "$work/threads1"
start=$(date +%s)
(cd "$work/threads1" && OMP_NUM_THREADS=1 run feFractureSolver)
echo "1 thread, uninterrupted: $(( $(date +%s) - start )) s wall"

log="$work/threads1/log.feFractureSolver"
grep -E "^Failure load|UTS|^Cracked|^Quasi" "$log"
# The peak within 3 % of the calibrated model's (2 mm: 12 932 N, seed 1 of the calibration;
# 4 mm at the small size: 10 666 N): a change of the material's strength by more than a few
# percent fails.
expected=$(bySize 12932 10666)
awk -F'\t' -v expected="$expected" '!/^#/ { f = $3; if (f > peak) { peak = f; tpeak = $1 } last = f }
    END { printf "peak %.1f N at t = %g s, final %.1f N (expected %s N +- 3 %%)\n", peak, tpeak, last, expected;
          if (!(peak > 0.97 * expected && peak < 1.03 * expected)) { print "FAIL: the peak moved"; exit 1 }
          if (!(last < 0.75 * peak)) { print "FAIL: the force did not drop by more than 25 %"; exit 1 } }' \
    "$work/threads1/$dat" || fail "BDT did not fail as expected"
[ -s "$work/threads1/postProcessing/failureLoad/0/failureLoad.dat" ] || fail "no failureLoad.dat"
[ -s "$work/threads1/postProcessing/extensometer/0/extensometer.dat" ] || fail "no extensometer.dat"
checkVtk "$work/threads1/VTK/fem_0.vtu" tets "$(grep -o '^Mesh: [0-9]*' "$log" | cut -d' ' -f2)"
share=$(sed -n 's/.* \([0-9.]*\) % of it within .*/\1/p' "$log")
if fullSize "one main crack ($share % of the cracked volume near the mid-plane)"; then
    awk -v s="$share" 'BEGIN { exit !(s > 60) }' || fail "only $share % of the cracked volume near the loaded mid-plane"
    echo "ok: $share % of the cracked volume within D/8 of the loaded mid-plane"
fi

# 2 threads with a restart: stop at the first write time of the uninterrupted run after
# 40 % of it (the step is computed, so write times are not round numbers), then continue.
stopTime=$(awk -F'\t' '!/^#/ { t = $1 } END { print t }' "$work/threads1/$dat")
half=$(cd "$work/threads1" && ls -d [0-9]* | sort -g | awk -v t="$stopTime" '$1 >= 0.4 * t { print; exit }')
cp -r "$work/base" "$work/restart" && cd "$work/restart"
endTime=$(caseDict -case . system/controlDict -entry endTime -value)
caseDict -case . system/controlDict -entry endTime -set "$half" > /dev/null
start=$(date +%s)
OMP_NUM_THREADS=2 run feFractureSolver
latest=$(ls -d [0-9]* | sort -g | tail -1)
caseDict -case . system/controlDict -entry endTime -set "$endTime" > /dev/null
OMP_NUM_THREADS=2 feFractureSolver > log.feFractureSolver.restart 2>&1 || fail "restart failed: $(tail -3 log.feFractureSolver.restart)"
echo "2 threads, stopped at $half and restarted: $(( $(date +%s) - start )) s wall"
grep -q "Restart from time $latest" log.feFractureSolver.restart || fail "the second run did not restart from $latest"
cmp "$work/threads1/$dat" "$dat" || fail "2 threads with a restart give a $dat different from 1 thread uninterrupted"
python3 -c "import json; json.load(open('VTK/fem.vtu.series'))" || fail "VTK/fem.vtu.series is not valid JSON"
echo "ok: 2 threads restarted from $latest reproduce the uninterrupted 1-thread $dat ($(wc -l < "$dat") lines)"
