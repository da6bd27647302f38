#!/usr/bin/env bash
# explainGap on twin data, plate friction: on a disc between flat plates the
# rock-steel friction leaves no signature (docs/validation.md), so this scenario
# uses the coarse irregular rock of tutorials/explainGap/spb (rock 7 of the SPB
# set at 60 cells), where nearly frictionless plates let the rock slip and turn.
# The hidden factor 0.05 must be attributed to plateFriction with the held-out
# gap shrinking by >= 30 %.
source "$(dirname "$0")/../caseTestFunctions"
export OMP_NUM_THREADS=1
copyTutorial tutorials/explainGap "$work/tutorial"
cd "$work/tutorial"
source "$(dirname "$0")/scenarioFunctions"
smallSizePlates spb
MODEL=spb EFFECTS=$(bySize "contactCrumbling machineCompliance plateFriction" "contactCrumbling plateFriction") \
    scenario friction "plateFriction { frictionFactor 0.05; }" explained plateFriction
# On the rock the plate friction has a signature: screened (on discs it is notTestable, twins.sh).
awk -F'\t' '$1 == "plateFriction" { found = 1; if ($2 != "screened") exit 1 } END { exit !found }' \
    friction/study/screening.dat || fail "friction: plateFriction not screened on the rock"
echo "PASS"
