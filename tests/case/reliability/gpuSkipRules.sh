#!/usr/bin/env bash
# The gpu tests are skipped only when there is no GPU (cudaBackendInfo exit 3) or no CUDA
# backend (4); a GPU the runtime cannot use (5, a driver mismatch) or a crash fails them, and
# ./Alltest adds the gpu label when a GPU is present (utilities/testLabels). Checked with fake
# cudaBackendInfo programs of each exit code, so it runs on any machine.
source "$(dirname "$0")/../caseTestFunctions"
fake="$work/fake"
for rc in 0 3 4 5 2; do
    mkdir -p "$fake/$rc"
    printf '#!/bin/sh\necho "compiled: yes"\necho "status: fake exit %s"\nexit %s\n' "$rc" "$rc" > "$fake/$rc/cudaBackendInfo"
    chmod +x "$fake/$rc/cudaBackendInfo"
done
self="$(cd "$(dirname "$0")" && pwd)/../caseTestFunctions"
skipRc() { (PATH="$fake/$1:$PATH"; source "$self" "$work/scratch$1"; skipWithoutCudaDevice; exit 0) > "$work/log.$1" 2>&1; echo $?; }
[ "$(skipRc 0)" = 0 ] || fail "a usable GPU must not skip: $(cat "$work/log.0")"
[ "$(skipRc 3)" = 77 ] || fail "no GPU must skip (77): $(cat "$work/log.3")"
[ "$(skipRc 4)" = 77 ] || fail "no CUDA backend must skip (77): $(cat "$work/log.4")"
[ "$(skipRc 5)" = 1 ] || fail "an unusable GPU must fail, not skip: $(cat "$work/log.5")"
[ "$(skipRc 2)" = 1 ] || fail "a crashing cudaBackendInfo must fail, not skip: $(cat "$work/log.2")"
grep -q "present but unusable" "$work/log.5" || fail "the failure does not say why: $(cat "$work/log.5")"
echo "ok: skipped on 3 and 4 only"

labels="$ROCKFRAC_SOURCE_DIR/utilities/testLabels"
[ "$("$labels" "$fake/0")" = "unit|case|gpu" ] || fail "a usable GPU: the gpu label is left out"
[ "$("$labels" "$fake/5")" = "unit|case|gpu" ] || fail "an unusable GPU: the gpu label is left out"
[ "$("$labels" "$fake/3")" = "unit|case" ] || fail "no GPU: the gpu label is added"
[ "$("$labels" "$fake/4")" = "unit|case" ] || fail "no backend: the gpu label is added"
[ "$("$labels" "$work/nowhere")" = "unit|case" ] || fail "no cudaBackendInfo: the gpu label is added"
echo "ok: ./Alltest runs the gpu label when a GPU is present"

# This machine: the real cudaBackendInfo's exit code is one of the documented ones.
rc=0
cudaBackendInfo > "$work/log.real" 2>&1 || rc=$?
case "$rc" in 0|3|4|5) echo "ok: cudaBackendInfo here exits $rc ($(grep '^status:' "$work/log.real"))" ;;
    *) fail "cudaBackendInfo exited $rc: $(cat "$work/log.real")" ;; esac
