#!/usr/bin/env bash
# FEM calibration twin: the stand-in (weibullStandIn: failure loads from a known
# Weibull law of kstDfh/dfh/weibullModulus, kstDfh/dfh/weibullStress, kstDfh/dfh/seed) made the
# "measured" failure loads with m = 8, sigma_w = 20 MPa and seeds 1..12;
# calibrateModel must recover m and sigma_w within 3 % from the same seeds,
# starting from the centre of its bounds, and write them into the case.
source "$(dirname "$0")/../caseTestFunctions"
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$work/study/system" "$work/study/fem/constant"
cd "$work/study"
cat > fem/constant/rockProperties <<'DICT'
FoamFile { format ascii; class dictionary; object rockProperties; }
kstDfh
{
    dfh
    {
        weibullModulus  5;
        weibullStress   [1 -1 -2 0 0 0 0] 30e6;
        referenceVolume [0 3 0 0 0 0 0] 2e-8;
        seed            1;
    }
}
DICT
# The measurements: the stand-in at the truth, one run per seed.
{
    echo 'FoamFile { format ascii; class dictionary; object measurements; }'
    echo 'test BDT; material standIn;'
    echo 'specimens {'
    for seed in $(seq 1 12); do
        rm -rf run && cp -r fem run
        (cd run && caseDict -case . constant/rockProperties -entry kstDfh/dfh/weibullModulus -set 8 >/dev/null &&
            caseDict -case . constant/rockProperties -entry kstDfh/dfh/weibullStress -set 20e6 >/dev/null &&
            caseDict -case . constant/rockProperties -entry kstDfh/dfh/seed -set "$seed" >/dev/null && "$here/weibullStandIn")
        printf '    s%02d { failureLoad [N] %s; }\n' "$seed" "$(awk '!/^#/ { print $2 }' run/postProcessing/failureLoad/0/failureLoad.dat)"
    done
    echo '}'
} > measurements
rm -rf run
cat > system/calibrationDict <<DICT
FoamFile { format ascii; class dictionary; object calibrationDict; }
model        fem;
case         "fem";
measurements "measurements";
command      "$here/weibullStandIn";
jobs         2;
parameters
{
    weibullModulus { entry kstDfh/dfh/weibullModulus; range (4 16); }
    weibullStress  { entry kstDfh/dfh/weibullStress;  range (10e6 40e6); unit Pa; }
}
seeds  { entry kstDfh/dfh/seed; values (1 2 3 4 5 6 7 8 9 10 11 12); }
bobyqa { maxEvaluations 60; initialStep 0.5; tolerance 1e-4; }
target { response "postProcessing/failureLoad/0/failureLoad.dat"; failureLoad failureLoad; distance wasserstein1; }
DICT
calibrateModel -case . > log.calibrateModel 2>&1 || fail "calibrateModel failed: $(tail -3 log.calibrateModel)"
grep "calibrated" log.calibrateModel
m=$(caseDict -case fem constant/rockProperties -entry kstDfh/dfh/weibullModulus -value)
s=$(caseDict -case fem constant/rockProperties -entry kstDfh/dfh/weibullStress -value | awk '{ print $NF }')
awk -v m="$m" -v s="$s" 'BEGIN { em = m / 8 - 1; es = s / 20e6 - 1;
    printf "recovered m %.4g (%+.2f %%), sigma_w %.4g Pa (%+.2f %%)\n", m, 100 * em, s, 100 * es;
    exit !(em < 0.03 && em > -0.03 && es < 0.03 && es > -0.03) }' || fail "m or sigma_w not recovered within 3 %"
grep -q "calibrateModel .* study study, BOBYQA" fem/constant/rockProperties || fail "no provenance comment in rockProperties"
[ -f calibratedValues.bobyqa ] || fail "no calibratedValues.bobyqa"
echo "ok: FEM twin recovered m and sigma_w"
