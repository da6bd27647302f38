#!/usr/bin/env bash
# bondedDemFoam -parallel on the CH660 tiny crusher (three rocks of 30 cells fed beside the
# mantle, nipped from 17 ms on, one fragment discharged at 49 ms). The feed and the destructor
# change the whole model, gathered on every rank, which is then cut anew; so is a model whose
# cells have moved half the ghost layer's allowance, or whose ranks' costs drift apart
# (imbalanceTolerance). With 2 ranks, and with 4 ranks (--oversubscribe) re-balancing at every
# list build that finds the imbalance grown (imbalanceTolerance 0), machine.dat equals the serial
# run's byte for byte in every column but `exchanged` and `balanceError` (the energy carried out
# with a discharged fragment is a difference of the whole model's energies, which are sums of the
# ranks' sums: within 1e-9 of the work done), discharge.dat and every VTK frame byte for byte.
# The full size runs the whole 0.05 s with 2 ranks and the first 0.02 s (the nip) with 4; the
# small size (the sanitized pass) 4 ms with 2 ranks (the feed and a cut for moved cells).
# Bad input on one rank only (mpirun's MPMD form gives rank 1 another case, with a broken
# decomposeParDict): exit 1 within 30 s with one message naming that file.
source "$(dirname "$0")/../caseTestFunctions"
source "$(dirname "$0")/mpiTestFunctions"

copyTutorial tutorials/CH660/tiny "$work/base"
cd "$work/base"
run() { "$@" > "log.$1" 2>&1 || fail "$1 failed: $(tail -3 "log.$1")"; }
run meshCrusher
(cd feedRock && run meshRock && run voronoiMesh) || fail "the feed rock's mesh"
[ "$(bySize full small)" = small ] && caseDict -case . system/controlDict -entry endTime -set 0.004 > /dev/null
writeDecomposeParDict 2
cp -r "$work/base" "$work/serial"
(cd "$work/serial" && bondedDemFoam > log 2>&1) || fail "serial run failed: $(tail -3 "$work/serial/log")"

rows=$(grep -vc '^#' "$work/serial/$machine")
cp -r "$work/base" "$work/np2"
(cd "$work/np2" && mpirun --oversubscribe -np 2 bondedDemFoam -parallel > log 2>&1) ||
    fail "mpirun -np 2 failed: $(tail -5 "$work/np2/log")"
grep -q "^Decomposition: 2 ranks (rcb, cost weights)" "$work/np2/log" || fail "np2: no decomposition line"
grep -q "cells cut anew (a cell moved" "$work/np2/log" || fail "np2: the cells were never cut anew for moving"
[ "$(grep -vc '^#' "$work/np2/$machine")" = "$rows" ] || fail "np2: not $rows rows in machine.dat"
sameMachine "$work/serial" "$work/np2" "$rows"
cmp -s "$work/serial/$discharge" "$work/np2/$discharge" || fail "np2: discharge.dat differs from the serial run's"
sameFramesAsSerial "$work/serial" "$work/np2"
grep "^Mass: fed" "$work/serial/log" | cmp -s - <(grep "^Mass: fed" "$work/np2/log") || fail "np2: another mass balance"
if [ "$(bySize full small)" = full ]; then
    [ "$(grep -vc '^#' "$work/serial/$discharge")" -ge 1 ] || fail "the serial run discharged nothing"
    cp -r "$work/base" "$work/np4"
    caseDict -case "$work/np4" system/decomposeParDict -entry numberOfSubdomains -set 4 > /dev/null
    caseDict -case "$work/np4" system/decomposeParDict -entry imbalanceTolerance -add 0 > /dev/null
    caseDict -case "$work/np4" system/controlDict -entry endTime -set 0.02 > /dev/null
    (cd "$work/np4" && mpirun --oversubscribe -np 4 bondedDemFoam -parallel > log 2>&1) ||
        fail "mpirun -np 4 failed: $(tail -5 "$work/np4/log")"
    balanced=$(grep -o "cells cut anew (imbalance" "$work/np4/log" | wc -l)
    [ "$balanced" -ge 5 ] || fail "np4: re-balanced $balanced times (imbalanceTolerance 0)"
    sameMachine "$work/serial" "$work/np4" "$(($(grep -vc '^#' "$work/np4/$machine") - 1))"
    sameFramesAsSerial "$work/serial" "$work/np4"
    echo "np4: re-balanced $balanced times during the run"
fi

# Bad input on rank 1 only.
cp -r "$work/base" "$work/other"
caseDict -case "$work/other" system/decomposeParDict -entry method -set frob > /dev/null
code=0
start=$(date +%s)
timeout 60 mpirun --oversubscribe -np 1 bondedDemFoam -parallel -case "$work/base" : \
    -np 1 bondedDemFoam -parallel -case "$work/other" > "$work/other.log" 2>&1 || code=$?
seconds=$(($(date +%s) - start))
[ "$code" = 1 ] || fail "bad input on rank 1: exit $code (expected 1): $(tail -3 "$work/other.log")"
[ "$seconds" -le 30 ] || fail "bad input on rank 1: $seconds s to stop"
[ "$(grep -c "bondedDemFoam: error: .*other/system/decomposeParDict.*frob" "$work/other.log")" = 1 ] ||
    fail "bad input on rank 1: not one message naming the file: $(grep -i error "$work/other.log" | head -3)"
echo "bad input on rank 1 only: exit 1 after $seconds s with one message"
