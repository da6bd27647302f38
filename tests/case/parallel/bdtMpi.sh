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
# from its latest time directory. The full size runs to the split (the stop criterion: bonds
# breaking, contacts, 379 list rebuilds); the small size (the sanitized pass) to 3e-4 s. Bad
# input: numberOfSubdomains other than -np, and a crusher case under -parallel, each exit 1
# with one message naming the file.
source "$(dirname "$0")/../caseTestFunctions"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
export OMPI_MCA_mca_base_component_disable_dlclose=1
[ -n "${LSAN_OPTIONS:-}" ] && export LSAN_OPTIONS="$LSAN_OPTIONS:fast_unwind_on_malloc=0"
command -v mpirun > /dev/null || fail "mpirun not found: utilities/installDependencies installs openmpi-bin"

copyTutorial tutorials/BDT/granite "$work/base"
cd "$work/base"
run() { "$@" > "log.$1" 2>&1 || fail "$1 failed: $(tail -3 "log.$1")"; }
run meshRock
run voronoiMesh
[ "$(bySize full small)" = small ] && caseDict -case . system/controlDict -entry endTime -set 3e-4 > /dev/null
cat > system/decomposeParDict <<'DICT'
FoamFile { format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains  2;
method              rcb;
weights             cost;
DICT
dat=postProcessing/plateForce/0/plateForce.dat

cp -r "$work/base" "$work/serial"
(cd "$work/serial" && bondedDemFoam > log 2>&1) || fail "serial run failed: $(tail -3 "$work/serial/log")"
rows=$(grep -vc '^#' "$work/serial/$dat")

# same <dir>: plateForce.dat as described above, the VTK frames byte for byte, the state files
# but for the energies.
same() {
    [ "$(wc -l < "$1/$dat")" = "$(wc -l < "$work/serial/$dat")" ] || fail "$1: $(wc -l < "$1/$dat") lines, serial $(wc -l < "$work/serial/$dat")"
    diff <(cut -f1-10,12 "$work/serial/$dat") <(cut -f1-10,12 "$1/$dat") > /dev/null ||
        fail "$1: plateForce.dat differs from the serial run: $(diff <(cut -f1-10,12 "$work/serial/$dat") <(cut -f1-10,12 "$1/$dat") | head -3)"
    paste <(grep -v '^#' "$work/serial/$dat") <(grep -v '^#' "$1/$dat") | awk -F'\t' -v run="$1" '
        { d = $11 - $23; if (d < 0) d = -d; if (d > worst) worst = d; if (d > 1e-11 * $10 + 1e-18) bad++ }
        END { printf "%s: balanceError at most %.3g J from the serial run'"'"'s\n", run, worst; exit bad > 0 }' ||
        fail "$1: balanceError beyond 1e-11 of the external work"
    local frames=0 f
    for f in $(cd "$work/serial" && find VTK -type f | sort); do
        cmp -s "$work/serial/$f" "$1/$f" || fail "$1: $f differs from the serial run's"
        frames=$((frames + 1))
    done
    [ "$frames" -gt 4 ] || fail "$1: only $frames VTK files"
    local t
    for t in $(cd "$work/serial" && ls -d [0-9]*); do
        [ -f "$1/$t/demState" ] || fail "$1: no $t/demState"
        python3 "$src/tests/case/parallel/compareStates.py" "$work/serial/$t/demState" "$1/$t/demState" ||
            fail "$1: $t/demState differs from the serial run's beyond its energies"
    done
}

for np in 1 2 4; do
    cp -r "$work/base" "$work/np$np"
    caseDict -case "$work/np$np" system/decomposeParDict -entry numberOfSubdomains -set "$np" > /dev/null
    (cd "$work/np$np" && mpirun --oversubscribe -np "$np" bondedDemFoam -parallel > log 2>&1) ||
        fail "mpirun -np $np failed: $(tail -5 "$work/np$np/log")"
    grep -q "^Decomposition: $np ranks (rcb, cost weights)" "$work/np$np/log" || fail "np$np: no decomposition line"
    grep -q "^Parallel: rank 0 gathers the state" "$work/np$np/log" || fail "np$np: the log does not say how -parallel writes"
    same "$work/np$np"
done
cp -r "$work/base" "$work/hybrid"
(cd "$work/hybrid" && OMP_NUM_THREADS=2 mpirun --oversubscribe -x OMP_NUM_THREADS -np 2 bondedDemFoam -parallel > log 2>&1) ||
    fail "2 ranks x 2 threads failed: $(tail -5 "$work/hybrid/log")"
same "$work/hybrid"
echo "$rows rows identical for 1, 2 and 4 ranks and 2 ranks x 2 threads"

# Restart with other numbers of ranks: 4 ranks to a write time, 2 ranks to a later one (a run
# ending between write times adds a row there), then serially to the end.
cp -r "$work/base" "$work/restart"
cd "$work/restart"
for leg in "4 $(bySize 3e-4 1e-4)" "2 $(bySize 6e-4 2e-4)" "1 $(caseDict -case . system/controlDict -entry endTime -value)"; do
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
copyTutorial tutorials/CH660/tiny "$work/crusher"
refused "$work/crusher" 1 "constant/loading: -parallel runs plates cases only yet"
echo "bad input: exit 1 with one message"
