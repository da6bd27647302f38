#!/usr/bin/env bash
# bondedDemFoam interrupted: SIGTERM (exit 143) and SIGINT (exit 130) write the
# state at the current step as a complete time directory, and `startFrom
# latestTime` continues to a plateForce.dat bitwise identical to the
# uninterrupted run's; SIGKILL ten times (at random moments and at the fault
# points of a time directory's creation, libs/core/faultPoint.hpp) leaves only
# complete time directories and whole VTK files, and the continuation's
# plateForce.dat and every VTK frame are bitwise the uninterrupted run's.
source "$(dirname "$0")/../caseTestFunctions"
source "$(dirname "$0")/interruptFunctions"
solver=bondedDemFoam state=demState base="$work/base"
copyTutorial tutorials/BDT/granite "$base"
(cd "$base" && meshRock > log.meshRock 2>&1 && voronoiMesh > log.voronoiMesh 2>&1) || fail "meshing failed"
# 6000 steps, 24 time directories (small size, the sanitized CI pass: 2000 steps, 20 directories
# and 4 kills): a kill at a fault point's third pass moves the run on by two directories.
caseDict -case "$base" system/controlDict -entry endTime -set "$(bySize 6e-4 2e-4)" > /dev/null
caseDict -case "$base" system/controlDict -entry writeInterval -set "$(bySize 2.5e-5 1e-5)" > /dev/null
reference
interruptWith TERM 143
interruptWith INT 130
killRepeatedly "$(bySize 10 4)"
