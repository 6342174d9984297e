#!/bin/sh
# Layered textures (`texture { A } texture { B }`, B on A, as woods.inc and
# stones.inc write them) and interior_texture, in TAP: the scenes of
# tests/layered-textures/ (see-through upper layers over patterned ones, a
# finish and a normal per layer, shadows through filtering and transmitting
# layers, a POV-Ray 3.6 scene with an object moved between its layers;
# interior textures on shapes and boxes, a mirrored one, seen through gaps
# in the outer texture and filtering shadows, on prisms, lathes, sors and
# superellipsoids cut open; tiles, POV-Ray's checker of
# two textures), each rendered by hstrace
# and by POV-Ray 3.7 (+Q9 for the image, +Q3 and +Q4 for the shadow mask)
# and compared by `hstrace compare` against the limits measured for each;
# then every exact shadow method on each scene with --verify-shadows: not
# one decision may differ from the shadow ray's. And: the same image on 1
# thread as on 2; a layered texture renders under --strict (it is shaded as
# POV-Ray shades it, not approximated), while a layered texture_map entry,
# still blended into one pigment, is refused by --strict; a texture_map as
# a layer, an interior texture on a surface whose inside hstrace cannot
# tell, one without an outer texture, and tiles without a tile's texture
# (POV-Ray stops with a segmentation fault on a missing tile2 texture) are
# refused at FILE:LINE:COLUMN.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (path or name of
# povray; may be empty: the comparisons with POV-Ray are skipped).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$(cd "$builddir" && pwd)/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
tap_work hstlayers
[ -x "$hstrace" ] || bail "$hstrace is not built"
run() { # runs hstrace, keeps stderr in $work/err and the status in $status
    "$hstrace" "$@" --threads 1 >"$work/out" 2>"$work/err"; status=$?
}

scenes="layers-transparent layers-finishes layers-normals layers-shadow layers-legacy interior-texture interior-texture-placed interior-texture-swept interior-texture-prism-below tiles"
for s in $scenes; do
    cp "$srcdir/tests/layered-textures/$s.pov" "$work/$s.pov" || bail "cannot copy tests/layered-textures/$s.pov"
done

# Before layers were shaded one by one (blended into one pigment with the
# top layer finish) these scenes were off by an RMSE of 0.027 to 0.087.
limits='
# scene              RMSE   (measured)   off (m.)  mask pixels (m.)
layers-transparent   1e-4   (1.4e-6)     0 (0)     1 (0)
layers-finishes      1e-4   (2.1e-5)     0 (0)     1 (0)
layers-normals       1e-4   (2.3e-5)     0 (0)     1 (0)
layers-shadow        1e-4   (3.0e-6)     0 (0)     1 (0)
layers-legacy        1e-4   (1.9e-6)     0 (0)     1 (0)
# interior-texture: one pixel on the silhouette of the see-through sphere,
# as many without its interior texture
interior-texture     7e-4   (3.6e-4)     2 (1)     1 (0)
# interior-texture-placed: six single pixels, two where a ray meets the
# union box edge (as many without its interior texture) and four where a
# shadow ray from inside the box leaves it by an edge, lit in one render
# and not in the other (none with an interior texture that takes no light)
interior-texture-placed 3.6e-3 (1.8e-3)  12 (6)    1 (0)
# interior-texture-swept: one pixel (100, 150) off, and one at a shadow edge
interior-texture-swept 1e-3 (4.8e-4)     2 (1)     2 (1)
# interior-texture-prism-below: a row of pixels along the far edges of the bases,
# where a cap and a side meet, shows the texture of the other surface
interior-texture-prism-below 5e-3 (4.4e-3) 80 (74)  1 (0)
tiles                1e-4   (1.2e-6)     0 (0)     1 (0)
'
# shellcheck disable=SC2086 # the scene names, one word each
povray_scenes_check "$limits" tests/layered-textures.sh $scenes

# Every exact method decides as the shadow ray does, light through the
# layers included.
# shellcheck disable=SC2086 # the scene names, one word each
verify_methods_check $scenes

# The same image on any number of threads.
"$hstrace" "$work/layers-shadow.pov" --width 160 --height 120 --threads 1 -o "$work/one.exr" >/dev/null 2>&1
check "layers-shadow: renders on 1 thread" test -s "$work/one.exr"
"$hstrace" "$work/layers-shadow.pov" --width 160 --height 120 --threads 2 -o "$work/two.exr" >/dev/null 2>&1
check "layers-shadow: the same image on 1 thread as on 2" \
    "$hstrace" compare "$work/one.exr" "$work/two.exr" --max-error 0

# Layered textures are shaded, not approximated: --strict renders them.
run "$work/layers-transparent.pov" --strict --width 32 --height 24 -o "$work/strict.exr"
check "layered textures render under --strict" exited 0
# A texture_map entry that is a layered texture is still blended into one
# pigment: noted, and refused by --strict at the texture_map.
cat >"$work/map-entry.pov" <<'EOF'
#declare T = texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 0.5> } }
sphere { 0, 1 texture { gradient x texture_map { [0 T] [1 pigment { rgb 0 }] } } }
EOF
run "$work/map-entry.pov" --width 8 --height 6 -o "$work/map-entry.png"
check "a layered texture_map entry: renders" exited 0
check "a layered texture_map entry: noted as blended" grep -q "map-entry.pov:2:36: warning: 'texture_map' approximated: texture layers blended" "$work/err"
run "$work/map-entry.pov" --strict --width 8 --height 6 -o "$work/map-entry.png"
check "a layered texture_map entry: refused by --strict" exited 2

# Mistakes and what hstrace does not shade: status 2, FILE:LINE:COLUMN, no image.
bad_scenes_check <<'BAD'
sphere { 0, 1 texture { pigment { rgbt 0.5 } } texture { checker texture { pigment { rgb 1 } } texture { } } }|'texture_map in layered textures' is not supported
sphere { 0, 1 texture { pigment { rgbt 0.5 } } texture { pigment { rgbt } } }|expected
mesh { triangle { 0, x, y } texture { pigment { rgb 1 } } interior_texture { pigment { rgb 1 } } }|'interior_texture' on a 'mesh' is not supported
sphere { 0, 1 interior_texture { pigment { rgb 1 } } }|Interior texture requires an exterior texture
sphere { 0, 1 texture { tiles { tile2 texture { pigment { rgb 1 } } } } }|First texture missing from tiles
sphere { 0, 1 texture { tiles { texture { pigment { rgb 1 } } tile2 } } }|Second texture missing from tiles
sphere { 0, 1 texture { tiles { texture { pigment { rgb 1 } } } } }|expected texture or tile2 in 'tiles'
sphere { 0, 1 texture { pigment { rgb 1 } tiles { texture { pigment { rgb 1 } } tile2 texture { pigment { rgb 0 } } } } }|tiles must come first in its texture
BAD
tap_end
