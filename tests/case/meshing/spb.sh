#!/usr/bin/env bash
# The 14 SPB rocks: cell counts exactly as Table 7 from the meso constant.
source "$(dirname "$0")/../caseTestFunctions"
declare -A expected=(
  [granite]="376 312 206 339 211 372 198"
  [limestone]="353 280 381 408 243 349 298")
for rock in granite limestone; do
    copyTutorial "tutorials/SPB/$rock" "$work/$rock"
    "$work/$rock/Allrun" -meshOnly > "$work/$rock.log"
    i=1
    for n in ${expected[$rock]}; do
        log="$work/$rock/rock$i/log.voronoiMesh"
        grep -q "voronoiMesh: $n cells" "$log" || fail "$rock rock$i: expected $n cells: $(grep voronoiMesh: "$log")"
        checkVtk "$work/$rock/rock$i/VTK/voronoiMesh.vtu" polyhedra "$n"
        i=$((i + 1))
    done
done
echo "SPB meshing ok"
