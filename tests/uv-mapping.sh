#!/bin/sh
# uv_mapping in its places, against POV-Ray, in TAP: a mesh2 with
# uv_vectors (its uv square twice over its faces, turned against them)
# textured by `pigment { uv_mapping DECLARED }` (an image_map pigment and a
# pattern, declared with and without transforms of their own), `texture {
# uv_mapping pigment { ... } }`, `texture { uv_mapping DECLARED_TEXTURE }`,
# a declared uv-mapped pigment (which transforms after it do not move) and
# the object's own uv_mapping; hstrace and POV-Ray render each to EXR
# and the images must agree to RMSE 0.001. POV-Ray's parser makes every
# one of them a uv_mapping pattern whose entry is seen at the surface's
# (u, v, 0) (Parse_Pattern's UV_MAPPING_TOKEN, Parse_Item_Into_Blend_List),
# whatever the entry's own mapping. Skipped without POV-Ray.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (may be empty:
# skipped).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$(cd "$builddir" && pwd)/hstrace" # the scenes are rendered from their folder
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
need_povray
[ -x "$hstrace" ] || bail "$hstrace is not built"
tap_work hstuv

# RMSE each case must keep to, in linear light
limit=0.001

perl "$srcdir/tests/make-picture.pl" png "$work/p.png" || bail "cannot make p.png"

# mesh TEXTURING: a 4x4 square of two faces, its uv square [0,2]^2 turned
# by a quarter against it, then TEXTURING (pigment, texture, uv_mapping ...;
# each lit by its ambient alone, from a finish of its own: POV-Ray refuses
# an object's finish after a patterned texture)
mesh() {
    cat <<EOF
mesh2 {
  vertex_vectors { 4, <-2, -2, 0>, <2, -2, 0>, <2, 2, 0>, <-2, 2, 0> }
  uv_vectors { 4, <0, 2>, <0, 0>, <2, 0>, <2, 2> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  $1
  rotate <20, -25, 0>
}
EOF
}
head='#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 60 }
#declare Picture = pigment { image_map { png "p.png" } }
#declare Small_Picture = pigment { image_map { png "p.png" } scale 0.5 rotate z * 10 }
#declare UV_Picture = pigment { uv_mapping image_map { png "p.png" } rotate z * 10 }
#declare Checks = pigment { checker rgb <0.9, 0.3, 0.1>, rgb <0.1, 0.4, 0.8> scale 0.25 }
#declare Picture_Texture = texture { pigment { image_map { png "p.png" } } finish { ambient 1 diffuse 0 } }'
for case in \
    "uv_mapping-declared-image_map|pigment { uv_mapping Picture } finish { ambient 1 diffuse 0 }" \
    "uv_mapping-declared-transformed|pigment { uv_mapping Small_Picture } finish { ambient 1 diffuse 0 }" \
    "uv_mapping-declared-pattern|pigment { uv_mapping Checks } finish { ambient 1 diffuse 0 }" \
    "uv_mapping-declared-then-scale|pigment { uv_mapping Picture scale 0.5 } finish { ambient 1 diffuse 0 }" \
    "uv_mapping-image_map|pigment { uv_mapping image_map { png \"p.png\" } } finish { ambient 1 diffuse 0 }" \
    "texture-uv_mapping-pigment|texture { uv_mapping pigment { image_map { png \"p.png\" } } finish { ambient 1 diffuse 0 } }" \
    "texture-uv_mapping-pigment-scaled|texture { uv_mapping pigment { Picture } scale 0.5 finish { ambient 1 diffuse 0 } }" \
    "texture-uv_mapping-declared|texture { uv_mapping Picture_Texture }" \
    "declared-uv_mapping|pigment { UV_Picture } finish { ambient 1 diffuse 0 }" \
    "declared-uv_mapping-then-scale|pigment { UV_Picture scale 3 } finish { ambient 1 diffuse 0 }" \
    "object-uv_mapping|uv_mapping pigment { Picture } finish { ambient 1 diffuse 0 }"; do
    name=${case%%|*} texturing=${case#*|}
    { printf '%s\n' "$head"; mesh "$texturing"; } >"$work/$name.pov"
    (cd "$work" && "$hstrace" "$name.pov" --width 64 --height 48 --threads 1 -A -o "$name.h.exr" >/dev/null 2>"$work/err")
    status=$?
    check "$name: hstrace renders" exited 0
    # POV-Ray 3.7 can time out starting its threads on a loaded machine: one retry
    (cd "$work" && { "$povray" "+I$name.pov" "+O$name.p.exr" +W64 +H48 -A -D -GA +WT1 +FE >/dev/null 2>&1 ||
        "$povray" "+I$name.pov" "+O$name.p.exr" +W64 +H48 -A -D -GA +WT1 +FE >/dev/null 2>&1; })
    check "$name: POV-Ray renders" [ -s "$work/$name.p.exr" ]
    "$hstrace" compare "$work/$name.p.exr" "$work/$name.h.exr" --json >"$work/cmp.json" 2>&1
    rmse=$(json_value rmse "$work/cmp.json")
    check "$name: as POV-Ray: RMSE $rmse <= $limit" within "$rmse" "$limit"
done
tap_end
