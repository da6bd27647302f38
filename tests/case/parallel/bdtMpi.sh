#!/usr/bin/env bash
# bondedDemFoam -parallel on the BDT granite disc (300 cells, split at ~13.4 kN): with 1, 2
# and 4 ranks (4 on 2 cores: --oversubscribe) and with 2 ranks x 2 threads, plateForce.dat
# equals the serial run's byte for byte in every column but balanceError (time, gap change,
# both plate forces, broken bonds, the energies as written, the plate approach), and
# balanceError within 1e-11 of the external work (the energies are sums of the ranks' sums:
# their last bits differ, and the balance is a small difference of them). The full size runs
# to the split (the stop criterion: bonds breaking, contacts, 379 list rebuilds); the small
# size (the sanitized pass) to 3e-4 s. Bad input: numberOfSubdomains other than -np, and a
# crusher case under -parallel, each exit 1 with one message naming the file.
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

# same <dir>: every column but balanceError identical as written, balanceError within bounds.
same() {
    [ "$(wc -l < "$1/$dat")" = "$(wc -l < "$work/serial/$dat")" ] || fail "$1: $(wc -l < "$1/$dat") lines, serial $(wc -l < "$work/serial/$dat")"
    diff <(cut -f1-10,12 "$work/serial/$dat") <(cut -f1-10,12 "$1/$dat") > /dev/null ||
        fail "$1: plateForce.dat differs from the serial run: $(diff <(cut -f1-10,12 "$work/serial/$dat") <(cut -f1-10,12 "$1/$dat") | head -3)"
    paste <(grep -v '^#' "$work/serial/$dat") <(grep -v '^#' "$1/$dat") | awk -F'\t' -v run="$1" '
        { d = $11 - $23; if (d < 0) d = -d; if (d > worst) worst = d; if (d > 1e-11 * $10 + 1e-18) bad++ }
        END { printf "%s: balanceError at most %.3g J from the serial run'"'"'s\n", run, worst; exit bad > 0 }' ||
        fail "$1: balanceError beyond 1e-11 of the external work"
}

for np in 1 2 4; do
    cp -r "$work/base" "$work/np$np"
    caseDict -case "$work/np$np" system/decomposeParDict -entry numberOfSubdomains -set "$np" > /dev/null
    (cd "$work/np$np" && mpirun --oversubscribe -np "$np" bondedDemFoam -parallel > log 2>&1) ||
        fail "mpirun -np $np failed: $(tail -5 "$work/np$np/log")"
    grep -q "^Decomposition: $np ranks (rcb, cost weights)" "$work/np$np/log" || fail "np$np: no decomposition line"
    grep -q "not built yet" "$work/np$np/log" || fail "np$np: the log does not say what -parallel does not write"
    same "$work/np$np"
done
cp -r "$work/base" "$work/hybrid"
(cd "$work/hybrid" && OMP_NUM_THREADS=2 mpirun --oversubscribe -x OMP_NUM_THREADS -np 2 bondedDemFoam -parallel > log 2>&1) ||
    fail "2 ranks x 2 threads failed: $(tail -5 "$work/hybrid/log")"
same "$work/hybrid"
echo "$rows rows identical for 1, 2 and 4 ranks and 2 ranks x 2 threads"

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
