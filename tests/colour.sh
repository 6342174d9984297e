#!/bin/sh
# Colour management from the command line, in TAP: ociocheck accepts the
# shipped config; without OCIO options and $OCIO, PNG and PPM keep POV-Ray's
# encoding; the shipped config's sRGB view is the sRGB formula within one
# 8-bit step and its Raw view the bare values; a test config's other view
# changes the PNG as its curve says; $OCIO is honoured (and --ocio-config
# wins over it); missing or broken configs give a message and status 3;
# unknown names give a message listing the valid ones and status 1. Built
# without OpenColorIO, the OCIO options are refused with a message instead.
#
# Environment: top_srcdir, top_builddir (default .), OCIOCHECK (path of
# ociocheck, may be empty), HSTRACE_DATADIR (set by make check: the source
# tree's data folder).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
codes="$builddir/tests/display_codes"
shipped="$srcdir/data/ocio/config.ocio"
gamma22="$srcdir/tests/ocio/gamma22.ocio"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstcolour.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
unset OCIO OCIO_ACTIVE_DISPLAYS OCIO_ACTIVE_VIEWS OCIO_INACTIVE_COLORSPACES
n=0
check() { # description, then a shell condition
    n=$((n + 1)); d=$1; shift
    if eval "$@"; then echo "ok $n - $d"; else echo "not ok $n - $d"; fi
}
skip() { n=$((n + 1)); echo "ok $n - $1 # SKIP $2"; }
run() { # runs hstrace, keeps stderr in $work/err and the status in $status
    "$hstrace" "$@" >"$work/out" 2>"$work/err"; status=$?
}
for tool in "$hstrace" "$codes"; do
    [ -x "$tool" ] || { echo "Bail out! $tool is not built"; exit 1; }
done

# 1. The shipped config, as OpenColorIO's own checker sees it.
ociocheck=""
[ -n "${OCIOCHECK:-}" ] && ociocheck=$(command -v "$OCIOCHECK" 2>/dev/null || true)
[ -z "$ociocheck" ] && ociocheck=$(command -v ociocheck 2>/dev/null || true)
if [ -n "$ociocheck" ]; then
    "$ociocheck" --iconfig "$shipped" >"$work/ociocheck" 2>&1; st=$?
    sed 's/^/# /' "$work/ociocheck" | grep -E 'Version:|Default|\(sRGB|passed|failed|ERROR|WARNING'
    check "ociocheck accepts the shipped config: status 0, validation passed" \
        '[ $st -eq 0 ] && grep -q "^passed" "$work/ociocheck"'
    check "ociocheck finds no error and no missing role in it" '! grep -q -e ERROR -e WARNING "$work/ociocheck"'
    "$ociocheck" --iconfig "$srcdir/tests/ocio/missing-space.ocio" >/dev/null 2>&1; st=$?
    check "ociocheck refuses the deliberately broken test config (the check has teeth)" '[ $st -ne 0 ]'
else
    skip "ociocheck accepts the shipped config" "ociocheck not installed (Debian package opencolorio-tools)"
fi

scene="$srcdir/scenes/desk.pov"
size="--width 48 --height 36"
# The linear render every encoding is compared with (float, so no half rounding).
"$hstrace" "$scene" $size --exr-float -o "$work/lin.exr" 2>"$work/err" || { echo "Bail out! cannot render $scene"; cat "$work/err"; exit 1; }
# (That this PNG is POV-Ray's encoding, code for code, tests/encoding.sh
# checks against POV-Ray's own files.)
run "$scene" $size -o "$work/default.png"
OCIO= "$hstrace" "$scene" $size -o "$work/empty.png" 2>/dev/null
check "an empty \$OCIO is the same as none" 'cmp -s "$work/default.png" "$work/empty.png"'

if ! "$hstrace" --version | grep -q "OpenColorIO [0-9]"; then
    # Built with configure --without-ocio.
    for opt in "--ocio-config $shipped" "--display sRGB" "--view Raw" "--colorspace scene_linear"; do
        run "$scene" $size -o "$work/x.png" $opt
        check "without OpenColorIO, ${opt%% *} is refused: status 1 and the reason" \
            '[ $status -eq 1 ] && grep -q "built without OpenColorIO (configure --without-ocio)" "$work/err" && [ ! -e "$work/x.png" ]'
    done
    OCIO="$gamma22" "$hstrace" "$scene" $size -o "$work/env.png" 2>"$work/err"; status=$?
    check "without OpenColorIO, \$OCIO is ignored with a warning and the PNG is POV-Ray's" \
        '[ $status -eq 0 ] && grep -q "OCIO ignored" "$work/err" && cmp -s "$work/default.png" "$work/env.png"'
    echo "1..$n"
    exit 0
fi

# 2. The shipped config's views.
run "$scene" $size -o "$work/srgb.png" --display sRGB --view Standard
check "shipped config, sRGB display, Standard view: renders" '[ $status -eq 0 ]'
check "Standard view is the sRGB formula within one 8-bit step" \
    '"$codes" "$work/lin.exr" "$work/srgb.png" --curve srgb --steps 1 >"$work/cmp" && sed "s/^/# /" "$work/cmp"'
run "$scene" $size -o "$work/shipped.png" --ocio-config "$shipped"
check "the shipped config's defaults are that view (--ocio-config alone gives the same PNG)" \
    '[ $status -eq 0 ] && cmp -s "$work/srgb.png" "$work/shipped.png"'
run "$scene" $size -o "$work/raw.png" --view Raw
check "Raw view writes the linear values, clamped and rounded, code for code" \
    '[ $status -eq 0 ] && "$codes" "$work/lin.exr" "$work/raw.png" --curve raw --steps 0 >"$work/cmp" && sed "s/^/# /" "$work/cmp"'
run "$scene" $size -o "$work/raw.ppm" --view Raw
check "PPM goes through the view too" \
    '[ $status -eq 0 ] && "$codes" "$work/lin.exr" "$work/raw.ppm" --curve raw --steps 0 >/dev/null'
check "and the Raw PNG differs from the sRGB one" '! cmp -s "$work/raw.png" "$work/srgb.png"'

# 3. A config with another view.
run "$scene" $size -o "$work/g22.png" --ocio-config "$gamma22" --display Gamma --view "Gamma 2.2"
check "test config's Gamma 2.2 view: the PNG is x^(1/2.2) within one step" \
    '[ $status -eq 0 ] && "$codes" "$work/lin.exr" "$work/g22.png" --curve gamma --gamma 2.2 --steps 1 >"$work/cmp" && sed "s/^/# /" "$work/cmp"'
check "and not the sRGB curve (dark values differ by more than a step)" \
    '"$codes" "$work/lin.exr" "$work/g22.png" --curve srgb --steps 1 >"$work/cmp"; r=$?; sed "s/^/# /" "$work/cmp"; [ $r -eq 1 ]'

# 4. $OCIO.
OCIO="$gamma22" "$hstrace" "$scene" $size -o "$work/env.png" 2>"$work/err"; status=$?
check "\$OCIO alone selects that config and its default view" \
    '[ $status -eq 0 ] && cmp -s "$work/env.png" "$work/g22.png"'
OCIO="$work/no-such.ocio" "$hstrace" "$scene" $size -o "$work/wins.png" --ocio-config "$shipped" 2>"$work/err"; status=$?
check "--ocio-config wins over \$OCIO" '[ $status -eq 0 ] && cmp -s "$work/wins.png" "$work/srgb.png"'

# 5. Missing and broken configs: status 3, a message, no image.
run "$scene" $size -o "$work/x.png" --ocio-config "$work/no-such.ocio"
check "missing --ocio-config: status 3, names the file ($(head -1 "$work/err"))" \
    '[ $status -eq 3 ] && grep -q "no-such.ocio" "$work/err" && [ ! -e "$work/x.png" ]'
OCIO="$work/no-such.ocio" "$hstrace" "$scene" $size -o "$work/x.png" 2>"$work/err"; status=$?
check "missing \$OCIO config: status 3, says it came from \$OCIO" \
    '[ $status -eq 3 ] && grep -q "no-such.ocio.*OCIO" "$work/err" && [ ! -e "$work/x.png" ]'
run "$scene" $size -o "$work/x.png" --ocio-config "$srcdir/tests/ocio/broken-yaml.ocio"
check "malformed config: status 3 and OpenColorIO's reason ($(head -1 "$work/err" | cut -c1-100)...)" \
    '[ $status -eq 3 ] && grep -q "broken.*yaml" "$work/err" && [ ! -e "$work/x.png" ]'
run "$scene" $size -o "$work/x.png" --ocio-config "$srcdir/tests/ocio/missing-space.ocio"
check "config naming an undefined colour space: status 3" \
    '[ $status -eq 3 ] && grep -q "no such space" "$work/err" && [ ! -e "$work/x.png" ]'
run "$scene" $size -o "$work/x.png" --ocio-config "$srcdir/tests"
check "a folder as config: status 3, says so" '[ $status -eq 3 ] && grep -q "Is a directory" "$work/err"'

# 6. Unknown names: status 1, the valid ones listed.
run "$scene" $size -o "$work/x.png" --view Filmic
check "unknown view: status 1, lists 'Standard' and 'Raw' ($(cat "$work/err"))" \
    '[ $status -eq 1 ] && grep -q "Filmic.*valid: .Standard., .Raw." "$work/err" && [ ! -e "$work/x.png" ]'
run "$scene" $size -o "$work/x.png" --display Projector
check "unknown display: status 1, lists 'sRGB'" '[ $status -eq 1 ] && grep -q "Projector.*valid: .sRGB." "$work/err"'
run "$scene" $size -o "$work/x.png" --colorspace ACEScg
check "unknown colour space: status 1, lists the colour spaces" \
    '[ $status -eq 1 ] && grep -q "ACEScg.*Linear Rec.709" "$work/err"'
run "$scene" $size -o "$work/x.png" --display ""
check "an empty name is a usage error" '[ $status -eq 1 ]'

# 7. The EXR's chromaticities (exrheader, Debian package openexr).
if command -v exrheader >/dev/null 2>&1; then
    exrheader "$work/lin.exr" >"$work/hdr" 2>&1
    check "EXR tagged with Rec.709 primaries and D65 white" \
        'grep -A4 "^chromaticities" "$work/hdr" | tr -s " " | grep -q "red.*0.64.*0.33" && grep -A4 "^chromaticities" "$work/hdr" | grep -q "white.*0.3127.*0.329"'
    run "$scene" $size -o "$work/g22.exr" --ocio-config "$gamma22"
    exrheader "$work/g22.exr" >"$work/hdr" 2>&1
    check "a config that cannot say the working space's primaries leaves the EXR untagged" \
        '[ $status -eq 0 ] && ! grep -q "^chromaticities" "$work/hdr"'
else
    skip "EXR chromaticities" "exrheader not installed (Debian package openexr)"
fi

run "$scene" $size -o "$work/s.png" --view Raw --stats
check "--stats names the config, display, view and working space" \
    'grep -q "colour: OpenColorIO.*display .sRGB., view .Raw., working space .Linear Rec.709." "$work/err"'
echo "1..$n"
