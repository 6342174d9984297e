#!/bin/sh
# The working gamma against POV-Ray, in TAP: the same scene with
# assumed_gamma 1, 2.2 and srgb, with #version 3.7 and no assumed_gamma
# (linear), and with neither (a pre-3.7 scene: "gamma correction off",
# colours taken as sRGB-encoded), rendered by hstrace and POV-Ray to EXR and
# to PNG; the images must be equal to within regress.sh's limits (RMSE <=
# 0.01, pixels off by more than 0.02 <= 1%). Skipped without POV-Ray.
#
# Environment: top_builddir (default .), POVRAY (may be empty: skipped).
set -u
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
povray=""
if [ -n "${POVRAY:-}" ]; then povray=$(command -v "$POVRAY" 2>/dev/null || true); fi
if [ -z "$povray" ]; then
    echo "1..0 # SKIP povray is not installed: nothing to compare with"
    exit 0
fi
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/hstgamma.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
n=0
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
        "$hstrace" "$work/$name.pov" --width 64 --height 48 --threads 1 -o "$work/$name.h.$ext" 2>/dev/null
        (cd "$work" && { "$povray" "+I$name.pov" "+O$name.p.$ext" +W64 +H48 -A -D -GA +WT1 "+F$([ $ext = exr ] && echo E || echo N)" \
            >/dev/null 2>&1 || "$povray" "+I$name.pov" "+O$name.p.$ext" +W64 +H48 -A -D -GA +WT1 \
            "+F$([ $ext = exr ] && echo E || echo N)" >/dev/null 2>&1; })
        n=$((n + 1))
        report=$("$hstrace" compare "$work/$name.p.$ext" "$work/$name.h.$ext" --max-rmse 0.01 --max-share 0.01 2>&1)
        if [ $? -eq 0 ]; then
            echo "ok $n - $name, $ext: as POV-Ray: $(echo "$report" | sed -n 2p | sed 's/^ *//')"
        else
            echo "not ok $n - $name, $ext: as POV-Ray: $(echo "$report" | tr '\n' ' ')"
        fi
    done
done
echo "1..$n"
