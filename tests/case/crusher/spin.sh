#!/usr/bin/env bash
# CH660 tiny with the mantle free to spin: the rocks nipped at about 11 ms turn the mantle
# about its axis (I psi'' = tau_a - c psi', libs/crusher/mantleSpin.hpp); the machine series
# books the drive's work as the wall's work plus the spin energy plus the bearing loss, and
# the rocks' energy balance is the one of the fixed-spin run's kind (mass exact).
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/CH660/tiny "$work/tiny"
cd "$work/tiny"
export OMP_NUM_THREADS=1
# An estimate for the CH660 head (about 1.5 t, radius 0.55 m: I = 0.3 m R^2 = 140 kg m^2) and
# a bearing drag that stops a free spin within about a second (c = I / 1 s); the mantle is
# nipping one rock from 11 ms on, the run stops at 15 ms.
caseDict -case . constant/loading -entry machine/spin -set free > /dev/null
caseDict -case . constant/loading -entry machine/spinInertia -add "[kg m^2] 140" > /dev/null
caseDict -case . constant/loading -entry machine/bearingDamping -add "[N m s] 140" > /dev/null
caseDict -case . system/controlDict -entry endTime -set "$(bySize 0.015 0.0125)" > /dev/null
./Allrun > /dev/null || fail "Allrun failed: $(tail -3 log.bondedDemFoam*)"
grep -q "spin free (inertia 140 kg m^2" log.bondedDemFoam || fail "the log does not report the free spin"
line=$(grep "^Mass: fed" log.bondedDemFoam) || fail "no mass balance line"
imbalance=$(echo "$line" | sed -n 's/.*(imbalance \([^ ]*\) kg).*/\1/p')
fed=$(echo "$line" | awk '{ print $3 }')
awk -v i="$imbalance" -v f="$fed" 'BEGIN { exit !(f > 0 && (i < 0 ? -i : i) <= 1e-12 * f) }' || fail "mass balance: $line"
dat=postProcessing/machine/0/machine.dat
# Columns by name: spinRate, spinEnergy, bearingLoss, driveWork, mantleWork.
awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; ++i) { n = $i; sub(/ \[.*/, "", n); sub(/^# /, "", n); c[n] = i }; next }
    !/^#/ && NF > 1 { rate = $c["spinRate"]; ke = $c["spinEnergy"]; loss = $c["bearingLoss"];
                      drive = $c["driveWork"]; wall = $c["mantleWork"]; if (rate != 0) moved = 1 }
    END { printf "spin rate %.4g rad/s, spin energy %.4g J, bearing loss %.4g J; drive work %.6g J = wall %.6g J + %.4g J\n",
                 rate, ke, loss, drive, wall, drive - wall;
          if (!moved) { print "FAIL: the mantle never turned"; exit 1 }
          d = drive - wall - ke - loss; if (d < 0) d = -d;
          if (d > 1e-9 * (drive < 0 ? -drive : drive) + 1e-15) { print "FAIL: drive work != wall work + spin energy + bearing loss"; exit 1 } }' \
    "$dat" || fail "spin books"
power=$(awk '$1 == "powerMean_W" { print $2 }' postProcessing/crusherPost/summary.dat)
awk -v p="$power" 'BEGIN { exit !(p > 0) }' || fail "mean drive power $power W is not positive"
echo "ok: free spin, drive power $power W"

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
