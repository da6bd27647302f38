#!/usr/bin/env bash
# bondedDemFoam -parallel on the BDT granite disc (300 cells, split at ~13.4 kN): with 1, 2
# and 4 ranks (4 on 2 cores: --oversubscribe) and with 2 ranks x 2 threads, plateForce.dat
# equals the serial run's byte for byte in every column but balanceError (time, gap change,
# both plate forces, broken bonds, the energies as written, the plate approach), and
# balanceError within 1e-11 of the external work (the energies are sums of the ranks' sums:
# their last bits differ, and the balance is a small difference of them); every VTK frame
# equals the serial run's, and every <time>/demState too but for its energies, force rates and
# initial balance (within 1e-12 relative). A run written with 4 ranks, continued with 2 and then
# serially, gives the same again; so does a run whose rank 1 is killed (SIGKILL), restarted
# from its latest time directory, and a run stopped by SIGTERM to mpirun (every rank stops at
# the same step and the state is written there), continued. The full size runs to the split
# (the stop criterion: bonds breaking, contacts, 379 list rebuilds); the small size (the
# sanitized pass) to 1.5e-4 s with 2 and 4 ranks only, without the signal. Bad input:
# numberOfSubdomains other than -np, and an imbalanceTolerance below 0, each exit 1 with one
# message naming the file.
source "$(dirname "$0")/../caseTestFunctions"
source "$(dirname "$0")/mpiTestFunctions"

copyTutorial tutorials/BDT/granite "$work/base"
cd "$work/base"
run() { "$@" > "log.$1" 2>&1 || fail "$1 failed: $(tail -3 "log.$1")"; }
run meshRock
run voronoiMesh
if [ "$(bySize full small)" = small ]; then
    caseDict -case . system/controlDict -entry endTime -set 1.5e-4 > /dev/null
    caseDict -case . system/controlDict -entry writeInterval -set 5e-5 > /dev/null
fi
writeDecomposeParDict 2
dat=$mpiDat

cp -r "$work/base" "$work/serial"
(cd "$work/serial" && bondedDemFoam > log 2>&1) || fail "serial run failed: $(tail -3 "$work/serial/log")"
rows=$(grep -vc '^#' "$work/serial/$dat")

# same <dir>: plateForce.dat as described above, the VTK frames byte for byte, the state files
# but for the energies.
same() {
    samePlateForce "$work/serial" "$1"
    sameFrames "$work/serial" "$1"
    local t
    for t in $(cd "$work/serial" && ls -d [0-9]*); do
        [ -f "$1/$t/demState" ] || fail "$1: no $t/demState"
        python3 "$src/tests/case/parallel/compareStates.py" "$work/serial/$t/demState" "$1/$t/demState" ||
            fail "$1: $t/demState differs from the serial run's beyond its energies"
    done
}

for np in $(bySize "1 2 4" "2 4"); do
    cp -r "$work/base" "$work/np$np"
    caseDict -case "$work/np$np" system/decomposeParDict -entry numberOfSubdomains -set "$np" > /dev/null
    (cd "$work/np$np" && mpirun --oversubscribe -np "$np" bondedDemFoam -parallel > log 2>&1) ||
        fail "mpirun -np $np failed: $(tail -5 "$work/np$np/log")"
    grep -q "^Decomposition: $np ranks (rcb, cost weights)" "$work/np$np/log" || fail "np$np: no decomposition line"
    grep -q "^Parallel: rank 0 gathers the state" "$work/np$np/log" || fail "np$np: the log does not say how -parallel writes"
    same "$work/np$np"
done
if [ "$(bySize full small)" = full ]; then
    cp -r "$work/base" "$work/hybrid"
    (cd "$work/hybrid" && OMP_NUM_THREADS=2 mpirun --oversubscribe -x OMP_NUM_THREADS -np 2 bondedDemFoam -parallel > log 2>&1) ||
        fail "2 ranks x 2 threads failed: $(tail -5 "$work/hybrid/log")"
    same "$work/hybrid"
fi
echo "$rows rows identical for $(bySize "1, 2 and 4 ranks and 2 ranks x 2 threads" "2 and 4 ranks")"

# Restart with other numbers of ranks: 4 ranks to a write time, 2 ranks to a later one (a run
# ending between write times adds a row there), then serially to the end.
# The legs re-balance whenever a list build finds the ranks' imbalance grown (imbalanceTolerance 0).
cp -r "$work/base" "$work/restart"
cd "$work/restart"
caseDict -case . system/decomposeParDict -entry imbalanceTolerance -add 0 > /dev/null
for leg in "4 $(bySize 3e-4 5e-5)" "2 $(bySize 6e-4 1e-4)" "1 $(caseDict -case . system/controlDict -entry endTime -value)"; do
    set -- $leg
    caseDict -case . system/controlDict -entry endTime -set "$2" > /dev/null
    caseDict -case . system/decomposeParDict -entry numberOfSubdomains -set "$1" > /dev/null
    if [ "$1" = 1 ]; then
        bondedDemFoam > "log.$1" 2>&1 || fail "serial continuation failed: $(tail -3 "log.$1")"
    else
        mpirun --oversubscribe -np "$1" bondedDemFoam -parallel > "log.$1" 2>&1 || fail "$1 ranks failed: $(tail -5 "log.$1")"
    fi
done
grep -q "^Restart from time" log.2 && grep -q "^Restart from time" log.1 || fail "the continuations did not restart"
balanced=$(cat log.4 log.2 | tr '\r' '\n' | grep -c "cells cut anew (imbalance" || true)
# (the small size ends before contacts form: the costs do not change)
[ "$balanced" -ge "$(bySize 1 0)" ] || fail "the 4- and 2-rank legs never re-balanced (imbalanceTolerance 0)"
same "$work/restart"

# A rank killed: the run ends, its time directories are whole, and the restart ends as the serial run.
cp -r "$work/base" "$work/killed"
cd "$work/killed"
caseDict -case . system/controlDict -entry writeInterval -set "$(caseDict -case . system/controlDict -entry deltaT -value | awk '{ printf "%.6g", 50 * $1 }')" > /dev/null
mpirun --oversubscribe -np 2 bondedDemFoam -parallel > log.killed 2>&1 &
runner=$!
for i in $(seq 1 400); do [ "$(ls -d [0-9]* 2> /dev/null | wc -l)" -ge 4 ] && break; sleep 0.05; done
victim=$(pgrep -f "bondedDemFoam -parallel" | sort -n | tail -1)
[ -n "$victim" ] || fail "no rank to kill"
kill -9 "$victim"
code=0
wait "$runner" || code=$?
[ "$code" != 0 ] || fail "the run with a killed rank exited 0"
for t in $(ls -d [0-9]* | sort -g); do [ -f "$t/demState" ] || fail "killed run: $t has no demState"; done
mpirun --oversubscribe -np 2 bondedDemFoam -parallel > log.restart 2>&1 || fail "restart after the kill failed: $(tail -5 log.restart)"
caseDict -case . system/controlDict -entry writeInterval -set "$(caseDict -case "$work/serial" system/controlDict -entry writeInterval -value)" > /dev/null
cut -f1-10,12 "$dat" | diff - <(cut -f1-10,12 "$work/serial/$dat") > /dev/null || fail "the run restarted after the kill differs from the serial run"
echo "restart 4 -> 2 -> 1 ranks and after a killed rank: the serial run's results"

# SIGTERM to mpirun (what Ctrl-C or a batch system's time limit does): every rank stops at the
# same step and the state is written there; the continued run ends as the serial run.
# Full size only: the small run ends within a second or two, before mpirun forwards a signal.
if [ "$(bySize full small)" = full ]; then
    cp -r "$work/base" "$work/signal"
    cd "$work/signal"
    mpirun --oversubscribe -np 2 bondedDemFoam -parallel > log.signal 2>&1 &
    runner=$!
    for i in $(seq 1 400); do [ "$(ls -d [0-9]* 2> /dev/null | wc -l)" -ge 2 ] && break; sleep 0.02; done
    kill -TERM "$runner"
    code=0
    wait "$runner" || code=$?
    [ "$code" != 0 ] || fail "the signalled run exited 0"
    grep -q "interrupted by a signal: state written" log.signal || fail "the signalled run did not write its state: $(tail -5 log.signal)"
    mpirun --oversubscribe -np 2 bondedDemFoam -parallel > log.continued 2>&1 || fail "the continuation after the signal failed: $(tail -5 log.continued)"
    cut -f1-10,12 "$dat" | diff - <(cut -f1-10,12 "$work/serial/$dat") > /dev/null || fail "the run continued after the signal differs from the serial run"
    echo "SIGTERM: the state written at one step by every rank, the continued run the serial run's"
fi

# Bad input: exit 1 within 30 s with one message naming the file.
# refused <case> <ranks> <message>
refused() {
    local code=0
    (cd "$1" && timeout 30 mpirun --oversubscribe -np "$2" bondedDemFoam -parallel > log 2>&1) || code=$?
    [ "$code" = 1 ] || fail "$1: exit $code (expected 1): $(tail -3 "$1/log")"
    [ "$(grep -c "bondedDemFoam: error: .*$3" "$1/log")" = 1 ] || fail "$1: not one message '$3': $(grep error "$1/log")"
}
cp -r "$work/base" "$work/mismatch"
caseDict -case "$work/mismatch" system/decomposeParDict -entry numberOfSubdomains -set 3 > /dev/null
refused "$work/mismatch" 2 "decomposeParDict: numberOfSubdomains is 3 but mpirun started 2 ranks"
cp -r "$work/base" "$work/tolerance"
caseDict -case "$work/tolerance" system/decomposeParDict -entry imbalanceTolerance -add -1 > /dev/null
refused "$work/tolerance" 2 "decomposeParDict:.*imbalanceTolerance"
echo "bad input: exit 1 with one message"
