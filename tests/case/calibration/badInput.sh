#!/usr/bin/env bash
# Bad input to calibrateModel: each stops with exit code 1 and one line saying
# what is wrong, and the case's rockProperties is left byte for byte as it was.
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
        seed            1;
    }
}
bond
{
    voronoiQNSC
    {
        E               [1 -1 -2 0 0 0 0] 46e9;
        tensileStrength [1 -1 -2 0 0 0 0] 28e6;
        cohesion        [1 -1 -2 0 0 0 0] 42e6;
    }
}
DICT
cp "$src/cases/experiments/BDT/granite/measurements" measurements
sum=$(sha1sum fem/constant/rockProperties)
unchanged() { [ "$sum" = "$(sha1sum fem/constant/rockProperties)" ] || fail "$1 changed rockProperties"; }

femDict()  # femDict <seeds values> <command>
{
    cat > system/calibrationDict <<DICT
FoamFile { format ascii; class dictionary; object calibrationDict; }
model fem; case "fem"; measurements "measurements"; command "$2";
parameters { weibullModulus { entry kstDfh/dfh/weibullModulus; range (4 16); } }
seeds { entry kstDfh/dfh/seed; values ($1); }
bobyqa { maxEvaluations 5; }
target { response "postProcessing/failureLoad/0/failureLoad.dat"; }
DICT
}
demDict()  # demDict <responseSurface settings>
{
    cat > system/calibrationDict <<DICT
FoamFile { format ascii; class dictionary; object calibrationDict; }
model dem; case "fem"; measurements "measurements"; command "false";
parameters { E { entry bond/voronoiQNSC/E; range (20e9 80e9); } tensileStrength { entry bond/voronoiQNSC/tensileStrength; range (10e6 40e6); } }
tied { cohesion { entry bond/voronoiQNSC/cohesion; factor 1.5; of tensileStrength; } }
responseSurface { $1 }
target { response "postProcessing/plateForce/0/plateForce.dat"; }
DICT
}

# A design with zero runs.
demDict "levels 0;"
expectUserError "levels 0: the design has no runs" calibrateModel -case .
demDict "design latinHypercube; samples 0;"
expectUserError "samples 0: the design has no runs" calibrateModel -case .
femDict "" "$here/weibullStandIn"
expectUserError "no seeds: the design has no runs" calibrateModel -case .
unchanged "a design without runs"

# Every member fails: the objective cannot be evaluated.
demDict "levels 3;"
expectUserError "the objective cannot be evaluated: all 9 members of the design failed" calibrateModel -case .
femDict "1 2 3" "exit 3"
expectUserError "the objective cannot be evaluated at weibullModulus=10: all 3 seeds failed" calibrateModel -case .
unchanged "failed runs"

# Measurements the stats reader refuses: the message reaches the user.
femDict "1 2 3" "$here/weibullStandIn"
sed -i 's/BD-G-01 { failureLoad \[N\] 10.9e3;/BD-G-01 { failureLoad [N] -10.9e3;/' measurements
expectUserError "measurements" calibrateModel -case .
cp "$src/cases/experiments/BDT/granite/measurements" measurements
sed -i 's/BD-G-02 { failureLoad \[N\] 15.7e3;/BD-G-02 { failureLoad [Pa] 15.7e3;/' measurements
expectUserError "measurements" calibrateModel -case .
cp "$src/cases/experiments/BDT/granite/measurements" measurements
sed -i 's/BD-G-03 { failureLoad \[N\] 12.3e3; tensileStrength \[Pa\] 12.5e6; }/BD-G-03 { }/' measurements
expectUserError "measurements" calibrateModel -case .
unchanged "bad measurements"

# A parameter entry the case does not have, an unknown method.
cp "$src/cases/experiments/BDT/granite/measurements" measurements
femDict "1 2 3" "$here/weibullStandIn"
sed -i 's|entry kstDfh/dfh/weibullModulus|entry kstDfh/dfh/weibulModulus|' system/calibrationDict
expectUserError "has no entry 'kstDfh/dfh/weibulModulus'" calibrateModel -case .
femDict "1 2 3" "$here/weibullStandIn"
expectUserError "-method responseSurface: the FEM calibration uses bobyqa" calibrateModel -case . -method responseSurface
unchanged "bad dictionaries"
echo "ok: every bad input stopped with one line and left rockProperties unchanged"
