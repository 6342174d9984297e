#!/bin/sh
# POV-Ray's own sample scenes (Debian package povray-examples) that hstrace
# models, in TAP: each renders unmodified, and its shadow mask (+Q3 against
# +Q4) agrees with POV-Ray's by the rule of scenes/ in regress.sh (at most
# 0.1% of the pixels, none in the interior of a shadow). POV-Ray renders
# them here, at a small size to keep the test short. The scenes stay where
# the package installed them (hstrace and POV-Ray run from their folder, so
# their own #includes are found); nothing is written there.
#
# One scene renders but its mask is known to differ, for a reason hstrace
# reports as an approximation; it is a TAP TODO item, with the figures:
# caustic2.pov's fake caustics change how much light its filtering plane
# lets through. (mesh2.pov, with its bozo plane under turbulence and its
# uv-mapped spiral2 meshes, agrees since those patterns are evaluated.)
#
# Environment: top_builddir (default .), POVRAY (may be empty: skipped),
# HST_POVRAY_EXAMPLES (default /usr/share/doc/povray/examples).
set -u
builddir=${top_builddir:-.}
hstrace=$(cd "$builddir" && pwd)/hstrace
examples=${HST_POVRAY_EXAMPLES:-/usr/share/doc/povray/examples}
if [ ! -f "$examples/objects/polygon.pov" ]; then
    echo "1..0 # SKIP POV-Ray's sample scenes are not installed (Debian package povray-examples; looked in $examples)"
    exit 0
fi
povray=""
if [ -n "${POVRAY:-}" ]; then povray=$(command -v "$POVRAY" 2>/dev/null || true); fi
if [ -z "$povray" ]; then
    echo "1..0 # SKIP povray is not installed: the sample scenes' masks need POV-Ray's renders"
    exit 0
fi
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/hstexamples.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
n=0
width=160 height=120

# scene, then "" or the TODO reason
scenes="objects/polygon.pov|
objects/mesh2.pov|
objects/chesmsh.pov|
lights/parallel_lights.pov|
interior/caustic2.pov|fake caustics (interior caustics) are not modelled: its filtering plane passes other light
templates/Basic_Scenes/DarkBlueSky_Axes.pov|
templates/Basic_Scenes/Orthographic_scene.pov|
templates/Basic_Scenes/Sea_blue_sky.pov|
textures/normals/normal.pov|
textures/normals/normmap.pov|
textures/normals/slopemap.pov|
textures/patterns/fractals3.pov|
textures/patterns/quilt2.pov|
textures/patterns/slopemt_dat_36.pov|
textures/patterns/slopemt_dat_37.pov|
animations/raddem/raddem.pov|
animations/fractalzoom/fractalzoom.pov|
camera/mesh_camera/baking_repair_seams.pov|
incdemo/strings.pov|
textures/pigments/blkhole.pov|"

while IFS='|' read -r scene todo; do
    dir="$examples/$(dirname "$scene")"
    base=$(basename "$scene" .pov)
    out="$work/$base"
    n=$((n + 1))
    if [ ! -f "$examples/$scene" ]; then
        echo "ok $n - $scene # SKIP not in this version of povray-examples"
        continue
    fi
    failed=""
    for q in 3 4; do
        (cd "$dir" && "$hstrace" "$examples/$scene" --width $width --height $height "+Q$q" --threads 1 \
            -o "$out.h$q.exr" 2>"$out.err") || failed="hstrace +Q$q: $(grep -v ': warning: ' "$out.err" | head -1)"
        # POV-Ray 3.7 can time out starting its threads on a loaded machine: one retry
        (cd "$dir" && { "$povray" "+I$base.pov" "+O$out.p$q.exr" +FE +W$width +H$height -A -D -GA +WT1 "+Q$q" \
            >/dev/null 2>&1 || "$povray" "+I$base.pov" "+O$out.p$q.exr" +FE +W$width +H$height -A -D -GA +WT1 \
            "+Q$q" >/dev/null 2>&1; }) || failed="${failed:+$failed; }povray +Q$q failed"
    done
    if [ -n "$failed" ]; then
        echo "not ok $n - $scene renders: $failed"
        continue
    fi
    approx=$(grep ': warning: ' "$out.err" | sed 's/.*warning: //; s/ approximated: /: /; s/ (.*//' | tr '\n' ';' | sed 's/;$//; s/;/; /g')
    report=$("$hstrace" compare "$out.p4.exr" "$out.h4.exr" --mask-a "$out.p3.exr" "$out.p4.exr" \
        --mask-b "$out.h3.exr" "$out.h4.exr" --max-mask-share 0.001 --max-interior 0 2>&1)
    status=$?
    figures=$(echo "$report" | grep -E 'shadow masks:|disagreements:' | tr -s ' \n' ' ')
    if [ -n "$todo" ]; then
        [ $status -eq 0 ] && r=ok || r="not ok"
        echo "$r $n - $scene: shadow mask against POV-Ray:$figures # TODO $todo"
    elif [ $status -eq 0 ]; then
        echo "ok $n - $scene: shadow mask matches POV-Ray:$figures${approx:+ (approximated: $approx)}"
    else
        echo "not ok $n - $scene: shadow mask matches POV-Ray:$figures${approx:+ (approximated: $approx)}"
    fi
done <<SCENES
$scenes
SCENES
echo "1..$n"
