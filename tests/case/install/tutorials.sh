#!/usr/bin/env bash
# Every tutorial runs where it is copied (cp -r, the OpenFOAM habit), once etc/bashrc is
# sourced: no links under tutorials/ or cases/; no dictionary names a file outside its
# tutorial (the nearest directory with an Allrun; measured data is copied in by the Allrun,
# copyMeasurements, from $ROCKFRAC_DIR/cases/experiments); the scripts find RunFunctions
# through ROCKFRAC_DIR or their own depth in the tree, name other tutorials only through
# tutorialCase (which falls back on $ROCKFRAC_TUTORIALS) and copy only measurements that
# exist; the rocks of the FEM and explainGap tutorials are those of the DEM tutorials. And
# each script, copied with its tutorial outside the tree and run without the environment,
# stops with one line saying to source etc/bashrc (or, for the Allclean scripts that need
# nothing of rockfrac's, cleans).
source "$(dirname "$0")/../caseTestFunctions"
cd "$src"

links=$(find tutorials cases -type l)
[ -z "$links" ] || fail "links (cp -r copies them as links, dangling outside the tree): $links"
echo "ok: no links under tutorials/ and cases/"

# tutorialOf <path>: the nearest directory above <path> with an Allrun.
tutorialOf()
{
    local d
    d=$(dirname "$1")
    while [ "$d" != tutorials ] && [ "$d" != . ]; do
        [ -f "$d/Allrun" ] && { echo "$d"; return; }
        d=$(dirname "$d")
    done
    echo "$d"
}

# Dictionaries: every quoted relative path with a ../ (outside comments), resolved from its
# case (the directory holding system/ and constant/), stays in the tutorial.
n=0
while IFS= read -r f; do
    case "$f" in */Allrun|*/Allclean|*.gp|*.edp) continue ;; esac
    caseDir=$(dirname "$f")
    case "$caseDir" in */system|*/constant) caseDir=$(dirname "$caseDir") ;; esac
    tutorial=$(tutorialOf "$f")
    while IFS= read -r path; do
        resolved=$(realpath -m --relative-to=. "$caseDir/$path")
        case "$resolved/" in
            "$tutorial/"*) n=$((n + 1)) ;;
            *) fail "$f: \"$path\" is $resolved, outside the tutorial $tutorial: copy the file in from its Allrun" ;;
        esac
    done < <(sed 's#//.*##' "$f" | grep -o '"\.\./[^"]*"' | tr -d '"')
done < <(find tutorials -type f | LC_ALL=C sort)
echo "ok: the $n relative paths of the tutorials' dictionaries stay in their tutorials"

# Scripts.
n=0
for script in $(find tutorials -name Allrun -o -name Allclean | LC_ALL=C sort); do
    n=$((n + 1))
    dir=$(dirname "$script")
    up=$(realpath -m --relative-to="$dir" .)
    if grep -q RunFunctions "$script"; then
        grep -qxF "rf=\"\${ROCKFRAC_DIR:-$up}/utilities/RunFunctions\"  # ROCKFRAC_DIR: set by etc/bashrc" "$script" ||
            fail "$script: RunFunctions is not found through \${ROCKFRAC_DIR:-$up} (see tutorials/BDT/granite/Allrun)"
    fi
    # ../ outside comments and the RunFunctions line: only tutorialCase <dir> <tutorial>.
    other=$(grep -v '^ *#' "$script" | grep -v '^rf="\${ROCKFRAC_DIR' | grep '\.\./' | grep -v 'tutorialCase \.\./' || true)
    [ -z "$other" ] || fail "$script names a file outside itself (use tutorialCase or copyMeasurements): $other"
    while read -r sibling tutorial; do
        [ "$(realpath -m --relative-to=. "$dir/$sibling")" = "tutorials/$tutorial" ] && [ -d "tutorials/$tutorial/system" ] ||
            fail "$script: tutorialCase $sibling $tutorial: $dir/$sibling is not the case tutorials/$tutorial"
    done < <(grep -o 'tutorialCase [^ )]* [^ )]*' "$script" | cut -d' ' -f2-)
    for experiment in $(grep -o 'copyMeasurements [^ ]*' "$script" | cut -d' ' -f2); do
        [ -f "cases/experiments/$experiment/measurements" ] ||
            fail "$script: copyMeasurements $experiment: no cases/experiments/$experiment/measurements"
    done
done
echo "ok: the $n Allrun and Allclean scripts find RunFunctions and name nothing outside themselves"

# The rocks: one set per rock type, whatever tutorial reads it.
rockLines() { grep '^rock[0-9]' "$1" | tr -s ' '; }
for rock in granite limestone; do
    explain=paperSPB; [ "$rock" = limestone ] && explain=paperSPBLimestone
    for copy in "tutorials/SPB/${rock}FEM/rocks" "tutorials/explainGap/$explain/model/constant/rocks"; do
        [ "$(rockLines "tutorials/SPB/$rock/rocks")" = "$(rockLines "$copy")" ] ||
            fail "$copy holds other rocks than tutorials/SPB/$rock/rocks"
    done
done
echo "ok: the FEM and explainGap tutorials hold the rocks of the DEM tutorials"

# Copied without the environment (env -i, the PATH of a new login): one line naming
# etc/bashrc and exit 1, or (an Allclean that needs nothing of rockfrac's) exit 0.
outside=$(mktemp -d "${TMPDIR:-/tmp}/rockfrac-tutorials.XXXXXX")
trap 'rm -rf "$outside"' EXIT
for script in $(find tutorials -name Allrun -o -name Allclean | LC_ALL=C sort); do
    dir=$(dirname "$script")
    copy="$outside/$(tr / _ <<< "$dir")"
    [ -d "$copy" ] || cp -r "$dir" "$copy"
    rc=0
    err=$(env -i HOME="$outside" PATH=/usr/bin:/bin bash --noprofile --norc "$copy/$(basename "$script")" 2>&1 >/dev/null) || rc=$?
    if [ "$rc" -eq 0 ] && [ -z "$err" ] && [ "$(basename "$script")" = Allclean ]; then
        continue
    fi
    [ "$rc" -eq 1 ] && [ "$(wc -l <<< "$err")" -eq 1 ] && [[ $err == *"etc/bashrc"* ]] ||
        fail "$script copied to $copy, run without the environment: exit $rc, '$err' (expected 1 and one line naming etc/bashrc)"
done
echo "ok: every script copied outside the tree and run without the environment says to source etc/bashrc"
