#!/bin/sh
# Normal perturbation (issue 20), in TAP, against the installed POV-Ray.
#
# 1. Every normal pattern, one at a time, on a plane seen straight on by an
#    orthographic camera and lit by three parallel lights, red, green and
#    blue, from three directions, with diffuse light only: each pixel's
#    colour is then the perturbed normal's dot product with the three
#    directions, so matching POV-Ray's image to rounding is matching its
#    normals. The same scene with the flat normal (+Q7: no normals) must
#    differ, so that a pattern doing nothing cannot pass.
# 2. A scene as exporters write them: declared normals, a texture's and a
#    material's transforms, bump_map from a PNG and a JPEG, uv-mapped
#    normals on meshes, per-triangle textures, a bumped glass that
#    reflects and refracts, #default; the same image as POV-Ray's, every
#    shadow method the same image, --verify-shadows 0 disagreements; and
#    a texture_map whose textures have normals.
# 3. Mistakes: FILE:LINE:COLUMN, status 2, no image.
#
# Environment: top_builddir (default .), POVRAY (path or name of povray;
# default povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstnormal.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
run() { (cd "$work" && "$hstrace" "$@") >"$work/out" 2>"$work/err"; status=$?; }
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
pov() { (cd "$work" && "$povray" "$@" -D -GA +WT1 </dev/null >/dev/null 2>&1); }

# Height fields for bump_map, made by hstrace itself: noise in grey.
cat >"$work/heights.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 0.5, -2> look_at <0.5, 0.5, 0> right x up y }
plane { z, 0 pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } scale 0.15 } finish { ambient 1 diffuse 0 } }
EOF
run heights.pov +W32 +H32 -o heights.png
check "a height field for bump_map: heights.png" exited 0
run heights.pov +W40 +H30 -o heights.jpg
check "a height field for bump_map: heights.jpg" exited 0

# --- 1. each pattern's normals -------------------------------------------------
probe() {
    cat <<EOF
#version 3.7;
global_settings { assumed_gamma 1 $2 }
camera { orthographic location <0, 0, -3> look_at 0 right 2*x up 2*y }
light_source { <3, 0, -3> color rgb <1, 0, 0> parallel point_at 0 }
light_source { <0, 3, -3> color rgb <0, 1, 0> parallel point_at 0 }
light_source { <-2, -1, -3> color rgb <0, 0, 1> parallel point_at 0 }
plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { $1 } }
EOF
}
n=0
while IFS='|' read -r normal globals measured; do
    n=$((n + 1))
    probe "$normal" "$globals" >"$work/p$n.pov"
    run "p$n.pov" +W48 +H48 -o "p$n.png"
    if [ "$status" != 0 ]; then
        not_ok "normal { $normal }: renders ($(head -n 1 "$work/err"))"
        continue
    fi
    run "p$n.pov" +W48 +H48 +Q7 -o "p$n-flat.png"
    # shellcheck disable=SC2016 # the inner shell expands its arguments
    check "normal { $normal }: perturbs the normal (differs from the flat normal of +Q7 by RMSE > 0.01)" \
        sh -c '! "$1" compare "$2" "$3" --max-rmse 0.01 >/dev/null' sh "$hstrace" "$work/p$n.png" "$work/p$n-flat.png"
    if [ -n "$povray" ]; then
        pov "+Ip$n.pov" +W48 +H48 "+Op$n-pov.png"
        check "normal { $normal }: POV-Ray's normals (RMSE $measured measured; limit 1e-5)" \
            "$hstrace" compare "$work/p$n-pov.png" "$work/p$n.png" --max-rmse 1e-5 --max-share 0
    else
        skip "normal { $normal }: POV-Ray's normals" "povray not installed"
    fi
done <<'NORMALS'
bumps 0.8 scale 0.2||0
bumps 0.8 scale 0.2 no_bump_scale||0
bumps 0.8 scale <0.2, 0.5, 0.3> rotate <20, 30, 40>||0
dents 3 scale 0.3||0
dents 3 scale 0.3 noise_generator 1||0
wrinkles 1.2 scale 0.3||0
waves 0.8 scale 0.4||0
waves 0.8 frequency 3 phase 0.2 scale 0.4|number_of_waves 3|0
ripples 0.9 scale 0.3||0
ripples 0.9 scale 0.3|number_of_waves 1|0
quilted 1 scale 0.4||0
quilted 1 control0 0.2 control1 0.9 scale 0.4||0
granite 0.8 scale 0.6||0
agate 0.6||0
marble 0.8 turbulence 0.6 scale 0.5||0
wood 0.8 scale 0.3||0
bozo 1.5 scale 0.25 noise_generator 3||0
spotted 1 scale 0.3||0
spiral1 4 0.8 scale 0.6||0
spiral2 6 0.7 scale 0.6||0
checker 0.6 scale 0.4 rotate 20*z||0
hexagon 0.6 scale 0.3 rotate 90*x||0
gradient x 0.8 scale 0.3||0
gradient <1, 1, 0> 0.8 frequency 2 sine_wave||0
granite 0.8 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale 0.6||0
bozo 1 accuracy 0.05 scale 0.3||0
bozo bump_size 1.4 turbulence 0.4 octaves 3 scale 0.3||0
bumps 0.8 warp { turbulence 0.5 } scale 0.3||0
gradient x normal_map { [0.3 bumps 0.8 scale 0.1] [0.7 dents 2 scale 0.2] } scale 0.7||0
bozo normal_map { [0 granite 0.5] [0.5 ripples 0.6] [1 wrinkles 0.5 scale 0.2] } scale 0.4||0
average normal_map { [1 bumps 0.7 scale 0.1] [2 ripples 0.5] }||0
checker normal { bumps 0.8 scale 0.1 } normal { wrinkles 0.7 scale 0.2 } scale 0.5||0
bump_map { png "heights.png" bump_size 2 } scale 1.2 translate -0.6*x||0
bump_map { png "heights.png" interpolate 2 bump_size -3 once } scale 1.5||0
bump_map { jpeg "heights.jpg" gamma 2.2 bump_size 2 } scale 0.9||0
NORMALS
# A declared normal with a map, used as `normal { N }`: the same normals as
# written in place (the map was dropped at the '}' after the name, and an
# average refused: "Average must have map.").
for normal in "gradient x normal_map { [0.3 bumps 0.8 scale 0.1] [0.7 dents 2 scale 0.2] } scale 0.7" \
    "average normal_map { [1 bumps 0.7 scale 0.1] [2 ripples 0.5] }"; do
    probe "$normal" "" >"$work/inline.pov"
    probe "N" "" | sed "s|^camera|#declare N = normal { $normal }\\
camera|" >"$work/declared.pov"
    run inline.pov +W48 +H48 -o inline.png
    run declared.pov +W48 +H48 -o declared.png
    check "#declare N = normal { $normal } ... normal { N }: renders ($(head -n 1 "$work/err"))" exited 0
    check "normal { N } of $normal: the same image as written in place" \
        "$hstrace" compare "$work/inline.png" "$work/declared.png" --max-rmse 0 --max-share 0
done

# --- 2. a scene as exporters write it ------------------------------------------
cat >"$work/scene.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 number_of_waves 5 }
camera { location <0, 3, -4.5> look_at <0, 0.5, 0> }
light_source { <3, 6, -4> color rgb 1 }
light_source { <-4, 3, -1> color rgb 0.5 }
#declare Water = normal { ripples 0.6 frequency 3 scale 0.5 }
#declare Floor = texture { pigment { rgb <0.9, 0.6, 0.3> } normal { Water } finish { phong 0.8 } }
#declare Glass = material {
    texture { pigment { rgbf <0.9, 0.9, 1, 0.8> } normal { wrinkles 0.6 scale 0.2 } finish { reflection 0.1 } }
    interior { ior 1.4 }
    scale 0.5
}
plane { y, 0 texture { Floor scale 2 } }
polygon { 4, <-2, 0.01, 1>, <2, 0.01, 1>, <2, 2, 1.5>, <-2, 2, 1.5>
    pigment { rgb <0.3, 0.5, 0.9> }
    normal { bump_map { png "heights.png" interpolate 2 bump_size 3 } scale <4, 2, 1> translate <-2, 0, 0> }
    finish { specular 0.5 reflection 0.2 } }
mesh2 {
    vertex_vectors { 4, <-1.5, 0.3, -1>, <-0.3, 0.3, -1>, <-0.3, 1.5, -0.5>, <-1.5, 1.5, -0.5> }
    uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
    texture_list { 2,
        texture { pigment { rgb 0.8 } normal { uv_mapping bumps 0.7 scale 0.1 } finish { phong 1 } }
        texture { pigment { rgb <0.5, 0.9, 0.5> } normal { dents 3 scale 0.2 } } }
    face_indices { 2, <0, 1, 2>, 0, <0, 2, 3>, 1 }
    uv_indices { 2, <0, 1, 2>, <0, 2, 3> }
}
mesh2 {
    vertex_vectors { 4, <0.3, 0.3, -1>, <1.5, 0.3, -1>, <1.5, 1.5, -0.5>, <0.3, 1.5, -0.5> }
    uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
    face_indices { 2, <0, 1, 2>, <0, 2, 3> }
    uv_indices { 2, <0, 1, 2>, <0, 2, 3> }
    uv_mapping
    texture { pigment { rgb <0.7, 0.7, 1> } normal { bump_map { jpeg "heights.jpg" bump_size 2 } } finish { phong 0.5 } }
}
triangle { <-0.5, 0.05, -2>, <0.5, 0.05, -2>, <0, 1, -1.8> material { Glass } }
#default { normal { granite 0.3 scale 0.5 } }
triangle { <1.6, 0, -1.8>, <2.4, 0, -1.8>, <2, 1.2, -1.6> pigment { rgb <1, 0.8, 0.8> } finish { phong 0.5 } }
EOF
run scene.pov +W160 +H120 --verify-shadows --stats-json scene.json -o scene.png
check "an exporter's scene with normals: renders, 0 disagreements with the shadow ray" \
    test "$status $(grep -o '"disagreements": [0-9]*' "$work/scene.json" | head -n 1 | grep -o '[0-9]*$')" = "0 0"
# shellcheck disable=SC2016 # the inner shell expands its argument
check "... and reports no approximation" sh -c '! grep -q "approximated" "$1"' sh "$work/err"
if [ -n "$povray" ]; then
    pov +Iscene.pov +W160 +H120 +Oscene-pov.png
    # One pixel, in the bump-mapped polygon's specular highlight, differs
    # by 0.04 (the highlight's power of 20 magnifies the last bits).
    check "... as POV-Ray renders it (RMSE 2.15e-4 and 1 pixel off by more than 0.02 measured; limits 4e-4, 0.02%)" \
        "$hstrace" compare "$work/scene-pov.png" "$work/scene.png" --max-rmse 4e-4 --max-share 0.02
    run scene.pov +W160 +H120 +Q7 -o scene-q7.png
    pov +Iscene.pov +W160 +H120 +Q7 +Oscene-q7-pov.png
    check "... and at +Q7, where neither perturbs normals, as POV-Ray (RMSE 0 measured)" \
        "$hstrace" compare "$work/scene-q7-pov.png" "$work/scene-q7.png" --max-rmse 1e-5 --max-share 0
else
    skip "... as POV-Ray renders it" "povray not installed"
fi
for method in conventional cache volume hst; do
    run scene.pov +W160 +H120 --shadows "$method" --volumes always -o "scene-$method.png"
    check "normals: --shadows $method gives the same image" \
        "$hstrace" compare "$work/scene.png" "$work/scene-$method.png" --max-error 0
done
run scene.pov +W160 +H120 --threads 1 -o scene-1.png
check "normals: 1 thread gives the same image as 2" "$hstrace" compare "$work/scene.png" "$work/scene-1.png" --max-error 0

# A texture_map whose textures have normals of their own (a tree's bark
# and leaves), nested, under turbulence, moved: POV-Ray moves each entry's
# normal through the maps' transforms.
cat >"$work/treemap.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -4.5> look_at <0, 0.5, 0> }
light_source { <3, 6, -4> color rgb 1 }
light_source { <-4, 3, -1> color rgb 0.5 }
#declare Bark = texture { pigment { rgb <0.4, 0.25, 0.1> } normal { wrinkles 0.8 scale 0.1 } finish { phong 0.3 } }
#declare Leaf = texture { pigment { rgb <0.2, 0.6, 0.1> } normal { bumps 0.5 scale <0.05, 0.2, 0.05> rotate 30*z } finish { specular 0.4 } }
plane { y, 0 texture { gradient x texture_map { [0.3 Bark] [0.7 Leaf] } scale 0.8 rotate 20*y } }
polygon { 4, <-2, 0.01, 1>, <2, 0.01, 1>, <2, 2, 1.5>, <-2, 2, 1.5>
  texture { bozo turbulence 0.4 texture_map { [0.2 Bark] [0.5 gradient y texture_map { [0 Leaf] [1 pigment { rgb 0.9 } normal { dents 2 scale 0.2 } finish { reflection 0.2 } ] } scale 0.3 ] [0.8 Leaf scale 2] } scale 0.5 }
}
mesh2 {
  vertex_vectors { 3, <-1.5,0.3,-1>, <-0.3,0.3,-1>, <-0.3,1.5,-0.5> }
  face_indices { 1, <0,1,2> }
  texture { granite texture_map { [0.3 Bark] [0.6 Leaf] } scale 0.5 }
  translate x
}
EOF
run treemap.pov +W160 +H120 --verify-shadows --stats-json treemap.json -o treemap.png
check "texture_map entries with normals: renders, 0 disagreements with the shadow ray" \
    test "$status $(grep -o '"disagreements": [0-9]*' "$work/treemap.json" | head -n 1 | grep -o '[0-9]*$')" = "0 0"
run treemap.pov +W160 +H120 +Q7 -o treemap-flat.png
# shellcheck disable=SC2016 # the inner shell expands its arguments
check "... whose normals perturb (differs from +Q7's flat normals by RMSE > 0.01)" \
    sh -c '! "$1" compare "$2" "$3" --max-rmse 0.01 >/dev/null' sh "$hstrace" "$work/treemap.png" "$work/treemap-flat.png"
if [ -n "$povray" ]; then
    pov +Itreemap.pov +W160 +H120 +Otreemap-pov.png
    check "... as POV-Ray renders it (RMSE 0 measured; limit 1e-5)" \
        "$hstrace" compare "$work/treemap-pov.png" "$work/treemap.png" --max-rmse 1e-5 --max-share 0
else
    skip "... as POV-Ray renders it" "povray not installed"
fi

# A pattern hstrace does not evaluate in a normal: the flat normal, noted.
printf 'camera { location <0,0,-3> look_at 0 }\nlight_source { <1,2,-3> rgb 1 }\nplane { z, 0 normal { facets 0.5 } }\n' \
    >"$work/facets.pov"
run facets.pov +W16 +H12 -o facets.png
check "normal { facets }: renders, with a warning that the normal is left unperturbed" \
    exited 0 "facets.pov:3:23: warning: 'facets' approximated: normal pattern not evaluated"

# --- 3. mistakes ---------------------------------------------------------------
echo junk >"$work/junk.png"
while IFS='|' read -r body where message; do
    printf 'camera { location <0,0,-3> look_at 0 }\n#declare P = pigment { rgb 1 }\n%s\n' "$body" >"$work/bad.pov"
    run bad.pov +W8 +H6 -o bad.png
    check "$body: status 2, bad.pov:$where: $message, no image" \
        test "$status $(grep -c "^bad.pov:$where: .*$message" "$work/err") $([ -e "$work/bad.png" ] && echo image || echo none)" = "2 1 none"
done <<'BAD'
plane { z, 0 normal { } }|3:14|No normal type given
plane { z, 0 normal { 0.5 scale 2 } }|3:14|No normal type given
plane { z, 0 normal { average } }|3:14|Average must have map
plane { z, 0 normal { image_map { png "junk.png" } } }|3:23|'image_map' can only be used in a pigment
plane { z, 0 normal { checker slope_map { [0 <0, 1>] } } }|3:31|Cannot use slope_map with this normal type
plane { z, 0 normal { bump_map { png "heights.png" } normal_map { [0 bumps] } } }|3:54|Cannot use normal_map with this normal type
plane { z, 0 normal { bumps control0 1 } }|3:29|Cannot use control0 with this pattern
plane { z, 0 normal { bumps 0.5 scale 2 granite } }|3:41|the pattern must come first in a normal
plane { z, 0 normal { P } }|3:23|'P' cannot be used in a normal
plane { z, 0 normal { bump_map { png "nothere.png" } } }|3:38|cannot find the image 'nothere.png'
plane { z, 0 normal { bump_map { png "junk.png" } } }|3:38|bump_map: cannot read .*junk.png
plane { z, 0 normal { bumps normal_map { [0.5 bumps] [0.2 } } }|3:59|expected a normal modifier or .]. in a normal_map entry, found .}.
global_settings { number_of_waves 1e6 }|3:35|number_of_waves 1e+06 is more than hstrace supports (10000)
BAD
printf 'camera { location <0,0,-3> look_at 0 }\nglobal_settings { number_of_waves 0 }\nplane { z, 0 normal { waves } }\n' \
    >"$work/waves0.pov"
run waves0.pov +W8 +H6 -o waves0.png
check "number_of_waves 0: renders with one wave and POV-Ray's warning at its position" \
    exited 0 "waves0.pov:2:35: warning: Illegal Value: number_of_waves must be greater than 0. Changed to 1."
tap_end
