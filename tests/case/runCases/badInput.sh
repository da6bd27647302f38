#!/usr/bin/env bash
# runCases refuses a bad study with one clear line and exit code 1, before
# making any member.
source "$(dirname "$0")/../caseTestFunctions"
source "$(dirname "$0")/studyFunctions"

makeStudy "$work/empty" "" "1 2"
expectUserError "the design has no runs" runCases -case "$work/empty"
[ ! -e "$work/empty/members" ] || fail "members made for a design with no runs"

makeStudy "$work/noFile" "1 2" "1"
caseDict -case "$work/noFile" system/runCasesDict -entry parameters/x/file -set constant/nothing >/dev/null
expectUserError "constant/nothing' is not in the template case" runCases -case "$work/noFile"

makeStudy "$work/noEntry" "1 2" "1"
caseDict -case "$work/noEntry" system/runCasesDict -entry parameters/x/entry -set z >/dev/null
expectUserError "has no entry 'z'" runCases -case "$work/noEntry"

makeStudy "$work/lhs" "1" "1"
caseDict -case "$work/lhs" system/runCasesDict -entry design -add latinHypercube >/dev/null
expectUserError "there is none" runCases -case "$work/lhs"

mkdir -p "$work/nothing"
expectUserError "system/runCasesDict" runCases -case "$work/nothing"
makeStudy "$work/jobs" "1" "1"
expectUserError "-jobs" runCases -case "$work/jobs" -jobs zero

# A Latin hypercube over ranges: 5 samples, each value in its stratum, reproducible.
makeStudy "$work/hyper" "1" "1"
caseDict -case "$work/hyper" system/runCasesDict -entry parameters/y/values -remove >/dev/null
caseDict -case "$work/hyper" system/runCasesDict -entry parameters/y/range -add "(0 10)" >/dev/null
caseDict -case "$work/hyper" system/runCasesDict -entry samples -add 5 >/dev/null
caseDict -case "$work/hyper" system/runCasesDict -entry seed -add 3 >/dev/null
# (the banner's clock line left out: two runs may straddle a second)
runCases -case "$work/hyper" -dry-run | grep -v ' date: ' > "$work/hyper.1"
runCases -case "$work/hyper" -dry-run | grep -v ' date: ' > "$work/hyper.2"
cmp "$work/hyper.1" "$work/hyper.2" || fail "Latin hypercube not reproducible"
strata=$(grep -o 'y=[0-9.e+-]*' "$work/hyper.1" | cut -d= -f2 | awk '{ print int($1 / 2) }' | sort -u | wc -l)
[ "$strata" -eq 5 ] || fail "Latin hypercube: $strata strata of 5 filled"
runCases -case "$work/hyper" > /dev/null || fail "the Latin hypercube study failed"
echo "runCases bad input ok"
