#!/usr/bin/env bash
# feFractureSolver refuses bad input before the run: exit code 1, one line, nothing written.
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/BDT/graniteFEM "$work/case"
cd "$work/case"
caseDict -case . system/feMeshDict -entry elementSize -set 4e-3 > /dev/null
expectUserError "run meshRock" feFractureSolver -case .
meshRock > log.meshRock

variant() { rm -rf "$work/$1"; cp -r "$work/case" "$work/$1"; echo "$work/$1"; }

v=$(variant material); caseDict -case "$v" constant/rockProperties -entry material -set kstDFH > /dev/null
expectUserError "kstDfh" feFractureSolver -case "$v"
v=$(variant weibull); caseDict -case "$v" constant/rockProperties -entry kstDfh/dfh/weibullModulus -set 0 > /dev/null
expectUserError "weibullModulus" feFractureSolver -case "$v"
v=$(variant erosion); caseDict -case "$v" constant/rockProperties -entry kstDfh/dfh/erodeAfterCracks -add 1.5 > /dev/null
expectUserError "erodeAfterCracks" feFractureSolver -case "$v"
v=$(variant fractureEnergy); caseDict -case "$v" constant/rockProperties -entry kstDfh/dfh/fractureEnergy -set "[N/m] -30" > /dev/null
expectUserError "fractureEnergy" feFractureSolver -case "$v"
v=$(variant fractureEnergyUnits); caseDict -case "$v" constant/rockProperties -entry kstDfh/dfh/fractureEnergy -set "[Pa] 30" > /dev/null
expectUserError "fractureEnergy" feFractureSolver -case "$v"
v=$(variant gap); caseDict -case "$v" constant/loading -entry plates/startGap -set 1 > /dev/null
expectUserError "never touches the specimen" feFractureSolver -case "$v"
v=$(variant units); caseDict -case "$v" constant/rockProperties -entry rock/E -set "[m] 77e9" > /dev/null
expectUserError "E" feFractureSolver -case "$v"
# An inverted element: swap two nodes of the first tetrahedron in the mesh file (msh 4 ASCII:
# $Elements, a count line, then blocks "dim tag type n" of n element lines; tets are type 4).
v=$(variant inverted)
awk '/^\$Elements/ { inside = 1; print; getline; print; next }
     inside && left == 0 && NF == 4 { type = $3; left = $4; print; next }
     inside && left > 0 { left--; if (type == 4 && !done) { a = $2; $2 = $3; $3 = a; done = 1 } }
     /^\$EndElements/ { inside = 0 }
     { print }' "$work/case/constant/feMesh/specimen.msh" > "$v/constant/feMesh/specimen.msh"
cmp -s "$v/constant/feMesh/specimen.msh" "$work/case/constant/feMesh/specimen.msh" && fail "could not invert an element"
expectUserError "inverted" feFractureSolver -case "$v"
for d in material weibull erosion fractureEnergy fractureEnergyUnits gap units inverted; do
    [ ! -d "$work/$d/0" ] && [ ! -e "$work/$d/VTK/fem_0.vtu" ] || fail "$d: a refused run wrote output"
done
echo "bad input ok"
