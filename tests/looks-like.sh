#!/bin/sh
# light_source's looks_like { OBJECT } (POV-Ray 3.7's Parse_Light_Source and
# LightSource): the object placed where the light is when looks_like is
# read, then its own modifiers, then moved by every transform of the light
# after it (as a declared light's copies, a union's light with the union),
# and casting no shadow; for point, spot, cylinder, area and parallel
# lights. In TAP, on the scenes of tests/looks-like/:
#   - hstrace's image and shadow mask against POV-Ray's renders (+Q9, and
#     +Q3/+Q4 for the mask) within the limits below (skipped without POV-Ray);
#   - every exact shadow method deciding as the shadow ray does;
#   - the same image on 1 thread and 2;
#   - bad looks_like: status 2, the message at FILE:LINE:COLUMN, no image.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (may be empty:
# the comparisons with POV-Ray are skipped).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$(cd "$builddir" && pwd)/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
tap_work hstlookslike
[ -x "$hstrace" ] || bail "$hstrace is not built"
run() { # runs hstrace, keeps stderr in $work/err and the status in $status
    "$hstrace" "$@" --threads 1 >"$work/out" 2>"$work/err"; status=$?
}

scenes="point spot declared"
for s in $scenes; do
    cp "$srcdir/tests/looks-like/$s.pov" "$work/$s.pov" || bail "cannot copy tests/looks-like/$s.pov"
done

limits='
# scene    RMSE   (measured)   off (m.)  mask pixels (m.)
point      1e-5   (2.7e-6)     1 (0)     1 (0)
spot       1e-5   (1.1e-6)     1 (0)     1 (0)
declared   1e-5   (3.9e-6)     1 (0)     1 (0)
'
# shellcheck disable=SC2086 # the scene names, one word each
povray_scenes_check "$limits" tests/looks-like.sh $scenes

# Every exact method decides as the shadow ray does: the objects that look
# like lights are left out of every shadow test.
# shellcheck disable=SC2086 # the scene names, one word each
verify_methods_check $scenes

# The same image on one thread as on two.
"$hstrace" "$work/declared.pov" --width 120 --height 90 --threads 1 -o "$work/t1.exr" >/dev/null 2>&1
"$hstrace" "$work/declared.pov" --width 120 --height 90 --threads 2 -o "$work/t2.exr" >/dev/null 2>&1
check "declared: the same image on 1 thread as on 2" "$hstrace" compare "$work/t1.exr" "$work/t2.exr" --max-rmse 0

# Mistakes: status 2, the message at FILE:LINE:COLUMN, no image.
bad_scenes_check <<'BAD'
light_source { 0, 1 looks_like { sphere { 0, 1 } } looks_like { sphere { 0, 1 } } }|only one looks_like allowed per light_source
light_source { 0, 1 looks_like { } }|expected an object in 'looks_like'
light_source { 0, 1 looks_like { light_source { 0, 1 } } }|expected an object in 'looks_like'
light_source { 0, 1 looks_like { sphere { 0, 1 } sturdy } }|an object modifier or '}' in 'looks_like'
BAD
tap_end
