#!/usr/bin/env bash
# fragmentPSD on a short bondedDemFoam run of the BDT granite disc (loaded, not yet
# broken): one fragment holding all the mass, the disc's sizes, every output file,
# the VTK cells read back, time selection, -dry-run writing nothing, bad input refused.
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/BDT/granite "$work/bdt"
cd "$work/bdt"
run() { "$@" > "log.$1" 2>&1 || fail "$1 failed: $(tail -3 "log.$1")"; }
run meshRock
run voronoiMesh
caseDict -case . system/controlDict -entry endTime -set 2e-4 > /dev/null
OMP_NUM_THREADS=2 run bondedDemFoam
[ -f 0.0002/demState ] || fail "bondedDemFoam wrote no 0.0002/demState"

# Dry run first: reads everything, writes nothing.
before=$(snapshot .)
fragmentPSD -dry-run > "$work/log.dry" 2>&1 || fail "fragmentPSD -dry-run failed: $(tail -3 "$work/log.dry")"
[ "$(snapshot .)" = "$before" ] || fail "fragmentPSD -dry-run changed the case"

run fragmentPSD
out=postProcessing/fragmentPSD/0.0002
for f in fragments.dat psd.dat summary.dat; do [ -s "$out/$f" ] || fail "no $out/$f"; done
if [ -x /usr/bin/gnuplot ]; then [ -s "$out/psd.png" ] || fail "gnuplot is installed but there is no $out/psd.png"; fi
checkVtk VTK/fragments_0.0002.vtu polyhedra 300 volume 2.1753e-5 0.005 || fail "VTK/fragments_0.0002.vtu"
grep -q "Time 0.0002" log.fragmentPSD || fail "the latest time was not chosen"

# One fragment of all 300 cells: mass = density x volume, sieve size = the disc
# diameter 44.8 mm (intermediate of 44.8, 44.8, 13.8), equivalent diameter of the disc.
awk -F'\t' '!/^#/ { n++; cells = $3; mass = $4; vol = $5; deq = $6; sieve = $7 }
    END { if (n != 1 || cells != 300) { print "expected 1 fragment of 300 cells, got " n; exit 1 }
          if (mass / vol < 2539.999 || mass / vol > 2540.001) { print "mass/volume " mass / vol; exit 1 }
          if (sieve < 0.0446 || sieve > 0.0450) { print "sieve size " sieve; exit 1 }
          d = (6 * vol / 3.141592653589793) ^ (1 / 3); if (deq / d < 0.999999 || deq / d > 1.000001) exit 1 }' \
    "$out/fragments.dat" || fail "fragments.dat does not describe the intact disc"
awk -F'\t' '!/^#/ { if ($6 != 1 || $9 != 0 || $12 != 0) { print "largest " $6 " t10 " $9 " " $12; exit 1 } }' \
    "$out/summary.dat" || fail "summary.dat: an intact disc has largest fraction 1 and t10 0"
echo "ok: one fragment of 300 cells, the disc's sizes"

# -time picks an earlier directory; unknown times and a corrupt state are user errors.
fragmentPSD -time 1e-4 -noPlot -noVTK > log.time 2>&1 || fail "fragmentPSD -time 1e-4 failed"
[ -s postProcessing/fragmentPSD/0.0001/fragments.dat ] || fail "-time 1e-4 did not write 0.0001"
[ ! -e VTK/fragments_0.0001.vtu ] || fail "-noVTK wrote a VTK file"
expectUserError "available times: 0 0.0001 0.0002" fragmentPSD -time 7
cp -r "$work/bdt" "$work/corrupt" && cd "$work/corrupt"
head -c 1000 0.0002/demState > 0.0002/demState.part && mv 0.0002/demState.part 0.0002/demState
expectUserError "0.0002/demState" fragmentPSD
rm -rf 0 0.0001 0.0002
expectUserError "run bondedDemFoam first" fragmentPSD
