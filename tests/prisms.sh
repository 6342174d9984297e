#!/bin/sh
# POV-Ray's prism as an analytic shape, in TAP: its four splines (linear,
# quadratic, cubic with and without sturm, Bezier) converted to cubic
# segments as Compute_Prism converts them, both sweeps (linear and conic,
# one through its apex, one below it), open, as parts of CSG (difference,
# intersection, POV-Ray's logo.inc), clipped and transformed, in the scenes
# of tests/prisms/:
#   - hstrace's image and shadow mask against POV-Ray's renders (+Q9, and
#     +Q3/+Q4 for the mask), within the limits measured below, no interior
#     mask disagreement (skipped without POV-Ray);
#   - every exact shadow method deciding as the shadow ray does
#     (--verify-shadows: 0 disagreements);
#   - mistakes: status 2 and FILE:LINE:COLUMN, no image; an unclosed curved
#     outline ignored with POV-Ray's warning.
# The linear prisms of tests/planar-shapes.sh are the same shape.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (path or name of
# povray; may be empty: the comparisons with POV-Ray are skipped).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$(cd "$builddir" && pwd)/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
tap_work hstprism
[ -x "$hstrace" ] || bail "$hstrace is not built"
run() { # runs hstrace, keeps stderr in $work/err and the status in $status
    "$hstrace" "$@" --threads 1 >"$work/out" 2>"$work/err"; status=$?
}

scenes="prism-splines prism-conic prism-csg"
for s in $scenes; do
    cp "$srcdir/tests/prisms/$s.pov" "$work/$s.pov" || bail "cannot copy tests/prisms/$s.pov"
done

limits='
# scene              RMSE   (measured)   off (m.)  mask pixels (m.)
prism-splines        1e-5   (3.0e-6)     1 (0)     1 (0)
prism-conic          1e-5   (1.4e-6)     1 (0)     1 (0)
prism-csg            1e-5   (1.2e-6)     1 (0)     1 (0)
'
# shellcheck disable=SC2086 # the scene names, one word each
povray_scenes_check "$limits" tests/prisms.sh $scenes

# Every exact method decides as the shadow ray does, on every scene.
verify_unlit=""
# shellcheck disable=SC2086 # the scene names, one word each
verify_methods_check $scenes

# Mistakes: status 2, the message at FILE:LINE:COLUMN, no image (POV-Ray's
# own messages; an open quadratic or cubic outline is its fatal "Too few
# points in prism."; the expressions refuse a NaN or infinite height).
bad_scenes_check <<'BAD'
prism { 0, 1, 2, <0, 0>, <1, 1> }|Prism with linear splines must have at least three points.
prism { quadratic_spline 0, 1, 4, <0, 0>, <1, 0>, <1, 1>, <0, 0> }|Prism with quadratic splines must have at least five points.
prism { cubic_spline 0, 1, 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <1, 0> }|Prism with cubic splines must have at least six points.
prism { bezier_spline 0, 1, 6, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0>, <1, 0> }|Prism with Bezier splines must have four points per segment.
prism { bezier_spline 0, 1, 0 }|Prism with Bezier splines must have four points per segment.
prism { quadratic_spline 0, 1, 6, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0.5>, <2, 2> }|Too few points in prism.
prism { cubic_spline 0, 1, 7, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0.5>, <2, 2>, <3, 3> }|Too few points in prism.
prism { 0, sqrt(-1), 3, <0, 0>, <1, 0>, <1, 1> }|sqrt of negative number
prism { 0, 1e200 * 1e200, 3, <0, 0>, <1, 0>, <1, 1> }|expected a finite number
prism { 0, 1, 1e300, <0, 0>, <1, 1>, <1, 0> }|is not a usable number of points
prism { 0, 1, 3, <0, 0>, <1, 1, 1>, <1, 0> }|UV vector expected
BAD

# An open Bezier outline: POV-Ray warns and leaves the prism out (status
# 0), alone or as a CSG part.
cat >"$work/open-bezier.pov" <<'POV'
camera { location <0, 3, -4> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
difference {
  box { -1, 1 }
  prism { bezier_spline 0, 1, 8, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 1>, <-1, 1>, <-1, 0>, <0, 0.5> }
  pigment { rgb 1 }
}
POV
run "$work/open-bezier.pov" --width 32 --height 24 -o "$work/open-bezier.exr"
check "an open Bezier outline: renders" exited 0
check "an open Bezier outline: POV-Ray's warning at FILE:LINE:COLUMN" \
    grep -q "^$work/open-bezier.pov:5:3: warning: Prism not closed. Ignoring it." "$work/err"
tap_end
