#!/usr/bin/env bash
# slab.sh <src case> <dest> <slab size m> : rerun a contact-refined SPB case with another slab size.
# <src case>: a rock case of tests/case/fem/spbFem.sh (4 mm) with, added to its system/feMeshDict,
#     contactRefinement { elementSize [m] 1.5e-3; distance [m] 5e-3; }
set -e
src=$1; dst=$2; size=$3
rm -rf "$dst"; mkdir -p "$dst"
cp -r "$src/system" "$dst/"
mkdir -p "$dst/constant"
for f in geometryProperties loading rockProperties; do cp "$src/constant/$f" "$dst/constant/"; done
cd "$dst"
caseDict -case . system/feMeshDict -entry contactRefinement/elementSize -set "[m] $size" > /dev/null
meshRock > log.meshRock 2>&1
OMP_NUM_THREADS=1 feFractureSolver > log.feFractureSolver 2>&1 || true
grep -E "^Mesh|^Failure|^End" log.feFractureSolver | sort -u
