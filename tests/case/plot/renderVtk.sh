#!/usr/bin/env bash
# renderVtk: a PNG of a VTK file, headless, and beside it a ParaView state that shows the
# same file, field, range and camera. With pvpython installed (optional: ParaView), the state
# is rendered too and must give a picture; without it, the state is checked as text.
source "$(dirname "$0")/../caseTestFunctions" "$1"
cd "$work"
cp -r "$src/tutorials/BDT/granite" disc
cd disc
meshRock > log.meshRock 2>&1 || fail "meshRock"
voronoiMesh > log.voronoiMesh 2>&1 || fail "voronoiMesh"

runner=""; [ -z "${DISPLAY:-}" ] && runner="xvfb-run -a"
# Sanitized builds: Mesa's OpenGL driver (swrast_dri.so, loaded by dlopen) leaks two 56-byte
# blocks and is unloaded before LeakSanitizer reports, so they come without a library name to
# suppress (LD_DEBUG=files shows the driver destroyed at exit). Leak checking is off for
# renderVtk alone; address and undefined-behaviour errors still stop it. No effect otherwise.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
$runner renderVtk VTK/voronoiMesh.vtu -field volume -title "cell volume" -out pictures/volume.png \
    > log.renderVtk 2>&1 || fail "renderVtk: $(cat log.renderVtk)"
[ -s pictures/volume.png ] || fail "no PNG"
state=pictures/volume-paraview.py
[ -s "$state" ] || fail "no ParaView state beside the PNG"
# The state names the data by its absolute path, colours by the field over the picture's
# range, and sets the camera of the picture.
grep -q "FileName=\['$work/disc/VTK/voronoiMesh.vtu'\]" "$state" || fail "state does not name the VTK file: $(grep FileName "$state")"
grep -q "ColorBy(display, ('CELLS', 'volume'))" "$state" || fail "state does not colour by volume"
grep -q "RescaleTransferFunction(" "$state" || fail "state has no colour range"
for c in CameraPosition CameraFocalPoint CameraViewUp CameraViewAngle; do
    grep -q "view.$c = " "$state" || fail "state lacks $c"
done
if command -v python3 > /dev/null; then
    python3 -c "import ast, sys; ast.parse(open(sys.argv[1]).read())" "$state" || fail "state is not valid Python"
fi
if command -v pvpython > /dev/null; then
    $runner pvpython "$state" "$work/paraview.png" > log.pvpython 2>&1 || fail "pvpython: $(tail -3 log.pvpython)"
    [ -s "$work/paraview.png" ] || fail "pvpython wrote no picture from the state"
    echo "ok: ParaView rendered the state ($(stat -c %s "$work/paraview.png") bytes)"
else
    echo "note: no pvpython (python3-paraview cannot coexist with libvtk9-dev on Debian 12); state checked as text"
fi

# -noState: the PNG alone.
$runner renderVtk VTK/voronoiMesh.vtu -out pictures/plain.png -noState > /dev/null 2>&1 || fail "renderVtk -noState"
[ -s pictures/plain.png ] || fail "no PNG with -noState"
[ ! -e pictures/plain-paraview.py ] || fail "-noState wrote a state"
echo "renderVtk: PNG and ParaView state ok"
