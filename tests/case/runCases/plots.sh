#!/usr/bin/env bash
# plotCdf and plotTimeSeries: PNGs are produced (magic bytes, > 5 kB) from a
# runCases results table, the paper's measured data and postProcessing files;
# a missing gnuplot and empty input stop them with one clear line.
source "$(dirname "$0")/../caseTestFunctions"
source "$(dirname "$0")/studyFunctions"
experiments="$src/cases/experiments"

# isPng <file>: the PNG signature and a size that holds a real picture.
isPng()
{
    [ -f "$1" ] || fail "$1 was not written"
    [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "$1 is not a PNG"
    [ "$(stat -c %s "$1")" -gt 5120 ] || fail "$1 is smaller than 5 kB"
    echo "ok: $1 ($(stat -c %s "$1") bytes)"
}

# Simulated failure loads from a study: result = 2x + y, 10.1 to 14.2 kN.
makeStudy "$work/study" "5000 6000 7000" "100 200 300"
runCases -case "$work/study" > /dev/null || fail "the study failed"
plotCdf -case "$work" -measured "$experiments/BDT/granite/measurements" -column result -weibull \
    -labels "simulated,limestone BDT" study/results.dat "$experiments/BDT/limestone/measurements" > "$work/log.plotCdf" ||
    fail "plotCdf failed: $(cat "$work/log.plotCdf")"
isPng "$work/plots/failureLoadCdf.png"
grep -q "simulated (n = 9): KS [0-9.]*, W1 [0-9.]* kN" "$work/log.plotCdf" || fail "no KS/W1 distances reported"
[ -f "$work/plots/failureLoadCdf.png.gp" ] || fail "the gnuplot script was not kept"
plotCdf -case "$work" -measured "$experiments/SPB/granite/measurements" -output spb.png > /dev/null
isPng "$work/spb.png"

# Force against displacement of two cases, with the measured band and a measured curve.
for c in a b; do
    mkdir -p "$work/$c/postProcessing/plateForce/0"
    awk -v peak="$([ $c = a ] && echo 13000 || echo 14500)" 'BEGIN {
        print "# Time [s]\tdisplacement [m]\tforce [N]";
        for (i = 0; i < 300; i++) { d = i * 1e-6; f = d < 2e-4 ? peak * d / 2e-4 : peak * (1 - (d - 2e-4) / 5e-5);
            if (f < 0) f = 0; printf "%g\t%g\t%g\n", i * 1e-3, d, f } }' > "$work/$c/postProcessing/plateForce/0/plateForce.dat"
done
mkdir -p "$work/measured/curves"
cat > "$work/measured/measurements" <<'DICT'
FoamFile { format ascii; class dictionary; object measurements; }
test BDT; material granite;
specimens
{
    S1 { failureLoad [N] 12.5e3; curve "curves/S1.dat"; }
    S2 { failureLoad [N] 14.0e3; }
}
DICT
awk 'BEGIN { print "# displacement [m]\tforce [N]"; for (i = 0; i <= 25; i++) printf "%g\t%g\n", i * 1e-5, 12500 * (i <= 20 ? i / 20 : (25 - i) / 5) }' \
    > "$work/measured/curves/S1.dat"
plotTimeSeries -case "$work" -x displacement -y force -measured measured/measurements -labels "case a,case b" \
    -title "Brazilian disc" a/postProcessing/plateForce/0/plateForce.dat b/postProcessing/plateForce/0/plateForce.dat \
    > /dev/null || fail "plotTimeSeries failed"
isPng "$work/plots/force.png"
grep -q 'set xlabel "displacement \[µm\]"' "$work/plots/force.png.gp" || fail "x label with unit"
grep -q 'set ylabel "force \[kN\]"' "$work/plots/force.png.gp" || fail "y label with unit"

# Errors: no gnuplot, empty input, a missing column; no picture is left behind.
rm -f "$work/plots/force.png"
ROCKFRAC_GNUPLOT=/nonexistent/gnuplot expectUserError "gnuplot not found" \
    plotTimeSeries -case "$work" -y force a/postProcessing/plateForce/0/plateForce.dat
[ ! -e "$work/plots/force.png" ] || fail "a PNG was written without gnuplot"
ROCKFRAC_GNUPLOT=/nonexistent/gnuplot expectUserError "gnuplot not found" \
    plotCdf -case "$work" -measured "$experiments/BDT/granite/measurements" -output none.png
printf '# Time [s]\tforce [N]\n' > "$work/empty.dat"
expectUserError "no data rows" plotTimeSeries -case "$work" -y force empty.dat
: > "$work/empty2.dat"
expectUserError "empty2.dat" plotCdf -case "$work" empty2.dat
expectUserError "no column 'load'" plotTimeSeries -case "$work" -y load a/postProcessing/plateForce/0/plateForce.dat
expectUserError "nothing to plot" plotCdf -case "$work"
echo "plots ok"
