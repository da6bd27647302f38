#!/usr/bin/env bash
# Studies through a real Slurm: a private single-node cluster (slurmFunctions: munged,
# slurmctld, slurmd on 127.0.0.1 with 2 CPUs, everything under the scratch directory)
# runs runCases studies with 'scheduler slurm;':
#  1. the study's results.dat is byte-identical to the same study run with 'scheduler local';
#  2. a submission Slurm refuses is one error line; a member made to fail is reported failed
#     with its Slurm state (FAILED) and its logs, one whose task is cancelled behind runCases'
#     back with CANCELLED;
#  3. a driver killed hard (SIGKILL) leaves its array in Slurm: the next runCases submits
#     nothing, waits for the queued members and collects those that ended meanwhile; a
#     SIGTERM cancels the array (scancel), exits 143 and squeue lists no job of the study;
#     the run after it finishes the study without re-running a member that was done;
#  4. calibrateModel, with one line of its dictionary changed ('scheduler slurm;'), runs its
#     design through Slurm and calibrates the same values as locally;
#  5. explainGap likewise: the same run tables and the same result file.
# Skipped (exit 77) only when the Slurm and munge packages are not installed.
source "$(dirname "$0")/../caseTestFunctions"
source "$(dirname "$0")/studyFunctions"
source "$(dirname "$0")/slurmFunctions"
export OMP_NUM_THREADS=1
requireSlurmPackages
startSlurm "$work/slurm"

# useSlurm <study dir>: 'scheduler slurm;' and its settings in the study's runCasesDict.
useSlurm()
{
    cat >> "$1/system/runCasesDict" <<DICT
scheduler  slurm;
slurm      { partition rockfrac; time 00:05:00; cpusPerTask 1; }
DICT
}
noJobsLeft() { [ -z "$(queuedJobs)" ] || fail "squeue still lists jobs: $(queuedJobs)"; }

echo "== 1. local and Slurm give the same table"
makeStudy "$work/local" "1 2 3" "1 2"
runCases -case "$work/local" > "$work/log.local" || fail "the local study failed"
makeStudy "$work/viaSlurm" "1 2 3" "1 2"
useSlurm "$work/viaSlurm"
runCases -case "$work/viaSlurm" > "$work/log.viaSlurm" || { cat "$work/log.viaSlurm"; fail "the Slurm study failed"; }
cat "$work/log.viaSlurm"
grep -q "submitted 6 member(s) as Slurm job array" "$work/log.viaSlurm" || fail "the 6 members were not one array"
cmp "$work/local/results.dat" "$work/viaSlurm/results.dat" || fail "results.dat differs between local and Slurm"
[ -s "$work/viaSlurm/members/0000/log.slurm" ] || [ -f "$work/viaSlurm/members/0000/log.slurm" ] ||
    fail "no Slurm log in the member directory"
noJobsLeft

echo "== 2. a failing member is reported with its Slurm state"
makeStudy "$work/failing" "1 2" "1" 2
useSlurm "$work/failing"
rc=0; runCases -case "$work/failing" > "$work/log.failing" || rc=$?
cat "$work/log.failing"
[ "$rc" -eq 1 ] || fail "runCases exited $rc with one failed member, expected 1"
grep -q "^failed 0001 .*exited with 3 (Slurm state FAILED)" "$work/log.failing" ||
    fail "the failed member's line lacks its exit code and Slurm state"
grep -q 'Slurm state FAILED' "$work/failing/members/0001/runCases.status" || fail "the status lacks the Slurm state"
grep -q "fails on purpose" "$work/failing/members/0001/log.runCases" || fail "the member's log lacks its error"
[ "$(column "$work/failing/results.dat" status | tr '\n' ' ')" = "done failed " ] || fail "wrong states in the table"
noJobsLeft

# A submission Slurm refuses (no such partition): one line with sbatch's reason, exit 1.
makeStudy "$work/badPartition" "1" "1"
printf 'scheduler slurm;\nslurm { partition nosuchpartition; }\n' >> "$work/badPartition/system/runCasesDict"
expectUserError "invalid partition" runCases -case "$work/badPartition"
[ "$(column "$work/badPartition/results.dat" status)" = "pending" ] || fail "the refused member is not pending"
noJobsLeft

# A task cancelled by someone else (as a time limit or a node failure would end it): the
# member never writes its exit code and is failed with the state Slurm gives it.
makeStudy "$work/cancelled" "1 2" "1" none 5
useSlurm "$work/cancelled"
runCases -case "$work/cancelled" > "$work/log.cancelled" &
pid=$!; driverPid=$pid
for _ in $(seq 300); do    # until member 0001 runs
    task=$(queuedJobs | awk '$1 ~ /_1$/ && $2 == "RUNNING" { print $1 }')
    [ -n "$task" ] && break
    sleep 0.1
done
[ -n "$task" ] || fail "member 0001 never ran: $(queuedJobs)"
scancel "$task"
rc=0; wait "$pid" || rc=$?; driverPid=""
cat "$work/log.cancelled"
[ "$rc" -eq 1 ] || fail "runCases exited $rc with one cancelled member, expected 1"
# scancel stops the task's shell first or its command first, as the scheduler's signals race:
# either way the line names the Slurm state.
grep -Eq "^failed 0001 .*(ended before the command did|the command exited with [0-9]+) \(Slurm state CANCELLED\)" \
    "$work/log.cancelled" || fail "the cancelled member's line lacks its Slurm state"
grep -q "^done 0000 " "$work/log.cancelled" || fail "the other member did not finish"
noJobsLeft

echo "== 3. a killed driver, a resumed one, a cancelled one"
study="$work/interrupted"
makeStudy "$study" "1 2 3 4" "1 2" none 2    # 8 members of 2 s, 2 at a time on 2 CPUs
useSlurm "$study"
runCases -case "$study" > "$work/log.1" &
pid=$!; driverPid=$pid
for _ in $(seq 300); do    # until 2 members are done
    [ "$(grep -c '^done ' "$work/log.1" 2> /dev/null)" -ge 2 ] && break
    sleep 0.1
done
kill -KILL "$pid"; wait "$pid" 2> /dev/null || true; driverPid=""
cat "$work/log.1"
doneBefore=$(grep '^done ' "$work/log.1" | awk '{ print $2 }')
[ -n "$doneBefore" ] || fail "no member finished before the kill"
[ -n "$(queuedJobs)" ] || fail "the killed driver's array is no longer in Slurm"

runCases -case "$study" > "$work/log.2" &
pid=$!; driverPid=$pid
for _ in $(seq 300); do    # until one more member is done
    [ "$(grep -c '^done ' "$work/log.2" 2> /dev/null)" -ge 1 ] && break
    sleep 0.1
done
kill -TERM "$pid"
rc=0; wait "$pid" || rc=$?; driverPid=""
cat "$work/log.2"
[ "$rc" -eq 143 ] || fail "the cancelled runCases exited $rc, expected 143"
grep -q "already submitted to Slurm, 0 to submit" "$work/log.2" || fail "the resumed runCases submitted members again"
grep -q "^submitted " "$work/log.2" && fail "the resumed runCases submitted a member"
grep -q "cancelling Slurm job array" "$work/log.2" || fail "SIGTERM did not cancel the array"
noJobsLeft
grep -q "submitted" "$study/results.dat" && fail "a member is still 'submitted' after the cancel"

runCases -case "$study" > "$work/log.3" || { cat "$work/log.3"; fail "the study did not finish after the cancel"; }
cat "$work/log.3"
for m in $doneBefore; do
    [ "$(wc -l < "$study/counts/$m")" -eq 1 ] || fail "member $m was done before the kill but ran again"
    grep -q "^submitted $m " "$work/log.3" && fail "member $m was submitted again"
done
[ "$(column "$study/results.dat" status | sort -u)" = "done" ] || fail "not every member is done"
awk -F'\t' '!/^#/ && $4 != 2*$2 + $3 { exit 1 }' "$study/results.dat" || fail "a result is wrong"
noJobsLeft

echo "== 4. calibrateModel through Slurm: one line of calibrationDict changed"
# A 60-cell Brazilian disc, one parameter, a 3-level response surface: 4 DEM runs of ~1 s.
mkdir -p "$work/calLocal/system"
copyTutorial tutorials/BDT/granite "$work/calLocal/bdt"
caseDict -case "$work/calLocal/bdt" system/voronoiMeshDict -entry nCells -set 60 > /dev/null
cat > "$work/calLocal/measurements" <<DICT
FoamFile { format ascii; class dictionary; object measurements; }
test BDT; material twin;
specimens { twin { failureLoad [N] 12000; } }
DICT
cat > "$work/calLocal/system/calibrationDict" <<DICT
FoamFile { format ascii; class dictionary; object calibrationDict; }
model        dem;
case         "bdt";
measurements "measurements";
prepare      "meshRock > log.meshRock 2>&1 && voronoiMesh > log.voronoiMesh 2>&1";
command      "bondedDemFoam";
parameters   { tensileStrength { entry bond/voronoiQNSC/tensileStrength; range (15e6 35e6); unit Pa; } }
responseSurface { levels 3; }
target       { response "postProcessing/plateForce/0/plateForce.dat"; }
DICT
cp -r "$work/calLocal" "$work/calSlurm"
(cd "$work/calLocal" && calibrateModel -case . -noWrite > log.calibrateModel 2>&1) ||
    fail "local calibration: $(tail -3 "$work/calLocal/log.calibrateModel")"
sed -i 's/^command .*/&\nscheduler    slurm;/' "$work/calSlurm/system/calibrationDict"
diff "$work/calLocal/system/calibrationDict" "$work/calSlurm/system/calibrationDict" || true
(cd "$work/calSlurm" && calibrateModel -case . -noWrite > log.calibrateModel 2>&1) ||
    fail "calibration through Slurm: $(tail -3 "$work/calSlurm/log.calibrateModel")"
grep "calibrated" "$work/calSlurm/log.calibrateModel"
grep -q "submitted 3 member(s) as Slurm job array" "$work/calSlurm/runs/responseSurface/design/log.runCases" ||
    fail "the design did not go through Slurm"
for t in design/results.dat confirmation/results.dat; do
    cmp "$work/calLocal/runs/responseSurface/$t" "$work/calSlurm/runs/responseSurface/$t" ||
        fail "runs/responseSurface/$t differs between local and Slurm"
done
diff <(grep -v "date\|wallTime" "$work/calLocal/calibratedValues.responseSurface") \
    <(grep -v "date\|wallTime" "$work/calSlurm/calibratedValues.responseSurface" | sed s/calSlurm/calLocal/) ||
    fail "calibrateModel calibrated other values through Slurm"
noJobsLeft

echo "== 5. explainGap through Slurm: one line of explainGapDict changed"
# The tutorial's paperBDT study at its smallest: 2 seeds, one effect (6 sets of 2 runs).
copyTutorial tutorials/explainGap "$work/exLocal"
scalePlateSpeed "$work/exLocal/bdt" 4    # a quarter of the steps, at any case size
sed -i -e "s#^measurements .*#measurements \"$src/cases/experiments/BDT/granite/measurements\";#" \
    -e "s/^seeds .*/seeds { file system\/voronoiMeshDict; entry seed; values (1 2); }/" \
    -e "s/^effects .*/effects (contactCrumbling);/" "$work/exLocal/paperBDT/system/explainGapDict"
grep -q "values (1 2); }" "$work/exLocal/paperBDT/system/explainGapDict" || fail "the seeds did not apply"
cp -r "$work/exLocal" "$work/exSlurm"
(cd "$work/exLocal" && explainGap -case paperBDT > log.explainGap 2>&1) ||
    fail "local explainGap: $(tail -3 "$work/exLocal/log.explainGap")"
sed -i 's/^command .*/&\nscheduler     slurm;/' "$work/exSlurm/paperBDT/system/explainGapDict"
diff "$work/exLocal/paperBDT/system/explainGapDict" "$work/exSlurm/paperBDT/system/explainGapDict" || true
(cd "$work/exSlurm" && explainGap -case paperBDT > log.explainGap 2>&1) ||
    fail "explainGap through Slurm: $(tail -3 "$work/exSlurm/log.explainGap")"
tail -2 "$work/exSlurm/log.explainGap"
arrays=$(cat "$work"/exSlurm/study/runs/*/log.runCases | grep -c "as Slurm job array")
tables=$(ls "$work"/exLocal/study/runs/*/results.dat | wc -l)
[ "$arrays" -eq "$tables" ] || fail "$arrays Slurm arrays for $tables sets of runs"
for t in "$work"/exLocal/study/runs/*/results.dat; do
    cmp "$t" "$work/exSlurm/${t#"$work"/exLocal/}" || fail "${t#"$work"/exLocal/} differs between local and Slurm"
done
diff <(grep -v "date" "$work/exLocal/paperBDT/explainGap.result") \
    <(grep -v "date" "$work/exSlurm/paperBDT/explainGap.result") || fail "explainGap's result differs through Slurm"
echo "explainGap: $tables sets of runs through Slurm, the same tables and result as locally"
noJobsLeft

echo "runCases, calibrateModel and explainGap through Slurm ok"
