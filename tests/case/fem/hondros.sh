#!/usr/bin/env bash
# Elastic Brazilian disc under the distributed arc load (2 alpha = 10 deg): the mean
# stress of the elements within `radius` of the disc axis against Hondros' centre
# values for the applied resultant P, sigma_x -> 2P/(pi D t) and sigma_z -> -6P/(pi D t).
# The reference is the finite-arc Hondros value (factors (sin 2a - a)/sin a and
# (sin 2a + a)/(3 sin a): 0.991 and 0.998 for a = 5 deg) times the mean of the
# concentrated-load field over the same circle (0.992 and 0.997 for r = 2 mm): both
# corrections are printed. The default mesh is the tutorial's own 1.5 mm (the fine 1.0 mm
# one, system/feMeshDict.fine, takes three times longer: `hondros.sh <dir> 1.0e-3`, 0.7 %
# and 0.3 % off, docs/validation.md); the load ramp is stopped at 0.3 ms, when the
# stress-to-load ratios have settled (measured on a run to 0.4 ms: from 0.3 ms on they
# stay within 0.05 % of their final values; at 0.2 ms they are 0.4 % off).
# Measured (docs/validation.md): sigma_x -2.5 / -1.8 / -0.7 %, sigma_z -0.7 / -0.5 /
# -0.3 % on 2.0 / 1.5 / 1.0 mm meshes.
# Usage: hondros.sh <scratch> [elementSize] [tolerance].
source "$(dirname "$0")/../caseTestFunctions"
# Small size (sanitized CI pass): the 2.0 mm mesh, 2.5 % off, checked against 5 %.
elementSize="${2:-$(bySize 1.5e-3 2.0e-3)}"
tolerance="${3:-$(bySize 0.03 0.05)}"
copyTutorial tutorials/BDT/graniteFEM "$work/case"
cd "$work/case"
cp system/feMeshDict.fine system/feMeshDict
[ -z "$elementSize" ] || caseDict -case . system/feMeshDict -entry elementSize -set "$elementSize" > /dev/null
elementSize=$(caseDict -case . system/feMeshDict -entry elementSize -value)
caseDict -case . constant/rockProperties -entry material -set linearElastic > /dev/null
cp "$src/tests/case/fem/arcLoading" constant/loading
caseDict -case . system/controlDict -entry endTime -set 3e-4 > /dev/null
caseDict -case . system/controlDict -entry writeInterval -set 3e-4 > /dev/null
caseDict -case . system/controlDict -entry functions/centreStress -add "{ radius 2e-3; }" > /dev/null
meshRock > log.meshRock 2>&1 || fail "meshRock: $(tail -3 log.meshRock)"
OMP_NUM_THREADS=1 feFractureSolver > log.feFractureSolver 2>&1 || fail "feFractureSolver: $(tail -3 log.feFractureSolver)"
grep -E "^Mesh|centreStress|Quasi" log.feFractureSolver
awk -F'\t' -v tol="$tolerance" '!/^#/ { t = $1; P = $2; sx = $3; sz = $5 }
    END { pi = 3.14159265358979; D = 44.8e-3; th = 13.8e-3; a = 5 * pi / 180;
          s0 = 2 * P / (pi * D * th);
          fx = (sin(2 * a) - a) / sin(a) * 0.9920; fz = (sin(2 * a) + a) / (3 * sin(a)) * 0.9973;
          ex = sx / (s0 * fx) - 1; ez = sz / (-3 * s0 * fz) - 1;
          printf "P = %.5g N at t = %g s: sigma_x %.5g MPa (2P/(pi D t) = %.5g, reference %.5g): error %+.2f %%\n",
                 P, t, sx / 1e6, s0 / 1e6, s0 * fx / 1e6, 100 * ex;
          printf "  sigma_z %.5g MPa (-6P/(pi D t) = %.5g, reference %.5g): error %+.2f %%\n",
                 sz / 1e6, -3 * s0 / 1e6, -3 * s0 * fz / 1e6, 100 * ez;
          printf "  against the limit formulas: sigma_x %+.2f %%, sigma_z %+.2f %%\n", 100 * (sx / s0 - 1), 100 * (sz / (-3 * s0) - 1);
          if (ex < -tol || ex > tol || ez < -tol || ez > tol) { printf "FAIL: beyond %g %%\n", 100 * tol; exit 1 } }' \
    postProcessing/centreStress/0/centreStress.dat || fail "centre stresses differ from Hondros"
echo "Hondros ok (element size $elementSize m, tolerance $tolerance)"
