#!/bin/sh
# POV-Ray 3.7's blob (src/geometry/blob.c, its solver polynomial_solver.c), in
# TAP, on the scenes of tests/blob/: spherical components in both syntaxes
# and of negative strength, cylindrical ones, components made ellipsoids by
# their own transforms, blobs transformed as a whole, sturm, hierarchy off,
# a blob as a part of CSG (difference, intersection, inverse) and a glass
# one that shadow rays and refracted rays cross:
#   - hstrace's image and shadow mask against POV-Ray's renders (+Q9, and
#     +Q3/+Q4 for the mask) within the limits below (skipped without POV-Ray);
#   - every exact shadow method deciding as the shadow ray does
#     (--verify-shadows);
#   - the same image on 1 thread and 2;
#   - bad blobs: status 2, the message at FILE:LINE:COLUMN, no image.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (may be empty:
# the comparisons with POV-Ray are skipped).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$(cd "$builddir" && pwd)/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
tap_work hstblob
[ -x "$hstrace" ] || bail "$hstrace is not built"
run() { # runs hstrace, keeps stderr in $work/err and the status in $status
    "$hstrace" "$@" --threads 1 >"$work/out" 2>"$work/err"; status=$?
}

scenes="spheres cylinders ellipsoids csg"
for s in $scenes; do
    cp "$srcdir/tests/blob/$s.pov" "$work/$s.pov" || bail "cannot copy tests/blob/$s.pov"
done

limits='
# scene      RMSE   (measured)   off (m.)  mask pixels (m.)
spheres      1e-5   (2.2e-6)     1 (0)     1 (0)
cylinders    1e-5   (3.1e-6)     1 (0)     1 (0)
ellipsoids   1e-5   (1.2e-6)     1 (0)     1 (0)
csg          1e-5   (2.5e-6)     1 (0)     1 (0)
'
# shellcheck disable=SC2086 # the scene names, one word each
povray_scenes_check "$limits" tests/blob.sh $scenes

# Every exact method decides as the shadow ray does.
# shellcheck disable=SC2086 # the scene names, one word each
verify_methods_check $scenes

# The same image on one thread as on two.
for s in cylinders csg; do
    "$hstrace" "$work/$s.pov" --width 120 --height 90 --threads 1 -o "$work/t1.exr" >/dev/null 2>&1
    "$hstrace" "$work/$s.pov" --width 120 --height 90 --threads 2 -o "$work/t2.exr" >/dev/null 2>&1
    check "$s: the same image on 1 thread as on 2" "$hstrace" compare "$work/t1.exr" "$work/t2.exr" --max-rmse 0
done

# Mistakes: status 2, the message at FILE:LINE:COLUMN, no image.
bad_scenes_check <<'BAD'
blob { threshold 0.5 }|need at least one component in a blob
blob { cylinder { <1, 2, 3>, <1, 2, 3>, 1, 1 } }|degenerate cylindrical component in blob
blob { sphere { 0, 1, 1 pigment { rgb 1 } } }|a texture on a blob component is not supported by hstrace
blob { sphere { 0, 1 } }|expected a numeric expression
blob { sphere { 0, 1, 1 } hierarchy sturm wobble }|an object modifier or '}' in 'blob'
BAD
tap_end
