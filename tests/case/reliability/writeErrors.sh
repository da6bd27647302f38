#!/usr/bin/env bash
# Write errors during a run: a case that becomes read-only, and a disk that
# fills up. bondedDemFoam must stop with exit code 1 and one line naming what
# it could not write, and keep the previous write time complete.
#
# Root ignores permissions, so as root the case lives on small tmpfs mounts
# (remounted read-only, or too small); without root, chmod makes the case
# read-only and the disk-full half cannot run. Exit 77 (skipped) when either half
# cannot run.
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/BDT/granite "$work/base"
(cd "$work/base" && meshRock > log.meshRock 2>&1 && voronoiMesh > log.voronoiMesh 2>&1) || fail "meshing failed"
caseDict -case "$work/base" system/controlDict -entry endTime -set 2e-4 > /dev/null
caseDict -case "$work/base" system/controlDict -entry writeInterval -set 2e-5 > /dev/null

mounts=()
cleanup() { for m in "${mounts[@]}"; do umount "$m" 2>/dev/null || true; done; }
trap cleanup EXIT
tryMount() { mkdir -p "$1" && mount -t tmpfs -o "size=$2" tmpfs "$1" 2>/dev/null && mounts+=("$1"); }

# expectOneLine <log of stderr> <rc> <fragment>
expectOneLine()
{
    [ "$2" -eq 1 ] || fail "exit code $2, expected 1: $(cat "$1")"
    [ "$(wc -l < "$1")" -eq 1 ] || fail "more than one line on stderr: $(cat "$1")"
    grep -q -- "$3" "$1" || fail "message lacks '$3': $(cat "$1")"
    echo "ok: $(cat "$1")"
}

# -- 1. The case becomes read-only after the first part of the run ---------------
readOnly="$work/readOnly"
if [ "$(id -u)" -eq 0 ]; then
    tryMount "$readOnly" 64m || { echo "SKIPPED: cannot mount a tmpfs"; exit 77; }
    cp -r "$work/base/." "$readOnly"
else
    cp -r "$work/base" "$readOnly"
fi
caseDict -case "$readOnly" system/controlDict -entry endTime -set 1e-4 > /dev/null
(cd "$readOnly" && bondedDemFoam > log.1 2>&1) || fail "the first part failed"
caseDict -case "$readOnly" system/controlDict -entry endTime -set 2e-4 > /dev/null
before=$(snapshot "$readOnly")
if [ "$(id -u)" -eq 0 ]; then mount -o remount,ro "$readOnly"; else chmod -R a-w "$readOnly"; fi
rc=0; (cd "$readOnly" && bondedDemFoam > "$work/ro.out" 2> "$work/ro.err") || rc=$?
expectOneLine "$work/ro.err" "$rc" "cannot"
[ "$before" = "$(snapshot "$readOnly")" ] || fail "the read-only case changed"
if [ "$(id -u)" -eq 0 ]; then mount -o remount,rw "$readOnly"; else chmod -R u+w "$readOnly"; fi

# -- 2. The disk fills up mid-run -------------------------------------------------
# Without root the disk-full half cannot run: the test reports itself skipped (77), not passed,
# although the read-only half above did pass.
if [ "$(id -u)" -ne 0 ]; then
    echo "SKIPPED: the read-only half passed; the disk-full half needs root (a tmpfs)"
    exit 77
fi
need=$(du -sk "$work/base" | cut -f1)
full="$work/full"
tryMount "$full" "$((need + 3000))k" || fail "cannot mount the small tmpfs"
cp -r "$work/base/." "$full"
rc=0; (cd "$full" && bondedDemFoam > "$work/full.out" 2> "$work/full.err") || rc=$?
expectOneLine "$work/full.err" "$rc" "cannot"
grep -q "disk full\|No space left" "$work/full.err" || fail "the message does not say the disk is full: $(cat "$work/full.err")"
latest=$(cd "$full" && ls -d [0-9]* | sort -g | tail -1)
[ -s "$full/$latest/demState" ] || fail "the last time directory $latest is not complete"
for t in $(cd "$full" && ls -d [0-9]*); do [ -s "$full/$t/demState" ] || fail "partial time directory $t"; done
# Every VTK file is whole (VTK's writer reported success on a cut-short file, which was then
# renamed into place: a torn 16 kB frame).
wholeFrames "$full"
# The kept state is good: with room again, the run continues from it.
mkdir -p "$work/roomy" && cp -r "$full/." "$work/roomy"
(cd "$work/roomy" && bondedDemFoam > log.roomy 2>&1) || fail "continuing from $latest failed: $(tail -3 "$work/roomy/log.roomy")"
[ "$latest" = 0 ] || grep -q "Restart from time $latest" "$work/roomy/log.roomy" || fail "did not continue from $latest"
wholeFrames "$work/roomy"
echo "ok: disk full at a write after $latest: one line, $latest kept and continued"
