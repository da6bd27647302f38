#!/usr/bin/env bash
# explainGap and makeTwinData refuse bad input before any simulation, with one
# message naming the file and what to do, and exit code 1: too few specimens for
# the held-out split, a curve without a load drop, an unknown effect, a missing
# fixed entry of an effect, conditions beside a top-level case or with differently
# calibrated cases, a pairs entry that is no count 0-3 nor off, and an unknown effect in a
# case's constant/modelEffects.
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/explainGap "$work/t"
cd "$work/t"
mkdir -p data/curves
for i in 1 2 3 4 5; do
    printf '# displacement [m]\tforce [N]\n0\t0\n1e-4\t5000\n2e-4\t10000\n3e-4\t2000\n' > data/curves/S$i.dat
done
cat > data/measurements <<'DICT'
FoamFile { format ascii; class dictionary; object measurements; }
test BDT; material granite;
specimens
{
    S1 { curve "curves/S1.dat"; } S2 { curve "curves/S2.dat"; } S3 { curve "curves/S3.dat"; }
    S4 { curve "curves/S4.dat"; } S5 { curve "curves/S5.dat"; }
}
DICT
sed -i 's#^measurements .*#measurements "../data/measurements";#' study/system/explainGapDict
expectUserError "5 specimens; explainGap fits on some and checks on the others held out" explainGap -case study

# Six specimens, one curve stops before its load drop.
printf '# displacement [m]\tforce [N]\n0\t0\n1e-4\t5000\n2e-4\t10000\n3e-4\t9000\n' > data/curves/S6.dat
sed -i 's#S5 { curve "curves/S5.dat"; }#S5 { curve "curves/S5.dat"; } S6 { curve "curves/S6.dat"; }#' data/measurements
expectUserError "S6.dat (specimen S6): no load drop" explainGap -case study
printf '# displacement [m]\tforce [N]\n0\t0\n1e-4\t5000\n2e-4\t10000\n3e-4\t2000\n' > data/curves/S6.dat

cp study/system/explainGapDict keep
sed -i 's/^effects .*/effects (contactCrumbling crumble);/' study/system/explainGapDict
expectUserError "unknown model effect 'crumble'; the library has: contactCrumbling" explainGap -case study
cp keep study/system/explainGapDict
sed -i '/contactCrumbling    { depth/d' study/system/explainGapDict
expectUserError "effectSettings/contactCrumbling/depth is missing" explainGap -case study
cp keep study/system/explainGapDict

# Several test conditions: each names its own case and measurements (not beside a top-level
# case), and their cases start from the same calibrated values.
printf 'conditions\n{\n    slow { case "../bdt"; measurements "../data/measurements"; }\n    fast { case "../bdtOther"; measurements "../data/measurements"; }\n}\n' >> study/system/explainGapDict
cp -r bdt bdtOther
expectUserError "'case' and 'conditions' together" explainGap -case study
sed -i -e '/^case /d' -e '/^measurements /d' study/system/explainGapDict
sed -i 's/tensileStrength \[1 -1 -2 0 0 0 0\] 31.8e6;/tensileStrength [1 -1 -2 0 0 0 0] 30e6;/' bdtOther/constant/rockProperties
expectUserError "the conditions model the same rock" explainGap -case study
cp keep study/system/explainGapDict

# A tied entry that is not a sub-dictionary (it crashed on a null pointer).
sed -i 's/^    cohesion { entry bond/    bad 1;\n    cohesion { entry bond/' study/system/explainGapDict
expectUserError "tied entry 'bad' must be a sub-dictionary" explainGap -case study
cp keep study/system/explainGapDict

# pairs: a count 0-3 or off.
sed -i "s/^pairs .*/pairs 5;/" study/system/explainGapDict
expectUserError "pairs" explainGap -case study
cp keep study/system/explainGapDict
sed -i "s/^pairs .*/pairs all;/" study/system/explainGapDict
expectUserError "pairs is not a count nor off; give the most pairs of effects to refit" explainGap -case study
cp keep study/system/explainGapDict

printf 'FoamFile { format ascii; class dictionary; object modelEffects; }\nseatingGap { depth 1e-5; }\n' \
    > bdt/constant/modelEffects
(cd bdt && meshRock > /dev/null 2>&1 && voronoiMesh > /dev/null 2>&1) || fail "meshing failed"
expectUserError "unknown model effect 'seatingGap'" bondedDemFoam -case bdt
printf 'FoamFile { format ascii; class dictionary; object modelEffects; }\nseatingOffset { depth 1e-5; }\n' \
    > bdt/constant/modelEffects
expectUserError "closureForce" bondedDemFoam -case bdt
[ ! -d study/runs ] || fail "a simulation directory was made for bad input"
echo "PASS"
