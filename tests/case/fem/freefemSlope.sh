#!/usr/bin/env bash
# feFractureSolver against the FreeFEM reference (tutorials/FreeFEM/BDT-KSTDFH.edp) on a
# thin disc (t = D/10, nearly plane stress), both elastic under the same arc pressure
# (2 x 5 degrees): the slope force / extensometer shortening (l = 20 mm) within 5 %.
# Usage: freefemSlope.sh <scratch> [3D element size] [2D element size].
source "$(dirname "$0")/../caseTestFunctions"
h3="${2:-$(bySize 1.5e-3 2.5e-3)}"  # small size (sanitized CI pass): coarser meshes
h2="${3:-$(bySize 0.5e-3 1.0e-3)}"
thickness=4.48e-3
command -v FreeFem++ > /dev/null || fail "FreeFem++ not found (Debian package freefem++)"
mkdir -p "$work/freefem"
OMP_NUM_THREADS=1 FreeFem++ -nw "$src/tutorials/FreeFEM/BDT-KSTDFH.edp" -elastic 1 -t "$thickness" -h "$h2" -maxForce 4000 \
    -steps 4 -out "$work/freefem" > "$work/freefem/log.FreeFem++" 2>&1 || fail "FreeFem++: $(tail -3 "$work/freefem/log.FreeFem++")"
slope2=$(awk -F'\t' '!/^#/ { s = $2 / -$4 } END { printf "%.8g", s }' "$work/freefem/postProcessing/plateForce/0/plateForce.dat")

copyTutorial tutorials/BDT/graniteFEM "$work/case"
cd "$work/case"
caseDict -case . system/meshRockDict -entry disc/thickness -set "$thickness" > /dev/null
caseDict -case . system/feMeshDict -entry elementSize -set "$h3" > /dev/null
caseDict -case . constant/rockProperties -entry material -set linearElastic > /dev/null
cp "$src/tests/case/fem/arcLoading" constant/loading
caseDict -case . system/controlDict -entry endTime -set 5e-4 > /dev/null
meshRock > log.meshRock 2>&1 || fail "meshRock: $(tail -3 log.meshRock)"
OMP_NUM_THREADS=1 feFractureSolver > log.feFractureSolver 2>&1 || fail "feFractureSolver: $(tail -3 log.feFractureSolver)"
grep -E "^Mesh|^Quasi" log.feFractureSolver
slope3=$(awk -F'\t' '!/^#/ { s = $4 / -$2 } END { printf "%.8g", s }' postProcessing/extensometer/0/extensometer.dat)
awk -v a="$slope3" -v b="$slope2" 'BEGIN { e = a / b - 1;
    printf "elastic slope F / shortening: feFractureSolver %.5g N/m, FreeFEM %.5g N/m: %+.2f %%\n", a, b, 100 * e;
    exit !(e > -0.05 && e < 0.05) }' || fail "elastic slopes differ by more than 5 %"
echo "FreeFEM slope comparison ok"
