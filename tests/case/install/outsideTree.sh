#!/usr/bin/env bash
# rockfrac used outside its source tree, as a user does: `cmake --install` into a prefix
# outside the checkout; the prefix holds every application (one per page of
# docs/applications), etc/bashrc, RunFunctions, the docs, and the tutorials and cases as the
# source has them (no run outputs). In a clean environment (env -i, a minimal PATH, set -u)
# etc/bashrc sourced twice sets PATH, ROCKFRAC_BIN, ROCKFRAC_DIR and ROCKFRAC_TUTORIALS once;
# the BDT granite tutorial copied to a run directory outside the checkout runs with its
# ./Allrun and gives the plateForce.dat of the same tutorial run with the source tree's
# etc/bashrc and the build's applications, byte for byte; Allclean leaves its inputs. Copied
# without the environment, its Allrun stops with one line saying to source etc/bashrc.
# Small size (the sanitized CI pass): both discs have 100 cells instead of 300.
source "$(dirname "$0")/../caseTestFunctions"
build="${ROCKFRAC_BINARY_DIR:?}"
outside=$(mktemp -d "${TMPDIR:-/tmp}/rockfrac-install.XXXXXX")
trap 'rm -rf "$outside"' EXIT
case "$outside/" in "$src/"*) fail "the scratch directory $outside is inside the checkout $src" ;; esac
prefix="$outside/prefix"

"${CMAKE_COMMAND:-cmake}" --install "$build" --prefix "$prefix" > "$work/log.install" 2>&1 ||
    fail "cmake --install failed: $(tail -3 "$work/log.install")"

# The layout (cmake/RockfracInstall.cmake).
for page in "$src"/docs/applications/*.md; do
    app=$(basename "$page" .md)
    [ "$app" = README ] && continue
    [ -x "$prefix/bin/$app" ] || fail "the application $app (docs/applications/$app.md) is not in $prefix/bin"
done
[ ! -e "$prefix/bin/benchDem" ] || fail "bench/ programs are installed"
for f in etc/bashrc share/rockfrac/utilities/RunFunctions share/doc/rockfrac/README.md \
         share/doc/rockfrac/CHANGELOG.md share/doc/rockfrac/docs/user-guide.md \
         share/rockfrac/cases/experiments/BDT/granite/measurements; do
    [ -f "$prefix/$f" ] || fail "no $f in the installation"
done
# Tutorials and cases: the source's files, inputs only (git's view when the source is a
# checkout: every file that is tracked or not ignored). No links: cp -r keeps them relative.
if git -C "$src" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    diff <(cd "$src" && git ls-files --cached --others --exclude-standard tutorials cases | LC_ALL=C sort) \
         <(cd "$prefix/share/rockfrac" && find tutorials cases -type f -o -type l | LC_ALL=C sort) > "$work/files.diff" ||
        fail "the installed tutorials and cases differ from the source's (< source only, > installed only):
$(head -20 "$work/files.diff")"
    echo "ok: the installed tutorials and cases are the source's $(wc -l < <(cd "$prefix/share/rockfrac" && find tutorials cases -type f)) files"
fi
links=$(find "$prefix/share/rockfrac" -type l)
[ -z "$links" ] || fail "links in the installation: $links"

# clean <script>: bash -c <script> with nothing of rockfrac's in the environment: env -i, the
# PATH of a new login, one OpenMP thread; the sanitizers' options pass (ci-sanitize).
clean()
{
    local pass=() v
    for v in LSAN_OPTIONS ASAN_OPTIONS UBSAN_OPTIONS; do
        [ -n "${!v:-}" ] && pass+=("$v=${!v}")
    done
    env -i HOME="$outside" PATH=/usr/bin:/bin OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE "${pass[@]}" \
        bash --noprofile --norc -c "set -euo pipefail; $1"
}

# The environment, sourced twice under set -u.
env=$(clean "source '$prefix/etc/bashrc'; first=\$PATH; source '$prefix/etc/bashrc'
    [ \"\$PATH\" = \"\$first\" ] || { echo \"PATH grew: \$first -> \$PATH\"; exit 1; }
    echo \"PATH=\$PATH\"; echo \"ROCKFRAC_BIN=\$ROCKFRAC_BIN\"; echo \"ROCKFRAC_DIR=\$ROCKFRAC_DIR\"
    echo \"ROCKFRAC_TUTORIALS=\$ROCKFRAC_TUTORIALS\"; echo \"meshRock=\$(command -v meshRock)\"") ||
    fail "sourcing etc/bashrc twice failed: $env"
expected="PATH=$prefix/bin:/usr/bin:/bin
ROCKFRAC_BIN=$prefix/bin
ROCKFRAC_DIR=$prefix/share/rockfrac
ROCKFRAC_TUTORIALS=$prefix/share/rockfrac/tutorials
meshRock=$prefix/bin/meshRock"
[ "$env" = "$expected" ] || fail "etc/bashrc set
$env
instead of
$expected"
echo "ok: etc/bashrc sourced twice under set -u: $(tr '\n' ' ' <<< "$env")"

# Without the environment: one line naming etc/bashrc, exit 1.
mkdir -p "$outside/bare" && cp -r "$prefix/share/rockfrac/tutorials/BDT/granite" "$outside/bare/"
rc=0
err=$(clean "'$outside/bare/granite/Allrun'" 2>&1 >/dev/null) || rc=$?
[ "$rc" -eq 1 ] && [ "$(wc -l <<< "$err")" -eq 1 ] && [[ $err == *"etc/bashrc"* ]] ||
    fail "Allrun without the environment exited $rc with '$err' (expected 1 and one line naming etc/bashrc)"
echo "ok: without the environment: $err"

# runCopy <bashrc> <run directory> [<assignments>]: the BDT granite tutorial of
# $ROCKFRAC_TUTORIALS copied to <run directory> and run there by its ./Allrun.
cells=$(bySize 300 100)
resize=""
[ "$cells" = 300 ] || resize="caseDict -case . system/voronoiMeshDict -entry nCells -set $cells > /dev/null"
runCopy()
{
    clean "${3:-} source '$1'
        mkdir -p '$2' && cp -r \"\$ROCKFRAC_TUTORIALS/BDT/granite\" '$2/' && cd '$2/granite'
        ./Allclean
        $resize
        ./Allrun" > "$work/log.$(basename "$2")" 2>&1 ||
        fail "the tutorial copied to $2 failed: $(tail -5 "$work/log.$(basename "$2")")"
}
runCopy "$prefix/etc/bashrc" "$outside/installed"
runCopy "$src/etc/bashrc" "$outside/sourceTree" "export ROCKFRAC_BUILD_DIR='$build';"
grep -q "Running meshRock on $outside/installed/granite" "$work/log.installed" ||
    fail "the installed copy did not run in $outside/installed/granite: $(head -3 "$work/log.installed")"
dat=postProcessing/plateForce/0/plateForce.dat
cmp "$outside/installed/granite/$dat" "$outside/sourceTree/granite/$dat" ||
    fail "the installed applications give another $dat than the build's"
awk -F'\t' '!/^#/ { f = $3; if (f > peak) peak = f; last = f }
    END { printf "peak %.2f N, final %.2f N\n", peak, last
          if (!(peak > 1000 && last < 0.5 * peak)) { print "FAIL: the disc did not split"; exit 1 } }' \
    "$outside/installed/granite/$dat" > "$work/peak" || fail "$(cat "$work/peak")"
echo "ok: BDT granite ($cells cells) copied to $outside/installed: $(cat "$work/peak"), $dat identical to the build's"

# Allclean in the copy leaves exactly the tutorial's inputs.
clean "source '$prefix/etc/bashrc'; '$outside/installed/granite/Allclean'" ||
    fail "Allclean of the installed copy failed"
diff <(cd "$prefix/share/rockfrac/tutorials/BDT/granite" && find . -type f | LC_ALL=C sort) \
     <(cd "$outside/installed/granite" && find . -type f | LC_ALL=C sort) > "$work/clean.diff" ||
    fail "after Allclean the copy holds other files than the tutorial (< tutorial, > copy): $(head "$work/clean.diff")"
echo "ok: Allclean leaves the tutorial's inputs"
