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
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstcolour.XXXXXX") || bail "cannot make a temporary folder"
trap 'rm -rf "$work"' EXIT
unset OCIO OCIO_ACTIVE_DISPLAYS OCIO_ACTIVE_VIEWS OCIO_INACTIVE_COLORSPACES
run() { # runs hstrace, keeps stderr in $work/err and the status in $status
    "$hstrace" "$@" >"$work/out" 2>"$work/err"; status=$?
}
# encoding LINEAR DISPLAY OPTIONS...: tests/display_codes on the two images;
# its status in $codes_status, its summary line shown as a comment.
encoding() {
    "$codes" "$@" >"$work/cmp" 2>&1; codes_status=$?
    sed 's/^/# /' "$work/cmp"
}
# The display-code limits are in 8-bit codes. Measured on desk at 48x36
# (2026-11, OpenColorIO 2.1.2): POV-Ray's curve, the shipped sRGB view, Raw
# and the test config's Gamma 2.2 view all give 0 codes off. POV-Ray's
# curve and Raw are asserted code for code (0). The two OpenColorIO views
# keep 1 code, the smallest limit above 0, and more than 10x the measured 0
# on purpose: OpenColorIO's CPU processor evaluates its curves in float
# with fast power approximations (OCIO's SSE path), so a sample a hair from
# a rounding boundary may round one code the other way on another build or
# CPU; a wrong curve is several codes off (the sRGB curve against Gamma 2.2:
# 6 codes in the test below).
for tool in "$hstrace" "$codes"; do
    [ -x "$tool" ] || bail "$tool is not built"
done

# 1. The shipped config, as OpenColorIO's own checker sees it.
ociocheck=""
[ -n "${OCIOCHECK:-}" ] && ociocheck=$(command -v "$OCIOCHECK" 2>/dev/null || true)
[ -z "$ociocheck" ] && ociocheck=$(command -v ociocheck 2>/dev/null || true)
if [ -n "$ociocheck" ]; then
    "$ociocheck" --iconfig "$shipped" >"$work/ociocheck" 2>&1; st=$?
    sed 's/^/# /' "$work/ociocheck" | grep -E 'Version:|Default|\(sRGB|passed|failed|ERROR|WARNING'
    check_status "ociocheck accepts the shipped config: status 0" "$st" 0
    check "ociocheck: validation passed" grep -q "^passed" "$work/ociocheck"
    check_fails "ociocheck finds no error and no missing role in it" grep -q -e ERROR -e WARNING "$work/ociocheck"
    check_fails "ociocheck refuses the deliberately broken test config (the check has teeth)" \
        "$ociocheck" --iconfig "$srcdir/tests/ocio/missing-space.ocio"
else
    for d in "ociocheck accepts the shipped config: status 0" "ociocheck: validation passed" \
             "ociocheck finds no error and no missing role in it" "ociocheck refuses the deliberately broken test config"; do
        skip "$d" "ociocheck not installed (Debian package opencolorio-tools)"
    done
fi

scene="$srcdir/scenes/desk.pov"
# The linear render every encoding is compared with (float, so no half rounding).
"$hstrace" "$scene" --width 48 --height 36 --exr-float -o "$work/lin.exr" 2>"$work/err" || { sed 's/^/# /' "$work/err"; bail "cannot render $scene"; }
# (That this PNG is POV-Ray's encoding, code for code, tests/encoding.sh
# checks against POV-Ray's own files.)
run "$scene" --width 48 --height 36 -o "$work/default.png"
check_status "no OCIO option, no \$OCIO: renders a PNG" "$status" 0
OCIO='' "$hstrace" "$scene" --width 48 --height 36 -o "$work/empty.png" 2>/dev/null
check "an empty \$OCIO is the same as none" cmp "$work/default.png" "$work/empty.png"

if ! "$hstrace" --version | grep -q "OpenColorIO [0-9]"; then
    # Built with configure --without-ocio.
    for opt in "--ocio-config $shipped" "--display sRGB" "--view Raw" "--colorspace scene_linear"; do
        # shellcheck disable=SC2086 # $opt is an option and its value
        run "$scene" --width 48 --height 36 -o "$work/x.png" $opt
        check "without OpenColorIO, ${opt%% *} is refused: status 1 and the reason" \
            exited 1 "built without OpenColorIO (configure --without-ocio)"
        check "... no image" [ ! -e "$work/x.png" ]
    done
    OCIO="$gamma22" "$hstrace" "$scene" --width 48 --height 36 -o "$work/env.png" 2>"$work/err"; status=$?
    check "without OpenColorIO, \$OCIO is ignored with a warning" exited 0 "OCIO ignored"
    check "... and the PNG is POV-Ray's" cmp "$work/default.png" "$work/env.png"
    skip "the OpenColorIO views, configs and names (sections 2 to 7 below)" \
        "built without OpenColorIO (configure --without-ocio)"
    tap_end
    exit 0
fi

# 2. The shipped config's views.
run "$scene" --width 48 --height 36 -o "$work/srgb.png" --display sRGB --view Standard
check_status "shipped config, sRGB display, Standard view: renders" "$status" 0
encoding "$work/lin.exr" "$work/srgb.png" --curve srgb --steps 1
check_status "Standard view is the sRGB formula within one 8-bit step" "$codes_status" 0
run "$scene" --width 48 --height 36 -o "$work/shipped.png" --ocio-config "$shipped"
check_status "--ocio-config alone: renders" "$status" 0
check "the shipped config's defaults are that view (--ocio-config alone gives the same PNG)" \
    cmp "$work/srgb.png" "$work/shipped.png"
run "$scene" --width 48 --height 36 -o "$work/raw.png" --view Raw
check_status "Raw view: renders" "$status" 0
encoding "$work/lin.exr" "$work/raw.png" --curve raw --steps 0
check_status "Raw view writes the linear values, clamped and rounded, code for code" "$codes_status" 0
run "$scene" --width 48 --height 36 -o "$work/raw.ppm" --view Raw
check_status "Raw view, PPM: renders" "$status" 0
check "PPM goes through the view too" "$codes" "$work/lin.exr" "$work/raw.ppm" --curve raw --steps 0
check_fails "and the Raw PNG differs from the sRGB one" cmp -s "$work/raw.png" "$work/srgb.png"

# 3. A config with another view.
run "$scene" --width 48 --height 36 -o "$work/g22.png" --ocio-config "$gamma22" --display Gamma --view "Gamma 2.2"
check_status "test config's Gamma 2.2 view: renders" "$status" 0
encoding "$work/lin.exr" "$work/g22.png" --curve gamma --gamma 2.2 --steps 1
check_status "test config's Gamma 2.2 view: the PNG is x^(1/2.2) within one step" "$codes_status" 0
encoding "$work/lin.exr" "$work/g22.png" --curve srgb --steps 1
check_status "and not the sRGB curve (dark values differ by more than a step)" "$codes_status" 1

# 4. $OCIO.
OCIO="$gamma22" "$hstrace" "$scene" --width 48 --height 36 -o "$work/env.png" 2>"$work/err"; status=$?
check_status "\$OCIO alone: renders" "$status" 0
check "\$OCIO alone selects that config and its default view" cmp "$work/env.png" "$work/g22.png"
OCIO="$work/no-such.ocio" "$hstrace" "$scene" --width 48 --height 36 -o "$work/wins.png" --ocio-config "$shipped" 2>"$work/err"; status=$?
check_status "--ocio-config and a missing \$OCIO: renders" "$status" 0
check "--ocio-config wins over \$OCIO" cmp "$work/wins.png" "$work/srgb.png"

# 5. Missing and broken configs: status 3, a message, no image.
run "$scene" --width 48 --height 36 -o "$work/x.png" --ocio-config "$work/no-such.ocio"
check "missing --ocio-config: status 3, names the file ($(head -1 "$work/err"))" exited 3 "no-such.ocio"
check "... no image" [ ! -e "$work/x.png" ]
OCIO="$work/no-such.ocio" "$hstrace" "$scene" --width 48 --height 36 -o "$work/x.png" 2>"$work/err"; status=$?
check "missing \$OCIO config: status 3, says it came from \$OCIO" exited 3 "no-such.ocio.*OCIO"
check "... no image" [ ! -e "$work/x.png" ]
run "$scene" --width 48 --height 36 -o "$work/x.png" --ocio-config "$srcdir/tests/ocio/broken-yaml.ocio"
check "malformed config: status 3 and OpenColorIO's reason ($(head -1 "$work/err" | cut -c1-100)...)" \
    exited 3 "broken.*yaml"
check "... no image" [ ! -e "$work/x.png" ]
run "$scene" --width 48 --height 36 -o "$work/x.png" --ocio-config "$srcdir/tests/ocio/missing-space.ocio"
check "config naming an undefined colour space: status 3" exited 3 "no such space"
check "... no image" [ ! -e "$work/x.png" ]
run "$scene" --width 48 --height 36 -o "$work/x.png" --ocio-config "$srcdir/tests"
check "a folder as config: status 3, says so" exited 3 "Is a directory"

# 6. Unknown names: status 1, the valid ones listed.
run "$scene" --width 48 --height 36 -o "$work/x.png" --view Filmic
check "unknown view: status 1, lists 'Standard' and 'Raw' ($(cat "$work/err"))" exited 1 "Filmic.*valid: .Standard., .Raw."
check "... no image" [ ! -e "$work/x.png" ]
run "$scene" --width 48 --height 36 -o "$work/x.png" --display Projector
check "unknown display: status 1, lists 'sRGB'" exited 1 "Projector.*valid: .sRGB."
run "$scene" --width 48 --height 36 -o "$work/x.png" --colorspace ACEScg
check "unknown colour space: status 1, lists the colour spaces" exited 1 "ACEScg.*Linear Rec.709"
run "$scene" --width 48 --height 36 -o "$work/x.png" --display ""
check "an empty name is a usage error" exited 1

# 7. The EXR's chromaticities (exrheader, Debian package openexr).
if command -v exrheader >/dev/null 2>&1; then
    exrheader "$work/lin.exr" >"$work/hdr" 2>&1
    grep -A4 "^chromaticities" "$work/hdr" | tr -s " " >"$work/chroma"
    check "EXR tagged with Rec.709 primaries" grep -q "red.*0.64.*0.33" "$work/chroma"
    check "EXR tagged with D65 white" grep -q "white.*0.3127.*0.329" "$work/chroma"
    run "$scene" --width 48 --height 36 -o "$work/g22.exr" --ocio-config "$gamma22"
    exrheader "$work/g22.exr" >"$work/hdr" 2>&1
    check_status "an EXR with the Gamma 2.2 test config: renders" "$status" 0
    check_fails "a config that cannot say the working space's primaries leaves the EXR untagged" \
        grep -q "^chromaticities" "$work/hdr"
else
    for d in "EXR tagged with Rec.709 primaries" "EXR tagged with D65 white" "an EXR with the Gamma 2.2 test config: renders" \
             "a config that cannot say the working space's primaries leaves the EXR untagged"; do
        skip "$d" "exrheader not installed (Debian package openexr)"
    done
fi

run "$scene" --width 48 --height 36 -o "$work/s.png" --view Raw --stats
check "--stats names the config, display, view and working space" \
    grep -q "colour: OpenColorIO.*display .sRGB., view .Raw., working space .Linear Rec.709." "$work/err"
tap_end
