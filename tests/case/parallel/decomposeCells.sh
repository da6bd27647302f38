#!/usr/bin/env bash
# decomposeCells on the BDT granite disc (300 cells): every cell in exactly one subdomain, the
# weights balanced, the halo symmetric for two subdomains cut across the disc, the same
# decomposition on every run, -dry-run writing nothing, the VTK read back, bad input refused.
source "$(dirname "$0")/../caseTestFunctions"
copyTutorial tutorials/BDT/granite "$work/bdt"
cd "$work/bdt"
run() { "$@" > "log.$1" 2>&1 || fail "$1 failed: $(tail -3 "log.$1")"; }
run meshRock
run voronoiMesh
cat > system/decomposeParDict <<'DICT'
FoamFile { format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains  4;
method              rcb;
weights             cost;
DICT

before=$(snapshot .)
decomposeCells -dry-run > "$work/log.dry" 2>&1 || fail "decomposeCells -dry-run failed: $(tail -3 "$work/log.dry")"
[ "$(snapshot .)" = "$before" ] || fail "decomposeCells -dry-run changed the case"

run decomposeCells
table=postProcessing/decomposeCells/decomposition.dat
# Four subdomains of 75 cells (300 cells of nearly equal cost), weights within 1 % of the mean,
# each exchanging with every other (a disc cut twice), cut interfaces counted from both sides.
awk -F'\t' '!/^#/ { n++; cells += $2; w[n] = $3; total += $3; cut += $5
                    if ($2 < 70 || $2 > 80) { print "subdomain " $1 " has " $2 " cells"; exit 1 }
                    if ($4 < 1 || $6 < 1) { print "subdomain " $1 " has no halo"; exit 1 } }
    END { if (n != 4 || cells != 300) { print n " subdomains, " cells " cells"; exit 1 }
          for (i = 1; i <= n; i++) if (w[i] / (total / n) > 1.01) { print "weight " w[i]; exit 1 }
          if (cut % 2) { print "odd cut count " cut; exit 1 } }' "$table" || fail "$table: $(cat "$table")"
grep -q "cut interfaces: [1-9][0-9]* of 1769" log.decomposeCells || fail "the interfaces were not counted"
checkVtk VTK/decomposition.vtu polyhedra 300 volume 2.1753e-5 0.005 || fail "VTK/decomposition.vtu"
echo "ok: 4 subdomains of the 300-cell disc"

# The same decomposition again (deterministic), and with -subdomains 2 a symmetric halo.
cp "$table" "$work/first.dat"
run decomposeCells -noVTK
cmp -s "$table" "$work/first.dat" || fail "a second run decomposed differently"
run decomposeCells -subdomains 2 -noVTK
awk -F'\t' '!/^#/ { n++; cells[n] = $2; cut[n] = $5 }
    END { if (n != 2 || cells[1] != 150 || cells[2] != 150 || cut[1] != cut[2]) exit 1 }' "$table" ||
    fail "two subdomains: $(cat "$table")"
echo "ok: deterministic, and two halves cut symmetrically"

# Bad input: one message naming the file and entry, exit 1.
expectUserError "numberOfSubdomains must be in [1, 300]" decomposeCells -subdomains 301
sed -i 's/^method .*/method              scotch;/' system/decomposeParDict
expectUserError "decomposeParDict:3" decomposeCells
sed -i 's/^method .*/method              rcb;/; s/^weights .*/weights             heavy;/' system/decomposeParDict
expectUserError "decomposeParDict:4" decomposeCells
rm system/decomposeParDict
expectUserError "decomposeParDict: not found" decomposeCells
echo "ok: bad input refused"
