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
icosphere() {
    python3 - "$@" <<'PY'
import math, sys
kind, n, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
t = (1 + 5 ** 0.5) / 2
V = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
     (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
     (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7),
     (9, 8, 1)]
unit = lambda v: tuple(c / math.sqrt(sum(x * x for x in v)) for c in v)
V = [unit(v) for v in V]
for _ in range(n):
    middle, G = {}, []
    def mid(a, b):
        k = (min(a, b), max(a, b))
        if k not in middle:
            V.append(unit(tuple((V[a][i] + V[b][i]) / 2 for i in range(3))))
            middle[k] = len(V) - 1
        return middle[k]
    for a, b, c in F:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        G += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    F = G
R = 20.0
P = []
for v in V:
    p = [R * c for c in v]
    if kind == "dented" and v[2] > 0.3:
        p[2] = R * 0.3 - (R * v[2] - R * 0.3) * 0.8  # the cap folded inwards: a crater
    P.append(p)
with open(out, "w") as f:
    f.write("solid rock\n")
    for tri in F:
        f.write("facet normal 0 0 0\nouter loop\n")
        for i in tri:
            f.write("vertex %.9g %.9g %.9g\n" % tuple(P[i]))
        f.write("endloop\nendfacet\n")
    f.write("endsolid rock\n")
PY
}

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
