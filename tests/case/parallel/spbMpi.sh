#!/usr/bin/env bash
# bondedDemFoam -parallel on SPB granite rock 7 (198 cells, a scanned-like hull between plates):
# 2 ranks give the serial run's plateForce.dat in every column but balanceError (within 1e-11 of the external
# work) and its VTK frames byte for byte, to 25 % of the run (the rock loaded through its
# bonds; 15 % at the small size, the plates in contact). Not 3 ranks: oversubscribed ranks
# poll in their waits, and beside another test on 2 cores the run took minutes.
source "$(dirname "$0")/../caseTestFunctions"
source "$(dirname "$0")/mpiTestFunctions"

copyTutorial tutorials/SPB/granite "$work/spb"
cd "$work/spb"
source "$src/utilities/RunFunctions" > /dev/null || fail "RunFunctions"
makeRockCase rock7 > log.makeRockCase 2>&1 || fail "makeRockCase failed: $(tail -3 log.makeRockCase)"
cd rock7
for app in meshRock voronoiMesh; do "$app" > "log.$app" 2>&1 || fail "$app failed: $(tail -3 "log.$app")"; done
endTime=$(caseDict -case . system/controlDict -entry endTime -value)
caseDict -case . system/controlDict -entry endTime -set "$(awk -v t="$endTime" -v f="$(bySize 0.25 0.15)" 'BEGIN { printf "%.6g", f * t }')" > /dev/null
caseDict -case . system/controlDict -entry writeInterval -set "$(awk -v t="$endTime" 'BEGIN { printf "%.6g", t / 40 }')" > /dev/null
writeDecomposeParDict 2
dat=$mpiDat
cp -r . "$work/serial"
(cd "$work/serial" && bondedDemFoam > log 2>&1) || fail "serial run failed: $(tail -3 "$work/serial/log")"
for np in 2; do
    cp -r . "$work/np$np"
    caseDict -case "$work/np$np" system/decomposeParDict -entry numberOfSubdomains -set "$np" > /dev/null
    (cd "$work/np$np" && mpirun --oversubscribe -np "$np" bondedDemFoam -parallel > log 2>&1) ||
        fail "mpirun -np $np failed: $(tail -5 "$work/np$np/log")"
    samePlateForce "$work/serial" "$work/np$np"
    sameFrames "$work/serial" "$work/np$np"
done
awk -F'\t' -v ranks=2 '!/^#/ { f = $3 } END { printf "SPB rock 7: %d rows and the VTK frames of %s ranks equal the serial run'"'"'s (force %.1f N at the end)\n", NR, ranks, f }' "$work/serial/$dat"
