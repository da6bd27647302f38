#!/usr/bin/env bash
# Dense and concave STL scans through meshRock and voronoiMesh: an icosphere of 5 120 triangles
# (radius 20 mm) has a convex hull of 5 120 planes, more than Voro++ takes as walls (2 048):
# voronoiMesh clips the cells by them and the cells fill the hull (volume error below 1e-6 %);
# the same sphere with its cap folded into a crater (hull 45 % larger than the scan) is meshed
# with a warning naming both volumes. Several shells and self-crossing scans are refused
# (tests/badInput/catalogue.sh: stlTwoShells, stlCrossesItself).
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/BDT/granite "$work/base"
mkdir -p "$work/base/constant/triSurface"
cat > "$work/base/system/meshRockDict" <<'DICT'
FoamFile { format ascii; class dictionary; object meshRockDict; }
geometry stl;
stl { file "constant/triSurface/rock.stl"; scale 1e-3; }
DICT
# icosphere <kind: sphere|dented> <subdivisions> <file>
icosphere() { python3 "$src/tests/case/meshing/icosphere.py" "$@"; }

cp -r "$work/base" "$work/dense"
cd "$work/dense"
icosphere sphere 4 constant/triSurface/rock.stl
meshRock > log.meshRock 2>&1 || fail "meshRock failed on the dense sphere: $(tail -3 log.meshRock)"
grep -q "convex hull: 5120 planes, 5120 triangles" log.meshRock || fail "not a 5120-plane hull: $(grep 'convex hull' log.meshRock)"
voronoiMesh > log.voronoiMesh 2>&1 || fail "voronoiMesh failed on a 5120-plane hull: $(tail -3 log.voronoiMesh)"
error=$(sed -n 's/.*volume error \([^ ]*\) %.*/\1/p' log.voronoiMesh)
awk -v e="$error" 'BEGIN { exit !(e != "" && (e < 0 ? -e : e) < 1e-6) }' || fail "volume error $error %"
echo "dense: a 5120-plane hull meshed into $(sed -n 's/^voronoiMesh: \([0-9]*\) cells.*/\1/p' log.voronoiMesh) cells, volume error $error %"

cp -r "$work/base" "$work/dented"
cd "$work/dented"
icosphere dented 3 constant/triSurface/rock.stl
meshRock > log.meshRock 2>&1 || fail "meshRock failed on the dented sphere: $(tail -3 log.meshRock)"
grep -q "^Warning: the convex hull (.* mm^3) is 4[0-9].[0-9] % larger than the scan (.* mm^3)" log.meshRock ||
    fail "no warning for a hull 45 % larger than the scan: $(grep -i 'hull' log.meshRock)"
echo "dented: $(grep '^Warning' log.meshRock | cut -c1-100)"
