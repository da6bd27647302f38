#!/usr/bin/env bash
# BDT failure-load distribution of the FEM (KST-DFH) against Table 5 (label validation):
# the tutorial tutorials/BDT/<rock>FEM on one mesh, `seeds` seeds of the element thresholds
# (kstDfh/dfh/seed), the failure load of each (first drop of 20 %) into <scratch>/results.dat
# (seed, failureLoad), and the CDF plot against the measured sample (plotCdf). Passes when
# every simulated failure load lies within the measured range (min..max of Table 5).
# Usage: bdtCdf.sh <scratch> [granite|limestone] [seeds] [element size, default 2 mm]
#        [kstDfh/dfh/fractureEnergy N/m, default the tutorial's; 0: the paper's complete cracks]
#        [kstDfh/dfh/weibullStress Pa, default the tutorial's]
#        [kstDfh/dfh/referenceVolume m^3, default the tutorial's].
source "$(dirname "$0")/../caseTestFunctions"
rock="${2:-granite}"
seeds="${3:-10}"
h="${4:-2.0e-3}"
fractureEnergy="${5:-}"
weibullStress="${6:-}"
referenceVolume="${7:-}"
measured="$src/cases/experiments/BDT/$rock/measurements"
copyTutorial "tutorials/BDT/${rock}FEM" "$work/mesh"
cd "$work/mesh"
caseDict -case . system/feMeshDict -entry elementSize -set "$h" > /dev/null
caseDict -case . system/controlDict -entry writeInterval -set 1 > /dev/null  # no VTK before the end
[ -z "$fractureEnergy" ] || caseDict -case . constant/rockProperties -entry kstDfh/dfh/fractureEnergy -set "[N/m] $fractureEnergy" > /dev/null
[ -z "$weibullStress" ] || caseDict -case . constant/rockProperties -entry kstDfh/dfh/weibullStress -set "[Pa] $weibullStress" > /dev/null
[ -z "$referenceVolume" ] || caseDict -case . constant/rockProperties -entry kstDfh/dfh/referenceVolume -set "[m^3] $referenceVolume" > /dev/null
meshRock > log.meshRock 2>&1 || fail "meshRock: $(tail -3 log.meshRock)"
printf '# seed [-]\tfailureLoad [N]\n' > "$work/results.dat"
for seed in $(seq 1 "$seeds"); do
    c="$work/seed$seed"
    mkdir -p "$c"
    cp -r system constant "$c"
    caseDict -case "$c" constant/rockProperties -entry kstDfh/dfh/seed -set "$seed" > /dev/null
    (cd "$c" && OMP_NUM_THREADS=${OMP_NUM_THREADS:-1} feFractureSolver > log.feFractureSolver 2>&1) ||
        fail "feFractureSolver seed $seed: $(tail -3 "$c/log.feFractureSolver")"
    load=$(awk -F'\t' '!/^#/ { print $2 }' "$c/postProcessing/failureLoad/0/failureLoad.dat")
    printf '%d\t%s\n' "$seed" "$load" >> "$work/results.dat"
    echo "seed $seed: failure load $load N ($(grep -E '^End' "$c/log.feFractureSolver"))"
done
grep -E "^Mesh" "$work/seed1/log.feFractureSolver"
plotCdf -case "$work" -measured "$measured" -column failureLoad -labels "FEM KST-DFH ($h m mesh)" \
    -title "BDT $rock: FEM failure loads vs Table 5" -output "$work/bdt-$rock-fem-cdf.png" results.dat
range=$(grep -oE 'failureLoad \[N\] [0-9.e]+' "$measured" | awk '{ v = $3 + 0; if (NR == 1 || v < lo) lo = v; if (v > hi) hi = v } END { print lo, hi }')
read -r lo hi <<< "$range"
grep -v '^#' "$work/results.dat" | cut -f2 | sort -g | awk -v lo="$lo" -v hi="$hi" '
    { n++; v[n] = $1; s += $1; if ($1 >= lo && $1 <= hi) inside++ }
    END { med = (n % 2) ? v[(n + 1) / 2] : 0.5 * (v[n / 2] + v[n / 2 + 1]);
          printf "%d seeds: median %.4g kN, mean %.4g kN, range %.4g-%.4g kN; measured range %.4g-%.4g kN; %d of %d inside\n",
                 n, med / 1e3, s / n / 1e3, v[1] / 1e3, v[n] / 1e3, lo / 1e3, hi / 1e3, inside, n;
          exit !(inside == n) }' || fail "simulated failure loads outside the measured range"
echo "BDT $rock FEM CDF ok"
