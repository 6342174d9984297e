#!/bin/sh
# The shapes POV-Ray 3.7 itself intersects as planar triangles and polygons
# (issue 43), in TAP: height_field (a 16-bit grey PNG lit low to shadow
# itself, the same smooth, and two placed by transforms, one smooth and cut
# by its water level from an 8-bit PGM, one from an 8-bit colour PNG, one
# from a palette PNG),
# bicubic_patch (type 0 by flatness, type 1 by steps, uv-mapped), and
# linear-spline prisms (a linear sweep with a hole, an open one, conic
# sweeps, two through their apex: planar, though hstrace now intersects
# every prism as POV-Ray's analytic shape, tests/prisms.sh), all in
# tests/planar-shapes/:
#   - hstrace's image and shadow mask against POV-Ray's renders (+Q9, and
#     +Q3/+Q4 for the mask), RMSE within the limits below, no interior mask
#     disagreement (skipped without POV-Ray);
#   - every exact shadow method and Embree (when built in) deciding as the
#     shadow ray does, --verify-shadows: 0 disagreements;
#   - a smooth height field renders the same on 1 thread and 2.
# Their bad input (a missing picture, counts and types POV-Ray refuses) is
# in tests/hostile/ (height-field-*, prism-*, bicubic-patch-*).
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (may be empty:
# the comparisons with POV-Ray are skipped).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$(cd "$builddir" && pwd)/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
[ -x "$hstrace" ] || bail "$hstrace is not built"
tap_work hstplanar

run() { # runs hstrace from the scenes' folder, keeps stderr in $work/err and the status in $status
    (cd "$work" && exec "$hstrace" --threads 2 "$@") >"$work/out" 2>"$work/err"
    status=$?
}
# json_number FILE KEY: the first number after "KEY": in FILE.
json_number() {
    sed -n "s/.*\"$2\": \\([0-9][0-9.]*\\).*/\\1/p" "$1" | head -1
}

cp "$srcdir"/tests/planar-shapes/*.pov "$work/" || bail "cannot copy the scenes"
for kind in png16:png pgm:pgm png8:png pal:png; do
    perl "$srcdir/tests/make-heights.pl" "${kind%%:*}" "$work/hf-${kind%%:*}.${kind#*:}" ||
        bail "cannot make the height field picture ${kind%%:*}"
done
scenes="height-field height-field-smooth height-field-placed bicubic-patch prism prism-conic"

# --- against POV-Ray ---------------------------------------------------------
# At 240x180: the image (RMSE, pixels off by more than 0.02) and the shadow
# mask (no interior disagreement, at most MAX at shadow edges and
# silhouettes) against POV-Ray's, then the image again without the mask's
# tie pixels: RMSE at most 1e-4 and no pixel off there. The height fields
# lit low have a few: single pixels where POV-Ray's grid walk lets a shadow
# ray slip between two cells' triangles (its block_traversal and
# dda_traversal step by epsilons) at a shadow edge, lit in its image alone.
limits='
# scene               RMSE   (measured)   off (m.)  mask pixels (m.)  RMSE without ties (m.)
height-field          2e-3   (1.09e-3)    6 (4)     6 (3)             1e-4 (3.33e-5)
height-field-smooth   1e-3   (2.31e-4)    6 (3)     6 (3)             1e-4 (1.31e-6)
height-field-placed   1e-4   (1.59e-6)    0 (0)     2 (0)             1e-4 (1.59e-6)
bicubic-patch         1e-4   (1.80e-6)    0 (0)     2 (0)             1e-4 (1.80e-6)
prism                 1e-4   (2.31e-6)    0 (0)     2 (0)             1e-4 (2.31e-6)
prism-conic           1e-4   (1.44e-6)    0 (0)     2 (0)             1e-4 (1.44e-6)
'
if [ -n "${POVRAY:-}" ] && povray=$(command -v "$POVRAY" 2>/dev/null); then
    for name in $scenes; do
        rendered=1
        for q in 9 3 4; do
            run "$name.pov" --width 240 --height 180 "+Q$q" -o "$name.h$q.exr"
            check "$name: hstrace renders at +Q$q" exited 0 || rendered=0
            # POV-Ray 3.7 can time out starting its threads on a loaded machine: one retry
            (cd "$work" && { "$povray" "+I$name.pov" "+O$name.p$q.exr" +FE +W240 +H180 -A -D -GA +WT1 "+Q$q" \
                >/dev/null 2>&1 || "$povray" "+I$name.pov" "+O$name.p$q.exr" +FE +W240 +H180 -A -D -GA +WT1 \
                "+Q$q" >/dev/null 2>&1; })
            [ -s "$work/$name.p$q.exr" ] || { not_ok "$name: POV-Ray renders at +Q$q"; rendered=0; }
        done
        [ $rendered = 1 ] || continue
        # shellcheck disable=SC2046 # four limits, each with its measured value
        set -- $(limit_row "$limits" "$name")
        [ $# -eq 8 ] || { not_ok "$name: limits recorded in tests/planar-shapes.sh"; continue; }
        a=$work/$name.p b=$work/$name.h
        image_check "$name: image matches POV-Ray" "${a}9.exr" "${b}9.exr" "$1" "$2" "$3" "$4"
        mask_check "$name: shadow mask matches POV-Ray" "${a}3.exr" "${a}4.exr" "${b}3.exr" "${b}4.exr" "$5" "$6"
        ties_check "$name: image matches POV-Ray" "${a}9.exr" "${b}9.exr" "$7" "$8" 0 0
    done
else
    skip "images and shadow masks against POV-Ray" "povray not installed (Debian package povray)"
fi

# --- every method decides as the shadow ray ---------------------------------
methods="conventional cache light-buffer volume hst"
if "$hstrace" --version 2>/dev/null | grep -q 'Embree [0-9]'; then methods="$methods embree"; fi
for name in $scenes; do
    for method in $methods; do
        run "$name.pov" --width 160 --height 120 --shadows "$method" --volumes always --verify-shadows \
            --stats-json "$name.$method.json" -o "$name.$method.exr"
        check "$name: $method renders with --verify-shadows" exited 0
        verified=$(json_number "$work/$name.$method.json" verified)
        disagreements=$(json_number "$work/$name.$method.json" disagreements)
        check "$name: $method verified $verified decisions" above "$verified" 0
        check_status "$name: $method agrees with the shadow ray: $disagreements disagreements in $verified decisions" \
            "$disagreements" 0
    done
done

# --- the same image on any number of threads --------------------------------
run height-field-placed.pov --width 160 --height 120 -o one.exr --threads 1
check "height-field-placed: renders on 1 thread" exited 0
check "height-field-placed: the same image on 1 thread as on 2" \
    "$hstrace" compare "$work/one.exr" "$work/height-field-placed.conventional.exr" --max-error 0
tap_end
