#!/bin/sh
# The analysis channels (--aov) as a user meets them, in TAP: exrheader (the
# openexr package's tool, when installed) lists every channel and the header
# attributes; the scene hash follows the scene's text; bad --aov uses are
# refused with a message and status 1; and on every shipped scene the shadow
# mask hstrace compare takes from one render's shadow channels agrees with
# POV-Ray's +Q3/+Q4 mask under regress.sh's limits (at most 0.1% of the
# pixels, none in the interior). tests/test_aov.c checks the values.
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstaov.XXXXXX") || { echo "Bail out! no temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
n=0
check() { # description, then a shell condition
    n=$((n + 1)); d=$1; shift
    if eval "$@"; then echo "ok $n - $d"; else echo "not ok $n - $d"; sed 's/^/# /' "$work/err" 2>/dev/null; fi
}
: >"$work/err"

# exrheader on a render with every channel (desk: three lights).
"$hstrace" "$srcdir/scenes/desk.pov" --width 64 --height 48 --aov all -o "$work/desk.exr" 2>"$work/err"
check "--aov all renders desk" '[ $? -eq 0 ]'
"$hstrace" "$srcdir/scenes/holes.pov" --width 16 --height 12 -o "$work/h0.exr" 2>"$work/err"
check "a plain EXR (no --aov) renders" '[ $? -eq 0 ]'
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
    check "exrheader lists exactly the 25 channels of --aov all" 'cmp -s "$work/want.sorted" "$work/got"'
    check "exrheader: hst.L1 is a 32-bit unsigned integer channel, Z 32-bit float, shadow.L1 half" \
        'grep -q "^    hst.L1, 32-bit unsigned integer" "$work/header" &&
         grep -q "^    Z, 32-bit floating-point" "$work/header" &&
         grep -q "^    shadow.L1, 16-bit floating-point" "$work/header"'
    for a in chromaticities hstrace.version hstrace.commandLine hstrace.options hstrace.scene hstrace.sceneHash \
             hstrace.shadows hstrace.nth hstrace.cost.Cs hstrace.time.wall hstrace.aov.hstCodes; do
        check "exrheader shows the attribute $a" "grep -q '^$a (type ' \"\$work/header\""
    done
    check "the hst codes are spelt out in the header" \
        'grep -q "^hstrace.aov.hstCodes (type string): \"0 none (no hit), 1 sustain, 2 self-shadow, 3 volume, 4 conventional, 5 cache hit, 6 faces away" "$work/header"'
    check "the options in force include the defaults" \
        'grep -q "^hstrace.options (type string): \"--width 64 --height 48 +Q9 --shadows hst --nth auto --pixel-coherence on" "$work/header"'
    # The hash is of the scene's bytes: a comment changes it, a copy does not.
    cp "$srcdir/scenes/holes.pov" "$work/a.pov"
    { cat "$srcdir/scenes/holes.pov"; echo "// one more line"; } >"$work/b.pov"
    "$hstrace" "$work/a.pov" --width 16 --height 12 -o "$work/ha.exr" 2>"$work/err" &&
    "$hstrace" "$work/b.pov" --width 16 --height 12 -o "$work/hb.exr" 2>>"$work/err"
    hash() { "$exrheader" "$1" | sed -n 's/^hstrace.sceneHash (type string): "\(.*\)"$/\1/p'; }
    h0=$(hash "$work/h0.exr") ha=$(hash "$work/ha.exr") hb=$(hash "$work/hb.exr")
    check "scene hash: fnv1a64 of the text, the same for a copy, another for an edit ($h0 $ha $hb)" \
        'printf "%s\n" "$h0" | grep -Eq "^fnv1a64:[0-9a-f]{16}$" && [ "$h0" = "$ha" ] && [ "$h0" != "$hb" ]'
else
    echo "# exrheader not installed (Debian package openexr): header checks skipped"
fi

# Refusals.
"$hstrace" "$srcdir/scenes/holes.pov" --aov all -o "$work/x.png" >/dev/null 2>"$work/err"; status=$?
check "--aov with a PNG output: status 1 and a message" \
    '[ $status -eq 1 ] && grep -q "analysis channels need an EXR output" "$work/err" && [ ! -e "$work/x.png" ]'
"$hstrace" "$srcdir/scenes/holes.pov" --aov Z,colour -o "$work/x.exr" >/dev/null 2>"$work/err"; status=$?
check "--aov with an unknown group: status 1, the group and the valid ones named" \
    '[ $status -eq 1 ] && grep -q "unknown channel group .colour. (valid: Z, N, P, shadow, hst, depth, cost, all" "$work/err"'
"$hstrace" compare "$work/h0.exr" "$work/h0.exr" --mask-a "$work/h0.exr" "$work/h0.exr" >/dev/null 2>"$work/err"
status=$?
check "compare: B without shadow channels and no --mask-b: status 2, told what to do" \
    '[ $status -eq 2 ] && grep -q "no channel .shadow.loss.R.*--mask-b B3 B4, or B rendered by hstrace with --aov shadow" "$work/err"'

# The shadow mask from one render's channels against POV-Ray's pair.
refs="$srcdir/reference"
for scene in "$srcdir"/scenes/*.pov; do
    name=$(basename "$scene" .pov)
    [ -f "$refs/$name.q3.exr" ] || continue
    "$hstrace" "$scene" --width 320 --height 240 --aov shadow -o "$work/$name.exr" 2>"$work/err"
    report=$("$hstrace" compare "$refs/$name.q4.exr" "$work/$name.exr" --threshold 0.02 \
        --mask-a "$refs/$name.q3.exr" "$refs/$name.q4.exr" --max-mask-share 0.001 --max-interior 0 2>&1)
    status=$?
    summary=$(printf '%s\n' "$report" | grep -E '^ *(shadow masks|disagreements):' | sed 's/^ *//' | tr '\n' ' ')
    check "$name: the mask from one +Q9 render's shadow channels matches POV-Ray's +Q3/+Q4 mask: $summary" \
        '[ $status -eq 0 ]'
done
echo "1..$n"
