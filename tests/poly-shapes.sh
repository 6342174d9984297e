#!/bin/sh
# POV-Ray's algebraic shapes, in TAP: quadric, poly, cubic and quartic
# with POV-Ray 3.7's own polynomial solver (its closed-form quartic, and
# its Sturm sequences for sturm, degrees above 4 and difficult quartics),
# superellipsoid with its own root finder, lathe (its four splines) and
# sor with the same solver, in the scenes of
# tests/poly-shapes/:
#   - hstrace's image and shadow mask against POV-Ray's renders (+Q9, and
#     +Q3/+Q4 for the mask), within the limits measured below, no interior
#     mask disagreement (skipped without POV-Ray): transformed, unevenly
#     scaled, infinite and clipped, in CSG, inverted, bounded_by where
#     POV-Ray keeps the bound, the eye inside, casting shadows (through
#     see-through ones too: POV-Ray casts the shadow ray again from each
#     crossing, which its superellipsoid and solver find anew);
#   - every exact shadow method deciding as the shadow ray does
#     (--verify-shadows: 0 disagreements);
#   - mistakes: status 2 and FILE:LINE:COLUMN, no image;
#   - one image for any thread count.
# The solver's own unit test is tests/test_polynomial_solver.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (path or name of
# povray; may be empty: the comparisons with POV-Ray are skipped).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$(cd "$builddir" && pwd)/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
tap_work hstpoly
[ -x "$hstrace" ] || bail "$hstrace is not built"
run() { # runs hstrace, keeps stderr in $work/err and the status in $status
    "$hstrace" "$@" --threads 1 >"$work/out" 2>"$work/err"; status=$?
}

scenes="quadric poly poly-eye-inside poly-graze superellipsoid superellipsoid-eye-inside lathe sor"
for s in $scenes; do
    cp "$srcdir/tests/poly-shapes/$s.pov" "$work/$s.pov" || bail "cannot copy tests/poly-shapes/$s.pov"
done

limits='
# scene              RMSE   (measured)   off (m.)  mask pixels (m.)
quadric              1e-5   (3.6e-6)     1 (0)     1 (0)
poly                 1e-5   (2.6e-6)     1 (0)     1 (0)
poly-eye-inside      1e-5   (1.7e-6)     1 (0)     1 (0)
poly-graze           1e-5   (6.1e-7)     1 (0)     1 (0)
superellipsoid       1e-5   (3.6e-6)     1 (0)     1 (0)
superellipsoid-eye-inside 1e-5 (1.9e-6)    1 (0)     1 (0)
lathe                1e-5   (4.5e-7)     1 (0)     1 (0)
sor                  1e-5   (6.8e-7)     1 (0)     1 (0)
'
# shellcheck disable=SC2086 # the scene names, one word each
povray_scenes_check "$limits" tests/poly-shapes.sh $scenes

# Every exact method decides as the shadow ray does, on every scene.
verify_unlit=""
# shellcheck disable=SC2086 # the scene names, one word each
verify_methods_check $scenes

# Mistakes: status 2, the message at FILE:LINE:COLUMN, no image (too few
# coefficients end at the '>' where the next is due, too many at the one
# after the last).
bad_scenes_check <<'BAD'
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0> }|expected
poly { 1, <1, 2, 3, 4> }|Order of poly is out of range
poly { 36, <1> }|Order of poly is out of range
cubic { <1, 2, 3> }|expected a numeric expression, found '>'
quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0> }|expected '>' after the 35 coefficients of a quartic of order 4, found ','
quartic { 1 }|expected '<' before the 35 coefficients of 'quartic', found '1'
superellipsoid { <0, 1> }|both must be positive
superellipsoid { <1, 2, 3> }|UV vector expected
lathe { quadratic_spline 2, <0, 0>, <1, 1> }|at least three points
lathe { bezier_spline 5, <0, 0>, <1, 1>, <1, 2>, <0, 3>, <0, 4> }|four points per segment
lathe { 3, <0, 0>, <-1, 1>, <0, 2> }|Incorrect point in lathe
sor { 3, <0, 0>, <1, 1>, <1, 2> }|at least four points
sor { 5, <0, 0>, <1, 1>, <1, 0.5>, <1, 2>, <0, 3> }|Incorrect point in surface of revolution
poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> bounded_by { triangle { 0, x, y } } }|'triangle' in 'bounded_by' of a 'poly' is not supported
BAD

# Extreme coefficients render (status 0) with no NaN or infinite pixel.
cat >"$work/extreme.pov" <<'POV'
camera { location <0, 1, -5> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
quadric { <1e300, 1e300, 1e300>, <0, 0, 0>, <0, 0, 0>, -1e300 pigment { rgb 1 } }
quadric { <0, 0, 0>, <0, 0, 0>, <0, 0, 0>, 0 pigment { rgb 1 } }
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 scale <1, 1e-300, 1> pigment { rgb 1 } }
quartic { <1e300, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, -1e-300> pigment { rgb 1 } }
poly { 5, <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0> sturm pigment { rgb 1 } }
POV
run "$work/extreme.pov" --width 32 --height 24 -o "$work/extreme.exr"
check "extreme coefficients and transforms: renders" exited 0
"$hstrace" compare "$work/extreme.exr" "$work/extreme.exr" --json >"$work/extreme.json" 2>&1
check_status "extreme coefficients and transforms: no NaN or infinite pixels" "$(json_value nonfinite_pixels "$work/extreme.json")" 0

# The same image on one thread as on two.
for s in poly poly-eye-inside; do
    "$hstrace" "$work/$s.pov" --width 120 --height 90 --threads 1 -o "$work/t1.exr" >/dev/null 2>&1
    "$hstrace" "$work/$s.pov" --width 120 --height 90 --threads 2 -o "$work/t2.exr" >/dev/null 2>&1
    check "$s: the same image on 1 thread as on 2" "$hstrace" compare "$work/t1.exr" "$work/t2.exr" --max-rmse 0
done
tap_end
