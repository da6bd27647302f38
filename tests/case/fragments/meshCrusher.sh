#!/usr/bin/env bash
# meshCrusher on the CH660 tutorial: CSS 38 mm and OSS 64 mm printed, the STL and VTK
# surfaces with the documented counts, constant/crusherKinematics readable; bad input refused.
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/CH660/geometry "$work/ch660"
cd "$work/ch660"
before=$(snapshot .)
meshCrusher -dry-run > "$work/log.dry" 2>&1 || fail "meshCrusher -dry-run failed: $(tail -3 "$work/log.dry")"
[ "$(snapshot .)" = "$before" ] || fail "meshCrusher -dry-run changed the case"
./Allrun > /dev/null || fail "Allrun failed: $(tail -3 log.meshCrusher)"
grep -q "Closed side setting 38.00 mm" log.meshCrusher || fail "CSS is not 38.00 mm: $(grep Closed log.meshCrusher)"
grep -q "open side setting 64.00 mm" log.meshCrusher || fail "OSS is not 64.00 mm"
# 360 segments, well-shaped triangles (revolveProfileShaped: rings of 360 points on the
# outer half of the radii, fewer towards the axis, rows 0.87 x the spacing apart; the
# unit test tests/unit/crusher checks their shape): 114098 and 61920 triangles (with the undersides at the discharge; 108338 and 56880 before 2026-12-03).
checkVtk VTK/mantle.vtp triangles 114098 || fail "VTK/mantle.vtp"
checkVtk VTK/concave.vtp triangles 61920 || fail "VTK/concave.vtp"
[ "$(grep -c "facet normal" constant/triSurface/mantle.stl)" -eq 114098 ] || fail "mantle.stl triangle count"
[ "$(grep -c "facet normal" constant/triSurface/concave.stl)" -eq 61920 ] || fail "concave.stl triangle count"
angle=$(caseDict -case . constant/crusherKinematics -entry eccentricAngle -value)
awk -v a="$angle" 'BEGIN { exit !(a > 0.007 && a < 0.010) }' || fail "eccentric angle $angle rad"
echo "ok: CH660 surfaces, CSS 38 mm, OSS 64 mm, eccentric angle $angle rad"
./Allclean && [ ! -e constant ] && [ ! -e VTK ] || fail "Allclean left outputs"

caseDict -case . system/meshCrusherDict -entry closedSideSetting -set 0.5 > /dev/null
expectUserError "meshCrusherDict: the concave cannot be placed at closedSideSetting" meshCrusher
caseDict -case . system/meshCrusherDict -entry closedSideSetting -set 0.038 > /dev/null
caseDict -case . system/meshCrusherDict -entry nSegments -set 2 > /dev/null
expectUserError "nSegments must be at least 3" meshCrusher
