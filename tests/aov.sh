#!/bin/sh
# The analysis channels (--aov) as a user meets them, in TAP: exrheader (the
# openexr package's tool; its checks are skipped, with the reason, when it
# is not installed) lists every channel and the header attributes; the
# scene hash follows the scene's text; bad --aov uses are refused with a
# message and status 1; and on every shipped scene the shadow mask hstrace
# compare takes from one render's shadow channels agrees with POV-Ray's
# +Q3/+Q4 mask (the committed references): none in the interior, and at
# most the disagreeing pixels measured for that scene (the table below).
# tests/test_aov.c checks the values.
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstaov.XXXXXX") || bail "no temporary folder"
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || bail "$hstrace is not built"
run() { # runs hstrace, keeps stderr in $work/err and the status in $status
    "$hstrace" "$@" >"$work/out" 2>"$work/err"; status=$?
}

# exrheader on a render with every channel (desk: three lights).
run "$srcdir/scenes/desk.pov" --width 64 --height 48 --aov all -o "$work/desk.exr"
check "--aov all renders desk" exited 0
run "$srcdir/scenes/holes.pov" --width 16 --height 12 -o "$work/h0.exr"
check "a plain EXR (no --aov) renders" exited 0
exrheader=$(command -v exrheader 2>/dev/null || true)
if [ -n "$exrheader" ]; then
    "$exrheader" "$work/desk.exr" >"$work/header" 2>"$work/err"
    for c in A B G R Z N.X N.Y N.Z P.X P.Y P.Z shadow.L1 shadow.L2 shadow.L3 shadow.loss.R shadow.loss.G \
             shadow.loss.B hst.L1 hst.L2 hst.L3 depth.L1 depth.L2 depth.L3 cost.shadow cost.rays; do
        printf '%s\n' "$c" >>"$work/want"
    done
    sort "$work/want" >"$work/want.sorted"
    awk '/^channels/ { on = 1; next } on && /^    / { sub(/^ +/, ""); sub(/,.*/, ""); print; next } { on = 0 }' \
        "$work/header" | sort >"$work/got"
    check "exrheader lists exactly the 25 channels of --aov all" diff "$work/want.sorted" "$work/got"
    check "exrheader: hst.L1 is a 32-bit unsigned integer channel" grep -q "^    hst.L1, 32-bit unsigned integer" "$work/header"
    check "exrheader: Z is a 32-bit float channel" grep -q "^    Z, 32-bit floating-point" "$work/header"
    check "exrheader: shadow.L1 is a half channel" grep -q "^    shadow.L1, 16-bit floating-point" "$work/header"
    for a in chromaticities hstrace.version hstrace.commandLine hstrace.options hstrace.scene hstrace.sceneHash \
             hstrace.shadows hstrace.volumes hstrace.time.wall hstrace.aov.hstCodes; do
        check "exrheader shows the attribute $a" grep -q "^$a (type " "$work/header"
    done
    check "hstrace.volumes says per light whether the cost model built its volumes" \
        grep -Eq '^hstrace.volumes \(type string\): "auto; L1 [a-z].*; L2 [a-z].*; L3 [a-z]' "$work/header"
    # The cost model's calibration is there when volumes were built.
    "$hstrace" "$srcdir/scenes/desk.pov" --width 32 --height 24 --volumes always -o "$work/always.exr" 2>"$work/err"
    "$exrheader" "$work/always.exr" >"$work/header-always" 2>"$work/err"
    for a in hstrace.nth hstrace.cost.Cs; do
        check "with --volumes always, exrheader shows the attribute $a" grep -q "^$a (type " "$work/header-always"
    done
    check "with --volumes always, hstrace.volumes says so" \
        grep -q '^hstrace.volumes (type string): "always; L1 built (--volumes always)' "$work/header-always"
    check "the hst codes are spelt out in the header" \
        grep -q '^hstrace.aov.hstCodes (type string): "0 none (no hit), 1 sustain, 2 self-shadow, 3 volume, 4 conventional, 5 cache hit, 6 faces away' "$work/header"
    check "the options in force include the defaults" \
        grep -q '^hstrace.options (type string): "--width 64 --height 48 +Q9 --shadows hst --volumes auto --nth auto --pixel-coherence on' "$work/header"
    # The hash is of the scene's bytes: a comment changes it, a copy does not.
    cp "$srcdir/scenes/holes.pov" "$work/a.pov"
    { cat "$srcdir/scenes/holes.pov"; echo "// one more line"; } >"$work/b.pov"
    run "$work/a.pov" --width 16 --height 12 -o "$work/ha.exr"
    check "a copy of holes.pov renders" exited 0
    run "$work/b.pov" --width 16 --height 12 -o "$work/hb.exr"
    check "holes.pov with a comment added renders" exited 0
    hash() { "$exrheader" "$1" | sed -n 's/^hstrace.sceneHash (type string): "\(.*\)"$/\1/p'; }
    h0=$(hash "$work/h0.exr") ha=$(hash "$work/ha.exr") hb=$(hash "$work/hb.exr")
    # is_hash VALUE: an fnv1a64 hash as the header spells it
    is_hash() { expr "$1" : 'fnv1a64:[0-9a-f]\{16\}$' >/dev/null || { echo "not a hash: '$1'"; return 1; }; }
    check "scene hash: fnv1a64 of the text ($h0)" is_hash "$h0"
    # same_hash A B: two hashes, equal; other_hash A B: two hashes, different
    same_hash() { is_hash "$1" && is_hash "$2" && [ "$1" = "$2" ]; }
    other_hash() { is_hash "$1" && is_hash "$2" && [ "$1" != "$2" ]; }
    check "scene hash: the same for a copy ($ha)" same_hash "$ha" "$h0"
    check "scene hash: another for an edit ($hb)" other_hash "$hb" "$h0"
else
    for d in "exrheader lists exactly the 25 channels of --aov all" "exrheader: the channels' types" \
             "exrheader shows the attributes" "the hst codes are spelt out in the header" \
             "the options in force include the defaults" "scene hash: fnv1a64 of the text, the same for a copy, another for an edit"; do
        skip "$d" "exrheader not installed (Debian package openexr)"
    done
fi

# Refusals.
run "$srcdir/scenes/holes.pov" --aov all -o "$work/x.png"
check "--aov with a PNG output: status 1 and a message" exited 1 "analysis channels need an EXR output"
check "... no image" [ ! -e "$work/x.png" ]
run "$srcdir/scenes/holes.pov" --aov Z,colour -o "$work/x.exr"
check "--aov with an unknown group: status 1, the group and the valid ones named" \
    exited 1 "unknown channel group .colour. (valid: Z, N, P, shadow, hst, depth, cost, all"
run compare "$work/h0.exr" "$work/h0.exr" --mask-a "$work/h0.exr" "$work/h0.exr"
check "compare: B without shadow channels and no --mask-b: status 2, told what to do" \
    exited 2 "no channel .shadow.loss.R.*--mask-b B3 B4, or B rendered by hstrace with --aov shadow"

# The shadow mask from one render's channels against POV-Ray's pair (the
# committed references, which do not change from run to run): the pixels
# that disagree (all at shadow edges or silhouettes), measured 2026-11-23,
# and the limit, twice that and at least 1 (the rule of tests/regress.sh);
# glasses measured again on 2026-12-01 (3 before transparent surfaces
# within POV-Ray's SMALL_TOLERANCE along a shadow ray filtered once);
# poseray measured on 2026-12-02; tree and water measured on 2026-12-02,
# when they were added (water's 37, all at shadow edges, come with its
# perturbed normals: at +Q8 and above a light's facing test takes the
# shading normal, which POV-Ray's +Q3/+Q4 pair never perturbs; at +Q4 the
# two masks agree there). soft and spot (area lights) are rendered at
# +Q4, where both renderers take an area light as a point light at its
# centre, as POV-Ray's +Q3/+Q4 pair does: at +Q9 the channels record the
# soft shadows of the samples, which that pair cannot show (their +Q9
# images are held to POV-Ray's by tests/regress.sh); measured on
# 2026-12-02, when they were added.
limits='
# scene    pixels (measured)  [render options]
cards      12 (6)
desk       8 (4)
glasses    2 (1)
holes      1 (0)
mesh2      6 (3)
poseray    10 (5)
stars      2 (1)
soft       1 (0)              +Q4
spot       1 (0)              +Q4
tree       2 (1)
water      74 (37)
'
refs="$srcdir/reference"
for scene in "$srcdir"/scenes/*.pov; do
    name=$(basename "$scene" .pov)
    # shellcheck disable=SC2046 # the limit and its measured value
    set -- $(printf '%s\n' "$limits" | awk -v n="$name" '$1 == n { print $2, $3, $4 }')
    if [ $# -lt 2 ] || [ ! -f "$refs/$name.q3.exr" ]; then
        not_ok "$name: a reference in reference/ and a limit in tests/aov.sh"
        continue
    fi
    max=$1 measured=${2#(} quality=${3:-+Q9}
    run "$scene" --width 320 --height 240 "$quality" --aov shadow -o "$work/$name.exr"
    check "$name: renders with --aov shadow" exited 0
    "$hstrace" compare "$refs/$name.q4.exr" "$work/$name.exr" --threshold 0.02 \
        --mask-a "$refs/$name.q3.exr" "$refs/$name.q4.exr" --max-interior 0 --json >"$work/mask.json" 2>&1
    status=$?
    j() { json_value "$1" "$work/mask.json"; }
    split="$(j shadow_edge) at shadow edges, $(j silhouette) at silhouettes, $(j interior) interior"
    check "$name: the mask from one $quality render's shadow channels matches POV-Ray's +Q3/+Q4 mask: none in the interior ($split)" \
        no_interior "$status" "$(j interior)"
    check "$name: ... $(j disagree) pixels disagree <= $max (measured $measured" within "$(j disagree)" "$max"
done
tap_end
