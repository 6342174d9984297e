#!/bin/sh
# What mesh exporters write (issue 20), in TAP: `material { texture {...}
# interior {...} }` declared and used, image_map on polygons and uv-mapped
# meshes, texture_map (patterned textures, see-through ones casting
# shadows), a material identifier first in a
# material, transforms in a material that move its texture and not the
# object, on a polygon, a triangle and mesh objects, against the installed
# POV-Ray's image of the same scene; and the mistakes: another kind of
# identifier in a material, a material identifier after its first item,
# interior_texture; and image_map's bad pictures (a missing file, junk, the
# damaged ones of tests/hostile/images: truncated PNG and JPEG, 0x0 and
# oversized headers): status 2 at the file name, which the message names,
# and no image. (The project's exporter-style scenes, scenes/poseray.pov
# among them, are held to POV-Ray by tests/regress.sh.)
#
# Environment: top_builddir (default .), POVRAY (path or name of povray;
# default povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstexport.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
run() { (cd "$work" && "$hstrace" "$@") >"$work/out" 2>"$work/err"; status=$?; }
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)

# --- material, as PoseRay and Blender's exporter write it ----------------------
cat >"$work/material.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> }
light_source { <3, 6, -4> color rgb 1 }
#declare Glass = material {
    texture { pigment { color rgbf <0.9, 1, 0.9, 0.8> } finish { reflection 0.1 } }
    interior { ior 1.4 }
}
#declare Checks = material {
    texture { pigment { checker color rgb <1,0.3,0.2> color rgb <0.9,0.9,0.8> scale 0.5 } }
    translate <0.25, 0, 0.25>
}
#declare Tri = mesh { triangle { <-1,0,0>, <1,0,0>, <0,1.5,0> } }
polygon { 4, <-3,0,-2>, <3,0,-2>, <3,0,4>, <-3,0,4> material { Checks } }
object { Tri material { Glass } translate <-1.2, 0, 0> }
object { Tri material { Checks scale 2 } translate <1.2, 0, 0.5> }
triangle { <-0.5,0.2,-1>, <0.5,0.2,-1>, <0,1,-1> material { texture { pigment { color rgb <0.2,0.8,0.3> } } } }
EOF
run material.pov +W160 +H120 -o material.png
check "declared materials (texture, interior, a transform), on a polygon, a triangle and meshes: renders" \
    test "$status $(wc -c <"$work/err" | tr -d ' ')" = "0 0"
if [ -n "$povray" ]; then
    (cd "$work" && "$povray" +Imaterial.pov +W160 +H120 +Omaterial-pov.png -D -GA +WT1 >/dev/null 2>&1)
    check "... as POV-Ray renders it, pixel for pixel (RMSE 0 measured; limit 1e-5)" \
        "$hstrace" compare "$work/material-pov.png" "$work/material.png" --max-rmse 1e-5 --max-share 0
    # The material's translate moves its checker, not the polygon: moving
    # the polygon instead (hstrace's old reading) gives another image.
    sed 's/polygon { 4, <-3,0,-2>, <3,0,-2>, <3,0,4>, <-3,0,4> material { Checks } }/polygon { 4, <-3,0,-2>, <3,0,-2>, <3,0,4>, <-3,0,4> material { Checks } translate <0.25, 0, 0.25> }/' \
        "$work/material.pov" >"$work/moved.pov"
    run moved.pov +W160 +H120 -o moved.png
    check_fails "a material's transform is not the object's: moving the object too is outside the limits" \
        "$hstrace" compare "$work/material-pov.png" "$work/moved.png" --max-rmse 1e-5 --max-share 0
else
    skip "... as POV-Ray renders it" "povray not installed"
    skip "a material's transform is not the object's" "povray not installed"
fi

# --- mistakes --------------------------------------------------------------------
while IFS='|' read -r scene message; do
    printf '%s\n' "$scene" >"$work/bad.pov"
    run bad.pov +W8 +H6 -o bad.png
    check "$message: status 2, FILE:LINE:COLUMN, no image" \
        test "$status $(grep -c "^bad.pov:[0-9]*:[0-9]*: .*$message" "$work/err") $([ -e "$work/bad.png" ] && echo image || echo none)" = "2 1 none"
done <<'BAD'
#declare T = texture { pigment { color rgb 1 } } triangle { <0,0,0>, <1,0,0>, <0,1,0> material { T } }|'T' cannot be used in a material
#declare M = material { texture { pigment { color rgb 1 } } } triangle { <0,0,0>, <1,0,0>, <0,1,0> material { texture { pigment { color rgb 0.5 } } M } }|expected a material identifier (only first)
triangle { <0,0,0>, <1,0,0>, <0,1,0> material { interior_texture { pigment { color rgb 0.5 } } } }|'interior_texture' is not supported
#declare T = texture { pigment { color rgb 1 } } triangle { <0,0,0>, <1,0,0>, <0,1,0> texture { tiling 3 texture_map { [0 T] [1 T] } } }|'texture_map (a texture patterned by tiling)' is not supported
BAD
# --- includes from the current folder, where POV-Ray looks first ------------------
mkdir -p "$work/scenes"
printf '#declare Paint = rgb <1, 0.2, 0.1>;\n' >"$work/paint.inc"
printf '#include "paint.inc"\ncamera { location <0,0,-3> look_at 0 }\nlight_source { <2,4,-3> color rgb 1 }\ntriangle { <-1,-1,0>, <1,-1,0>, <0,1,0> pigment { color Paint } }\n' \
    >"$work/scenes/uses-inc.pov"
run scenes/uses-inc.pov +W16 +H12 -o inc.png
check "an include found in the current folder, not the scene's: renders" exited 0
if [ -n "$povray" ]; then
    (cd "$work" && "$povray" +Iscenes/uses-inc.pov +W16 +H12 +Oinc-pov.png -D -GA +WT1 >/dev/null 2>&1)
    check "... as POV-Ray renders it" "$hstrace" compare "$work/inc-pov.png" "$work/inc.png" --max-error 0
else
    skip "... as POV-Ray renders it" "povray not installed"
fi
# Both folders have one: the current folder's is taken, as POV-Ray takes it.
printf '#declare Paint = rgb <0.1, 0.2, 1>;\n' >"$work/scenes/paint.inc"
run scenes/uses-inc.pov +W16 +H12 -o inc-both.png
if [ -n "$povray" ]; then
    (cd "$work" && "$povray" +Iscenes/uses-inc.pov +W16 +H12 +Oinc-both-pov.png -D -GA +WT1 >/dev/null 2>&1)
    check "an include in both the current and the scene's folder: the current folder's, as POV-Ray takes it" \
        "$hstrace" compare "$work/inc-both-pov.png" "$work/inc-both.png" --max-error 0
else
    skip "an include in both folders: the current folder's" "povray not installed"
fi
check "... which is not the scene's folder's" "$hstrace" compare "$work/inc.png" "$work/inc-both.png" --max-error 0
rm "$work/scenes/paint.inc"
(cd "$work/scenes" && "$hstrace" uses-inc.pov +W16 +H12 -o ../inc-elsewhere.png) >"$work/out" 2>"$work/err"
status=$?
check "... and from another current folder: an I/O error naming the include, status 3" exited 3 "paint.inc"
# --- radiosity scenes: POV-Ray 3.7 uses no ambient -----------------------------
# An emitter lit by ambient only, and a floor it would light by radiosity,
# which is black when ambient is off: the image is exact though radiosity
# is not modelled.
cat >"$work/radiosity.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 radiosity { count 20 } }
camera { location <0,0,-3> look_at 0 }
light_source { <2,4,-3> color rgb 1 }
triangle { <-1,-1,0>, <1,-1,0>, <0,1,0> pigment { color rgb <1,0.5,0.2> } finish { ambient 1 diffuse 0 } }
triangle { <-2,-1,1>, <2,-1,1>, <0,-1,-2> pigment { color rgb 0.7 } finish { ambient 0.3 diffuse 0.6 } }
EOF
run radiosity.pov +W32 +H24 -o radiosity.png
check "a radiosity scene: renders (radiosity noted as approximated)" exited 0 "radiosity"
if [ -n "$povray" ]; then
    (cd "$work" && "$povray" +Iradiosity.pov +W32 +H24 +Oradiosity-pov.png -D -GA +WT1 >/dev/null 2>&1)
    check "... with no ambient, as POV-Ray 3.7 renders it (RMSE 0 measured)" \
        "$hstrace" compare "$work/radiosity-pov.png" "$work/radiosity.png" --max-error 0
else
    skip "... with no ambient, as POV-Ray 3.7 renders it" "povray not installed"
fi
# Below +Q9 POV-Ray turns radiosity off, and the ambient is back.
run radiosity.pov +W32 +H24 +Q8 -o radiosity-q8.png
if [ -n "$povray" ]; then
    (cd "$work" && "$povray" +Iradiosity.pov +W32 +H24 +Q8 +Oradiosity-q8-pov.png -D -GA +WT1 >/dev/null 2>&1)
    check "... at +Q8, where POV-Ray turns radiosity off, with the ambient, as POV-Ray renders it" \
        "$hstrace" compare "$work/radiosity-q8-pov.png" "$work/radiosity-q8.png" --max-error 0
else
    skip "... at +Q8, with the ambient, as POV-Ray renders it" "povray not installed"
fi
check_fails "... which is not the +Q9 image" "$hstrace" compare "$work/radiosity.png" "$work/radiosity-q8.png" --max-error 0.1
sed 's/#version 3.7;/#version 3.6;/' "$work/radiosity.pov" >"$work/radiosity36.pov"
run radiosity36.pov +W32 +H24 -o radiosity36.png
check_fails "a #version 3.6 radiosity scene keeps its ambient (another image)" \
    "$hstrace" compare "$work/radiosity.png" "$work/radiosity36.png" --max-error 0.1
# --- old includes: #version 2.0 and values without ';' ----------------------------
# As old include files are written (and the idiom that restores the caller's
# version at their end): the last #declare lacks its ';', and the lookahead
# for it reads the #version that follows.
cat >"$work/old.inc" <<'EOF'
#local Saved_Version = version;
#version 2.0;
#declare Old_Red = color red 1 green 0.2
#declare Old_Blue = colour rgb <0.1, 0.2, 1>
#declare Old_Scale = 0.5
#version Saved_Version;
EOF
cat >"$work/uses-old.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
#include "old.inc"
camera { location <0,0,-3> look_at 0 }
light_source { <2,4,-3> color rgb 1 }
triangle { <-1,-1,0>, <1,-1,0>, <0,1,0> pigment { color Old_Red } scale Old_Scale }
triangle { <-1,-1,0.5>, <2,-1,0.5>, <0,1.5,0.5> pigment { color Old_Blue } }
EOF
run uses-old.pov +W32 +H24 -o old.png
check "an include of #version 2.0 with values without ';', ending with #version Saved_Version: renders" exited 0
if [ -n "$povray" ]; then
    (cd "$work" && "$povray" +Iuses-old.pov +W32 +H24 +Oold-pov.png -D -GA +WT1 >/dev/null 2>&1)
    check "... as POV-Ray renders it" "$hstrace" compare "$work/old-pov.png" "$work/old.png" --max-error 0
else
    skip "... as POV-Ray renders it" "povray not installed"
fi
# Which version decides, as POV-Ray 3.7.0.10 decides it (measured): the one
# the value was read under.
while IFS='|' read -r before after want; do
    printf '%s\n#declare F = 0.5\n%s\ncamera { location <0,0,-3> look_at 0 }\ntriangle { <-1,-1,0>, <1,-1,0>, <0,1,0> }\n' \
        "$before" "$after" >"$work/semicolon.pov"
    run semicolon.pov +W8 +H6 -o semicolon.png
    got=$([ "$status" = 0 ] && echo renders || echo "error $status")
    check "'$before #declare F = 0.5 $after': $want, as in POV-Ray" test "$got" = "$want"
done <<'VERSIONS'
#version 3.7;|#version 3.1;|error 2
#version 3.7;||error 2
#version 2.0;|#version 3.7;|renders
#version 2.0;|#declare Q = 1; #version 3.7;|renders
VERSIONS
# --- image_map, as exporters write it ---------------------------------------------
# Pictures made here: a 4x3 PPM written by hand, and desk rendered small to
# PNG with alpha, JPEG and Targa with alpha.
printf 'P3\n4 3\n255\n255 0 0  0 255 0  0 0 255  255 255 0\n0 255 255  255 0 255  128 128 128  255 255 255\n10 20 30  200 100 50  50 200 100  0 0 0\n' \
    >"$work/tex.ppm"
# Colour-mapped pictures (tests/make-indexed.pl): 8-bit and 4-bit palette
# PNGs, one with a half transparent entry, and an 8-bit BMP.
for args in "png p8.png" "png p4.png 4" "png pt.png trns" "bmp p8.bmp"; do
    # shellcheck disable=SC2086 # split into words on purpose
    set -- $args
    kind=$1 name=$2
    shift 2
    perl "$srcdir/tests/make-indexed.pl" "$kind" "$work/$name" "$@" ||
        { echo "Bail out! tests/make-indexed.pl failed (perl's Compress::Zlib, Debian package perl)"; exit 1; }
done
head -c 90 "$work/p8.png" >"$work/p8-truncated.png" # its palette read, its pixels cut short
cp "$srcdir/scenes/desk.pov" "$work/desk.pov"
run desk.pov +W40 +H30 +FN +UA +Odesk-alpha
run desk.pov +W40 +H30 +UA -o desk-alpha.exr
run desk.pov +W40 +H30 +FJ +Odesk-pic
run desk.pov +W40 +H30 +FT +UA +Odesk-pic
cat >"$work/imagemap.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 1.2, -2.5> look_at <0.5, 0.4, 0> }
light_source { <2, 5, -4> color rgb 1 }
plane { y, -0.01 pigment { color rgb <0.9, 0.8, 0.7> } }
polygon { 4, <-1,0,0>, <0,0,0>, <0,1,0>, <-1,1,0> pigment { image_map { ppm "tex.ppm" interpolate 2 } translate <-1,0,0> } }
polygon { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> pigment { image_map { jpeg "desk-pic.jpg" interpolate 4 once } scale 0.8 translate <0.1,0.1,0> } }
polygon { 4, <1,0,0>, <2,0,0>, <2,1,0>, <1,1,0> pigment { image_map { tga "desk-pic.tga" transmit all 0.3 } scale 0.5 translate <1,0,0> } }
polygon { 4, <-1,0,-0.5>, <2,0,-0.5>, <2,0.5,-0.7>, <-1,0.5,-0.7> pigment { image_map { "desk-alpha.png" filter all 0.4 interpolate 2 } scale <3,0.5,1> translate <-1,0,0> } }
mesh2 {
  vertex_vectors { 4, <-1,1.2,0.2>, <2,1.2,0.2>, <2,2,0.2>, <-1,2,0.2> }
  uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> }
  face_indices { 2, <0,1,2>, <0,2,3> }
  uv_indices { 2, <0,1,2>, <0,2,3> }
  uv_mapping pigment { image_map { ppm "tex.ppm" interpolate 2 } }
}
EOF
run imagemap.pov +W160 +H120 --verify-shadows --stats-json imagemap.json -o imagemap.png
check "image_map (PPM, JPEG, Targa and PNG with alpha; interpolate 0, 2, 4; once; filter and transmit all; a uv-mapped mesh2): renders, 0 disagreements with the shadow ray" \
    test "$status $(grep -o '"disagreements": [0-9]*' "$work/imagemap.json" | head -n 1 | grep -o '[0-9]*$')" = "0 0"
if [ -n "$povray" ]; then
    (cd "$work" && "$povray" +Iimagemap.pov +W160 +H120 +Oimagemap-pov.png -D -GA +WT1 >/dev/null 2>&1)
    check "... as POV-Ray renders it, shadows through the pictures' transparency included (RMSE 0 measured)" \
        "$hstrace" compare "$work/imagemap-pov.png" "$work/imagemap.png" --max-rmse 1e-5 --max-share 0
else
    skip "... as POV-Ray renders it" "povray not installed"
fi
# map_type 1 (spherical), 2 (cylindrical) and 5 (torus) on boxes, once
# and interpolated too (any other type is an error, as in POV-Ray: below).
cat >"$work/maptypes.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 0.3, 0> }
light_source { <3, 5, -4> color rgb 1 }
plane { y, -1 pigment { color rgb 0.7 } }
box { -0.6, 0.6 pigment { image_map { "desk-alpha.png" map_type 1 interpolate 2 } } rotate <20, 30, 0> translate <-1.6, 0, 0> }
box { -0.6, 0.6 pigment { image_map { ppm "tex.ppm" map_type 2 } scale <1, 0.5, 1> } rotate <-15, 40, 0> }
box { <-0.6, -0.3, -0.6>, <0.6, 0.3, 0.6> pigment { image_map { jpeg "desk-pic.jpg" map_type 2 once } } rotate 25*y translate <0, 1.2, 0.5> }
box { <-1.3, -0.25, -1.3>, <1.3, 0.25, 1.3> pigment { image_map { tga "desk-pic.tga" map_type 5 interpolate 4 } } rotate <30, 20, 0> scale 0.6 translate <1.6, 0, 0> }
box { -0.3, 0.3 pigment { image_map { ppm "tex.ppm" map_type 0 } } translate <1.6, 1.2, 0> }
EOF
run maptypes.pov +W160 +H120 -o maptypes.png
check "image_map map_type 1, 2, 5 and 0: renders" exited 0
sed 's/map_type [125]/map_type 0/' "$work/maptypes.pov" >"$work/maptypes-flat.pov"
run maptypes-flat.pov +W160 +H120 -o maptypes-flat.png
# shellcheck disable=SC2016 # the inner shell expands its arguments
check "... and not as planar ones (differs from all map_type 0 by RMSE > 0.01)" \
    sh -c '! "$1" compare "$2" "$3" --max-rmse 0.01 >/dev/null' sh "$hstrace" "$work/maptypes.png" "$work/maptypes-flat.png"
if [ -n "$povray" ]; then
    (cd "$work" && "$povray" +Imaptypes.pov +W160 +H120 +Omaptypes-pov.png -D -GA +WT1 >/dev/null 2>&1)
    check "... as POV-Ray maps them (spherical, cylindrical, torus, planar)" \
        "$hstrace" compare "$work/maptypes-pov.png" "$work/maptypes.png" --max-rmse 1e-5 --max-share 0
else
    skip "... as POV-Ray maps them" "povray not installed"
fi
for method in conventional cache volume hst; do
    run imagemap.pov +W160 +H120 --shadows "$method" --volumes always -o "imagemap-$method.png"
    check "image_map: --shadows $method gives the same image" "$hstrace" compare "$work/imagemap.png" "$work/imagemap-$method.png" --max-error 0
done
echo junk >"$work/junk.png"
# The damaged pictures of issue 20 (tests/hostile/images/make-bad-images.py):
# truncated in their data, declaring 0x0 pixels or more than the readers
# take (refused from the header, before anything is allocated).
for f in png-truncated.png png-0x0.png png-100000x100000.png jpg-truncated.jpg jpg-0x0.jpg jpg-65535x65535.jpg \
    jpg-65500x65500.jpg; do
    cp "$srcdir/tests/hostile/images/$f" "$work/"
done
while IFS='|' read -r map message; do
    printf 'camera { location <0,0,-3> look_at 0 }\ntriangle { <0,0,0>, <1,0,0>, <0,1,0> pigment { image_map { %s } } }\n' \
        "$map" >"$work/badmap.pov"
    run badmap.pov +W8 +H6 -o badmap.png
    check "image_map { $map }: status 2, FILE:LINE:COLUMN ($message), no image" \
        test "$status $(grep -c "^badmap.pov:2:[0-9]*: .*$message" "$work/err") $([ -e "$work/badmap.png" ] && echo image || echo none)" = "2 1 none"
done <<'BADMAPS'
png "nothere.png"|cannot find the image 'nothere.png'
png "junk.png"|image_map: cannot read .*junk.png.*not a PNG file
png "png-truncated.png"|image_map: cannot read .*png-truncated.png.: PNG data is truncated
png "png-0x0.png"|image_map: cannot read .*png-0x0.png.: unsupported PNG size 0x0
png "png-100000x100000.png"|image_map: cannot read .*png-100000x100000.png.: unsupported PNG size 100000x100000
jpeg "jpg-truncated.jpg"|image_map: cannot read .*jpg-truncated.jpg.: Premature end of JPEG file
jpeg "jpg-0x0.jpg"|image_map: cannot read .*jpg-0x0.jpg.: Empty JPEG image
jpeg "jpg-65535x65535.jpg"|image_map: cannot read .*jpg-65535x65535.jpg.: Maximum supported image dimension is 65500 pixels
jpeg "jpg-65500x65500.jpg"|image_map: cannot read .*jpg-65500x65500.jpg.: unsupported JPEG size 65500x65500
gif "tex.gif"|'gif' is not supported
ppm "tex.ppm" interpolate 3|'interpolate 3 (bicubic; 0, 2 and 4 are supported)' is not supported
ppm "tex.ppm" map_type 3|invalid map_type 3 (POV-Ray: "Invalid map_type value."
ppm "tex.ppm" filter 2, 0.5|Keyword 'filter' cannot be used with non color-mapped image
png "p8.png" transmit 6, 0.5|TRANSMIT color register value out of range
png "p8-truncated.png"|image_map: cannot read .*p8-truncated.png.: PNG data is truncated
ppm "tex.ppm" repeat <2, 2>|'repeat' is not supported
BADMAPS
# --- colour-mapped pictures, material_map, premultiplied --------------------------
# POV-Ray 3.7 keeps palette PNGs and 8-bit BMPs indexed: `filter N, F` and
# `transmit N, T` set one entry's, `filter all` sets every entry's;
# material_map picks one texture per point by the entry there (entries 1
# and 4 have the same colour, told apart only by their index), or by red
# times 255 of a picture without a palette; `premultiplied 1` reads a
# PNG's colours as premultiplied, `premultiplied 0` an EXR's as straight
# (interpolated first, divided after); bump_map's use_index takes the
# entries as heights.
cat >"$work/palette.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 1.2, -2.6> look_at <0.5, 0.45, 0> }
light_source { <2, 5, -4> color rgb 1 }
plane { y, -0.01 pigment { checker color rgb <0.9, 0.8, 0.7> color rgb 0.3 scale 0.25 } }
polygon { 4, <-1,0,0>, <0,0,0>, <0,1,0>, <-1,1,0> pigment { image_map { png "p8.png" filter 2, 0.6 transmit 3, 0.5 } translate <-1,0,0> } }
polygon { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> pigment { image_map { png "pt.png" interpolate 2 transmit all 0.2 filter 1, 0.9 } } }
polygon { 4, <1,0,0>, <2,0,0>, <2,1,0>, <1,1,0> pigment { image_map { bmp "p8.bmp" filter all 0.3 transmit 4, 0.7 } scale 0.5 translate <1,0,0> } }
polygon { 4, <-1,0,-0.6>, <2,0,-0.6>, <2,0.5,-0.7>, <-1,0.5,-0.7>
  texture { material_map { png "p4.png"
      texture { pigment { color rgb <1,0,0> } }
      texture { pigment { color rgb <0,1,0> } finish { phong 0.9 } }
      texture { pigment { gradient x colour_map { [0 rgb 0] [1 rgb <0,0,1>] } scale 0.1 } }
      texture { pigment { color rgb <1,1,0> } }
      texture { pigment { color rgbt <1,0,1,0.6> } }
    } scale <3,0.5,1> translate <-1,0,0> } }
polygon { 4, <-1,1.1,0.1>, <2,1.1,0.1>, <2,1.6,0.1>, <-1,1.6,0.1>
  texture { material_map { png "desk-alpha.png" once
      texture { pigment { color rgb <1,0.5,0> } }
      texture { pigment { color rgb <0,0.5,1> } }
      texture { pigment { color rgb <0.5,1,0> } }
    } scale <3,0.5,1> translate <-1,1.1,0> } }
EOF
# fade.png and fade.exr: a picture of alpha from 1 to 0.05 across, and a
# band of 0.3 over it, with +UA (PNG straight, EXR premultiplied).
cat >"$work/fade.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0> right x up y }
polygon { 4, <0,0>, <1,0>, <1,1>, <0,1>
  pigment { gradient x colour_map { [0 rgbt <1,0.2,0.1,0>] [0.5 rgbt <0.2,0.9,0.3,0.5>] [1 rgbt <0.1,0.3,1,0.95>] } }
  finish { ambient 1 diffuse 0 } }
polygon { 4, <0,0>, <1,0>, <1,0.3>, <0,0.3> pigment { rgbt <1,1,1,0.7> } finish { ambient 1 diffuse 0 } translate -0.01*z }
EOF
run fade.pov +W16 +H12 +UA +FN +Ofade
run fade.pov +W16 +H12 +UA -o fade.exr
cat >"$work/premul.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 1.0, -2.6> look_at <0.5, 0.5, 0> }
light_source { <2, 5, -4> color rgb 1 }
plane { y, -0.01 pigment { checker color rgb <0.9, 0.8, 0.7> color rgb 0.3 scale 0.25 } }
polygon { 4, <-1,0,0>, <0,0,0>, <0,1,0>, <-1,1,0> pigment { image_map { png "fade.png" premultiplied 1 interpolate 2 } translate <-1,0,0> } }
polygon { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> pigment { image_map { exr "fade.exr" interpolate 2 } } }
polygon { 4, <1,0,0>, <2,0,0>, <2,1,0>, <1,1,0> pigment { image_map { exr "fade.exr" premultiplied 0 } translate <1,0,0> } }
polygon { 4, <-1,1.1,0>, <0.4,1.1,0>, <0.4,1.8,0>, <-1,1.8,0> pigment { rgb 0.8 } normal { bump_map { png "p8.png" use_index bump_size 0.3 } scale <1.4,0.7,1> translate <-1,1.1,0> } }
polygon { 4, <0.6,1.1,0>, <2,1.1,0>, <2,1.8,0>, <0.6,1.8,0> pigment { rgb 0.8 } normal { bump_map { png "fade.png" premultiplied 1 interpolate 2 bump_size 2 } scale <1.4,0.7,1> translate <0.6,1.1,0> } }
EOF
# Interpolated indices, seen flat on (a perspective view puts hit points a
# rounding apart from POV-Ray's, and an interpolated index truncated near
# a whole number can then name its neighbour): 6 textures, interpolate 2
# and 4, and 3 textures (indices past them wrap, as POV-Ray's modulo does).
cat >"$work/mmflat.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <1, 0.5, -1> look_at <1, 0.5, 0> right 2*x up y }
#macro Textures(N)
  texture { pigment { color rgb <1,0,0> } finish { ambient 1 diffuse 0 } }
  texture { pigment { color rgb <0,1,0> } finish { ambient 1 diffuse 0 } }
  texture { pigment { color rgb <0,0,1> } finish { ambient 1 diffuse 0 } }
  #if (N > 3)
  texture { pigment { color rgb <1,1,0> } finish { ambient 1 diffuse 0 } }
  texture { pigment { color rgb <0,1,1> } finish { ambient 1 diffuse 0 } }
  texture { pigment { color rgb <1,0,1> } finish { ambient 1 diffuse 0 } }
  #end
#end
polygon { 4, <0,0.5>, <1,0.5>, <1,1>, <0,1> texture { material_map { png "p8.png" interpolate 2 Textures(6) } } }
polygon { 4, <1,0.5>, <2,0.5>, <2,1>, <1,1> texture { material_map { png "p8.png" interpolate 4 Textures(6) } translate x } }
polygon { 4, <0,0>, <1,0>, <1,0.5>, <0,0.5> texture { material_map { png "p8.png" interpolate 2 Textures(3) } } }
polygon { 4, <1,0>, <2,0>, <2,0.5>, <1,0.5> texture { material_map { png "p8.png" Textures(3) } translate x } }
EOF
for scene in palette premul mmflat; do
    run "$scene.pov" +W160 +H120 --verify-shadows --stats-json "$scene.json" -o "$scene.png"
    check "$scene.pov: renders, 0 disagreements with the shadow ray" \
        test "$status $(grep -o '"disagreements": [0-9]*' "$work/$scene.json" | head -n 1 | grep -o '[0-9]*$')" = "0 0"
done
if [ -n "$povray" ]; then
    for scene in palette premul mmflat; do
        (cd "$work" && "$povray" "+I$scene.pov" +W160 +H120 "+O$scene-pov.png" -D -GA +WT1 >/dev/null 2>&1)
    done
    check "palette pictures (per-entry filter and transmit, filter all, a tRNS entry, 8 and 4 bits, BMP) and material_map (by index, by red, once): as POV-Ray renders them (RMSE 0 measured)" \
        "$hstrace" compare "$work/palette-pov.png" "$work/palette.png" --max-rmse 1e-5 --max-share 0
    check "premultiplied 1 (PNG), an EXR's own premultiplied alpha and premultiplied 0, interpolated; bump_map use_index: as POV-Ray (RMSE 0 measured)" \
        "$hstrace" compare "$work/premul-pov.png" "$work/premul.png" --max-rmse 1e-5 --max-share 0
    check "material_map's interpolated indices and its wrap past the textures, seen flat on: pixel for pixel" \
        "$hstrace" compare "$work/mmflat-pov.png" "$work/mmflat.png" --max-error 0
    # Each reading must matter: the same scenes without it are off POV-Ray.
    while IFS='|' read -r scene from to what; do
        sed "s/$from/$to/" "$work/$scene.pov" >"$work/$scene-off.pov"
        run "$scene-off.pov" +W160 +H120 -o "$scene-off.png"
        check_fails "$what: without it, the image is off POV-Ray's" \
            "$hstrace" compare "$work/$scene-pov.png" "$work/$scene-off.png" --max-rmse 1e-5 --max-share 0
    done <<'OFF'
palette|filter 2, 0.6 transmit 3, 0.5|filter all 0.6|one entry's filter and transmit
palette|texture { pigment { color rgb <0,1,0> } finish { phong 0.9 } }||entries by index (1 and 4 share their colour)
premul|premultiplied 1 interpolate 2 }|interpolate 2 }|premultiplied 1
premul|premultiplied 0 ||premultiplied 0
premul|use_index ||use_index
OFF
else
    skip "palette pictures and material_map: as POV-Ray renders them" "povray not installed"
    skip "premultiplied and use_index: as POV-Ray" "povray not installed"
    skip "material_map's interpolated indices" "povray not installed"
fi
for method in conventional cache volume hst; do
    run palette.pov +W160 +H120 --shadows "$method" --volumes always -o "palette-$method.png"
    check "palette.pov: --shadows $method gives the same image" "$hstrace" compare "$work/palette.png" "$work/palette-$method.png" --max-error 0
done

# --- declared maps: color_map, pigment_map, texture_map, normal_map, slope_map ----
cat >"$work/maps.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,1.2,-4> look_at <0,0.3,0> }
light_source { <-2,5,-4> color rgb 1 }
#declare CM = color_map { [0 rgb <1,0,0>] [0.5 rgb <1,1,0>] [1 rgb <0,0,1>] }
#declare PM = pigment_map { [0 rgb <0.2,0.8,0.2>] [1 rgb <0.1,0.1,0.6>] }
#declare TM = texture_map { [0 pigment { rgb <1,0.5,0> } finish { phong 0.8 }] [1 pigment { gradient y color_map { CM } } ] }
#declare NM = normal_map { [0 bumps 0.5 scale 0.1] [1 dents 0.8 scale 0.2] }
#declare SM = slope_map { [0 <0,1>] [0.5 <1,0>] [1 <0,-1>] }
polygon { 4, <-3,0,-2>,<3,0,-2>,<3,0,4>,<-3,0,4> pigment { gradient x color_map { CM } scale 3 } }
polygon { 4, <-2,0,1>,<-0.1,0,1>,<-0.1,1.5,1>,<-2,1.5,1> pigment { gradient y pigment_map { PM } } }
polygon { 4, <0.1,0,1>,<2,0,1>,<2,1.5,1>,<0.1,1.5,1> texture { gradient x texture_map { TM } scale 2 } }
triangle { <-1.5,0.1,-1>,<0,0.1,-1.2>,<-0.7,1.2,-0.8> pigment { rgb 0.8 } normal { gradient x normal_map { NM } } }
triangle { <0,0.1,-1.2>,<1.5,0.1,-1>,<0.7,1.2,-0.8> pigment { rgb 0.8 } normal { gradient y 1 slope_map { SM } scale 0.3 } }
EOF
run maps.pov +W160 +H120 -o maps.png
check "declared color_map, pigment_map, texture_map, normal_map and slope_map, used in braces: renders" exited 0
if [ -n "$povray" ]; then
    (cd "$work" && "$povray" +Imaps.pov +W160 +H120 +Omaps-pov.png -D -GA +WT1 >/dev/null 2>&1)
    check "... as POV-Ray renders them (RMSE 0 measured)" \
        "$hstrace" compare "$work/maps-pov.png" "$work/maps.png" --max-rmse 1e-5 --max-share 0
else
    skip "... as POV-Ray renders them" "povray not installed"
fi

# --- texture_map, as Arbaro's trees and other exporters write it ------------------
# Patterned textures: a gradient floor of three entries with their own
# finishes (phong, reflection) and a declared and a patterned entry; bozo
# with turbulence whose entries are a texture_map (wood) and a declared
# texture; a declared texture_map texture moved after it and by the
# object's transforms; a mesh2 with per-triangle textures (a marble map,
# checker with a list of textures, a plain one); a material's transform.
cat >"$work/texmap.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.2, -4.5> look_at <0, 0.6, 0> }
light_source { <3, 6, -4> color rgb 1 }
light_source { <-4, 4, -1> color rgb <0.4, 0.4, 0.5> }
#declare Bark = texture { pigment { rgb <0.45, 0.3, 0.15> } finish { phong 0.7 phong_size 25 } }
#declare Moss = texture { pigment { granite color_map { [0 rgb <0.2, 0.5, 0.1>] [1 rgb <0.6, 0.8, 0.2>] } scale 0.4 } }
#declare Mirror = texture { pigment { rgb <0.8, 0.8, 0.9> } finish { reflection 0.5 specular 0.4 roughness 0.02 } }
#declare Rings = texture { wood turbulence 0.1 texture_map { [0.3 Bark] [0.7 Moss] } scale 0.2 rotate <90, 0, 0> }
// the floor: gradient x, three entries with their own finishes, a declared one and a patterned one
polygon { 4, <-3,0,-2>, <3,0,-2>, <3,0,4>, <-3,0,4>
  texture { gradient x texture_map {
      [0.2 Bark]
      [0.5 Mirror]
      [0.8 pigment { checker rgb 1 rgb <0.2, 0.2, 0.3> scale 0.25 } finish { diffuse 0.8 }]
    } scale 2 translate <0.3, 0, 0> } }
// bozo with turbulence, entries that are a texture_map (wood) and a declared texture
triangle { <-2,0,1>, <-0.2,0,1>, <-1.1,1.8,1.2> texture { bozo turbulence <0.6, 0.3, 0.2> octaves 4 texture_map { [0.35 Rings] [0.65 Mirror] } scale 0.35 } }
// a declared texture_map texture, moved after it and by the object's transforms written after it
#declare Patch = texture { granite frequency 2 sine_wave texture_map { [0 Moss] [0.5 Bark] [1 pigment { rgb <0.9, 0.4, 0.2> }] } }
triangle { <0,0,0>, <1.6,0,0>, <0.8,1.6,0.2> texture { Patch scale 0.7 rotate <0, 0, 20> } rotate <0, -15, 0> translate <0.3, 0, 1> }
// mesh2 with per-triangle textures: a texture_map, checker with a list of textures, a plain one
mesh2 {
  vertex_vectors { 5, <1.2,0.2,0.6>, <2.6,0.2,0.6>, <2.6,1.5,1.4>, <1.2,1.5,1.4>, <1.9,2.1,1.6> }
  texture_list { 3,
    texture { marble turbulence 0.7 texture_map { [0 Bark] [0.5 Mirror] [1 Moss] } scale 0.5 }
    texture { checker texture { Bark } texture { pigment { rgb <0.2, 0.4, 0.9> } finish { phong 1 } } scale 0.3 }
    texture { Mirror } }
  face_indices { 3, <0,1,2>, 0, <0,2,3>, 1, <3,2,4>, 2 }
}
// in a material: its transform moves the map; the translate written before it does not
polygon { 4, <-0.8,0.01,-1.6>, <0.8,0.01,-1.6>, <0.8,0.01,-0.9>, <-0.8,0.01,-0.9> translate <0.5, 0, 0> material { texture { Patch } scale 0.3 } }
EOF
run texmap.pov +W160 +H120 --verify-shadows --stats-json texmap.json -o texmap.png
check "texture_map (gradient, bozo with turbulence, nested maps, declared and patterned entries, mesh2 face textures, transforms): renders, 0 disagreements with the shadow ray" \
    test "$status $(grep -o '"disagreements": [0-9]*' "$work/texmap.json" | head -n 1 | grep -o '[0-9]*$')" = "0 0"
if [ -n "$povray" ]; then
    (cd "$work" && "$povray" +Itexmap.pov +W160 +H120 +Otexmap-pov.png -D -GA +WT1 >/dev/null 2>&1)
    check "... as POV-Ray renders it, each entry shaded with its own finish (RMSE 0 measured; limit 1e-5)" \
        "$hstrace" compare "$work/texmap-pov.png" "$work/texmap.png" --max-rmse 1e-5 --max-share 0
    # The entries' finishes count: the floor as one pigment_map of the same
    # colours with one finish (what blending the pigments alone gives) is
    # another image.
    sed '/^  texture { gradient x texture_map {/,/scale 2 translate/ { s/texture { gradient x texture_map {/pigment { gradient x pigment_map {/; s/\[0.2 Bark\]/[0.2 rgb <0.45, 0.3, 0.15>]/; s/\[0.5 Mirror\]/[0.5 rgb <0.8, 0.8, 0.9>]/; s/\[0.8 pigment { \(checker [^}]*\) } finish { diffuse 0.8 }\]/[0.8 \1]/; }' \
        "$work/texmap.pov" >"$work/texmap-pigments.pov"
    run texmap-pigments.pov +W160 +H120 -o texmap-pigments.png
    check "the floor as a pigment_map: renders" exited 0
    check_fails "... and not as a pigment_map of the entries' pigments with one finish (outside the limits)" \
        "$hstrace" compare "$work/texmap-pov.png" "$work/texmap-pigments.png" --max-rmse 1e-5 --max-share 0
else
    skip "... as POV-Ray renders it" "povray not installed"
    skip "... and not as a pigment_map of the entries' colours" "povray not installed"
fi
for method in conventional cache volume hst; do
    run texmap.pov +W160 +H120 --shadows "$method" --volumes always -o "texmap-$method.png"
    check "texture_map: --shadows $method gives the same image" "$hstrace" compare "$work/texmap.png" "$work/texmap-$method.png" --max-error 0
done
# See-through entries: a refracting pane of tinted, clear and opaque bands by
# gradient with turbulence, and a granite triangle of glass and a bozo map of
# its own against the sky, their shadows filtered on the floor by each entry's
# rgb*filter+transmit, blended as POV-Ray blends them; also with an alpha
# channel (+UA), whose transmittance is blended too.
cat >"$work/texmap-glass.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 2.4, -4.5> look_at <0, 0.5, 0.5> }
light_source { <1, 5, 6> color rgb 1 }
light_source { <-5, 3, 3> color rgb <0.5, 0.5, 0.6> }
background { rgb <0.1, 0.2, 0.4> }
polygon { 4, <-3,0,-2>, <3,0,-2>, <3,0,3>, <-3,0,3> pigment { checker rgb 0.95 rgb <0.5, 0.5, 0.55> scale 0.5 } }
#declare Tinted = texture { pigment { rgbf <1, 0.3, 0.2, 0.8> } finish { phong 0.6 } }
#declare Clear = texture { pigment { rgbt <0.6, 0.9, 1, 0.7> } finish { reflection 0.15 specular 0.5 roughness 0.01 } }
#declare Opaque = texture { pigment { rgb <0.2, 0.6, 0.2> } }
// a pane of three kinds of glass by gradient, one opaque band: its shadow filters by each
polygon { 4, <-2.2,0,0>, <-0.2,0,0>, <-0.2,1.6,0>, <-2.2,1.6,0>
  texture { gradient y turbulence 0.15 texture_map { [0.2 Tinted] [0.45 Opaque] [0.55 Opaque] [0.8 Clear] } scale 1.6 }
  interior { ior 1.4 } rotate <0, 15, 0> translate <0, 0, 0.8> }
// granite with turbulence between glass and a bozo map of its own, seen against the sky
triangle { <0.2,0,0>, <2.4,0,0>, <1.3,2.2,0>
  texture { granite turbulence 0.3 texture_map {
      [0.3 Clear]
      [0.6 bozo texture_map { [0.3 Tinted] [0.7 pigment { rgbf <0.9, 0.9, 0.2, 0.5> }] } scale 0.2] } scale 1.5 }
  rotate <0, -20, 0> translate <0, 0, 0.8> }
EOF
run texmap-glass.pov +W160 +H120 --verify-shadows --stats-json texmap-glass.json -o texmap-glass.png
check "texture_map with see-through entries casting shadows: renders, 0 disagreements with the shadow ray" \
    test "$status $(grep -o '"disagreements": [0-9]*' "$work/texmap-glass.json" | head -n 1 | grep -o '[0-9]*$')" = "0 0"
run texmap-glass.pov +W160 +H120 +UA -o texmap-glass-ua.png
codes="$builddir/tests/png_codes"
if [ -n "$povray" ]; then
    (cd "$work" && "$povray" +Itexmap-glass.pov +W160 +H120 +Otexmap-glass-pov.png -D -GA +WT1 >/dev/null 2>&1)
    check "... as POV-Ray renders it, shadows through the entries' filter and transmit included (RMSE 0 measured; limit 1e-5)" \
        "$hstrace" compare "$work/texmap-glass-pov.png" "$work/texmap-glass.png" --max-rmse 1e-5 --max-share 0
    (cd "$work" && "$povray" +Itexmap-glass.pov +W160 +H120 +UA +Otexmap-glass-ua-pov.png -D -GA +WT1 >/dev/null 2>&1)
    if [ -x "$codes" ]; then
        check "... with +UA: POV-Ray's PNG sample code for sample code, alpha included (0 samples differ measured)" \
            "$codes" "$work/texmap-glass-ua-pov.png" "$work/texmap-glass-ua.png"
    else
        skip "... with +UA: POV-Ray's PNG sample code for sample code" "tests/png_codes not built"
    fi
else
    skip "... as POV-Ray renders it" "povray not installed"
    skip "... with +UA: POV-Ray's PNG sample code for sample code" "povray not installed"
fi
for method in conventional cache volume hst; do
    run texmap-glass.pov +W160 +H120 --shadows "$method" --volumes always -o "texmap-glass-$method.png"
    check "texture_map with see-through entries: --shadows $method gives the same image" \
        "$hstrace" compare "$work/texmap-glass.png" "$work/texmap-glass-$method.png" --max-error 0
done
# Mistakes, and what hstrace does not do of texture_map: each names its construct.
while IFS='|' read -r tex message; do
    printf '#declare T = texture { pigment { color rgb 1 } } #declare C = color_map { [0 rgb 1] }\ntriangle { <0,0,0>, <1,0,0>, <0,1,0> %s }\n' "$tex" >"$work/badtex.pov"
    rm -f "$work/badtex.png"
    run badtex.pov +W8 +H6 -o badtex.png
    check "$tex: status 2, FILE:LINE:COLUMN ($message), no image" \
        test "$status $(grep -c "^badtex.pov:2:[0-9]*: .*$message" "$work/err") $([ -e "$work/badtex.png" ] && echo image || echo none)" = "2 1 none"
done <<'BADTEX'
texture { gradient x }|Patterned texture must have texture_map
texture { gradient x texture_map { } }|Must have at least one entry in map
texture { checker texture_map { [0 T] } }|texture_map cannot be used with checker
pigment { gradient x texture_map { [0 T] } }|texture_map can only be used in a texture
texture { pigment { rgb 1 } gradient x texture_map { [0 T] } }|cannot have a pigment, normal, finish, texture identifier or transform before its pattern
texture { gradient x texture_map { [0 texture { T }] } }|expected the items of a texture (without 'texture { }' around them)
texture { gradient x texture_map { [0 rgb 1] } }|expected a texture's items
texture { gradient x texture_map { [0 T] } finish { phong 1 } }|has no finish of its own
texture { gradient x texture_map { [0 T] } color_map { [0 rgb 1] } }|color_map can only be used in a pigment
texture { material_map { png "p8.png" } }|a material_map needs at least one texture
texture { pigment { rgb 1 } material_map { png "p8.png" texture { T } } }|material_map must come first in its texture
texture { material_map { png "p8.png" texture { T } once } }|expected texture or '}' in 'material_map', found 'once'
texture { material_map { png "nothere.png" texture { T } } }|cannot find the image 'nothere.png'
texture { material_map { png "p8-truncated.png" texture { T } } }|material_map: cannot read .*p8-truncated.png.: PNG data is truncated
texture { gradient x texture_map { C } }|'C' is a color_map, not a texture_map
texture { average texture_map { [1 T] } }|'texture_map (a texture patterned by average)' is not supported
texture { gradient x texture_map { [0 T] } } texture { T }|'texture_map in layered textures' is not supported
texture { gradient x texture_map { [0 T] } } pigment { rgb 1 }|'pigment, normal or finish over a texture_map (a layer on it)' is not supported
texture { gradient x texture_map { [0 gradient y texture_map { [0 gradient z texture_map { [0 bozo texture_map { [0 granite texture_map { [0 T] }] }] }] }] } }|'texture_map nested more than 4 deep' is not supported
BADTEX
printf '#declare T = texture { gradient x texture_map { [0 pigment { rgb 1 }] } }\ntriangle { <0,0,0>, <1,0,0>, <0,1,0> texture { T pigment { rgb 1 } } }\n' >"$work/badtex.pov"
run badtex.pov +W8 +H6 -o badtex.png
check "a texture_map texture identifier takes only transforms after it: status 2, FILE:LINE:COLUMN" \
    exited 2 "^badtex.pov:2:[0-9]*: expected a transform or the end of the texture after T"
printf '#declare M = material_map { png "p8.png" texture { } }\n' >"$work/badtex.pov"
run badtex.pov +W8 +H6 -o badtex.png
check "a material_map declared on its own (POV-Ray has no such identifier): status 2, FILE:LINE:COLUMN" \
    exited 2 "^badtex.pov:1:[0-9]*: a material_map cannot be declared on its own"
tap_end
