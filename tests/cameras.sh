#!/bin/sh
# POV-Ray 3.7's camera types beyond perspective and orthographic (fisheye,
# ultra_wide_angle, omnimax, panoramic, cylinder 1 to 4, spherical), in TAP,
# on the scenes of tests/cameras/ (one world, tests/cameras/world.inc, seen
# by each camera):
#   - hstrace's image and shadow mask against POV-Ray's renders (+Q9, and
#     +Q3/+Q4 for the mask) within the limits below (skipped without POV-Ray);
#   - the pixels no ray is traced through (outside the fisheye's circle,
#     below the omnimax's dome) black and transparent as POV-Ray writes them,
#     sample for sample in an 8-bit PNG with and without alpha;
#   - anti-aliasing through those cameras, against POV-Ray's;
#   - every exact shadow method deciding as the shadow ray does
#     (--verify-shadows), also for cameras whose rays start along a line;
#   - the same image on 1 thread and 2;
#   - bad cameras: status 2, the message at FILE:LINE:COLUMN, no image.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (may be empty:
# the comparisons with POV-Ray are skipped).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$(cd "$builddir" && pwd)/hstrace"
codes="$(cd "$builddir" && pwd)/tests/png_codes"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
tap_work hstcameras
[ -x "$hstrace" ] || bail "$hstrace is not built"
[ -x "$codes" ] || bail "$codes is not built"
run() { # runs hstrace from the scenes' folder, keeps stderr in $work/err and the status in $status
    (cd "$work" && "$hstrace" "$@" --threads 1) >"$work/out" 2>"$work/err"; status=$?
}

scenes="fisheye fisheye-default ultra-wide-angle omnimax panoramic cylinder1 cylinder2 cylinder3 cylinder4 spherical spherical-default"
cp "$srcdir/tests/cameras/world.inc" "$work/" || bail "cannot copy tests/cameras/world.inc"
for s in $scenes; do
    cp "$srcdir/tests/cameras/$s.pov" "$work/$s.pov" || bail "cannot copy tests/cameras/$s.pov"
done

limits='
# scene              RMSE   (measured)   off (m.)  mask pixels (m.)
fisheye              1e-5   (1.9e-6)     1 (0)     1 (0)
fisheye-default      1e-5   (2.2e-6)     1 (0)     1 (0)
ultra-wide-angle     1e-5   (3.1e-6)     1 (0)     1 (0)
omnimax              1e-5   (0)          1 (0)     1 (0)
panoramic            1e-5   (1.4e-6)     1 (0)     1 (0)
cylinder1            1e-5   (1.6e-6)     1 (0)     1 (0)
cylinder2            1e-5   (4.0e-6)     1 (0)     1 (0)
cylinder3            1e-5   (3.5e-7)     1 (0)     1 (0)
cylinder4            1e-5   (1.9e-6)     1 (0)     1 (0)
spherical            1e-5   (3.2e-6)     1 (0)     1 (0)
spherical-default    1e-5   (1.7e-6)     1 (0)     1 (0)
'
# shellcheck disable=SC2086 # the scene names, one word each
povray_scenes_check "$limits" tests/cameras.sh $scenes

povray=""
if [ -n "${POVRAY:-}" ]; then povray=$(command -v "$POVRAY" 2>/dev/null || true); fi

# The untraced pixels, sample for sample: 8-bit PNG with alpha and without.
for s in fisheye omnimax; do
    for ua in +UA -UA; do
        run "$s.pov" --width 160 --height 120 +FN $ua -o "$s$ua.png"
        check "$s $ua: renders a PNG" exited 0
        if [ -z "$povray" ]; then
            skip "$s $ua: the PNG sample for sample as POV-Ray's" "povray not installed (Debian package povray)"
            continue
        fi
        (cd "$work" && "$povray" "+I$s.pov" "+Opov-$s$ua.png" +FN +W160 +H120 $ua -A -D -GA +WT1 >/dev/null 2>&1)
        check "$s $ua: the PNG sample for sample as POV-Ray's" \
            test "$("$codes" "$work/pov-$s$ua.png" "$work/$s$ua.png" | sed 's/.*: \([0-9]*\) of.*/\1/')" = 0
    done
done

# Anti-aliasing (method 2, no jitter) at the circle's rim and beyond.
aa_limits='
# scene   RMSE   (measured)   off (m.)
fisheye   1e-5   (5.1e-7)     1 (0)
omnimax   1e-5   (0)          1 (0)
'
for s in fisheye omnimax; do
    run "$s.pov" --width 160 --height 120 --threads 2 +A0.1 +AM2 -J -o "$s-aa.exr"
    check "$s +A0.1 +AM2: renders" exited 0
    if [ -z "$povray" ]; then
        skip "$s +A0.1 +AM2: image matches POV-Ray" "povray not installed (Debian package povray)"
        continue
    fi
    (cd "$work" && "$povray" "+I$s.pov" "+Opov-$s-aa.exr" +FE +W160 +H120 +A0.1 +AM2 -J -D -GA +WT1 >/dev/null 2>&1)
    # shellcheck disable=SC2046 # two limits, each with its measured value
    set -- $(limit_row "$aa_limits" "$s")
    image_check "$s +A0.1 +AM2: image matches POV-Ray" "$work/pov-$s-aa.exr" "$work/$s-aa.exr" "$1" "$2" "$3" "$4"
done

# Every exact method decides as the shadow ray does: a camera with one
# origin whose outer pixels trace nothing, and two whose rays start along a line.
verify_methods_check omnimax cylinder3 cylinder4

# The same image on one thread as on two.
for s in fisheye cylinder3 spherical; do
    (cd "$work" && "$hstrace" "$s.pov" --width 120 --height 90 --threads 1 -o t1.exr >/dev/null 2>&1)
    (cd "$work" && "$hstrace" "$s.pov" --width 120 --height 90 --threads 2 -o t2.exr >/dev/null 2>&1)
    check "$s: the same image on 1 thread as on 2" "$hstrace" compare "$work/t1.exr" "$work/t2.exr" --max-rmse 0
done

# Mistakes: status 2, the message at FILE:LINE:COLUMN, no image.
bad_scenes_check <<'BAD'
camera { cylinder 5 }|invalid cylinder camera type, valid are types 1 to 4
camera { cylinder 0.5 }|invalid cylinder camera type, valid are types 1 to 4
camera { fisheye angle -10 }|negative viewing angle
camera { spherical angle -10 }|negative horizontal angle not allowed
camera { spherical angle 90, -10 }|negative vertical angle not allowed
camera { location 0 panoramic }|the camera type must come first
camera { mesh_camera { 1 0 } }|'mesh_camera' is not supported
BAD
tap_end
