#!/usr/bin/env bash
# feFractureSolver interrupted: the same checks as interruptDem.sh (it has the
# same SIGINT/SIGTERM handling and startFrom latestTime restart).
source "$(dirname "$0")/../caseTestFunctions"
source "$(dirname "$0")/interruptFunctions"
export OMP_WAIT_POLICY=passive
solver=feFractureSolver state=femState base="$work/base"
copyTutorial tutorials/BDT/graniteFEM "$base"
caseDict -case "$base" system/feMeshDict -entry elementSize -set 3e-3 > /dev/null
(cd "$base" && meshRock > log.meshRock 2>&1) || fail "meshRock failed"
caseDict -case "$base" system/controlDict -entry endTime -set 1e-3 > /dev/null
caseDict -case "$base" system/controlDict -entry writeInterval -set 1e-4 > /dev/null
reference
interruptWith TERM 143
interruptWith INT 130
killRepeatedly 4
