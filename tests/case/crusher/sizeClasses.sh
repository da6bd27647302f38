#!/usr/bin/env bash
# A size-resolved feed on CH660 tiny: two size classes, the tutorial's coarse feedRock for the
# rocks up to 16 mm and a second template meshed finer (feedRockFine) for the larger ones
# (constant/loading feed/classes). Rocks of both classes are fed (the log's count by class adds
# up to machine.dat's rocksFed), the mass balance closes exactly as case.crusher.tiny checks it,
# and the setup prints one line per class with its cells' size band, the larger class's cells
# smaller than the coarse template's would be. About 35 s on one core (small size: 15 s).
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/CH660/tiny "$work/classes"
cd "$work/classes"
export OMP_NUM_THREADS=1
caseDict -case . system/controlDict -entry endTime -set "$(bySize 0.012 0.005)" > /dev/null
# Six rocks of 14-18 mm instead of three: both classes are drawn (seed 1).
caseDict -case . constant/loading -entry feed/totalMass -set 0.025 > /dev/null
cp -r feedRock feedRockFine
caseDict -case feedRockFine system/voronoiMeshDict -entry mesoConstant -set 5.8e-7 > /dev/null
caseDict -case feedRockFine system/voronoiMeshDict -entry pruningDistance -set 2.6e-3 > /dev/null
sed -i 's|^ *rock  *"feedRock";.*|    classes { small { rock "feedRock"; upTo 0.016; } large { rock "feedRockFine"; upTo 0.018; } }|' \
    constant/loading
grep -q 'large { rock "feedRockFine"' constant/loading || fail "the feed classes were not set"
sed -i 's|^(cd feedRock \(.*\)$|&\n(cd feedRockFine \1|' Allrun
grep -q "^(cd feedRockFine" Allrun || fail "Allrun does not mesh feedRockFine"
./Allrun > /dev/null || fail "Allrun failed: $(tail -3 log.bondedDemFoam* 2>/dev/null)"

log=log.bondedDemFoam
# One setup line per class: its rock case, cells and cells' size band (also in CSS).
small=$(grep "^Feed class small: sizes 14-16 mm, rock .*feedRock: [0-9]* cells" $log) ||
    fail "no setup line for class small: $(grep '^Feed' $log)"
large=$(grep "^Feed class large: sizes 16-18 mm, rock .*feedRockFine: [0-9]* cells" $log) ||
    fail "no setup line for class large: $(grep '^Feed' $log)"
band() { echo "$1" | sed -n 's/.*; cells \([0-9.e+-]*\)-\([0-9.e+-]*\) mm (volume-equivalent), \([0-9.e+-]*\)-\([0-9.e+-]*\) CSS$/\1 \2 \3 \4/p'; }
read -r s_lo s_hi s_css_lo s_css_hi <<< "$(band "$small")"
read -r l_lo l_hi l_css_lo l_css_hi <<< "$(band "$large")"
[ -n "$s_hi" ] && [ -n "$l_hi" ] || fail "no cell band in the class lines: $small / $large"
echo "class small: cells $s_lo-$s_hi mm ($s_css_lo-$s_css_hi CSS); class large: cells $l_lo-$l_hi mm ($l_css_lo-$l_css_hi CSS)"
# The finer template keeps the large rocks' cells below the coarse one's at 16 mm, where one
# template for every size would have made them 18/16 larger still.
awk -v s="$s_hi" -v l="$l_hi" -v lo="$s_lo" 'BEGIN { exit !(lo > 0 && l < s) }' ||
    fail "the large class's cells ($l_lo-$l_hi mm) are not below the small class's ($s_lo-$s_hi mm)"
grep -q "^Time step .* of the smallest rock of class \(small\|large\) " $log ||
    fail "the time step does not name the class of the rock that sets it: $(grep '^Time step' $log)"

# Rocks of both classes were fed, and the count by class adds up to machine.dat's rocksFed.
byClass=$(grep "^Rocks fed by size class: " $log) || fail "no count of the rocks by class in $log"
n_small=$(echo "$byClass" | sed -n 's/.*small \([0-9]*\).*/\1/p')
n_large=$(echo "$byClass" | sed -n 's/.*large \([0-9]*\).*/\1/p')
[ "${n_small:-0}" -gt 0 ] && [ "${n_large:-0}" -gt 0 ] || fail "not both classes fed: $byClass"
fed_rocks=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i ~ /^(# )?rocksFed/) c = i; next }
                        !/^#/ && NF > 1 { n = $c } END { print n }' postProcessing/machine/0/machine.dat)
[ "$fed_rocks" = "$((n_small + n_large))" ] ||
    fail "machine.dat rocksFed $fed_rocks != $n_small + $n_large (the log's count by class)"
grep -q "; $fed_rocks rocks fed, " $log || fail "the mass line does not count $fed_rocks rocks"

# The mass balance, as case.crusher.tiny checks it (full precision).
line=$(grep "^Mass: fed" $log) || fail "no mass balance line in $log"
fed=$(echo "$line" | awk '{ print $3 }')
imbalance=$(echo "$line" | sed -n 's/.*(imbalance \([^ ]*\) kg).*/\1/p')
awk -v i="$imbalance" -v f="$fed" 'BEGIN { exit !(f > 0 && i != "" && (i < 0 ? -i : i) <= 1e-12 * f) }' ||
    fail "mass balance: fed $fed kg, imbalance $imbalance kg ($line)"
echo "ok: size classes, $n_small + $n_large rocks fed, $fed kg, imbalance $imbalance kg"

# The memory estimate takes the larger template's counts for every rock (an upper bound).
cells_fine=$(echo "$large" | sed -n 's/.*feedRockFine: \([0-9]*\) cells.*/\1/p')
estimate=$(bondedDemFoam -dry-run | grep "^Estimate: up to ") || fail "bondedDemFoam -dry-run: no estimate"
cells_est=$(echo "$estimate" | sed -n 's/^Estimate: up to \([0-9]*\) cells, .*(\([0-9]*\) feed rocks).*/\1 \2/p')
read -r n_est rocks_est <<< "$cells_est"
[ -n "$rocks_est" ] && [ "$n_est" -eq "$((cells_fine * rocks_est))" ] ||
    fail "the estimate is not $cells_fine cells per rock: $estimate"
echo "ok: $estimate"
