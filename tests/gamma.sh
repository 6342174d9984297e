#!/bin/sh
# The working gamma against POV-Ray, in TAP: the same scene with
# assumed_gamma 1, 2.2 and srgb, with #version 3.7 and no assumed_gamma
# (linear), and with neither (a pre-3.7 scene: "gamma correction off",
# colours taken as sRGB-encoded), rendered by hstrace and POV-Ray to EXR and
# to PNG; the images must be equal to within the limits measured for each
# case (the table below). Skipped without POV-Ray.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (may be empty:
# skipped).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
need_povray
[ -x "$hstrace" ] || bail "$hstrace is not built"
tap_work hstgamma

# The limits per case and format: RMSE and the pixels off by more than 0.02,
# each LIMIT (MEASURED): the value measured on 2026-11-23 (POV-Ray
# 3.7.0.10, 64x48, one thread; the same in two runs) and the limit, about
# the larger of twice that and 1e-5 (RMSE), twice that and 1 (pixels). The
# EXRs agree to the half float; the PNGs code for code (RMSE 0: one code
# off in the dark, decoded to linear, would be about 3e-4 in one sample, 3e-6
# of RMSE over the image's 9216 samples).
limits='
# case                    format  RMSE (measured)     off (measured)
gamma-1                   exr     1e-5 (2.54e-6)   1 (0)
gamma-1                   png     1e-5 (0)         1 (0)
gamma-2.2                 exr     1e-5 (7.11e-7)   1 (0)
gamma-2.2                 png     1e-5 (0)         1 (0)
gamma-srgb                exr     1e-5 (7.95e-8)   1 (0)
gamma-srgb                png     1e-5 (0)         1 (0)
version-3.7-no-gamma      exr     1e-5 (2.54e-6)   1 (0)
version-3.7-no-gamma      png     1e-5 (0)         1 (0)
no-version-no-gamma       exr     1e-5 (7.95e-8)   1 (0)
no-version-no-gamma       png     1e-5 (0)         1 (0)
version-3.6-no-gamma      exr     1e-5 (7.95e-8)   1 (0)
version-3.6-no-gamma      png     1e-5 (0)         1 (0)
'
body='camera { location <0, 1, -5> look_at <0, 0.5, 0> }
light_source { <3, 6, -4> rgb 1 }
plane { y, 0 pigment { rgb <0.6, 0.5, 0.4> } }
polygon { 4, <-1, 0>, <1, 0>, <1, 1.5>, <-1, 1.5> pigment { rgb <0.2, 0.5, 0.8> } finish { phong 0.4 } translate z * 0.5 }'
for case in "gamma-1|#version 3.7; global_settings { assumed_gamma 1 }" \
    "gamma-2.2|#version 3.7; global_settings { assumed_gamma 2.2 }" \
    "gamma-srgb|#version 3.7; global_settings { assumed_gamma srgb }" \
    "version-3.7-no-gamma|#version 3.7;" \
    "no-version-no-gamma|" \
    "version-3.6-no-gamma|#version 3.6;"; do
    name=${case%%|*}
    printf '%s\n%s\n' "${case#*|}" "$body" >"$work/$name.pov"
    for ext in exr png; do
        format=$([ $ext = exr ] && echo E || echo N)
        "$hstrace" "$work/$name.pov" --width 64 --height 48 --threads 1 -o "$work/$name.h.$ext" 2>"$work/err"
        status=$?
        check "$name, $ext: hstrace renders" exited 0
        # POV-Ray 3.7 can time out starting its threads on a loaded machine: one retry
        (cd "$work" && { "$povray" "+I$name.pov" "+O$name.p.$ext" +W64 +H48 -A -D -GA +WT1 "+F$format" \
            >/dev/null 2>&1 || "$povray" "+I$name.pov" "+O$name.p.$ext" +W64 +H48 -A -D -GA +WT1 \
            "+F$format" >/dev/null 2>&1; })
        check "$name, $ext: POV-Ray renders" [ -s "$work/$name.p.$ext" ]
        # shellcheck disable=SC2046 # two limits, each with its measured value
        set -- $(printf '%s\n' "$limits" | awk -v n="$name" -v e="$ext" '$1 == n && $2 == e { print $3, $4, $5, $6 }')
        if [ $# -ne 4 ]; then
            not_ok "$name, $ext: limits recorded in tests/gamma.sh"
            continue
        fi
        "$hstrace" compare "$work/$name.p.$ext" "$work/$name.h.$ext" --json >"$work/cmp.json" 2>&1
        rmse=$(json_value rmse "$work/cmp.json") off=$(json_value pixels_over_threshold "$work/cmp.json")
        check "$name, $ext: as POV-Ray: RMSE $rmse <= $1 (measured ${2#(}" within "$rmse" "$1"
        check "$name, $ext: as POV-Ray: $off pixels off by more than 0.02 <= $3 (measured ${4#(}" within "$off" "$3"
        check_status "$name, $ext: no NaN or infinite pixels" "$(json_value nonfinite_pixels "$work/cmp.json")" 0
    done
done
tap_end
