#!/usr/bin/env bash
# explainGap on twin data with a series element of another form than the library's
# (docs/explainGap.md, "Absolute test"): nothing hidden by libs/effects, but every measured
# curve gets d += k F^(2/3) added after makeTwinData (a Hertzian seat, k = SERIES_K), so no effect
# of the library matches it exactly.
source "$(dirname "$0")/../caseTestFunctions"
seriesK=${SERIES_K:-3e-7}  # [m N^-2/3]: 0.17 mm at 13 kN, about the compliance of issue 42's scenario
export OMP_NUM_THREADS=1 EFFECTS="machineCompliance seatingOffset"
copyTutorial tutorials/explainGap "$work/tutorial"
cd "$work/tutorial"
source "$(dirname "$0")/scenarioFunctions"
smallSizePlates bdt

# addSeries <measured directory>: d += k max(F, 0)^(2/3) on every curve.
addSeries()
{
    local file
    for file in "$1"/curves/*.dat; do
        awk -F'\t' -v k="$seriesK" '/^#/ { print; next }
            { f = $2 > 0 ? $2 : 0; printf "%.10g\t%.10g\n", $1 + k * exp(log(f + 1e-300) * 2 / 3), $2 }' \
            "$file" > series.dat && mv series.dat "$file"
    done
}
# The pair's screening is on here (scenarioFunctions' default is off).
PAIRS=3 NO_FAIL=1 POSTPROCESS=addSeries scenario series "" "" ""
result() { caseDict -case series/study explainGap.result -entry "$1" -value; }
got=$(result verdict)
effect=$(result effect | tr -d '"')
echo "series: verdict $got, effect $effect, remaining $(result remaining), pairs refitted $(result pairsRefitted)"
# What the code concludes (no effect of the library is a Hertzian seat, but over the loading
# range d = k F^(2/3) is close to a straight line with an offset):
#   full   the pair machineCompliance+seatingOffset explains it (no single effect passes the
#          absolute test), its compliance the seat's tangent compliance at the mean measured
#          peak, (2/3) k F^(-1/3) (found 8.9e-9 m/N against 7.7e-9 at 17.4 kN);
#   small  machineCompliance alone explains it (4 held-out specimens and 2 seeds), its compliance
#          the seat's secant compliance at the peak, k F^(-1/3) (found 1.20e-8 against 1.14e-8).
# Either compliance within 30 % of that figure.
expected=$(bySize machineCompliance+seatingOffset machineCompliance)
[ "$got" = explained ] && [ "$effect" = "$expected" ] || fail "series: verdict $got by '$effect', expected explained by $expected"
if [ "$caseSize" = full ]; then
    compliance=$(result pairValues | tr -d '()' | awk '{ print $1 }')
else
    compliance=$(result value)
fi
peak=$(awk -F'\t' '!/^#/ { if ($2 > p[FILENAME]) p[FILENAME] = $2 } END { for (f in p) { s += p[f]; n++ } print s / n }' \
    series/twin/measured/curves/*.dat)
reference=$(awk -v k="$seriesK" -v f="$peak" -v factor="$(bySize 0.6666667 1)" 'BEGIN { printf "%.4g", factor * k * exp(-log(f) / 3) }')
awk -v c="$compliance" -v r="$reference" 'BEGIN { exit !(c >= 0.7 * r && c <= 1.3 * r) }' ||
    fail "series: compliance $compliance m/N, not within 30 % of the seat's $(bySize tangent secant) compliance $reference at the mean peak $peak N"
echo "series: compliance $compliance m/N against the seat's $(bySize tangent secant) compliance $reference m/N at the mean peak $peak N"
echo "PASS"
