#!/usr/bin/env bash
# Runs every case of the bad-input catalogue (catalogue.sh, beside this
# script). A case is a small broken input made from one of a few prepared
# bases (a tutorial after meshRock, voronoiMesh, a short solver run ...) plus
# what its error must say. For each case the runner asserts:
#   - exit code 1 (a user error: not 0, not 2 = internal error, not a crash),
#   - exactly one line on stderr, containing the file (or option) that is wrong
#     and the expected fragment of the explanation,
#   - no file of the case changed, appeared or disappeared (checksums).
# Usage as a ctest: runCatalogue.sh <scratch dir> [case name pattern]
source "$(dirname "$0")/../case/caseTestFunctions"
here="$(cd "$(dirname "$0")" && pwd)"
only="${2:-*}"
bases="$work/bases"
mkdir -p "$bases"

quiet() { "$@" > /dev/null 2>&1 || fail "preparing the bases: '$*' failed"; }

# ---- Bases ---------------------------------------------------------------------
prepareBases()
{
    copyTutorial tutorials/BDT/granite "$bases/disc"               # pristine DEM tutorial
    cp -r "$bases/disc" "$bases/meshed"                            # after meshRock
    quiet meshRock -case "$bases/meshed"
    cp -r "$bases/meshed" "$bases/dem"                             # after voronoiMesh
    caseDict -case "$bases/dem" system/voronoiMeshDict -entry nCells -set 60 > /dev/null
    caseDict -case "$bases/dem" system/voronoiMeshDict -entry pruningDistance -set 3e-3 > /dev/null
    quiet voronoiMesh -case "$bases/dem"
    cp -r "$bases/dem" "$bases/demRun"                             # after a 20-step run
    caseDict -case "$bases/demRun" system/controlDict -entry endTime -set 2e-6 > /dev/null
    caseDict -case "$bases/demRun" system/controlDict -entry writeInterval -set 1e-6 > /dev/null
    quiet bondedDemFoam -case "$bases/demRun"
    copyTutorial tutorials/BDT/graniteFEM "$bases/fem"             # after meshRock, coarse
    caseDict -case "$bases/fem" system/feMeshDict -entry elementSize -set 4e-3 > /dev/null
    cp -r "$bases/fem" "$bases/femNoMesh"
    quiet meshRock -case "$bases/fem"
    mkdir -p "$bases/empty"                                        # a directory, nothing in it
    mkdir -p "$bases/lab"                                          # measured data, a .dat file
    cp "$src/cases/experiments/BDT/granite/measurements" "$bases/lab/measurements"
    cp "$bases/demRun/postProcessing/plateForce/0/plateForce.dat" "$bases/lab/plateForce.dat"
    cp -r "$src/tutorials/CH660/geometry" "$bases/crusher"
    copyTutorial tutorials/CH660/tiny "$bases/crusherFeed"          # liners and feed rocks meshed
    quiet meshCrusher -case "$bases/crusherFeed"
    quiet meshRock -case "$bases/crusherFeed/feedRock"
    quiet voronoiMesh -case "$bases/crusherFeed/feedRock"
    cp -r "$bases/crusherFeed/feedRock" "$bases/crusherFeed/feedRockB"
}

# ---- One case ------------------------------------------------------------------
nCases=0
nChecked=0
failed=()
# badCase <name> <base> <names> <expected> <command...>, with the setup script
# (bash, run inside the case copy) on stdin. <names>: what the message must
# name (the file or option at fault); <expected>: a fragment of the rest.
badCase()
{
    local name="$1" base="$2" names="$3" expected="$4"; shift 4
    local setup; setup="$(cat)"
    nCases=$((nCases + 1))
    # shellcheck disable=SC2053
    [[ "$name" == $only ]] || return 0
    # In a subshell, so that a failing case is reported and the others still run.
    if (checkCase "$name" "$base" "$names" "$expected" "$setup" "$@"); then
        nChecked=$((nChecked + 1))
    else
        failed+=("$name")
    fi
}

checkCase()
{
    local name="$1" base="$2" names="$3" expected="$4" setup="$5"; shift 5
    local dir="$work/cases/$name"
    rm -rf "$dir"; mkdir -p "$(dirname "$dir")"
    cp -r "$bases/$base" "$dir"
    (cd "$dir" && eval "$setup") > /dev/null 2>&1 || fail "$name: the setup failed"
    local before after err rc=0
    before=$(snapshot "$dir")
    err=$(cd "$dir" && "$@" 2>&1 > /dev/null) || rc=$?
    after=$(snapshot "$dir")
    [ "$rc" -eq 1 ] || fail "$name: '$*' exited $rc, expected 1 (stderr: $err)"
    [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] || fail "$name: more than one line on stderr: $err"
    case "$err" in *"$names"*) ;; *) fail "$name: message '$err' does not name '$names'" ;; esac
    case "$err" in *"$expected"*) ;; *) fail "$name: message '$err' lacks '$expected'" ;; esac
    [ "$before" = "$after" ] || fail "$name: the failed run changed the case: $(diff <(echo "$before") <(echo "$after") | head -5)"
    printf 'ok %-28s %s\n' "$name" "$err"
}

start=$SECONDS
prepareBases
echo "bases ready in $((SECONDS - start)) s"
source "$here/catalogue.sh"
[ "${#failed[@]}" -eq 0 ] || fail "${#failed[@]} case(s) failed: ${failed[*]}"
[ "$nChecked" -gt 0 ] || fail "no case matched '$only'"
echo "bad-input catalogue: $nChecked of $nCases cases ok in $((SECONDS - start)) s"
