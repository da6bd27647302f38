#!/usr/bin/env bash
# The BDT tutorial meshes: disc surface, Voronoi cells and bonds; the VTK files
# are read back by VTK's readers (checkVtk) and their counts and volumes checked.
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/BDT/granite "$work/case"
cd "$work/case"
./Allrun
grep -q "voronoiMesh: 300 cells" log.voronoiMesh || fail "expected 300 cells: $(tail -3 log.voronoiMesh)"
checkVtk VTK/voronoiMesh.vtu polyhedra 300 volume 2.1753e-5 0.005
checkVtk VTK/bonds.vtp lines "$(caseDict -case . constant/voronoiMesh/meshInfo -entry nBonds -value)"
checkVtk VTK/specimen.vtp triangles 512
# Same seed, same mesh: a second run in a copy gives identical mesh files.
cp -r "$work/case" "$work/again" && cd "$work/again" && rm -rf log.voronoiMesh constant/voronoiMesh
runApp() { voronoiMesh -case . > log.voronoiMesh; }
runApp
for f in "$work"/case/constant/voronoiMesh/*; do
    cmp -s "$f" "constant/voronoiMesh/$(basename "$f")" || fail "$(basename "$f") differs between two runs with the same seed"
done
echo "BDT meshing ok"

# Tetrahedra for the FEM solver through gmsh, on request (system/feMeshDict).
cd "$work/case"
cat > system/feMeshDict <<'DICT'
FoamFile { format ascii; class dictionary; object feMeshDict; }
elementSize 3e-3;
DICT
meshRock > log.meshRock.fe 2>&1 || fail "meshRock with feMeshDict failed: $(tail -3 log.meshRock.fe)"
grep -q "Tetrahedral mesh:" log.meshRock.fe || fail "no tetrahedral mesh report"
[ -s constant/feMesh/specimen.msh ] || fail "no constant/feMesh/specimen.msh"
nTets=$(sed -n 's/^Tetrahedral mesh: \([0-9]*\) tets.*/\1/p' log.meshRock.fe)
checkVtk VTK/feMesh.vtu tets "$nTets" volume 2.1753e-5 0.01
echo "feMesh ok ($nTets tets)"
