#!/bin/sh
# +UA (Output_Alpha), in TAP: the alpha channel as POV-Ray 3.7 computes it,
# sample code for sample code against the installed POV-Ray's PNG (read by
# tests/png_codes with libpng alone): the background transparent for camera
# rays and the rays refracted from them, opaque (its colour as given) for
# reflected ones; transmit and filter of surfaces, a background with its own
# filter and transmit, a sky sphere over it, fog, and a #version 3.6 scene
# (whose background is not there at all with +UA). Each also without +UA,
# where a background's transmit composites it on black (3.7) or not (3.6).
# And anti-aliasing with alpha, whose comparisons count the transparency.
#
# Environment: top_builddir (default .), POVRAY (path or name of povray;
# default povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
codes="$builddir/tests/png_codes"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstalpha.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
[ -x "$codes" ] || { echo "Bail out! $codes is not built"; exit 1; }
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
run() { (cd "$work" && "$hstrace" "$@") >"$work/out" 2>"$work/err"; status=$?; }
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
W=80 H=60

# The scene: a floor, a transmitting and a filtering triangle, a mirror, and
# a refracting triangle (ior 1.3) that shows the background behind it.
cat >"$work/base.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -3> color rgb 1 }
polygon { 4, <-2,0,-1>, <2,0,-1>, <2,0,3>, <-2,0,3> pigment { color rgb <0.8,0.7,0.6> } }
triangle { <-1.6,0.1,0>, <-0.4,0.1,0>, <-1,1.4,0> pigment { color rgbt <1,0.2,0.2,0.6> } }
triangle { <-0.3,0.1,0>, <0.9,0.1,0>, <0.3,1.6,0> pigment { color rgbf <0.2,1,0.2,0.7> } }
triangle { <1,0.1,0.5>, <2,0.1,0.5>, <1.5,1.5,0.5> pigment { color rgb 0.5 } finish { reflection 0.5 } }
triangle { <0.9,1.0,-0.5>, <1.9,1.0,-0.5>, <1.4,2.0,-0.5> pigment { color rgbf <1,1,1,0.9> } interior { ior 1.3 } }
EOF
cp "$work/base.pov" "$work/none.pov"
{ cat "$work/base.pov"; echo 'background { color rgbt <0.2,0.4,0.6,0.5> }'; } >"$work/bg.pov"
{
    cat "$work/base.pov"
    echo 'background { color rgbft <0.2,0.4,0.6,0.3,0.2> }'
    echo 'sky_sphere { pigment { gradient y color_map { [0 color rgbt <1,1,0,0.5>] [1 color rgbf <0,0,1,0.8>] } } }'
} >"$work/sky.pov"
{ cat "$work/base.pov"; echo 'fog { distance 5 color rgbt <0.5,0.5,0.5,0.3> }'; } >"$work/fog.pov"
sed 's/#version 3.7;/#version 3.6;/' "$work/sky.pov" >"$work/sky36.pov"
sed 's/#version 3.7;/#version 3.6;/' "$work/bg.pov" >"$work/bg36.pov"

for scene in none bg sky fog sky36 bg36; do
    for ua in +UA -UA; do
        run "$scene.pov" +W$W +H$H +FN $ua "+O$scene$ua.png"
        check "$scene.pov $ua: rendered" exited 0
        if [ -n "$povray" ]; then
            (cd "$work" && "$povray" "+I$scene.pov" +W$W +H$H +FN $ua "+Opov-$scene$ua.png" -A -D -GA +WT1 >/dev/null 2>&1)
            check "$scene.pov $ua: POV-Ray's PNG sample code for sample code" \
                "$codes" "$work/pov-$scene$ua.png" "$work/$scene$ua.png"
        else
            skip "$scene.pov $ua: against POV-Ray's PNG" "povray not installed"
        fi
    done
done
check "+UA writes RGBA (8 bits, 4 channels), -UA RGB" \
    test "$("$codes" "$work/none+UA.png" "$work/none+UA.png" | cut -d, -f3)" = " 4 channels: 0 of $((W * H * 4)) samples differ" \
    -a "$("$codes" "$work/none-UA.png" "$work/none-UA.png" | cut -d, -f3)" = " 3 channels: 0 of $((W * H * 3)) samples differ"
check_fails "+UA and -UA differ where the background shows" cmp "$work/bg+UA.png" "$work/bg-UA.png"

# Anti-aliasing with alpha: the comparisons add |d transmit|.
run bg.pov +W$W +H$H +FN +UA +A0.1 +Obg-aa.png
check "bg.pov +UA +A0.1: rendered" exited 0
if [ -n "$povray" ]; then
    (cd "$work" && "$povray" +Ibg.pov +W$W +H$H +FN +UA +A0.1 +Opov-bg-aa.png -D -GA +WT1 >/dev/null 2>&1)
    check "bg.pov +UA +A0.1: POV-Ray's image (RMSE <= 0.001)" \
        "$hstrace" compare "$work/pov-bg-aa.png" "$work/bg-aa.png" --max-rmse 0.001 --max-share 0.001
else
    skip "bg.pov +UA +A0.1: against POV-Ray's image" "povray not installed"
fi

# An INI file's Output_Alpha is +UA.
printf 'Output_Alpha=on\nWidth=%d\nHeight=%d\n' $W $H >"$work/alpha.ini"
run alpha.ini none.pov +FN +Oini.png
check "Output_Alpha=on: the image +UA gives" cmp "$work/ini.png" "$work/none+UA.png"
tap_end
