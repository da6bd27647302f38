#!/usr/bin/env bash
# Bad input to meshRock and voronoiMesh: exit code 1, one clear line, nothing changed.
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/BDT/granite "$work/disc"
cd "$work/disc"

expectUserError "does not exist" meshRock -case "$work/nonexistent"   # missing case dir
mkdir -p "$work/empty/system"
expectUserError "meshRockDict" meshRock -case "$work/empty"          # missing dictionary

# A negative diameter, then an unknown geometry.
cp -r "$work/disc" "$work/negative"
caseDict -case "$work/negative" system/meshRockDict -entry disc/diameter -set -1 >/dev/null
expectUserError "diameter" meshRock -case "$work/negative"
cp -r "$work/disc" "$work/unknown"
caseDict -case "$work/unknown" system/meshRockDict -entry geometry -set sphere >/dev/null
expectUserError "sphere" meshRock -case "$work/unknown"

# An unreadable STL, and an open one.
mkdir -p "$work/stl/system" "$work/stl/constant/triSurface"
cat > "$work/stl/system/meshRockDict" <<'DICT'
FoamFile { format ascii; class dictionary; object meshRockDict; }
geometry stl;
stl { file "constant/triSurface/rock.stl"; scale 1e-3; }
DICT
echo "this is not an stl" > "$work/stl/constant/triSurface/rock.stl"
expectUserError "rock.stl" meshRock -case "$work/stl"
printf 'solid open\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid open\n' \
    > "$work/stl/constant/triSurface/rock.stl"
expectUserError "not a closed surface" meshRock -case "$work/stl"
[ ! -e "$work/stl/constant/geometryProperties" ] || fail "a failed meshRock wrote geometryProperties"

# voronoiMesh before meshRock, then impossible pruning distances.
expectUserError "run meshRock first" voronoiMesh -case "$work/disc"
meshRock -case "$work/disc" > /dev/null
before=$(snapshot "$work/disc")
caseDict -case "$work/disc" system/voronoiMeshDict -entry nCells -set 1 >/dev/null
expectUserError "at least 2 cells" voronoiMesh -case "$work/disc"
caseDict -case "$work/disc" system/voronoiMeshDict -entry nCells -set 5000 >/dev/null
caseDict -case "$work/disc" system/voronoiMeshDict -entry pruningDistance -set 3.5e-3 >/dev/null
expectUserError "pruning distance" voronoiMesh -case "$work/disc"
caseDict -case "$work/disc" system/voronoiMeshDict -entry nCells -set 300 >/dev/null
caseDict -case "$work/disc" system/voronoiMeshDict -entry pruningDistance -set 2.5e-3 >/dev/null
after=$(snapshot "$work/disc")
[ "$before" = "$after" ] || fail "a failed voronoiMesh changed files in the case"
echo "bad input ok"
