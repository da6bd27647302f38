#!/usr/bin/env bash
# bondedDemFoam refuses bad input before the run: exit code 1, one line, nothing written.
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/BDT/granite "$work/case"
cd "$work/case"
meshRock > log.meshRock
expectUserError "run voronoiMesh first" bondedDemFoam -case .
voronoiMesh > log.voronoiMesh

variant() { rm -rf "$work/$1"; cp -r "$work/case" "$work/$1"; echo "$work/$1"; }

v=$(variant contact); caseDict -case "$v" constant/rockProperties -entry contact/model -set hertzMindlinn > /dev/null
expectUserError "hertzMindlin" bondedDemFoam -case "$v"
v=$(variant strength); caseDict -case "$v" constant/rockProperties -entry bond/voronoiQNSC/tensileStrength -set -28e6 > /dev/null
expectUserError "tensileStrength" bondedDemFoam -case "$v"
v=$(variant bondModel); caseDict -case "$v" constant/rockProperties -entry bond/model -set springs > /dev/null
expectUserError "voronoiQNSC" bondedDemFoam -case "$v"
v=$(variant speed); caseDict -case "$v" constant/loading -entry plates/upper/velocity -set "(0 0 0)" > /dev/null
expectUserError "stop criterion can never be met" bondedDemFoam -case "$v"
v=$(variant poisson); caseDict -case "$v" constant/rockProperties -entry rock/poissonRatio -set 0.5 > /dev/null
expectUserError "poissonRatio" bondedDemFoam -case "$v"
v=$(variant units); caseDict -case "$v" constant/rockProperties -entry bond/voronoiQNSC/E -set "[0 1 0 0 0 0 0] 46e9" > /dev/null
expectUserError "E" bondedDemFoam -case "$v"
for d in contact strength bondModel speed poisson units; do
    [ ! -d "$work/$d/0" ] && [ ! -e "$work/$d/VTK/cells_0.vtu" ] || fail "$d: a refused run wrote output"
done
echo "bad input ok"
