#!/bin/sh
# Light fading and beams against POV-Ray, in TAP: small scenes with point
# lights fading by fade_distance and fade_power (1, 2 and 1.5), a spotlight
# (radius, falloff, tightness) and a cylinder light that fade too, and a
# parallel light that fades (POV-Ray's distance to the plane the light
# shines from), rendered by hstrace and by POV-Ray at the same settings and
# compared by `hstrace compare`, POV-Ray's image as A. The limits are a
# little above what is measured: RMSE the larger of twice the measured value
# and 1e-5 (both renders are half-float EXR, whose rounding alone gives
# about 1e-6), the largest channel error twice the measured one (one
# half-float step near 1 is 2^-12 = 0.000244). And a check that the limits
# see the fade at all: the scene with its fade lines taken out is outside
# them. And rays that carry little of a pixel: two facing half mirrors with
# adc_bailout 0, which prunes no ray in POV-Ray (hstrace took 0 for its
# default, 1/255, and pruned them: RMSE 5.8e-4 at 80x60, issue 39's sweep),
# and with adc_bailout 0.01. Without povray every comparison is a TAP SKIP.
#
# Environment: top_builddir (default .), POVRAY (path or name of povray;
# default povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstlights.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
fails() { ! "$@"; }
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }

cat >"$work/fade.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> right x*4/3 }
light_source { <-2, 3, -1> rgb <1, 0.8, 0.6> fade_distance 1.5 fade_power 1 }
light_source { <2.5, 2, 1> rgb <0.5, 0.7, 1> fade_distance 3 fade_power 2 }
plane { y, 0 pigment { rgb 0.9 } }
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> pigment { rgb <1, 0.9, 0.8> } rotate y*25 }
POV
cat >"$work/spot.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -7> look_at <0, 0, 0.5> right x*4/3 }
light_source { <-1, 4, -1> rgb 1.5 spotlight radius 18 falloff 32 tightness 6 point_at <0.5, 0, 1>
  fade_distance 2.5 fade_power 2 }
light_source { <2, 5, 2> rgb 0.2 }
plane { y, 0 pigment { rgb 0.9 } }
box { <-0.4, 0, 0.2>, <0.4, 0.9, 1.0> pigment { rgb <0.9, 1, 0.8> } rotate y*-20 }
POV
cat >"$work/cylinder.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -7> look_at <0, 0, 0.5> right x*4/3 }
light_source { <0, 4, -5> rgb <1, 1, 0.8> cylinder radius 0.9 falloff 2 tightness 3 point_at <0.5, 0, 2>
  fade_distance 4 fade_power 1.5 }
light_source { <3, 6, -3> rgb 0.5 parallel point_at <0, 0, 0> fade_distance 5 fade_power 2 }
plane { y, 0 pigment { rgb 0.9 } }
box { <-0.5, 0, 0>, <0.5, 1, 1> pigment { rgb <0.8, 0.9, 1> } rotate y*15 }
POV

for bailout in 0 0.01; do
    cat >"$work/bailout$bailout.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 30 adc_bailout $bailout }
camera { location <0, 0, -0.5> look_at <0.3, 0.2, 1> }
light_source { <0, 0.4, 0>, rgb 1 }
plane { z, 1 pigment { rgb <0.9, 0.4, 0.2> } finish { reflection 0.7 ambient 0.1 diffuse 0.3 } }
plane { -z, 1 pigment { rgb <0.2, 0.4, 0.9> } finish { reflection 0.7 ambient 0.1 diffuse 0.3 } }
plane { y, -1.03 pigment { rgb 0.8 } }
POV
done

povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
# pov NAME: POV-Ray's render of NAME.pov (linear half-float EXR, no
# anti-aliasing, one thread), in $work, which POV-Ray may write to.
pov() {
    # POV-Ray 3.7 can time out starting its threads on a loaded machine: one retry
    (cd "$work" && { "$povray" "+I$1.pov" "+O$1.pov.exr" +FE +W160 +H120 -A -D -GA +WT1 >pov.log 2>&1 ||
        "$povray" "+I$1.pov" "+O$1.pov.exr" +FE +W160 +H120 -A -D -GA +WT1 >pov.log 2>&1; }) ||
        { tail -3 "$work/pov.log"; return 1; }
}
hst() { "$hstrace" "$work/$1.pov" --width 160 --height 120 -o "$work/$1.hst.exr"; }

# name, RMSE limit, max-error limit; measured with POV-Ray 3.7.0.10 at 160x120:
#   fade      RMSE 1.05e-6, max error 0.000244   -> 1e-5, 0.0005
#   spot      RMSE 4.4e-7,  max error 0.000061   -> 1e-5, 0.00013
#   cylinder  RMSE 1.97e-6, max error 0.000244   -> 1e-5, 0.0005
#   bailout0  RMSE 3e-6,    max error 0.000488   -> 1e-5, 0.001 (5.8e-4, 0.0029 when 0 meant 1/255)
#   bailout0.01 RMSE 3e-6,  max error 0.000488   -> 1e-5, 0.001
while read -r name rmse error what; do
    check "$name: hstrace renders it" hst "$name" || continue
    if [ -z "$povray" ]; then
        skip "$name: $what as POV-Ray renders them" "povray not installed"
        continue
    fi
    check "$name: POV-Ray renders it" pov "$name" || continue
    check "$name: $what as POV-Ray renders them (RMSE <= $rmse, max error <= $error)" \
        "$hstrace" compare "$work/$name.pov.exr" "$work/$name.hst.exr" --max-rmse "$rmse" --max-error "$error"
done <<'LIMITS'
fade 1e-5 0.0005 point lights fading with fade_power 1 and 2
spot 1e-5 0.00013 a fading spotlight's cone, falloff and tightness
cylinder 1e-5 0.0005 a fading cylinder light's beam and a fading parallel light
bailout0 1e-5 0.001 adc_bailout 0: no ray pruned by its weight
bailout0.01 1e-5 0.001 adc_bailout 0.01: rays pruned below 1% of a pixel
LIMITS

# The limits see the fade: the scene without its fade lines is outside them.
if [ -n "$povray" ] && [ -e "$work/fade.pov.exr" ]; then
    sed 's/ fade_distance [0-9.]* fade_power [0-9.]*//' "$work/fade.pov" >"$work/nofade.pov"
    check "fade: the copy without fade lines has none" fails grep fade "$work/nofade.pov" &&
        check "fade: hstrace renders the copy without fade lines" hst nofade &&
        check "fade: without its fade lines the scene is outside the limits (the comparison sees the fade)" \
            fails "$hstrace" compare "$work/fade.pov.exr" "$work/nofade.hst.exr" --max-rmse 1e-5 --max-error 0.0005
else
    skip "fade: without its fade lines the scene is outside the limits" "povray not installed"
fi
tap_end
