#!/usr/bin/env bash
# tutorials/CH660/full under -parallel (validation label): its Slurm batch script, slurmJob, run
# outside Slurm with the variables sbatch would set (SLURM_NTASKS=2, SLURM_CPUS_PER_TASK=1,
# SLURM_SUBMIT_DIR), meshes the liners and the 198-cell template rock, sets
# numberOfSubdomains, runs bondedDemFoam -parallel on 2 ranks and crusherPost; the first 0.01 s
# (40 000 steps: the empty chamber, then the first 0.68 kg rock fed at 2 ms falling towards the
# choke) give the serial run's machine.dat (as case.parallel.ch660Mpi compares it) and VTK frames.
source "$(dirname "$0")/../caseTestFunctions"
source "$(dirname "$0")/mpiTestFunctions"

copyTutorial tutorials/CH660/full "$work/base"
cd "$work/base"
caseDict -case . system/controlDict -entry endTime -set 0.01 > /dev/null
caseDict -case . system/controlDict -entry writeInterval -set 0.0025 > /dev/null
cp -r "$work/base" "$work/np2"
cp -r "$work/base" "$work/serial"
cd "$work/serial"
run() { "$@" > "log.$1" 2>&1 || fail "$1 failed: $(tail -3 "log.$1")"; }
run meshCrusher
(cd feedRock && run meshRock && run voronoiMesh) || fail "the template rock's mesh"
run bondedDemFoam
cd "$work/np2"
SLURM_NTASKS=2 SLURM_CPUS_PER_TASK=1 SLURM_SUBMIT_DIR="$work/np2" ROCKFRAC_DIR="$src" bash ./slurmJob > log.job 2>&1 ||
    fail "slurmJob failed: $(tail -5 log.job)"
grep -q "^CH660 full on 2 ranks x 1 threads" log.job || fail "slurmJob: no closing line: $(tail -3 log.job)"
[ "$(caseDict -case . system/decomposeParDict -entry numberOfSubdomains -value)" = 2 ] || fail "slurmJob did not set numberOfSubdomains"
[ -f postProcessing/crusherPost/summary.dat ] || fail "slurmJob: crusherPost wrote no summary"
grep -q "^Decomposition: 2 ranks" log.bondedDemFoam || fail "np2: no decomposition line"
grep "^Mass: fed" "$work/serial/log.bondedDemFoam" | cmp -s - <(grep "^Mass: fed" log.bondedDemFoam) || fail "np2: another mass balance"
grep -q "^Mass: fed 0.[0-9]* kg .*; [1-9][0-9]* rocks fed" log.bondedDemFoam || fail "no rock was fed: $(grep '^Mass' log.bondedDemFoam)"
rows=$(grep -vc '^#' "$work/serial/$machine")
[ "$(grep -vc '^#' "$work/np2/$machine")" = "$rows" ] || fail "np2: not $rows rows in machine.dat"
sameMachine "$work/serial" "$work/np2" "$rows"
sameFramesAsSerial "$work/serial" "$work/np2"
