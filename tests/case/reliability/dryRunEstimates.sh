#!/usr/bin/env bash
# Up-front estimates (docs/reliability.md, "Memory limit"): -dry-run of every application
# that allocates from its inputs prints one line
#   Estimate: <counts>, ~<bytes> peak memory; available <bytes> (<source>)
# the estimate is not below the peak resident memory of the real run and at most
# $maxRatio times it (measured with /usr/bin/time on small tutorials), and with a small
# ROCKFRAC_MEMORY_LIMIT_BYTES the dry run itself refuses (exit 1, one line naming the
# estimate and the limit). The ratio is checked at the full case size only: the
# sanitized build's (small size) shadow memory is not what the estimates model.
source "$(dirname "$0")/../caseTestFunctions"
maxRatio=3
[ -x /usr/bin/time ] || fail "/usr/bin/time is needed to measure the peak memory (apt-get install time)"

# bytesOf "34.8 MB" -> 34800000 (formatBytes: powers of 1000)
bytesOf()
{
    awk -v v="$1" -v u="$2" 'BEGIN { f["bytes"]=1; f["kB"]=1e3; f["MB"]=1e6; f["GB"]=1e9; f["TB"]=1e12;
        if (!(u in f)) exit 1; printf "%.0f\n", v * f[u] }'
}

# checkEstimate <label> <counts fragment> <dir> <command...>: -dry-run prints the line; the
# real run's peak RSS is within [1, maxRatio] of the estimate.
checkEstimate()
{
    local label="$1" counts="$2" dir="$3"; shift 3
    local out line estimate peak
    out=$(cd "$dir" && "$@" -dry-run) || fail "$label: '$* -dry-run' failed"
    line=$(grep '^Estimate: ' <<< "$out") || fail "$label: no 'Estimate:' line in the dry run: $out"
    [ "$(wc -l <<< "$line")" -eq 1 ] || fail "$label: more than one estimate line: $line"
    [[ "$line" == *"$counts"*"peak memory; available "*"("*")" ]] ||
        fail "$label: the estimate line '$line' lacks '$counts', the peak or the available memory"
    grep -q '^Dry run' <<< "$out" || fail "$label: the dry run's closing line is gone: $out"
    read -r value unit < <(sed 's/.*, ~\([0-9.e+]*\) \([a-zA-Z]*\) peak memory.*/\1 \2/' <<< "$line")
    estimate=$(bytesOf "$value" "$unit") || fail "$label: cannot read the estimate in '$line'"
    (cd "$dir" && /usr/bin/time -f '%M' -o "$work/$label.rss" "$@" > "$work/$label.log" 2>&1) ||
        fail "$label: the real run failed: $(tail -3 "$work/$label.log")"
    peak=$(( $(tail -1 "$work/$label.rss") * 1024 ))
    local ratio; ratio=$(awk -v e="$estimate" -v p="$peak" 'BEGIN { printf "%.2f", e / p }')
    echo "ok: $label: $line; measured peak $((peak / 1000)) kB, estimate / peak = $ratio"
    [ "$caseSize" = small ] && return 0
    awk -v r="$ratio" -v m="$maxRatio" 'BEGIN { exit !(r >= 1 && r <= m) }' ||
        fail "$label: estimate / measured peak = $ratio, outside [1, $maxRatio]"
}

# refuses <label> <dir> <command...>: with a 1 MB machine the dry run stops with the estimate.
refuses()
{
    local label="$1" dir="$2"; shift 2
    (cd "$dir" && export ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 && expectUserError "needs an estimated" "$@" -dry-run) ||
        fail "$label: the dry run did not refuse a 1 MB machine"
    local err; err=$(cd "$dir" && ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 "$@" -dry-run 2>&1 > /dev/null) || true
    [[ "$err" == *"only 1 MB are available (ROCKFRAC_MEMORY_LIMIT_BYTES)"* ]] ||
        fail "$label: the refusal '$err' does not name the available memory and its source"
}

# ---- DEM: meshRock (disc), voronoiMesh, bondedDemFoam, fragmentPSD ---------------------------
dem="$work/dem"
copyTutorial tutorials/BDT/granite "$dem"
caseDict -case "$dem" system/controlDict -entry endTime -set 2e-6 > /dev/null
caseDict -case "$dem" system/controlDict -entry writeInterval -set 1e-6 > /dev/null
refuses meshRock "$dem" meshRock
checkEstimate meshRock "512 surface triangles" "$dem" meshRock
refuses voronoiMesh "$dem" voronoiMesh
checkEstimate voronoiMesh "300 cells" "$dem" voronoiMesh
refuses bondedDemFoam "$dem" bondedDemFoam
checkEstimate bondedDemFoam "300 cells, " "$dem" bondedDemFoam
refuses fragmentPSD "$dem" fragmentPSD -noPlot
checkEstimate fragmentPSD "300 cells, " "$dem" fragmentPSD -noPlot

# ---- FEM: meshRock (tetrahedra), feFractureSolver --------------------------------------------
fem="$work/fem"
copyTutorial tutorials/BDT/graniteFEM "$fem"
caseDict -case "$fem" system/feMeshDict -entry elementSize -set 4e-3 > /dev/null
caseDict -case "$fem" system/controlDict -entry endTime -set 2e-6 > /dev/null
caseDict -case "$fem" system/controlDict -entry writeInterval -set 1e-6 > /dev/null
refuses meshRockTets "$fem" meshRock
checkEstimate meshRockTets "tetrahedra" "$fem" meshRock
refuses feFractureSolver "$fem" feFractureSolver
checkEstimate feFractureSolver " tetrahedra" "$fem" feFractureSolver

# ---- the crusher's liners: meshCrusher --------------------------------------------------------
crusher="$work/crusher"
cp -r "$src/tutorials/CH660/geometry" "$crusher"
refuses meshCrusher "$crusher" meshCrusher
checkEstimate meshCrusher "liner triangles" "$crusher" meshCrusher
echo "PASS"
