#!/bin/sh
# POV-Ray 3.7's patterns beyond the noise ones (brick, leopard, onion,
# radial, quilted, dents, ripples, waves, planar, spherical, cylindrical,
# boxed, square, triangular, cubic, cells, crackle, mandel, julia, magnet,
# pigment_pattern), and pigment_map, average and blend lists whose entries
# have patterns of their own, in TAP, against the installed POV-Ray.
#
# 1. Each pattern as a pigment, on a plane seen straight on by an
#    orthographic camera, lit by its ambient alone: each pixel is the
#    pattern's colour there, so matching POV-Ray's image is matching the
#    pattern's values and its colour map. Nothing reported as approximated.
# 2. Each pattern as a normal, in the probe of tests/normals.sh: three
#    parallel lights, red, green and blue, from three directions, diffuse
#    only, so that each pixel is the perturbed normal. It must differ from
#    the flat normal (+Q7), so that a pattern doing nothing cannot pass.
# 3. A scene of several of them: 1 and 2 threads give the same image.
# 4. Mistakes: FILE:LINE:COLUMN, status 2, no image.
#
# Environment: top_builddir (default .), POVRAY (path or name of povray;
# default povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstpatterns.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
run() { (cd "$work" && "$hstrace" "$@") >"$work/out" 2>"$work/err"; status=$?; }
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
pov() { (cd "$work" && "$povray" "$@" -D -GA +WT1 </dev/null >/dev/null 2>&1); }

# --- 1. each pattern as a pigment ----------------------------------------------
pigment_probe() {
    cat <<EOF
#version 3.7;
global_settings { assumed_gamma 1 $2 }
camera { orthographic location <0, 0, -3> look_at 0 right 4*x up 4*y }
plane { z, 0 pigment { $1 } finish { ambient 1 diffuse 0 } }
EOF
}
n=0
while IFS='|' read -r pigment globals measured; do
    n=$((n + 1))
    pigment_probe "$pigment" "$globals" >"$work/c$n.pov"
    run "c$n.pov" +W64 +H64 -o "c$n.png"
    if [ "$status" != 0 ]; then
        not_ok "pigment { $pigment }: renders ($(head -n 1 "$work/err"))"
        continue
    fi
    # shellcheck disable=SC2016 # the inner shell expands its argument
    check "pigment { $pigment }: evaluated, nothing reported as approximated" \
        sh -c '! grep -q "approximated" "$1"' sh "$work/err"
    if [ -n "$povray" ]; then
        pov "+Ic$n.pov" +W64 +H64 "+Oc$n-pov.png"
        check "pigment { $pigment }: POV-Ray's colours (RMSE $measured measured; limit 1e-5)" \
            "$hstrace" compare "$work/c$n-pov.png" "$work/c$n.png" --max-rmse 1e-5 --max-share 0
    else
        skip "pigment { $pigment }: POV-Ray's colours" "povray not installed"
    fi
done <<'PIGMENTS'
brick rgb 1, rgb <0.6, 0.2, 0.1> scale 0.1||0
brick rgb 1 brick_size <1, 0.5, 0.8> mortar 0.1 rotate <0, 30, 0>||0
brick scale 0.15 turbulence 0.1||0
leopard color_map { [0 rgb 0] [1 rgb <1, 0.8, 0.2>] } scale 0.1||0
onion color_map { [0 rgb <0, 0, 1>] [1 rgb 1] } scale 0.4 frequency 2 triangle_wave||0
radial frequency 8 scale 0.5 rotate 90*x||0
radial color_map { [0 rgb 0] [1 rgb 1] } rotate 90*x phase 0.25 sine_wave||0
quilted color_map { [0 rgb 0] [1 rgb 1] } scale 0.4||0
quilted control0 0.2 control1 0.9 color_map { [0 rgb 0] [1 rgb 1] } scale 0.4 rotate <10, 20, 0>||0
dents color_map { [0 rgb 0] [1 rgb 1] } scale 0.3||0
ripples color_map { [0 rgb 0] [1 rgb 1] } scale 0.3||0
ripples frequency 2 phase 0.3 color_map { [0 rgb 0] [1 rgb 1] } scale 0.3|number_of_waves 3|0
waves color_map { [0 rgb 0] [1 rgb 1] } scale 0.5||0
planar color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } scale 1.5||0
spherical color_map { [0 rgb 0] [1 rgb 1] } scale 1.8||0
cylindrical color_map { [0 rgb 0] [1 rgb 1] } scale 1.8 rotate 30*z||0
boxed color_map { [0 rgb 0] [1 rgb 1] } scale 1.8 rotate 20*z||0
square rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1> scale 0.3 rotate 90*x||0
triangular scale 0.3 rotate 90*x||0
cubic scale 1.2 rotate <30, 40, 0>||0
cells color_map { [0 rgb 0] [1 rgb 1] } scale 0.2||0
crackle color_map { [0 rgb 0] [1 rgb 1] } scale 0.3||0
crackle metric 1 offset 0.1 form <1, 0, 0> color_map { [0 rgb 0] [1 rgb 1] } scale 0.3||0
crackle solid color_map { [0 rgb 0] [1 rgb 1] } scale 0.3 turbulence 0.2||0
mandel 60 scale 1.2||0
mandel 40 exponent 3 interior 1, 1 exterior 6, 0.2 color_map { [0 rgb 0] [1 rgb 1] } scale 1.2||0
mandel 30 exponent 4 scale 1.2||0
julia <0.353, 0.288>, 50 color_map { [0 rgb 0] [0.3 rgb <1, 0.5, 0>] [1 rgb 1] } scale 1.2||0
magnet 1 mandel 40 color_map { [0 rgb 0] [1 rgb 1] } scale 1.5 translate <1, 0, 0>||0
magnet 2 julia <1.2, 0.3>, 40 exterior 7, 5 color_map { [0 rgb 0] [1 rgb 1] } scale 1.5||0
pigment_pattern { checker rgb 0.1, rgb 0.9 scale 0.5 } color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } turbulence 0.3||0
gradient x pigment_map { [0 checker rgb 0, rgb 1 scale 0.2] [0.5 rgb <1, 0, 0>] [1 leopard scale 0.05] } scale 2 translate -x||0
bozo pigment_map { [0.3 crackle scale 0.2] [0.7 radial frequency 6 rotate 90*x color_map { [0 rgb <0, 1, 0>] [1 rgb 1] }] } scale 0.5 noise_generator 1||0
checker pigment { brick rgb 1, rgb <0.5, 0, 0> scale 0.05 } pigment { onion scale 0.1 } scale 0.8||0
brick pigment { gradient y color_map { [0 rgb 0] [1 rgb <0, 0, 1>] } } pigment { ripples scale 0.2 } scale 0.3||0
average pigment_map { [1 checker rgb 0, rgb 1 scale 0.3] [2 leopard scale 0.05] [0.5 rgb <1, 0, 0>] } turbulence 0.2||0
PIGMENTS

# --- 2. each pattern as a normal -----------------------------------------------
normal_probe() {
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
while IFS='|' read -r normal globals measured; do
    n=$((n + 1))
    normal_probe "$normal" "$globals" >"$work/p$n.pov"
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
brick 0.5 scale 0.1||0
brick normal { bumps 0.8 scale 0.05 } normal { dents 2 scale 0.1 } scale 0.2||0
leopard 2 scale 0.05||0
onion 1.5 scale 0.2||0
radial 0.6 frequency 8 rotate 90*x||0
quilted 0.6 scale 0.3 slope_map { [0 <0, 1>] [1 <1, 0>] }||0
dents 2 normal_map { [0 bumps 0.5 scale 0.1] [1 wrinkles 0.5 scale 0.1] } scale 0.3||0
ripples 0.5 normal_map { [0.3 granite 0.4] [0.7 bumps 0.6 scale 0.1] } scale 0.3||0
planar 1 scale 0.3 rotate 40*z||0
spherical 1 scale 0.8||0
cylindrical 1 scale 0.7||0
boxed 1 scale 0.8 rotate 25*z||0
square 0.5 scale 0.3 rotate 90*x||0
triangular 0.5 scale 0.3 rotate 90*x||0
cubic 0.5 scale 0.6 rotate <30, 40, 0>||0
cells 0.8 scale 0.2||0
crackle 1.6 scale 0.2||0
crackle 1 metric 3 form <0.5, 0.5, 0> scale 0.25 accuracy 0.01||0
crackle 1 solid scale 0.25||0
mandel 50, 0.8 scale 0.7 translate -0.4*x||0
julia <0.353, 0.288>, 40 0.5 interior 1, 1 scale 0.8||0
magnet 1 mandel 30 0.2 slope_map { [0 <1, 0>] [1 <0, -1>] } interior 1, 200 accuracy 0.005 scale 0.8||0
pigment_pattern { leopard color_map { [0 rgb 0] [1 rgb 1] } scale 0.05 } 0.8||0
NORMALS

# --- 3. threads ------------------------------------------------------------------
cat >"$work/scene.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 number_of_waves 6 }
camera { location <0, 3, -4.5> look_at <0, 0.5, 0> }
light_source { <3, 6, -4> color rgb 1 }
plane { y, 0 pigment { brick rgb 0.9, rgb <0.7, 0.3, 0.2> scale 0.1 } normal { crackle 0.8 scale 0.3 } }
polygon { 4, <-2, 0.01, 1>, <2, 0.01, 1>, <2, 2, 1.5>, <-2, 2, 1.5>
    pigment { mandel 50 scale 0.5 translate <0.3, 1, 0> } normal { ripples 0.6 scale 0.3 } finish { phong 0.6 } }
triangle { <-1.5, 0.05, -1.5>, <1.5, 0.05, -1.5>, <0, 1.5, -1>
    pigment { leopard color_map { [0 rgb <1, 0.8, 0>] [1 rgb 0] } scale 0.05 } normal { quilted 0.5 scale 0.2 } }
EOF
run scene.pov +W160 +H120 --threads 2 --verify-shadows --stats-json scene.json -o scene-2.png
check "a scene of brick, crackle, mandel, ripples, leopard, quilted: renders, 0 disagreements with the shadow ray" \
    test "$status $(grep -o '"disagreements": [0-9]*' "$work/scene.json" | head -n 1 | grep -o '[0-9]*$')" = "0 0"
run scene.pov +W160 +H120 --threads 1 -o scene-1.png
check "... 1 thread gives the same image as 2" "$hstrace" compare "$work/scene-2.png" "$work/scene-1.png" --max-error 0

# Values at the edges: a brick of no size, points far beyond the range of
# int, fractal factors that POV-Ray divides by: an image, no crash.
cat >"$work/edges.pov" <<'EOF'
#version 3.7;
camera { orthographic location <0, 0, -3> look_at 0 right 4*x up 4*y }
light_source { <0, 0, -5> rgb 1 }
#declare Quarter = polygon { 4, <0, 0>, <2, 0>, <2, 2>, <0, 2> }
object { Quarter pigment { brick rgb 1, rgb 0 brick_size <0, 1, 0> } normal { brick 1 brick_size <1, 0, 1> } }
object { Quarter pigment { cells scale 1e-300 } normal { crackle 1 scale 1e-300 } translate -2*x }
object { Quarter pigment { square scale 1e-30 rotate 90*x } normal { triangular 1 scale 1e-300 } translate -2*y }
object { Quarter pigment { mandel 20 exterior 7, -3 } normal { julia <0, 0>, 10 1 exterior 8, 1e300 } translate <-2, -2, 0> }
EOF
run edges.pov +W32 +H24 -o edges.png
check "edge values (brick_size 0, points beyond int, fractal factors of 0 and 1e300): renders" \
    test "$status $([ -s "$work/edges.png" ] && echo image)" = "0 image"

# --- 4. mistakes -----------------------------------------------------------------
while IFS='|' read -r body where message; do
    printf 'camera { location <0,0,-3> look_at 0 }\n%s\n' "$body" >"$work/bad.pov"
    run bad.pov +W8 +H6 -o bad.png
    check "$body: status 2, bad.pov:$where: $message, no image" \
        test "$status $(grep -c "^bad.pov:$where: .*$message" "$work/err") $([ -e "$work/bad.png" ] && echo image || echo none)" = "2 1 none"
done <<'BAD'
plane { z, 0 pigment { magnet 3 mandel 20 } }|2:31|Invalid magnet-mandel pattern type found. Valid types are 1 and 2.
plane { z, 0 pigment { magnet 1 gradient x } }|2:33|Invalid magnet pattern found. Valid types are .mandel. and .julia.
plane { z, 0 pigment { mandel 20 exterior 9, 1 } }|2:43|Invalid fractal pattern exterior type. Valid types are 0 to 8.
plane { z, 0 normal { julia <0.3, 0.2>, 20 interior -1, 1 } }|2:53|Invalid fractal pattern interior type. Valid types are 0 to 6.
plane { z, 0 normal { leopard control0 1 } }|2:31|Cannot use control0 with this pattern
plane { z, 0 normal { brick slope_map { [0 <0, 1>] } } }|2:29|Cannot use slope_map with this normal type
plane { z, 0 pigment { pigment_pattern { bozo scale } } }|2:53|expected a numeric expression, found .}.
plane { z, 0 pigment { average scale 2 } }|2:24|an average pigment needs a pigment_map
BAD
tap_end
