#!/bin/sh
# How pictures' colours enter a scene, against POV-Ray, in TAP. One scene
# shows ten image_maps side by side (PNG without gamma chunks, with a gAMA
# chunk, with an sRGB chunk, a palette PNG, JPEG, PPM, Targa, BMP, EXR and
# HDR), each lit by its ambient alone; the cases change only what decides
# POV-Ray 3.7's reading of them: #version (given, absent, set by a
# standard include), assumed_gamma (absent, 1, 2.2, given after the
# pictures), `gamma G` in the image_map, and the options Display_Gamma and
# +MV3.7. hstrace and POV-Ray render
# each to EXR (linear light); the images must agree to RMSE 0.001. Skipped
# without POV-Ray.
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
tap_work hstimggamma

# RMSE each case must keep to, in linear light (0.001: a JPEG or PNG code
# off by one in the mid tones is about 0.002 in one sample of 7680)
limit=0.001

# ---- the pictures --------------------------------------------------------
for spec in "png p.png" "png gama.png gama=0.5556" "png srgb.png srgb" "ppm p.ppm" "tga p.tga" "bmp p.bmp"; do
    # shellcheck disable=SC2086 # the kind, the file and its options
    set -- $spec
    kind=$1 name=$2
    shift 2
    perl "$srcdir/tests/make-picture.pl" "$kind" "$work/$name" "$@" || bail "cannot make $name"
done
perl "$srcdir/tests/make-indexed.pl" png "$work/pal.png" || bail "cannot make pal.png"
# JPEG, EXR and HDR: the PNG rendered into them by hstrace (any picture of
# the type will do: both renderers read the same file)
cat >"$work/make.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0> right x up y }
polygon { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1>
  pigment { image_map { png "p.png" } } finish { ambient 1 diffuse 0 } }
EOF
for f in J E H; do
    ext=$(case $f in J) echo jpg ;; E) echo exr ;; H) echo hdr ;; esac)
    (cd "$work" && "$hstrace" make.pov +W8 +H8 -A "+F$f" -o "p.$ext" >/dev/null 2>&1) || bail "cannot make p.$ext"
done

# ---- the scenes ----------------------------------------------------------
# pictures PREAMBLE GAMMA: the ten squares, in a 5x2 grid, each picture
# given `GAMMA` (empty: none) in its image_map
pictures() {
    i=0
    for pic in 'png "p.png"' 'png "gama.png"' 'png "srgb.png"' 'png "pal.png"' 'jpeg "p.jpg"' \
        'ppm "p.ppm"' 'tga "p.tga"' 'bmp "p.bmp"' 'exr "p.exr"' 'hdr "p.hdr"'; do
        x=$((i % 5)) y=$((i / 5))
        printf 'polygon { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> pigment { image_map { %s %s } }\n' "$pic" "$1"
        printf '  finish { ambient 1 diffuse 0 } translate <%d, %d, 0> }\n' "$x" "$y"
        i=$((i + 1))
    done
}
camera='camera { orthographic location <2.5, 1, -1> look_at <2.5, 1, 0> right 5 * x up 2 * y }'
# case|before the pictures|the pictures' own gamma|after the pictures[|options
# of both renderers: Display_Gamma is the output's gamma when the scene
# turns gamma correction off; +MV3.7 sets the version before the first line]
for case in \
    "v3.7-no-assumed-gamma|#version 3.7;||" \
    "v3.7-assumed-gamma-1|#version 3.7; global_settings { assumed_gamma 1.0 }||" \
    "v3.7-assumed-gamma-2.2|#version 3.7; global_settings { assumed_gamma 2.2 }||" \
    "v3.7-assumed-gamma-srgb|#version 3.7; global_settings { assumed_gamma srgb }||" \
    "v3.7-assumed-gamma-after|#version 3.7;||global_settings { assumed_gamma 1.0 }" \
    "v3.7-second-assumed-gamma|#version 3.7; global_settings { assumed_gamma 1.0 } global_settings { assumed_gamma 2.2 }||" \
    "no-version|||" \
    "no-version-assumed-gamma-1|global_settings { assumed_gamma 1.0 }||" \
    "v3.6-assumed-gamma-2.2|#version 3.6; global_settings { assumed_gamma 2.2 }||" \
    "include-no-assumed-gamma|#include \"colors.inc\"||" \
    "include-assumed-gamma-1|#include \"colors.inc\" global_settings { assumed_gamma 1.0 }||" \
    "v3.7-gamma-1.8|#version 3.7; global_settings { assumed_gamma 1.0 }|gamma 1.8|" \
    "v3.7-gamma-srgb-assumed-2.2|#version 3.7; global_settings { assumed_gamma 2.2 }|gamma srgb|" \
    "v3.7-no-assumed-gamma-gamma-1.8|#version 3.7;|gamma 1.8|" \
    "no-version-gamma-1.8||gamma 1.8|" \
    "no-version-Display_Gamma-1.8||||Display_Gamma=1.8" \
    "v3.7-Display_Gamma-1.8|#version 3.7;|||Display_Gamma=1.8" \
    "no-version-MV3.7||||+MV3.7" \
    "no-version-MV3.7-assumed-gamma-1|global_settings { assumed_gamma 1.0 }|||+MV3.7"; do
    name=${case%%|*} rest=${case#*|}
    before=${rest%%|*} rest=${rest#*|}
    own=${rest%%|*} rest=${rest#*|}
    after=${rest%%|*} opts=${rest#*|}
    [ "$opts" != "$rest" ] || opts=""
    { printf '%s\n%s\n' "$before" "$camera"; pictures "$own"; printf '%s\n' "$after"; } >"$work/$name.pov"
    # shellcheck disable=SC2086 # the options, one word each
    (cd "$work" && "$hstrace" "$name.pov" --width 80 --height 32 --threads 1 -A $opts -o "$name.h.exr" >/dev/null 2>"$work/err")
    status=$?
    check "$name: hstrace renders" exited 0
    # POV-Ray 3.7 can time out starting its threads on a loaded machine: one retry
    # shellcheck disable=SC2086
    (cd "$work" && { "$povray" "+I$name.pov" "+O$name.p.exr" +W80 +H32 -A -D -GA +WT1 +FE $opts >/dev/null 2>&1 ||
        "$povray" "+I$name.pov" "+O$name.p.exr" +W80 +H32 -A -D -GA +WT1 +FE $opts >/dev/null 2>&1; })
    check "$name: POV-Ray renders" [ -s "$work/$name.p.exr" ]
    "$hstrace" compare "$work/$name.p.exr" "$work/$name.h.exr" --json >"$work/cmp.json" 2>&1
    rmse=$(json_value rmse "$work/cmp.json")
    check "$name: as POV-Ray: RMSE $rmse <= $limit" within "$rmse" "$limit"
done
tap_end
