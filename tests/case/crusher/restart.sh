#!/usr/bin/env bash
# CH660 tiny restarted (libs/crusher/crusherState.hpp): an uninterrupted run of 55 ms, and one
# run cut into legs: SIGTERM (exit 143, the state at that step written as a time directory),
# then `startFrom latestTime` to a write time after the feed (20 ms, inside a machine.dat
# window), to 30 ms (before the discharge at 49 ms), to 50 ms (after it: the fragment's cells
# are gone from the state) and to the end. machine.dat, discharge.dat and every VTK frame of the uninterrupted run
# are byte for byte those of the legs (which add one frame, at the signal). The uninterrupted
# run's state at 30 ms, continued by `mpirun -np 2 bondedDemFoam -parallel`, gives its files too
# (machine.dat but for the last digits of `exchanged` and `balanceError`, as in
# case.parallel.ch660Mpi). Small size (the sanitized pass): the first 7.5 ms, the signal at the
# first write (2.5 ms) and legs to 5 and 7.5 ms (fed, nothing nipped or discharged; the parallel
# continuation from 5 ms).
source "$(dirname "$0")/../caseTestFunctions"
if command -v mpirun > /dev/null; then
    source "$(dirname "$0")/../parallel/mpiTestFunctions"  # sameMachine, sameFramesAsSerial
else
    machine=postProcessing/machine/0/machine.dat discharge=postProcessing/discharge/0/discharge.dat
fi
export OMP_NUM_THREADS=1
copyTutorial tutorials/CH660/tiny "$work/base"
cd "$work/base"
run() { "$@" > "log.$1" 2>&1 || fail "$1 failed: $(tail -3 "log.$1")"; }
run meshCrusher
(cd feedRock && run meshRock && run voronoiMesh) || fail "the feed rock's mesh"
endTime=$(bySize 0.055 0.0075)
caseDict -case . system/controlDict -entry endTime -set "$endTime" > /dev/null
caseDict -case . system/controlDict -entry writeInterval -set "$(bySize 0.005 0.0025)" > /dev/null
caseDict -case . system/controlDict -entry startFrom -set latestTime > /dev/null
legs=$(bySize "0.02 0.03 0.05 0.055" "0.005 0.0075")
parallelFrom=$(bySize 0.03 0.005)

cp -r "$work/base" "$work/reference"
(cd "$work/reference" && bondedDemFoam > log 2>&1) || fail "the uninterrupted run failed: $(tail -3 "$work/reference/log")"
if fullSize "a fragment discharged between 30 and 50 ms"; then
    awk '!/^#/ && $1 > 0.03 && $1 < 0.05 { n++ } END { exit !(n >= 1) }' "$work/reference/$discharge" ||
        fail "the uninterrupted run discharged nothing between 30 and 50 ms"
fi

# The legs: SIGTERM once the first write is done, then the write times.
legs_dir="$work/legs"
cp -r "$work/base" "$legs_dir"
cd "$legs_dir"
bondedDemFoam > log.0 2>&1 &
pid=$!
# (Time directories are named by the time of the step that crossed the write time.)
for i in $(seq 1200); do ls -d [0-9]* > /dev/null 2>&1 && break; sleep 0.05; done
ls -d [0-9]* > /dev/null 2>&1 || fail "no time directory after 60 s: $(tail -3 log.0)"
kill -TERM "$pid"
rc=0
wait "$pid" || rc=$?
[ "$rc" = 143 ] || fail "SIGTERM: exit $rc, expected 143: $(tail -3 log.0)"
grep -q "interrupted by a signal: state written, continue with startFrom latestTime" log.0 ||
    fail "SIGTERM: the log does not say the state was written"
signalled=$(ls -d [0-9]* | sort -g | tail -1)
[ -s "$signalled/demState" ] && [ -s "$signalled/crusherState" ] || fail "SIGTERM: $signalled lacks its state"
echo "ok: SIGTERM: exit 143, state at $signalled"
leg=1
for t in $legs; do
    caseDict -case . system/controlDict -entry endTime -set "$t" > /dev/null
    from=$(ls -d [0-9]* | sort -g | tail -1)
    bondedDemFoam > "log.$leg" 2>&1 || fail "leg $leg (from $from to $t) failed: $(tail -3 "log.$leg")"
    grep -q "^Restart from time $from " "log.$leg" || fail "leg $leg did not restart from $from"
    leg=$((leg + 1))
done
cmp -s "$work/reference/$machine" "$machine" || fail "machine.dat differs from the uninterrupted run's: $(diff "$work/reference/$machine" "$machine" | head -4)"
cmp -s "$work/reference/$discharge" "$discharge" || fail "discharge.dat differs from the uninterrupted run's"
# Every file of VTK/: the uninterrupted run's byte for byte; the legs add the frames where they
# stopped (the signal's step, and an endTime a step short of the write time it names) and
# their entries in the .series files.
stops=$(cat log.[0-9]* | sed -n 's/^End: step \([0-9]*\) .*/\1/p' | sort -nu)
isStop() { local n; for n in $stops; do case "$1" in cells_$n.vtu|bonds_$n.vtp) return 0 ;; esac; done; return 1; }
frames=0
for f in $(cd "$work/reference/VTK" && ls); do
    case "$f" in
        *.series)  # the entries but for those at the stops, and every entry of the reference there
            grep -q "_$(echo "$stops" | tail -1)\." "$work/reference/VTK/$f" || fail "VTK/$f: no last frame"
            cmp -s <(grep -v -E "_($(echo $stops | tr ' ' '|'))\." "VTK/$f") \
                <(grep -v -E "_($(echo $stops | tr ' ' '|'))\." "$work/reference/VTK/$f") || fail "VTK/$f differs" ;;
        *) cmp -s "VTK/$f" "$work/reference/VTK/$f" || fail "VTK/$f differs from the uninterrupted run's"; frames=$((frames + 1)) ;;
    esac
done
[ "$frames" -ge 8 ] || fail "only $frames VTK frames"
for f in $(comm -13 <(cd "$work/reference/VTK" && ls) <(ls VTK)); do
    isStop "$f" || fail "the legs wrote VTK/$f, which is neither the uninterrupted run's nor at a stop"
done
echo "ok: SIGTERM at $signalled, restarts at $legs: machine.dat, discharge.dat and $frames VTK files identical"

# The state written by the serial run, continued on 2 ranks.
if command -v mpirun > /dev/null; then
    cp -r "$work/reference" "$work/np2"
    cd "$work/np2"
    for t in $(ls -d [0-9]*); do
        awk -v a="$t" -v b="$parallelFrom" 'BEGIN { exit !(a > 1.001 * b) }' && rm -rf "$t"
    done
    from=$(ls -d [0-9]* | sort -g | tail -1)
    writeDecomposeParDict 2
    rm -f VTK/*_*.vt?  # the frames after the restart are the continuation's
    mpirun --oversubscribe -np 2 bondedDemFoam -parallel > log 2>&1 || fail "mpirun -np 2 failed: $(tail -5 log)"
    grep -q "^Restart from time $from " log || fail "np2 did not restart from $from: $(grep -i restart log)"
    rows=$(grep -vc '^#' "$work/reference/$machine")
    [ "$(grep -vc '^#' "$machine")" = "$rows" ] || fail "np2: not $rows rows in machine.dat"
    sameMachine "$work/reference" "$work/np2" "$rows"
    cmp -s "$work/reference/$discharge" "$discharge" || fail "np2: discharge.dat differs from the serial run's"
    sameFramesAsSerial "$work/reference" "$work/np2"
else
    echo "no mpirun: the parallel continuation is not checked"
fi
