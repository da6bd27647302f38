#!/usr/bin/env bash
# A graded BDT granite disc (voronoiMeshDict sizeField): cells of half the base size along the
# two lines where the plates touch, graded back at 1.3. The mesh follows the field (more cells,
# finer at the contacts than in the middle, the volume kept), the run fails with one peak and a
# drop past 50 %, and its peak is compared with the uniform disc's of the same seed and base
# count (the stored bond parameters, no recalibration).
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/BDT/granite "$work/uniform"
cd "$work/uniform"
# Small size (the sanitized CI pass): 100 base cells instead of 300.
nBase=$(bySize 300 100)
caseDict -case . system/voronoiMeshDict -entry nCells -set "$nBase" > /dev/null
caseDict -case . constant/loading -entry stop/forceDropFraction -set 0.5 > /dev/null
runApplication() { "$@" > "log.$1" 2>&1 || fail "$1 failed: $(tail -3 "log.$1")"; }
runApplication meshRock
cp -r "$work/uniform" "$work/graded"

# Half the base size (the volume-equivalent diameter of V / nBase) at the contact lines.
size=$(awk -v n="$nBase" 'BEGIN { v = 3.141592653589793 * 0.0224^2 * 0.0138 / n;
                                   printf "%.6g", 0.5 * (6 * v / 3.141592653589793)^(1 / 3) }')
cat >> "$work/graded/system/voronoiMeshDict" <<EOF
sizeField
{
    grading     1.3;
    regions
    {
        top     { type line; point (0 0 0.0224);  direction (0 1 0); size $size; }
        bottom  { type line; point (0 0 -0.0224); direction (0 1 0); size $size; }
    }
}
EOF

for mesh in uniform graded; do
    (cd "$work/$mesh" && runApplication voronoiMesh && runApplication bondedDemFoam)
done
log="$work/graded/log.voronoiMesh"
grep -q "^Size field: base size" "$log" || fail "no size field line in $log"
grep -q "^Cell size histogram" "$log" || fail "no cell size histogram in $log"
nUniform=$(awk '/^voronoiMesh:/ { print $2 }' "$work/uniform/log.voronoiMesh")
nGraded=$(awk '/^voronoiMesh:/ { print $2 }' "$log")
[ "$nGraded" -gt "$nUniform" ] || fail "the graded mesh has $nGraded cells, the uniform $nUniform"
awk '/^voronoiMesh:/ { e = $11 + 0; if (e < 0) e = -e; if (e > 0.5) { print "FAIL: volume error " $11 " %"; exit 1 } }' \
    "$log" || fail "the graded mesh lost volume"
# The cells at the contacts (within the region size) are finer than the graded region's mean.
grep "^Graded region" "$log" | awk '{ for (i = 1; i <= NF; ++i) if ($i == "size") s[++k] = $(i + 1) }
    END { if (!(s[3] < s[2])) { print "FAIL: contact cells " s[3] " mm not finer than the region mean " s[2] " mm"; exit 1 } }' \
    || fail "the contact cells are not the finest"
grep -q "size" "$work/graded/VTK/voronoiMesh.vtu" && grep -q "targetSize" "$work/graded/VTK/voronoiMesh.vtu" ||
    fail "no size and targetSize fields in the graded VTK/voronoiMesh.vtu"
grep -q "targetSize" "$work/uniform/VTK/voronoiMesh.vtu" && fail "the uniform VTK/voronoiMesh.vtu changed"

dat=postProcessing/plateForce/0/plateForce.dat
peakOf() { awk -F'\t' '!/^#/ { f = $3; if (f > p) p = f; last = f }
                        END { if (!(last < 0.5 * p)) exit 1; printf "%.1f", p }' "$1"; }
uniformPeak=$(peakOf "$work/uniform/$dat") || fail "the uniform disc did not fail"
gradedPeak=$(peakOf "$work/graded/$dat") || fail "the graded disc did not fail"
# A single peak: once below half the peak, the force never climbs back above 90 % of it.
awk -F'\t' '!/^#/ { f = $3; if (f > peak) peak = f; if (f < 0.5 * peak) dropped = 1;
                    if (dropped && f > 0.9 * peak) { print "FAIL: second peak at t = " $1; exit 1 } }' \
    "$work/graded/$dat" || fail "the graded disc has more than one peak"
# The graded disc's peak within the seed-to-seed scatter of the uniform one (docs/validation.md
# section 2: the ten-seed spread of the 300-cell disc is about +-10 %): the stored bond
# parameters, their Weibull size effect included, stay close on the finer contact cells.
awk -v u="$uniformPeak" -v g="$gradedPeak" -v nu="$nUniform" -v ng="$nGraded" 'BEGIN {
    printf "uniform %d cells: peak %.1f N; graded %d cells: peak %.1f N (%+.1f %%)\n", nu, u, ng, g, 100 * (g / u - 1);
    if (!(g > 0.8 * u && g < 1.2 * u)) { print "FAIL: the graded peak is more than 20 % from the uniform"; exit 1 } }' ||
    fail "graded and uniform peaks differ"
