#!/usr/bin/env bash
# feFractureSolver interrupted: the same checks as interruptDem.sh (it has the
# same SIGINT/SIGTERM handling and startFrom latestTime restart).
source "$(dirname "$0")/../caseTestFunctions"
source "$(dirname "$0")/interruptFunctions"
export OMP_WAIT_POLICY=passive
solver=feFractureSolver state=femState base="$work/base"
copyTutorial tutorials/BDT/graniteFEM "$base"
caseDict -case "$base" system/feMeshDict -entry elementSize -set "$(bySize 3e-3 4e-3)" > /dev/null
(cd "$base" && meshRock > log.meshRock 2>&1) || fail "meshRock failed"
# Small size (the sanitized CI pass): 0.4 ms and 2 kills.
caseDict -case "$base" system/controlDict -entry endTime -set "$(bySize 1e-3 4e-4)" > /dev/null
caseDict -case "$base" system/controlDict -entry writeInterval -set "$(bySize 1e-4 4e-5)" > /dev/null
reference
interruptWith TERM 143
interruptWith INT 130
killRepeatedly "$(bySize 6 4)"
