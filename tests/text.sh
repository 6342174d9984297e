#!/bin/sh
# The text object (POV-Ray 3.7's TrueType text), in TAP: the scenes of
# tests/text/, which use the fonts Debian's povray-includes installs
# (timrom.ttf, cyrvetic.ttf, crystal.ttf, povlogo.ttf, read where they are
# installed), each rendered by hstrace and by POV-Ray 3.7 and compared
# against the limits measured for each (the table below); every exact
# shadow method on each with --verify-shadows; bad input refused at
# FILE:LINE:COLUMN with status 2; one image for any thread count. Built
# without FreeType, text is refused where it is written and the rest is
# skipped.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (path or name of
# povray; may be empty: the comparisons with POV-Ray are skipped), POVINC
# (POV-Ray's include folder, where its fonts are).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$(cd "$builddir" && pwd)/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
tap_work hsttext
[ -x "$hstrace" ] || bail "$hstrace is not built"
run() { # runs hstrace, keeps stderr in $work/err and the status in $status
    "$hstrace" "$@" --threads 1 >"$work/out" 2>"$work/err"; status=$?
}

fonts=${POVINC:-/usr/share/povray-3.7/include}
for f in timrom cyrvetic crystal povlogo; do
    if [ ! -f "$fonts/$f.ttf" ]; then
        echo "1..0 # SKIP $fonts/$f.ttf is not installed (Debian package povray-includes)"
        exit 0
    fi
done

# Built without FreeType: refused where it is written, nothing else to test.
printf '%s\n' 'camera { location -z look_at 0 }' 'text { ttf "timrom.ttf" "A" 1, 0 }' >"$work/probe.pov"
run "$work/probe.pov" --width 8 --height 6 -o "$work/probe.png"
if grep -q "built without FreeType" "$work/err"; then
    check "built without FreeType: text refused with status 2 at FILE:LINE:COLUMN" \
        test "$status $(grep -c "^$work/probe.pov:2:[0-9]*: .*built without FreeType" "$work/err")" = "2 1"
    skip "the text scenes" "hstrace built without FreeType (Debian package libfreetype-dev)"
    tap_end
    exit 0
fi
check "a text object renders" test "$status" = 0

scenes="text-front text-grazing text-transformed text-thickness text-csg text-utf8 text-ascii text-extent text-clip text-version"
for s in $scenes; do
    cp "$srcdir/tests/text/$s.pov" "$work/$s.pov" || bail "cannot copy tests/text/$s.pov"
done

limits='
# scene              RMSE   (measured)   off (m.)  mask pixels (m.)
text-front           1e-5   (2.5e-6)     1 (0)     1 (0)
text-grazing         1e-5   (2.1e-6)     1 (0)     1 (0)
text-transformed     1e-5   (1.4e-6)     1 (0)     1 (0)
text-thickness       1e-5   (2.9e-6)     1 (0)     1 (0)
# text-csg: one pixel seen through the see-through merge differs by 0.009
text-csg             5e-5   (2.4e-5)     1 (0)     1 (0)
text-utf8            1e-5   (2.7e-6)     1 (0)     1 (0)
text-ascii           1e-5   (2.6e-6)     1 (0)     1 (0)
text-extent          1e-5   (1.2e-6)     1 (0)     1 (0)
text-clip            1e-5   (2.1e-6)     1 (0)     1 (0)
text-version         1e-5   (2.6e-6)     1 (0)     1 (0)
'
# shellcheck disable=SC2086 # the scene names, one word each
povray_scenes_check "$limits" tests/text.sh $scenes

# Every exact method decides as the shadow ray does, on every scene.
# shellcheck disable=SC2086 # the scene names, one word each
verify_methods_check $scenes

# Mistakes: status 2, the message at FILE:LINE:COLUMN, no image.
bad_scenes_check <<'BAD'
text { ttf "no-such-font.ttf" "A" 1, 0 }|cannot find the font file 'no-such-font.ttf'
text { ttf "timrom.ttf" "A" 1 }|expected
text { ttf "timrom.ttf" 1, 0 }|expected a string
text { font "timrom.ttf" "A" 1, 0 }|ttf or internal
text { ttf "timrom.ttf" "A", , 0 }|expected a numeric expression
global_settings { charset latin1 }|ascii, utf8 or sys
text { ttf "timrom.ttf" "\u0041" 1, 0 }|the escape \\u in a text string
#declare S = lathe { 3, <0, 0>, <1, 1>, <0, 2> } #declare V = min_extent(S); sphere { V, 1 }|'min_extent' of this kind of object is not supported
BAD
# an empty text: POV-Ray's box of everything, +-1e10 (it was refused as
# "an object other than text")
printf '%s\n' '#declare T = text { internal 1 "" 0.1, 0 }' \
    '#debug concat(vstr(3, min_extent(T), ",", 0, 0), " ", vstr(3, max_extent(T), ",", 0, 0), "\n")' \
    'sphere { 0, 1 }' >"$work/empty-extent.pov"
run "$work/empty-extent.pov" --width 8 --height 6 -o "$work/empty-extent.png"
check "min_extent and max_extent of an empty text: POV-Ray's +-1e10 ($(grep -v warning "$work/err" | head -n 1))" \
    test "$status $(grep -c '^-10000000000,-10000000000,-10000000000 10000000000,10000000000,10000000000$' "$work/err")" = "0 1"
# a file that is no font
printf 'not a font\n' >"$work/bogus.ttf"
printf '%s\n' 'text { ttf "bogus.ttf" "A" 1, 0 }' >"$work/bogus.pov"
run "$work/bogus.pov" --width 8 --height 6 -o "$work/bogus.png"
check "a file that is no font: status 2 at FILE:LINE:COLUMN, no image" \
    test "$status $(grep -c "^$work/bogus.pov:1:[0-9]*: .*font" "$work/err") $([ -e "$work/bogus.png" ] && echo image || echo none)" = "2 1 none"

# The same image on one thread as on two.
for s in text-front text-csg; do
    "$hstrace" "$work/$s.pov" --width 120 --height 90 --threads 1 -o "$work/t1.exr" >/dev/null 2>&1
    "$hstrace" "$work/$s.pov" --width 120 --height 90 --threads 2 -o "$work/t2.exr" >/dev/null 2>&1
    check "$s: the same image on 1 thread as on 2" "$hstrace" compare "$work/t1.exr" "$work/t2.exr" --max-rmse 0
done
tap_end
