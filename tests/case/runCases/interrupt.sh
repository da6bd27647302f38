#!/usr/bin/env bash
# Interrupt a batch half-way (SIGTERM to runCases, as a scheduler does, then a
# SIGKILL that leaves 'running' members behind) and run it again: members done
# before are not run again (a counter file per member proves it), interrupted
# ones are, and the final table is complete.
source "$(dirname "$0")/../caseTestFunctions"
source "$(dirname "$0")/studyFunctions"
study="$work/study"
makeStudy "$study" "1 2 3 4" "1 2" none 1     # 8 members of 1 s, 2 at a time

runCases -case "$study" > "$work/log.1" &
pid=$!
for _ in $(seq 100); do    # wait until 2 members are done
    [ "$(grep -c '^done ' "$work/log.1" 2>/dev/null)" -ge 2 ] && break
    sleep 0.1
done
kill -TERM "$pid"
rc=0; wait "$pid" || rc=$?
cat "$work/log.1"
[ "$rc" -eq 143 ] || fail "interrupted runCases exited $rc, expected 143"
grep -q "^interrupted " "$work/log.1" || fail "no member was reported interrupted"
doneBefore=$(grep '^done ' "$work/log.1" | awk '{ print $2 }')
[ -n "$doneBefore" ] || fail "no member finished before the interrupt"
grep -q "running" "$study/results.dat" && fail "a member is still 'running' after a clean stop"

# A hard kill: the members it was running stay 'running' and are re-run.
runCases -case "$study" > "$work/log.2" &
pid=$!
sleep 0.5
kill -KILL "$pid"; wait "$pid" 2>/dev/null || true
# Let the orphaned members end: they hold the study's lock (inherited) until they do, and a
# resume is refused while they run (a loaded machine, e.g. the sanitized pass, takes seconds).
for _ in $(seq 600); do flock -n "$study/members/.runCases.lock" true && break; sleep 0.1; done
flock -n "$study/members/.runCases.lock" true || fail "the orphaned members still hold the study's lock after 60 s"
grep -l "state       running" "$study"/members/*/runCases.status > /dev/null || fail "no member left 'running'"

runCases -case "$study" > "$work/log.3" || fail "the resumed batch failed"
cat "$work/log.3"
for m in $doneBefore; do
    [ "$(wc -l < "$study/counts/$m")" -eq 1 ] || fail "member $m was done before the interrupt but ran again"
    grep -q "^started $m " "$work/log.3" && fail "member $m started again"
done
[ "$(column "$study/results.dat" status | sort -u)" = "done" ] || fail "not every member is done"
[ "$(grep -vc '^#' "$study/results.dat")" -eq 8 ] || fail "expected 8 rows"
awk -F'\t' '!/^#/ && $4 != 2*$2 + $3 { exit 1 }' "$study/results.dat" || fail "a result is wrong"
echo "runCases interrupt and resume ok"
