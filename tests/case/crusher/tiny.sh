#!/usr/bin/env bash
# CH660 tiny: three small rocks beside the mantle in the parallel zone; the mass balance
# closes (fed = inside + discharged) and the mantle draws power (it nips them); crusherPost's
# figures per tonne (specific energy, P80/CSS, F80, F80/P80) match their definitions. The mantle
# is free to spin here (the tutorial's `spin fixed` is the same code with the spin at rest,
# tests/unit/crusher "[spin]"): the nipped rocks turn it about its axis (I psi'' = tau_a -
# c psi', libs/crusher/mantleSpin.hpp) and machine.dat books the drive's work as the wall's
# work plus the spin energy plus the bearing loss. Free spin without the bearing drag, or
# with an inertia in the wrong unit, is refused with one line and nothing written.
# About a minute on one core (90 cells). One thread: with 90 cells more threads only wait
# on each other (and spin on a loaded machine).
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/CH660/tiny "$work/tiny"
cd "$work/tiny"
export OMP_NUM_THREADS=1
# Small size (the sanitized CI pass): 12.5 ms instead of 0.05 s; the rocks are fed and the
# mantle nips one of them from 11 ms on, nothing is discharged yet (the discharge is the
# unit test test_crusher "[feed]", which the sanitized pass runs in full).
caseDict -case . system/controlDict -entry endTime -set "$(bySize 0.05 0.0125)" > /dev/null
# An estimate for the CH660 head (about 1.5 t, radius 0.55 m: I = 0.3 m R^2 = 140 kg m^2) and
# a bearing drag that stops a free spin within about a second (c = I / 1 s).
caseDict -case . constant/loading -entry machine/spin -set free > /dev/null
caseDict -case . constant/loading -entry machine/spinInertia -add "[kg m^2] 140" > /dev/null
caseDict -case . constant/loading -entry machine/bearingDamping -add "[N m s] 140" > /dev/null
./Allrun > /dev/null || fail "Allrun failed: $(tail -3 log.bondedDemFoam*)"
grep -q "spin free (inertia 140 kg m^2" log.bondedDemFoam || fail "the log does not report the free spin"
# The solver's own balance (full precision; the summary's columns are rounded to ~10 digits).
line=$(grep "^Mass: fed" log.bondedDemFoam) || fail "no mass balance line in log.bondedDemFoam"
fed=$(echo "$line" | awk '{ print $3 }')
imbalance=$(echo "$line" | sed -n 's/.*(imbalance \([^ ]*\) kg).*/\1/p')
awk -v i="$imbalance" -v f="$fed" 'BEGIN { exit !(f > 0 && i != "" && (i < 0 ? -i : i) <= 1e-12 * f) }' ||
    fail "mass balance: fed $fed kg, imbalance $imbalance kg ($line)"
power=$(awk '$1 == "powerMean_W" { print $2 }' postProcessing/crusherPost/summary.dat)
awk -v p="$power" 'BEGIN { exit !(p > 0) }' || fail "mean power $power W is not positive"
echo "ok: CH660 tiny, fed $fed kg, imbalance $imbalance kg, power $power W"
# Bands around the documented run (one thread, this tutorial with the free spin): the three rocks'
# mass exactly as meshed, the mantle's work and mean power within 5 % (full size: 0.014504 J,
# 0.290017 W, one fragment of 0.0057005 kg discharged; small size: 0.0048439 J, 0.388186 W, none).
# A change of the contact or bond physics, the feed or the kinematics moves them further.
mantle_work=$(sed -n 's/^Energy: mantle work \([^ ]*\) J.*/\1/p' log.bondedDemFoam | tail -1)
discharged=$(echo "$line" | sed -n 's/.*discharged \([^ ]*\) kg.*/\1/p')
awk -v f="$fed" -v w="$mantle_work" -v p="$power" -v d="$discharged" -v ew="$(bySize 0.014504 0.0048439)" \
    -v ep="$(bySize 0.290017 0.388186)" -v ed="$(bySize 0.00570052776 0)" 'BEGIN {
        ok = (f > 0.0142821554 * (1 - 1e-9) && f < 0.0142821554 * (1 + 1e-9)) &&
             (w > 0.95 * ew && w < 1.05 * ew) && (p > 0.95 * ep && p < 1.05 * ep) &&
             (d >= 0.99 * ed && d <= 1.01 * ed)
        exit !ok }' ||
    fail "moved from the documented run: fed $fed kg, mantle work $mantle_work J, power $power W, discharged $discharged kg"
echo "ok: in the bands (mantle work $mantle_work J, discharged $discharged kg)"

# The figures per tonne (docs/theory-crusher.md "Figures per tonne"): the old keys first and in
# their order (readers of summary.dat by position), no inf or nan, and each new figure against
# its definition, computed here from the summary's own columns and from machine.dat alone.
summary=postProcessing/crusherPost/summary.dat
key() { awk -F'\t' -v k="$1" '$1 == k { print $2 }' "$summary"; }
keys=$(awk -F'\t' '!/^#/ { printf "%s ", $1 }' "$summary")
[ "$keys" = "powerMean_W powerSpread_W pressureMean_Pa pressureSpread_Pa throughputMean_kg_s throughputSpread_kg_s throughputMean_t_h massFed_kg massInside_kg massDischarged_kg massImbalance_kg fragmentsDischarged P50_m P80_m CSS_m specificEnergy_kWh_t specificEnergySpread_kWh_t P80_CSS F80_m reductionRatio_F80_P80 cellsFed cellsMass_kg cellsP50_m cellsP80_m " ] ||
    fail "summary.dat keys: $keys"
! grep -qiE '(^|[^a-z])(nan|inf)([^a-z]|$)' "$summary" || fail "summary.dat holds inf or nan: $(cat "$summary")"
# F80 of the feed's sizeRange (sizes uniform in number, mass ~ size^3), read here from constant/loading.
range=$(sed -n 's/^ *sizeRange *( *\([^ ]*\) *\([^ )]*\) *).*/\1 \2/p' constant/loading)
awk -v r="$range" -v f="$(key F80_m)" 'BEGIN { split(r, a, " "); lo = a[1]^4; hi = a[2]^4
        want = (lo + 0.8 * (hi - lo))^0.25; d = f - want; if (d < 0) d = -d
        exit !(a[1] > 0 && d <= 1e-5 * want && want > 0.0173 && want < 0.0175) }' ||
    fail "F80_m $(key F80_m) is not the 80 % passing size of sizeRange ($range)"
# Mean power and throughput over the steady window (steadyStart 0: every row after the first).
means=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; ++i) { n = $i; sub(/ \[.*/, "", n); sub(/^# /, "", n); c[n] = i }; next }
    !/^#/ && NF > 1 { t = $c["Time"]; m = $c["massDischarged"]
                      if (rows++ > 0) { p += $c["power"]; if (t > t0) q += (m - m0) / (t - t0); n++ }
                      t0 = t; m0 = m }
    END { printf "%.17g %.17g", p / n, q / n }' postProcessing/machine/0/machine.dat)
if [ "$(key fragmentsDischarged)" -gt 0 ]; then
    awk -v m="$means" -v e="$(key specificEnergy_kWh_t)" -v es="$(key specificEnergySpread_kWh_t)" \
        -v P="$(key powerMean_W)" -v sP="$(key powerSpread_W)" -v Q="$(key throughputMean_kg_s)" \
        -v sQ="$(key throughputSpread_kg_s)" 'function rel(a, b) { d = (a - b) / b; return d < 0 ? -d : d }
        BEGIN { split(m, a, " "); mine = a[1] / a[2] / 3600; fromCols = P / Q / 3600
                spread = fromCols * sqrt((sP / P)^2 + (sQ / Q)^2)
                printf "specific energy %s kWh/t (spread %s): machine.dat %.6g, summary columns %.6g, spread %.6g\n",
                       e, es, mine, fromCols, spread
                exit !(e > 0 && a[2] > 0 && rel(e, mine) < 1e-5 && rel(e, fromCols) < 2e-5 && rel(es, spread) < 2e-5) }' ||
        fail "specific energy: $(key specificEnergy_kWh_t) kWh/t is not mean power / mean throughput ($means)"
    awk -v r="$(key P80_CSS)" -v p="$(key P80_m)" -v c="$(key CSS_m)" -v rr="$(key reductionRatio_F80_P80)" \
        -v f="$(key F80_m)" 'function rel(a, b) { d = (a - b) / b; return d < 0 ? -d : d }
        BEGIN { exit !(p > 0 && rel(r, p / c) < 2e-5 && rel(rr, f / p) < 2e-5) }' ||
        fail "P80_CSS $(key P80_CSS) or reductionRatio_F80_P80 $(key reductionRatio_F80_P80) inconsistent with P80 $(key P80_m), CSS $(key CSS_m), F80 $(key F80_m)"
else
    # Nothing discharged (the small size): no throughput, no P80; the feed's F80 all the same.
    for k in specificEnergy_kWh_t P80_CSS reductionRatio_F80_P80; do
        key "$k" | grep -q "^not available: ." || fail "$k without a discharge: '$(key "$k")'"
    done
fi
# The cells' PSD (libs/crusher/feedCells.hpp): every cell of every rock fed, so the rocks fed
# times the template's cells, holding the mass fed (summed from the scaled template cells, not
# the model's: equal to round-off); its P50 <= P80, both positive; psd.dat's cells column a
# mass-passing curve ending at 1.
cells_per_rock=$(sed -n 's/^Feed class rock: .*: \([0-9]*\) cells, .*/\1/p' log.bondedDemFoam)
rocks=$(sed -n 's/.*; \([0-9]*\) rocks fed, .*/\1/p' log.bondedDemFoam | tail -1)
[ -n "$cells_per_rock" ] && [ -n "$rocks" ] && [ "$(key cellsFed)" = "$((rocks * cells_per_rock))" ] ||
    fail "cellsFed $(key cellsFed) is not $rocks rocks x $cells_per_rock cells"
awk -v m="$(key cellsMass_kg)" -v f="$(key massFed_kg)" -v p50="$(key cellsP50_m)" -v p80="$(key cellsP80_m)" \
    'BEGIN { d = (m - f) / f; if (d < 0) d = -d; exit !(f > 0 && d < 1e-8 && p50 > 0 && p50 <= p80) }' ||
    fail "cells' PSD: mass $(key cellsMass_kg) kg against massFed $(key massFed_kg) kg, P50 $(key cellsP50_m), P80 $(key cellsP80_m)"
awk -F'\t' '!/^#/ { if ($3 < last || $3 > 1) bad = 1; last = $3; n++ } END { exit !(n > 0 && !bad && last == 1) }' \
    postProcessing/crusherPost/psd.dat || fail "psd.dat's passingCells is not a passing curve ending at 1"
echo "ok: cells' PSD: $(key cellsFed) cells, $(key cellsMass_kg) kg (fed $(key massFed_kg) kg), P80 $(key cellsP80_m) m"
crusherPost -dry-run | grep -q "^Specific energy  " || fail "crusherPost's screen summary has no specific energy line"
echo "ok: per tonne: specificEnergy_kWh_t $(key specificEnergy_kWh_t); P80_CSS $(key P80_CSS); F80_m $(key F80_m); reductionRatio_F80_P80 $(key reductionRatio_F80_P80)"

# The spin's columns, by name: it turned, and drive work = wall work + spin energy + bearing loss.
# The identity holds by construction (driveWork is written as mantleWork + the spin's torque
# work, which MantleSpin books as spin energy + bearing loss): this checks that the columns are
# wired and written; the physics of the spin is tests/unit/crusher "[spin]".
awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; ++i) { n = $i; sub(/ \[.*/, "", n); sub(/^# /, "", n); c[n] = i }; next }
    !/^#/ && NF > 1 { rate = $c["spinRate"]; ke = $c["spinEnergy"]; loss = $c["bearingLoss"];
                      drive = $c["driveWork"]; wall = $c["mantleWork"]; if (rate != 0) moved = 1 }
    END { printf "spin rate %.4g rad/s, spin energy %.4g J, bearing loss %.4g J; drive work %.6g J = wall %.6g J + %.4g J\n",
                 rate, ke, loss, drive, wall, drive - wall;
          if (!moved) { print "FAIL: the mantle never turned"; exit 1 }
          d = drive - wall - ke - loss; if (d < 0) d = -d;
          if (d > 1e-9 * (drive < 0 ? -drive : drive) + 1e-15) { print "FAIL: drive work != wall work + spin energy + bearing loss"; exit 1 } }' \
    postProcessing/machine/0/machine.dat || fail "spin books"

# crusherPost -dry-run prints the summary and writes nothing (it wrote summary.dat).
mv postProcessing/crusherPost/summary.dat "$work/summary.dat"
crusherPost -dry-run > "$work/crusherPost.dryRun" || fail "crusherPost -dry-run failed"
grep -q "^Dry run: nothing written" "$work/crusherPost.dryRun" || fail "crusherPost -dry-run: no closing line"
[ ! -e postProcessing/crusherPost/summary.dat ] || fail "crusherPost -dry-run wrote summary.dat"
mv "$work/summary.dat" postProcessing/crusherPost/summary.dat
# The feed's memory estimate (5 rocks of the smallest size at most: 150 cells), and a machine
# too small for it refused before any cell exists (there was no estimate for the crusher).
bondedDemFoam -dry-run | grep -q "^Estimate: up to 150 cells, 3380 bonds (5 feed rocks), ~" ||
    fail "bondedDemFoam -dry-run: no feed estimate line"
(export ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 && expectUserError "needs an estimated" bondedDemFoam -dry-run) ||
    fail "the crusher's dry run did not refuse a 1 MB machine"

# Bad input: free spin without the bearing drag, or with an inertia in the wrong unit.
for broken in "remove bearingDamping" "unit"; do
    rm -rf "$work/bad" && cp -r "$work/tiny" "$work/bad" && rm -rf "$work/bad"/[0-9]* "$work/bad/postProcessing"
    if [ "$broken" = unit ]; then
        caseDict -case "$work/bad" constant/loading -entry machine/spinInertia -set "[kg m^2 s^-1] 140" > /dev/null
        before=$(snapshot "$work/bad")
        expectUserError "spinInertia" bondedDemFoam -case "$work/bad"
    else
        caseDict -case "$work/bad" constant/loading -entry machine/bearingDamping -remove > /dev/null
        before=$(snapshot "$work/bad")
        expectUserError "needs spinInertia [kg m^2]" bondedDemFoam -case "$work/bad"
    fi
    [ "$before" = "$(snapshot "$work/bad")" ] || fail "a refused run changed the case ($broken)"
done
