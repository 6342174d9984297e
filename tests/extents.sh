#!/bin/sh
# min_extent and max_extent (parser/grammar/object_extent.c), in TAP:
# tests/extents/extents.pov writes the bounding box POV-Ray keeps for each
# kind of object hstrace models it for (spheres through the transforms a
# sphere takes into its centre and radius and through those that make it
# an ellipsoid, boxes moved and turned, cylinders and cones either way
# round, tori, discs, triangles, meshes, polygons, planes,
# superellipsoids, unions and intersections, copies of declared objects
# turned again) and transforms.inc's Center_Trans and Align_Trans made of
# them; each line must be POV-Ray's own, every corner within 1e-6 of it
# (both print nine decimals of single-precision values). Then an object
# whose box hstrace does not keep: status 2, the position where the value
# is used, no image.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (may be empty:
# the comparison with POV-Ray is skipped).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$(cd "$builddir" && pwd)/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
tap_work hstextents
[ -x "$hstrace" ] || bail "$hstrace is not built"

mkdir "$work/h" "$work/p"
for d in h p; do
    cp "$srcdir/tests/extents/extents.pov" "$work/$d/" || bail "cannot copy the scene"
done
(cd "$work/h" && "$hstrace" extents.pov --width 4 --height 3 --threads 1 -o out.png >/dev/null 2>"$work/err")
check_status "extents.pov renders ($(head -1 "$work/err"))" $? 0
lines=$(grep -c . "$work/h/extents.txt" 2>/dev/null || echo 0)
check "extents.pov writes a line per object (45)" same_count "$lines" 45

povray=""
if [ -n "${POVRAY:-}" ]; then povray=$(command -v "$POVRAY" 2>/dev/null || true); fi
if [ -z "$povray" ]; then
    skip "each box is POV-Ray's" "povray is not installed"
else
    (cd "$work/p" && "$povray" +W4 +H3 -D -GA +Iextents.pov +Oout.png >/dev/null 2>&1)
    # name, then the six corners' values; every one within 1e-6 of POV-Ray's
    while read -r name v1 v2 v3 v4 v5 v6; do
        want=$(grep "^$name " "$work/p/extents.txt" | head -1)
        if [ -z "$want" ]; then
            not_ok "$name: POV-Ray wrote no box for it"
            continue
        fi
        close() {
            echo "$1 $2 $3 $4 $5 $6 $want" | awk '{ for (i = 1; i <= 6; i++) { d = $i - $(i + 7); if (d < 0) d = -d;
                m = $(i + 7) < 0 ? -$(i + 7) : $(i + 7); if (d > 1e-6 * (1 + m)) exit 1 } }'
        }
        check "$name: <$v1, $v2, $v3> to <$v4, $v5, $v6> as POV-Ray's ($want)" close "$v1" "$v2" "$v3" "$v4" "$v5" "$v6"
    done <"$work/h/extents.txt"
fi

# An object whose box hstrace does not keep: refused where the value is
# used (a declaration defers it, as POV-Ray's functions hstrace lacks).
printf '%s\n' '#declare L = lathe { 3, <0, 0>, <1, 1>, <0, 2> }' '#declare V = min_extent(L);' 'sphere { V, 1 }' \
    >"$work/bad.pov"
"$hstrace" "$work/bad.pov" --width 4 --height 3 -o "$work/bad.png" >/dev/null 2>"$work/err"
status=$?
check_status "min_extent of a lathe: status 2" "$status" 2
check "min_extent of a lathe: refused at bad.pov:3:10" \
    grep -q "bad.pov:3:10: 'min_extent' of this kind of object is not supported by hstrace (declared at .*bad.pov:2)" "$work/err"
check_fails "min_extent of a lathe: no image" test -e "$work/bad.png"
tap_end
