#!/usr/bin/env bash
# The CUDA backend configured and built (ROCKFRAC_CUDA=ON): the device library holds
# GPU code, cudaBackendInfo reports the architectures, bondedDemFoam -help names the
# backend, and asking for it without a usable device is one clear error naming
# controlDict and the entry (CUDA_VISIBLE_DEVICES=-1 hides any GPU there is).
source "$(dirname "$0")/../caseTestFunctions"
lib="$ROCKFRAC_BINARY_DIR/lib/librockfrac_demCuda.a"
[ -f "$lib" ] || fail "the device library $lib was not built"
fatbin=$(objdump -h "$lib" | awk '$2 == ".nv_fatbin" { print $3 }')
[ -n "$fatbin" ] && [ $((16#$fatbin)) -gt 0 ] || fail "$lib holds no GPU code (.nv_fatbin section)"
echo "ok: $lib holds $((16#$fatbin)) bytes of GPU code"

rc=0
out=$(cudaBackendInfo) || rc=$?
echo "$out"
[ "$rc" -eq 0 ] || [ "$rc" -eq 3 ] || fail "cudaBackendInfo exited $rc (4 = not compiled)"
grep -q "^compiled: yes" <<< "$out" || fail "cudaBackendInfo does not report a compiled backend"
grep -q "^architectures: .*sm_80" <<< "$out" || fail "no sm_80 code reported"
grep -q "^architectures: .*sm_90" <<< "$out" || fail "no sm_90 code reported"
bondedDemFoam -help | grep -q "cuda (compiled for .*sm_80" || fail "bondedDemFoam -help does not name the CUDA backend"
echo "ok: bondedDemFoam -help names the CUDA backend"

# backend cuda with no visible device: exit 1, one line naming controlDict and the entry.
copyTutorial tutorials/BDT/granite "$work/case"
cd "$work/case"
caseDict -case . system/controlDict -entry backend -add cuda > /dev/null
expectUserError "backend cuda is not available" env CUDA_VISIBLE_DEVICES=-1 bondedDemFoam -case . -dry-run
err=$(CUDA_VISIBLE_DEVICES=-1 bondedDemFoam -case . -dry-run 2>&1 >/dev/null) || true
case "$err" in *controlDict*) ;; *) fail "the message does not name controlDict: $err" ;; esac
caseDict -case . system/controlDict -entry backend -set gpu > /dev/null
expectUserError "cpu, cuda" bondedDemFoam -case . -dry-run
