#!/usr/bin/env bash
# explainGap stopped by SIGTERM (a scheduler's stop, or Ctrl-C) while its runs are going:
# it passes the stop on to runCases, then stops itself with exit code 1 and writes no
# verdict (until 2026-12-03 it took the cut-short runs for failed ones, left their
# effects out and went on to an "unexplained" verdict). Run again, it reuses every member
# finished before the stop and reaches a verdict. The study: Table 5's granite discs
# against the tutorial's 60-cell disc (tutorials/explainGap/paperBDT, about a minute; its runs
# are kept in study/runs, shared with the tutorial's twin study).
source "$(dirname "$0")/../caseTestFunctions"
export OMP_NUM_THREADS=1
copyTutorial tutorials/explainGap "$work/t"
cd "$work/t"
smallSizePlates bdt
sed -i "s#^measurements .*#measurements \"$src/cases/experiments/BDT/granite/measurements\";#" \
    paperBDT/system/explainGapDict
grep -q "^measurements \"$src" paperBDT/system/explainGapDict || fail "the measurements path did not apply"
# No pairs of effects: the test is about the stop and the resume, not about the verdict.
echo "pairs off;" >> paperBDT/system/explainGapDict
if [ "$caseSize" = small ]; then  # under the sanitizers: 4 seeds and two effects (5 min with 8 and six)
    sed -i -e "s/^seeds .*/seeds { file system\/voronoiMeshDict; entry seed; values (1 2 3 4); }/" \
        -e "s/^effects .*/effects (contactCrumbling plateFriction);/" paperBDT/system/explainGapDict
    grep -q "values (1 2 3 4); }" paperBDT/system/explainGapDict || fail "the small size's seeds did not apply"
fi

explainGap -case paperBDT > log.1 2>&1 &
pid=$!
# Stop it once the effects' probes have started (the baseline and its refit are done).
for _ in $(seq 6000); do  # up to 10 min on a loaded machine
    ls -d study/runs/probe-*/members/*/log.runCases > /dev/null 2>&1 && break
    kill -0 "$pid" 2> /dev/null || break
    sleep 0.1
done
ls -d study/runs/probe-* > /dev/null 2>&1 || fail "no probe started: $(tail -3 log.1)"
kill -TERM "$pid"
rc=0; wait "$pid" || rc=$?
cat log.1
[ "$rc" -eq 1 ] || fail "explainGap stopped by SIGTERM exited $rc, expected 1"
grep -q "interrupted (signal 15)" log.1 || fail "no 'interrupted' message"
[ ! -e paperBDT/explainGap.result ] || fail "an interrupted explainGap wrote a verdict"
grep -q "not screened" log.1 && fail "an interrupted probe was reported as a failed one"
done1=$(cat study/runs/*/results.dat | grep -c "	done$" || true)
[ "$done1" -gt 0 ] || fail "no member finished before the stop"

explainGap -case paperBDT > log.2 2>&1 || fail "the resumed explainGap failed: $(tail -3 log.2)"
tail -3 log.2
grep -q "already done" study/runs/baseline-*/log.runCases || fail "the baseline was run again"
verdict=$(caseDict -case paperBDT explainGap.result -entry verdict -value)
[ -n "$verdict" ] || fail "no verdict after the resumed run"
echo "explainGap interrupt and resume ok ($done1 members reused, verdict $verdict)"
