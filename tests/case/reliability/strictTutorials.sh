#!/usr/bin/env bash
# No tutorial or shipped case has an entry its applications do not know (issue 41 item 8):
#   1. caseDict -check is clean (exit 0) on every case and study directory of tutorials/ and
#      cases/, and exits 1 naming file:line and the nearest entry on a misspelt copy;
#   2. the applications themselves, run with -strict on copies of the tutorials (meshes made
#      as small as the check needs, the solvers with -dry-run), print no warning and succeed;
#   3. without -strict a misspelt entry is one warning line and the run goes on (exit 0).
source "$(dirname "$0")/../caseTestFunctions"

# 1. caseDict -check over every directory that holds a system/ dictionary.
checked=0
while IFS= read -r dir; do
    err=$(caseDict -case "$src/$dir" -check 2>&1 > /dev/null) || fail "caseDict -check $dir: $err"
    checked=$((checked + 1))
done < <(cd "$src" && find tutorials cases -type d -name system -printf '%h\n' | sort)
[ "$checked" -gt 30 ] || fail "only $checked case directories found under tutorials/ and cases/"
echo "ok: caseDict -check is clean on $checked case and study directories"
copyTutorial tutorials/BDT/granite "$work/typo"
sed -i 's/^writeInterval /writeIntervall /' "$work/typo/system/controlDict"
expectUserError "did you mean 'writeInterval'?" caseDict -case "$work/typo" -check
listed=$(caseDict -case "$work/typo" -check 2>/dev/null) && fail "caseDict -check exited 0 on a misspelt case"
grep -q "system/controlDict:[0-9]*:[0-9]*: unknown entry 'writeIntervall'" <<< "$listed" ||
    fail "caseDict -check does not list the entry with its file:line: $listed"

# strict <command...>: exit 0 and nothing on stderr.
strict()
{
    local err rc=0
    err=$("$@" -strict 2>&1 > /dev/null) || rc=$?
    [ "$rc" -eq 0 ] || fail "'$* -strict' exited $rc: $err"
    [ -z "$err" ] || fail "'$* -strict' wrote to stderr: $err"
}

# 2. The applications with -strict. DEM cases: the specimen, a small mesh, the solver's check.
demCase()
{
    local case="$1"
    strict meshRock -case "$case"
    caseDict -case "$case" system/voronoiMeshDict -entry nCells -remove > /dev/null 2>&1 || true
    caseDict -case "$case" system/voronoiMeshDict -entry mesoConstant -remove > /dev/null 2>&1 || true
    caseDict -case "$case" system/voronoiMeshDict -entry nCells -add 40 > /dev/null
    caseDict -case "$case" system/voronoiMeshDict -entry pruningDistance -set 0 > /dev/null
    strict voronoiMesh -case "$case"
}
femCase()
{
    local case="$1"
    caseDict -case "$case" system/feMeshDict -entry elementSize -set 6e-3 > /dev/null
    strict meshRock -case "$case"
}
n=0
for t in BDT/granite BDT/limestone SPB/granite/template SPB/limestone/template explainGap/bdt \
         explainGap/spb explainGap/spbVsFem/dem explainGap/paperSPB/model; do
    copyTutorial "tutorials/$t" "$work/dem$n"
    demCase "$work/dem$n"
    strict bondedDemFoam -case "$work/dem$n" -dry-run
    n=$((n + 1))
done
for t in BDT/graniteFEM BDT/limestoneFEM SPB/graniteFEM/template explainGap/spbVsFem/fem; do
    copyTutorial "tutorials/$t" "$work/fem$n"
    femCase "$work/fem$n"
    strict feFractureSolver -case "$work/fem$n" -dry-run
    n=$((n + 1))
done
for c in granite limestone; do  # the calibration studies' member cases
    cp -r "$src/cases/calibration/$c/bdt" "$work/cal$c"
    demCase "$work/cal$c"
    strict bondedDemFoam -case "$work/cal$c" -dry-run
    cp -r "$src/cases/calibration/${c}FEM/bdt" "$work/cal${c}FEM"
    femCase "$work/cal${c}FEM"
    strict feFractureSolver -case "$work/cal${c}FEM" -dry-run
done
# The crusher: liners, the feed rock, the solver's check, the post-processing dictionary.
copyTutorial tutorials/CH660/tiny "$work/crusher"
strict meshCrusher -case "$work/crusher"
demCase "$work/crusher/feedRock"
strict bondedDemFoam -case "$work/crusher" -dry-run
for t in full reduced; do strict meshCrusher -case "$src/tutorials/CH660/$t" -dry-run; done
# The size-resolved feed: its three templates and its feed classes.
copyTutorial tutorials/CH660/sizeResolved "$work/classes"
strict meshCrusher -case "$work/classes"
for rock in feedRock feedRockMedium feedRockFine; do demCase "$work/classes/$rock"; done
strict bondedDemFoam -case "$work/classes" -dry-run
# The studies: calibrateModel reads all its inputs; explainGap and makeTwinData stop at the
# measurements or cases their tutorials make first, after the dictionary is checked.
for c in granite graniteFEM limestone limestoneFEM; do strict calibrateModel -case "$src/cases/calibration/$c" -dry-run; done
while IFS= read -r dir; do
    app=explainGap
    [ -f "$src/$dir/system/twinDataDict" ] && app=makeTwinData
    err=$("$app" -case "$src/$dir" -dry-run -strict 2>&1 > /dev/null) || true
    case "$err" in *"unknown entry"*|*warning*) fail "$app -strict on $dir: $err" ;; esac
done < <(cd "$src" && find tutorials -path '*/system/explainGapDict' -o -path '*/system/twinDataDict' |
         sed 's|/system/[a-zA-Z]*$||' | sort)
echo "ok: meshRock, voronoiMesh, meshCrusher, bondedDemFoam, feFractureSolver, calibrateModel, explainGap and makeTwinData -strict on the tutorials"

# 3. Without -strict: one warning line naming file:line and the nearest entry; the run goes on.
copyTutorial tutorials/BDT/granite "$work/warn"
echo 'discs { }' >> "$work/warn/system/meshRockDict"
rc=0
err=$(meshRock -case "$work/warn" -dry-run 2>&1 > /dev/null) || rc=$?
[ "$rc" -eq 0 ] || fail "an unknown entry without -strict stopped meshRock (exit $rc): $err"
[ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] || fail "expected one warning line, got: $err"
case "$err" in
    "meshRock: warning: "*"system/meshRockDict:"*"unknown entry 'discs'"*"did you mean 'disc'?"*"ignored"*"-strict"*) ;;
    *) fail "the warning does not name file:line, the entry, the nearest one and -strict: $err" ;;
esac
echo "ok: without -strict: $err"
expectUserError "did you mean 'disc'?" meshRock -case "$work/warn" -dry-run -strict
echo "strictTutorials: every tutorial is clean under -strict"
