#!/usr/bin/env bash
# Odd STL scans and what each gets (issue 40). Here:
#   - a user's scan as a rock of the SPB tutorials' ./rocks (`<rock> { stl "<file>"; scale 1e-3; }`,
#     makeRockCase): a scan-like noisy icosphere through the DEM tutorial (5 120 triangles, a
#     3 476-facet hull: meshRock, voronoiMesh, bondedDemFoam -dry-run) and the FEM one at its
#     -coarse settings (20 480 triangles, a 6 188-facet hull; 4 mm tetrahedra, mass scaled to a
#     1e-7 s step): its sliver-rich mesh adds ~58 % mass and feFractureSolver warns with where
#     the small elements are;
#   - the tutorial's rock 7 at the same settings adds 1.3 %: no warning;
#   - a denser scan (20 480 triangles) in the DEM: cores of more than 255 vertices refused, exit 1;
#   - a scan with collapsed (zero-area) triangles: dropped with a warning, exit 0.
# Elsewhere: dense (case.meshing.denseScan: a 5 120-facet hull meshed; a concave scan warned);
# refused with exit 1 and one message (case.badInput.catalogue): open (stlHole), unwelded
# near-duplicate vertices (stlNearDuplicateVertices), several shells (stlTwoShells), crossing
# itself (stlCrossesItself), zero-area needles (stlZeroAreaNeedle), flat (stlFlatSheet,
# stlFlatTetrahedron).
source "$(dirname "$0")/../caseTestFunctions"
icosphere() { python3 "$src/tests/case/meshing/icosphere.py" "$@"; }
# addScanRock <subdivisions>: the noisy icosphere as rock `noisy` of ./rocks.
addScanRock() { mkdir -p scans && icosphere noisy "$1" scans/noisy.stl && echo 'noisy { stl "scans/noisy.stl"; scale 1e-3; }' >> rocks; }
runLogged() { "$@" > "log.$1" 2>&1 || fail "$* failed in $PWD: $(tail -3 "log.$1")"; }

# The DEM tutorial takes the scan: its case, its cells and a solver set-up.
copyTutorial tutorials/SPB/granite "$work/spb"
cd "$work/spb"
source "$src/utilities/RunFunctions" > /dev/null || fail "RunFunctions"
addScanRock 4
makeRockCase noisy > log.makeRockCase 2>&1 || fail "makeRockCase noisy: $(tail -3 log.makeRockCase)"
cd noisy
cmp constant/triSurface/rock.stl ../scans/noisy.stl || fail "the scan was not copied into the case"
[ "$(caseDict -case . system/meshRockDict -entry geometry -value)" = stl ] || fail "geometry is not stl"
runLogged meshRock
grep -q "convex hull: 3476 planes" log.meshRock || fail "not the scan's hull: $(grep 'convex hull' log.meshRock)"
grep -q "hull/scan volume ratio 1.00" log.meshRock || fail "hull/scan: $(grep 'ratio' log.meshRock)"
runLogged voronoiMesh
runLogged bondedDemFoam -dry-run
echo "DEM: $(grep -m1 '^voronoiMesh: ' log.voronoiMesh | cut -c1-100)"
# A denser scan (20 480 triangles, a 6 188-facet hull) gives cells whose cores have more
# than 255 vertices: bondedDemFoam refuses them with one message, exit 1.
cd "$work/spb"
icosphere noisy 5 scans/dense.stl && echo 'dense { stl "scans/dense.stl"; scale 1e-3; }' >> rocks
makeRockCase dense > log.makeRockCase.dense 2>&1 || fail "makeRockCase dense: $(tail -3 log.makeRockCase.dense)"
cd dense && runLogged meshRock && runLogged voronoiMesh
expectUserError "decimate the scan" bondedDemFoam -dry-run

# The FEM tutorial at its -coarse settings: the scan's mesh warns, the tutorial rock does not.
coarse() { setEntry system/feMeshDict elementSize 4e-3 && setEntry system/controlDict massScalingTimeStep 1e-7; }
copyTutorial tutorials/SPB/graniteFEM "$work/spbFem"
cd "$work/spbFem"
addScanRock 5
for rock in noisy rock7; do
    makeRockCase "$rock" coarse > "log.makeRockCase.$rock" 2>&1 || fail "makeRockCase $rock"
    (cd "$rock" && runLogged meshRock && OMP_NUM_THREADS=1 runLogged feFractureSolver -dry-run) || exit 1
done
added() { sed -n 's/.*added mass \([0-9.e+-]*\) %.*/\1/p' "$1/log.feFractureSolver"; }
warning=$(grep '^Warning: mass scaling adds' noisy/log.feFractureSolver) ||
    fail "no added-mass warning for the scan ($(added noisy) % added)"
awk -v a="$(added noisy)" 'BEGIN { exit !(a > 10) }' || fail "the scan adds $(added noisy) %"
for part in "elements are below the 1e-07 s step target" "of the added mass in elements with a face on the surface" \
    "smallest altitude" "elementSize in system/feMeshDict"; do
    [[ "$warning" == *"$part"* ]] || fail "the warning lacks '$part': $warning"
done
echo "FEM scan: ${warning:0:160}..."
! grep -q '^Warning: mass scaling' rock7/log.feFractureSolver || fail "a warning for rock 7: $(added rock7) %"
awk -v a="$(added rock7)" 'BEGIN { exit !(a > 0 && a < 10) }' || fail "rock 7 adds $(added rock7) %"
echo "FEM rock 7: $(added rock7) % added, no warning"

# Collapsed triangles (two corners welded into one point): dropped, with a warning.
copyTutorial tutorials/BDT/granite "$work/collapsed"
cd "$work/collapsed"
mkdir -p constant/triSurface
cat > system/meshRockDict <<'DICT'
FoamFile { format ascii; class dictionary; object meshRockDict; }
geometry stl;
stl { file "constant/triSurface/rock.stl"; scale 1e-3; }
DICT
{
    echo "solid collapsed"
    for f in "10 0 0|0 10 0|0 0 10" "0 10 0|-10 0 0|0 0 10" "-10 0 0|0 -10 0|0 0 10" "0 -10 0|10 0 0|0 0 10" \
        "0 10 0|10 0 0|0 0 -10" "-10 0 0|0 10 0|0 0 -10" "0 -10 0|-10 0 0|0 0 -10" "10 0 0|0 -10 0|0 0 -10" \
        "10 0 0|10 0 0|0 10 0" "0 0 10|0 0 10|0 0 10"; do
        IFS='|' read -r a b c <<< "$f"
        printf 'facet normal 0 0 0\nouter loop\nvertex %s\nvertex %s\nvertex %s\nendloop\nendfacet\n' "$a" "$b" "$c"
    done
    echo "endsolid collapsed"
} > constant/triSurface/rock.stl
runLogged meshRock
grep -q "^Warning: 2 zero-area triangles of the scan .* were dropped" log.meshRock ||
    fail "no warning for 2 collapsed triangles: $(grep -i 'warn' log.meshRock)"
grep -q "Specimen: stl, volume 1.33333e-06 m^3" log.meshRock || fail "not the octahedron: $(grep Specimen log.meshRock)"
echo "collapsed: $(grep '^Warning' log.meshRock)"
