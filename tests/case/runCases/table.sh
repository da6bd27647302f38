#!/usr/bin/env bash
# runCases over a 3 x 2 full factorial: the table holds result = 2x + y for
# every member; the member with x = 3 fails, is recorded, and the others
# complete; the exit code counts the failures; a re-run does nothing new.
source "$(dirname "$0")/../caseTestFunctions"
source "$(dirname "$0")/studyFunctions"
study="$work/study"
makeStudy "$study" "1 2 3" "10 20" 3

rc=0
runCases -case "$study" > "$work/log.1" || rc=$?
cat "$work/log.1"
[ "$rc" -eq 2 ] || fail "exit code $rc, expected 2 (two members with x = 3 fail)"
[ "$(grep -c '^started ' "$work/log.1")" -eq 6 ] || fail "expected 6 'started' lines"
[ "$(grep -c '^done ' "$work/log.1")" -eq 4 ] || fail "expected 4 'done' lines"
[ "$(grep -c '^failed ' "$work/log.1")" -eq 2 ] || fail "expected 2 'failed' lines"

table="$study/results.dat"
head -1 "$table" | grep -q $'^# member \[-\]\tx \[-\]\ty \[-\]\tresult \[N\]\tstatus \[-\]$' ||
    fail "unexpected header: $(head -1 "$table")"
[ "$(grep -vc '^#' "$table")" -eq 6 ] || fail "expected 6 rows"
# Every done row: result = 2x + y; every failed row: no result.
awk -F'\t' '!/^#/ { if ($5 == "done" && $4 != 2*$2 + $3) bad = bad " " $1; if ($5 == "failed" && $4 != "-") bad = bad " " $1 } END { if (bad) { print "wrong rows:" bad; exit 1 } }' "$table" ||
    fail "table content"
[ "$(column "$table" status | sort | uniq -c | tr -s ' ')" = "$(printf ' 4 done\n 2 failed')" ] || fail "states"
grep -q "state       failed" "$study/members/0004/runCases.status" || fail "member 0004 (x = 3) not recorded as failed"
grep -q "exitCode    3" "$study/members/0004/runCases.status" || fail "exit code of the failed member not recorded"
grep -q "fails on purpose" "$study/members/0004/log.runCases" || fail "the member's output is not in its log"
# The editor kept the rest of the template's file.
grep -q "// the two parameters of the study" "$study/members/0000/system/params" || fail "comment lost"
[ "$(caseDict -case "$study/members/0003" system/params -entry y -value)" = "20" ] || fail "member 0003 y"

# A re-run retries the failed members only; -collect rebuilds the same table.
cp "$table" "$work/table.1"
rc=0
runCases -case "$study" > "$work/log.2" || rc=$?
[ "$rc" -eq 2 ] || fail "re-run exit code $rc, expected 2"
[ "$(grep -c '^started ' "$work/log.2")" -eq 2 ] || fail "the re-run started more than the 2 failed members"
for m in 0000 0001 0002 0003; do
    [ "$(wc -l < "$study/counts/$m")" -eq 1 ] || fail "member $m ran more than once"
done
rm "$table"
runCases -case "$study" -collect > /dev/null
cmp "$table" "$work/table.1" || fail "-collect did not rebuild the same table"
runCases -case "$study" -dry-run | grep -q "^0004  failed  x=3 y=10$" || fail "-dry-run listing"

# Members share the cores: without OMP_NUM_THREADS each gets nproc / jobs threads (at least
# one); a user's OMP_NUM_THREADS is passed on unchanged.
threads="$work/threads"
makeStudy "$threads" "1 2" "10"
sed -i '2i echo "${OMP_NUM_THREADS:-unset}" > threads' "$threads/template/Allrun"
(unset OMP_NUM_THREADS; runCases -case "$threads" > "$work/log.threads") || fail "threads study failed"
expected=$(( $(nproc) / 2 )); [ "$expected" -ge 1 ] || expected=1
for m in 0000 0001; do
    [ "$(cat "$threads/members/$m/threads")" = "$expected" ] ||
        fail "member $m ran with OMP_NUM_THREADS=$(cat "$threads/members/$m/threads"), expected $expected"
done
grep -q "each member runs with OMP_NUM_THREADS=$expected" "$work/log.threads" || fail "the thread share is not reported"
rm -rf "$threads"
makeStudy "$threads" "1 2" "10"
sed -i '2i echo "${OMP_NUM_THREADS:-unset}" > threads' "$threads/template/Allrun"
OMP_NUM_THREADS=3 runCases -case "$threads" > /dev/null || fail "threads study (OMP_NUM_THREADS=3) failed"
[ "$(cat "$threads/members/0000/threads")" = 3 ] || fail "the user's OMP_NUM_THREADS was not passed on"
echo "runCases table ok"
