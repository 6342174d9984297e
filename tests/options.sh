#!/bin/sh
# The documented options that no other test would notice broken, in TAP:
# each is checked for its documented effect (what it changes in the image,
# the statistics or the files), not only for an exit status 0. The options
# the other tests already cover are mapped to their checks in
# tests/options.map, which tests/option-coverage.sh holds against --help and
# the man page. Small images (64x48 and less) keep it short.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (path or name of
# povray; may be empty: the vs-povray checks are skipped).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstoptions.XXXXXX") || { echo "Bail out! no temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
# Absolute, for the checks that run in another folder.
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
case $srcdir in /*) ;; *) srcdir=$(cd "$srcdir" && pwd) ;; esac
desk="$srcdir/scenes/desk.pov"
size="--width 64 --height 48"

n=0
# check DESCRIPTION COMMAND [ARG...]: ok when the command exits 0; on
# failure, the last hstrace messages as diagnostics.
check() {
    n=$((n + 1)); d=$1; shift
    if "$@"; then
        echo "ok $n - $d"
    else
        echo "not ok $n - $d"
        [ -s "$work/err" ] && head -5 "$work/err" | sed 's/^/#   /'
    fi
}
skip() { n=$((n + 1)); echo "ok $n - $1 # SKIP $2"; }
# run ARG...: hstrace ARG...; stdout in $work/out, stderr in $work/err, the
# exit status in $status.
run() { "$hstrace" "$@" >"$work/out" 2>"$work/err"; status=$?; }
status_is() { [ "$status" -eq "$1" ]; }
# json FILE KEY: the value after the first "KEY": in FILE (a number, a
# string without its quotes, or a [list]).
json() {
    sed -n "s/.*\"$2\": \\(\\[[^]]*\\]\\|\"[^\"]*\"\\|[^,}]*\\).*/\\1/p" "$1" | head -1 | tr -d '"'
}
gt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && b != "" && a + 0 > b + 0) }'; }
same_pixels() { "$hstrace" compare "$1" "$2" --max-error 0 >/dev/null 2>&1; }
# max_error A B: the largest channel difference, from compare --json.
max_error() { "$hstrace" compare "$1" "$2" --json 2>/dev/null | sed -n 's/^ *"max_error": \([^,]*\),$/\1/p'; }
# ppm FILE W H R G B: a P3 image of one colour.
ppm() {
    f=$1 w=$2 h=$3; shift 3
    { printf 'P3\n%s %s\n255\n' "$w" "$h"; i=0; while [ $i -lt $((w * h)) ]; do echo "$*"; i=$((i + 1)); done; } >"$f"
}
ppm "$work/red.ppm" 8 6 255 0 0
ppm "$work/blue.ppm" 8 6 0 0 255
ppm "$work/green.ppm" 8 6 0 255 0

# --- --include-path DIR and +LDIR --------------------------------------------
# A scene whose background colour comes from col.inc, found only in the
# folders given: d1 holds a red one, d2 a blue one; d3 holds extra.inc.
mkdir "$work/d1" "$work/d2" "$work/d3" "$work/own" "$work/cwd"
echo '#declare Col = rgb <1, 0, 0>;' >"$work/d1/col.inc"
echo '#declare Col = rgb <0, 0, 1>;' >"$work/d2/col.inc"
echo '#declare Extra = rgb <0, 1, 0>;' >"$work/d3/extra.inc"
cat >"$work/bg.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
#include "col.inc"
camera { location <0, 0, -3> look_at 0 }
background { Col }
POV
{ cat "$work/bg.pov"; echo '#include "extra.inc"'; echo 'background { Extra }'; } >"$work/two.pov"
cp "$work/bg.pov" "$work/own/bg.pov"
echo '#declare Col = rgb <0, 1, 0>;' >"$work/own/col.inc"
tiny="--width 8 --height 6"

# shellcheck disable=SC2086 # $tiny is options
run "$work/bg.pov" $tiny -o "$work/none.exr"
missing_include() {
    status_is 3 && grep -q "^$work/bg.pov:3:10: cannot open include file 'col.inc'" "$work/err" && [ ! -e "$work/none.exr" ]
}
check "without --include-path: the include is not found: FILE:LINE:COLUMN message, exit status 3 (as documented for an unreadable include), no image" \
    missing_include
rendered() { status_is 0 && same_pixels "$1" "$2"; }
# shellcheck disable=SC2086
run "$work/bg.pov" $tiny --include-path "$work/d2" -o "$work/inc-d2.exr"
check "--include-path DIR: the include is found in DIR (the background is its blue)" rendered "$work/inc-d2.exr" "$work/blue.ppm"
# shellcheck disable=SC2086
run "$work/bg.pov" $tiny --include-path "$work/d1" --include-path "$work/d2" -o "$work/inc-d1d2.exr"
check "--include-path is repeatable, searched in order: d1 before d2 (red)" rendered "$work/inc-d1d2.exr" "$work/red.ppm"
# shellcheck disable=SC2086
run "$work/bg.pov" $tiny --include-path "$work/d2" --include-path "$work/d1" -o "$work/inc-d2d1.exr"
check "--include-path in the other order: d2 before d1 (blue)" rendered "$work/inc-d2d1.exr" "$work/blue.ppm"
# shellcheck disable=SC2086
run "$work/two.pov" $tiny --include-path "$work/d1" --include-path "$work/d3" -o "$work/inc-two.exr"
check "--include-path twice: one include from each folder (extra.inc's green)" rendered "$work/inc-two.exr" "$work/green.ppm"
# shellcheck disable=SC2086
run "$work/own/bg.pov" $tiny --include-path "$work/d1" -o "$work/inc-own.exr"
check "--include-path comes after the including file's folder (its own col.inc: green)" \
    rendered "$work/inc-own.exr" "$work/green.ppm"
# shellcheck disable=SC2086
(cd "$work" && "$hstrace" bg.pov $tiny --include-path d2 -o inc-rel.exr >/dev/null 2>"$work/err"); status=$?
check "--include-path with a relative DIR, from the current folder (blue)" rendered "$work/inc-rel.exr" "$work/blue.ppm"
# shellcheck disable=SC2086
run "$work/bg.pov" $tiny "+L$work/d2" -o "$work/L-d2.exr"
check "+LDIR: the include is found in DIR (blue), as with --include-path" rendered "$work/L-d2.exr" "$work/blue.ppm"
# shellcheck disable=SC2086
run "$work/bg.pov" $tiny "+L$work/d1" "+L$work/d2" -o "$work/L-d1d2.exr"
check "+L twice: searched in order, d1 before d2 (red)" rendered "$work/L-d1d2.exr" "$work/red.ppm"

# --- --grid N and --grid NxNxN -----------------------------------------------
# Exact methods never change a decision with the grid: the pixels stay.
# shellcheck disable=SC2086
run "$desk" $size --nth 1e9 -o "$work/grid-default.exr" --stats-json "$work/grid-default.json"
default_grid=$(json "$work/grid-default.json" grid)
grid_is() { # JSON EXR GRID
    [ "$status" -eq 0 ] && [ "$(json "$1" grid)" = "$3" ] && same_pixels "$2" "$work/grid-default.exr"
}
# shellcheck disable=SC2086
run "$desk" $size --nth 1e9 --grid 8 -o "$work/grid8.exr" --stats-json "$work/grid8.json" --stats
check "--grid 8: --stats-json reports an 8x8x8 grid ($(json "$work/grid8.json" grid); default $default_grid) and the image is the default grid's" \
    grid_is "$work/grid8.json" "$work/grid8.exr" "[8, 8, 8]"
check "--grid 8: --stats reports 8x8x8 cells" grep -q "^  grid        8x8x8 cells" "$work/err"
# shellcheck disable=SC2086
run "$desk" $size --nth 1e9 --grid 4x5x6 -o "$work/grid456.exr" --stats-json "$work/grid456.json"
check "--grid 4x5x6: --stats-json reports a 4x5x6 grid ($(json "$work/grid456.json" grid)) and the image is the default grid's" \
    grid_is "$work/grid456.json" "$work/grid456.exr" "[4, 5, 6]"
check "the default grid is none of those ($default_grid)" test "$default_grid" != "[8, 8, 8]" -a "$default_grid" != "[4, 5, 6]"
for bad in 0 4x5 8x lots 4097 2x2x2x2 -3; do
    # shellcheck disable=SC2086
    run "$desk" $size --grid "$bad" -o "$work/grid-bad.exr"
    grid_refused() {
        status_is 1 && grep -q "^hstrace: --grid '$1': expected N or NxNxN, each 1 to 4096" "$work/err" && [ ! -e "$work/grid-bad.exr" ]
    }
    check "--grid $bad: a usage error (exit status 1) saying what is expected" grid_refused "$bad"
done

# --- --tolerance R, --plane-precision, --verify-shadows, --verify-reference ---
# light-in-plane.pov has its ties in the margins: with no margin the counting
# methods disagree with the shadow ray there (55 of 6972 decisions at 64x48,
# N_th 1e9; 0 with the default margin). far-coordinates.pov far from the
# origin: float planes with double's margin lose crossings (16 there), the
# widened float margin and double lose none.
hard="$srcdir/scenes/hard"
verify() { # NAME SCENE OPTION...: a verified hst render, its figures in $work/NAME.json
    name=$1 scene=$2; shift 2
    # shellcheck disable=SC2086
    run "$scene" $size --volumes always --nth 1e9 --verify-shadows --stats-json "$work/$name.json" -o "$work/$name.exr" "$@"
}
disagree() { # JSON none|some: verified decisions > 0, and no disagreement or some
    status_is 0 && gt "$(json "$1" verified)" 0 || return 1
    if [ "$2" = none ]; then [ "$(json "$1" disagreements)" = 0 ]; else gt "$(json "$1" disagreements)" 0; fi
}
verify tol-default "$hard/light-in-plane.pov"
check "light-in-plane, default --tolerance: --verify-shadows counts $(json "$work/tol-default.json" disagreements) disagreements in $(json "$work/tol-default.json" verified) decisions" \
    disagree "$work/tol-default.json" none
verify tol-0 "$hard/light-in-plane.pov" --tolerance 0
check "--tolerance 0 turns the margins off: the counting methods disagree with the shadow ray at ties ($(json "$work/tol-0.json" disagreements) disagreements, as --verify-shadows counts)" \
    disagree "$work/tol-0.json" some
verify tol-6 "$hard/light-in-plane.pov" --tolerance 1e-6
scaled() { # the margin in force is R times the scene's scale: 1e-6 is 1000 times the default 1e-9
    awk -v a="$(json "$work/tol-6.json" tolerance)" -v b="$(json "$work/tol-default.json" tolerance)" \
        'BEGIN { r = a / b; exit !(b > 0 && r > 999.999 && r < 1000.001) }'
}
check "--tolerance 1e-6: the margin in force is 1000 times the default's ($(json "$work/tol-6.json" tolerance) and $(json "$work/tol-default.json" tolerance))" \
    scaled
verify ref-0 "$hard/light-in-plane.pov" --tolerance 0 --verify-reference
verify ref-default "$hard/light-in-plane.pov" --verify-reference
reference_counts() {
    status_is 0 && gt "$(json "$work/ref-0.json" reference_wrong)" 0 && [ "$(json "$work/ref-default.json" reference_wrong)" = 0 ] &&
        [ "$(json "$work/ref-0.json" reference_ray_wrong)" = 0 ] && gt "$(json "$work/ref-0.json" reference_ties)" 0
}
check "--verify-reference counts hst wrong against the long-double reference with --tolerance 0 ($(json "$work/ref-0.json" reference_wrong) wrong, $(json "$work/ref-0.json" reference_ties) ties), not with the default (shadow ray never wrong)" \
    reference_counts
verify pp-double "$hard/far-coordinates.pov" --plane-precision double
check "far-coordinates, --plane-precision double: no disagreement with the shadow ray ($(json "$work/pp-double.json" disagreements))" \
    disagree "$work/pp-double.json" none
verify pp-naive "$hard/far-coordinates.pov" --plane-precision float-naive
check "--plane-precision float-naive: float planes with double's margin lose crossings ($(json "$work/pp-naive.json" disagreements) disagreements)" \
    disagree "$work/pp-naive.json" some
verify pp-float "$hard/far-coordinates.pov" --plane-precision float
check "--plane-precision float: the widened margin decides as double does ($(json "$work/pp-float.json" disagreements) disagreements)" \
    disagree "$work/pp-float.json" none
check "--plane-precision float is recorded in the EXR's hstrace.options" \
    grep -aq -- "--plane-precision float --" "$work/pp-float.exr"
check "--plane-precision float-naive is recorded in the EXR's hstrace.options" \
    grep -aq -- "--plane-precision float-naive --" "$work/pp-naive.exr"

# --- --nth N|auto|per-point ----------------------------------------------------
nth_run() { # NAME VALUE
    # shellcheck disable=SC2086
    run "$desk" $size --volumes always --nth "$2" -o "$work/nth-$1.exr" --stats-json "$work/nth-$1.json"
}
nth_run 0 0; nth_run 7 7; nth_run big 1e9; nth_run pp per-point; nth_run auto auto
# schemes JSON: the sub-scheme counts; scheme JSON NAME: one of them.
schemes() { sed -n 's/.*"schemes": {\(.*\)}.*/\1/p' "$1"; }
scheme() { sed -n "s/.*\"schemes\": {.*\"$2\": \\([0-9]*\\).*/\\1/p" "$1" | head -1; }
check "--nth 7: N_th fixed at 7 (--stats-json nth $(json "$work/nth-7.json" nth))" test "$(json "$work/nth-7.json" nth)" = 7.000
check "--nth per-point: --stats-json nth is per-point" test "$(json "$work/nth-pp.json" nth)" = per-point
check "--nth auto: N_th is the shadow ray's cost over counting's ($(json "$work/nth-auto.json" nth) and $(json "$work/nth-auto.json" nth_shadow_ray))" \
    test "$(json "$work/nth-auto.json" nth)" = "$(json "$work/nth-auto.json" nth_shadow_ray)"
threshold_moves() {
    gt "$(scheme "$work/nth-0.json" conventional)" "$(scheme "$work/nth-big.json" conventional)" &&
        gt "$(scheme "$work/nth-big.json" volume)" "$(scheme "$work/nth-0.json" volume)"
}
check "--nth 0 sends more decisions to the shadow ray and fewer to shadow volumes than --nth 1e9 ($(schemes "$work/nth-0.json") / $(schemes "$work/nth-big.json"))" \
    threshold_moves
same_nth() { same_pixels "$work/nth-0.exr" "$work/nth-big.exr" && same_pixels "$work/nth-0.exr" "$work/nth-pp.exr"; }
check "--nth 0, 1e9 and per-point: the same image" same_nth

# --- --pixel-coherence on|off ---------------------------------------------------
# shellcheck disable=SC2086
run "$desk" $size --volumes always --nth 1e9 --pixel-coherence on -o "$work/pc-on.exr" --stats-json "$work/pc-on.json"
# shellcheck disable=SC2086
run "$desk" $size --volumes always --nth 1e9 --pixel-coherence off -o "$work/pc-off.exr" --stats-json "$work/pc-off.json"
coherence() {
    gt "$(json "$work/pc-on.json" coherent)" 0 && [ "$(json "$work/pc-off.json" coherent)" = 0 ] &&
        same_pixels "$work/pc-on.exr" "$work/pc-off.exr"
}
check "--pixel-coherence on carries counts from the neighbouring pixel ($(json "$work/pc-on.json" coherent)), off none ($(json "$work/pc-off.json" coherent)); the same image" \
    coherence

# --- --shadows METHOD ---------------------------------------------------------
# (N_th fixed: eq. 7 depends on timings, and the counts checked on N_th;
# every light's volumes built: which pay depends on timings too)
for m in hst conventional cache volume light-buffer none; do
    # shellcheck disable=SC2086
    run "$desk" $size --volumes always --nth 1e9 --shadows $m -o "$work/sh-$m.exr" --stats-json "$work/sh-$m.json"
done
sj() { echo "$work/sh-$1.json"; }
method_is() { [ "$(json "$(sj "$1")" shadow_method)" = "$1" ]; }
shadows_conventional() {
    method_is conventional && gt "$(scheme "$(sj conventional)" conventional)" 0 &&
        [ "$(scheme "$(sj conventional)" conventional)" = "$(json "$(sj conventional)" queries)" ]
}
shadows_cache() { method_is cache && gt "$(scheme "$(sj cache)" "cache hit")" 0 && [ "$(scheme "$(sj cache)" volume)" = 0 ]; }
shadows_volume() { method_is volume && gt "$(scheme "$(sj volume)" volume)" 0 && [ "$(scheme "$(sj volume)" sustain)" = 0 ]; }
shadows_hst() { method_is hst && gt "$(scheme "$(sj hst)" sustain)" 0 && gt "$(scheme "$(sj hst)" volume)" 0; }
shadows_none() {
    method_is none && [ "$(json "$(sj none)" shadow_rays)" = 0 ] && ! same_pixels "$work/sh-none.exr" "$work/sh-hst.exr" &&
        [ "$(schemes "$(sj none)")" = '"sustain": 0, "self-shadow": 0, "volume": 0, "conventional": 0, "cache hit": 0, "area lit": 0, "area umbra": 0, "area beam": 0, "buffer lit": 0, "buffer cover": 0, "buffer list": 0' ]
}
same_shadows() {
    for m in conventional cache volume light-buffer; do same_pixels "$work/sh-$m.exr" "$work/sh-hst.exr" || return 1; done
}
check "--shadows conventional: every decision by the shadow ray ($(schemes "$(sj conventional)"))" shadows_conventional
check "--shadows cache: cache hits, no counting ($(schemes "$(sj cache)"))" shadows_cache
check "--shadows volume: shadow volumes, no sustain ($(schemes "$(sj volume)"))" shadows_volume
check "--shadows hst: sustain and shadow volumes ($(schemes "$(sj hst)"))" shadows_hst
check "--shadows none: no method decides, no shadow ray, and another image than hst's" shadows_none
check "--shadows conventional, cache, volume, light-buffer and hst: the same image" same_shadows

# --- --volumes auto|always -----------------------------------------------------
# A mesh of 20000 triangles seen at 16x12: 192 camera rays ask at most 192
# decisions a light, a few microseconds of shadow rays, against milliseconds
# of building volumes. Auto (the default) builds none and decides every
# point by the shadow ray; always builds them; both give the same image.
sh "$srcdir/scenes/make-mesh.sh" 20000 2 >"$work/mesh20k.pov"
run "$work/mesh20k.pov" --width 16 --height 12 -o "$work/va.exr" --stats-json "$work/va.json"
va_status=$status
run "$work/mesh20k.pov" --width 16 --height 12 --volumes always -o "$work/vw.exr" --stats-json "$work/vw.json"
vw_status=$status
volumes_auto() {
    [ "$va_status" = 0 ] && [ "$(json "$work/va.json" mode)" = auto ] &&
        [ "$(grep -c '"volumes": false' "$work/va.json")" = 2 ] && ! grep -q '"volumes": {' "$work/va.json" &&
        [ "$(scheme "$work/va.json" conventional)" = "$(json "$work/va.json" queries)" ] &&
        gt "$(json "$work/va.json" queries)" 0
}
check "--volumes auto (default): a big mesh seen small builds no volumes, every decision by the shadow ray ($(schemes "$work/va.json"))" \
    volumes_auto
volumes_always() {
    [ "$vw_status" = 0 ] && [ "$(json "$work/vw.json" mode)" = always ] && grep -q '"volumes": {' "$work/vw.json" &&
        gt "$(scheme "$work/vw.json" volume)" 0 && same_pixels "$work/va.exr" "$work/vw.exr"
}
check "--volumes always: every light's volumes built and counting ($(schemes "$work/vw.json")); the same image as auto" \
    volumes_always
# shellcheck disable=SC2086
run "$desk" $size --volumes sometimes -o "$work/vbad.exr"
volumes_bad() { status_is 1 && grep -q "^hstrace: --volumes 'sometimes': expected auto or always" "$work/err" && [ ! -e "$work/vbad.exr" ]; }
check "bad --volumes value: exit status 1, says what is valid, writes nothing" volumes_bad

# --- --threads N and +WTn -------------------------------------------------------
# shellcheck disable=SC2086
run "$desk" $size --threads 3 -o "$work/t3.exr" --stats-json "$work/t3.json"
check "--threads 3: renders on 3 threads (--stats-json threads $(json "$work/t3.json" threads))" test "$(json "$work/t3.json" threads)" = 3
# shellcheck disable=SC2086
run "$desk" $size +WT3 -o "$work/wt3.exr" --stats-json "$work/wt3.json"
check "+WT3: renders on 3 threads (--stats-json threads $(json "$work/wt3.json" threads))" test "$(json "$work/wt3.json" threads)" = 3
# shellcheck disable=SC2086
run "$desk" $size --threads 0 -o "$work/t0.exr"
threads_refused() { status_is 1 && grep -q -- "--threads '0': must be 1 to 1024" "$work/err" && [ ! -e "$work/t0.exr" ]; }
check "--threads 0: a usage error (exit status 1) saying the range" threads_refused

# --- --width N --height N, -o FILE, --output FILE, the default output ------------
size_is() { # IMAGE W H
    "$hstrace" compare "$1" "$1" --json >"$work/size.json" 2>/dev/null &&
        [ "$(json "$work/size.json" width)" = "$2" ] && [ "$(json "$work/size.json" height)" = "$3" ]
}
run "$desk" --width 24 --height 10 -o "$work/w24.exr"
check "--width 24 --height 10: a 24x10 image" size_is "$work/w24.exr" 24 10
run "$desk" --width 24 --height 10 --output "$work/long.ppm"
output_ppm() { status_is 0 && [ "$(head -c 2 "$work/long.ppm")" = P6 ] && size_is "$work/long.ppm" 24 10; }
check "--output FILE: writes FILE, in the format of its extension (.ppm: P6)" output_ppm
run "$desk" --width 24 --height 10 -o "$work/short.png"
output_png() { status_is 0 && [ "$(head -c 4 "$work/short.png" | tail -c 3)" = PNG ] && size_is "$work/short.png" 24 10; }
check "-o FILE: writes FILE (.png: a PNG)" output_png
(cd "$work/cwd" && "$hstrace" "$work/bg.pov" --width 8 --height 6 --include-path "$work/d1" >/dev/null 2>"$work/err"); status=$?
default_output() { status_is 0 && [ -s "$work/cwd/bg.png" ] && [ ! -e "$work/bg.png" ] && rendered "$work/cwd/bg.png" "$work/red.ppm"; }
check "no -o: writes SCENE.png in the current folder (not beside the scene)" default_output

# --- --exr-float ----------------------------------------------------------------
exrheader=$(command -v exrheader 2>/dev/null || true)
# shellcheck disable=SC2086
run "$desk" $size --exr-float -o "$work/float.exr"
# shellcheck disable=SC2086
run "$desk" $size -o "$work/half.exr"
if [ -n "$exrheader" ]; then
    channel_type() { "$exrheader" "$1" | grep "^    $2, "; }
    exr_float() {
        channel_type "$work/float.exr" R | grep -q "32-bit floating-point" &&
            channel_type "$work/half.exr" R | grep -q "16-bit floating-point"
    }
    check "--exr-float: 32-bit float channels (exrheader: R $(channel_type "$work/float.exr" R | sed 's/^ *R, //')); half without it" exr_float
else
    skip "--exr-float: 32-bit float channels" "exrheader not installed (Debian package openexr)"
fi

# --- --png16 -----------------------------------------------------------------------
# The PNG's bit depth (IHDR, byte 24), and its values: within 1e-4 of the
# float render (1.2e-5 measured on desk at 32x24; an 8-bit PNG is off by
# 2.9e-3 there, so the limit tells the two apart).
"$hstrace" "$desk" --width 32 --height 24 --exr-float -o "$work/ref.exr" 2>"$work/err"
run "$desk" --width 32 --height 24 --png16 -o "$work/p16.png"
"$hstrace" "$desk" --width 32 --height 24 -o "$work/p8.png" 2>"$work/err"
depth() { od -An -tu1 -j24 -N1 "$1" | tr -d ' '; }
e16=$(max_error "$work/ref.exr" "$work/p16.png") e8=$(max_error "$work/ref.exr" "$work/p8.png")
png16() { status_is 0 && [ "$(depth "$work/p16.png")" = 16 ] && [ "$(depth "$work/p8.png")" = 8 ]; }
check "--png16: a 16-bit PNG (bit depth $(depth "$work/p16.png"); $(depth "$work/p8.png") without it)" png16
check "--png16: within 1e-4 of the float render (max error $e16; 8-bit: $e8)" \
    awk -v a="$e16" -v b="$e8" 'BEGIN { exit !(a != "" && a + 0 <= 1e-4 && b + 0 > 1e-4) }'

# --- --colorspace NAME ---------------------------------------------------------------
if "$hstrace" --version | grep -q "OpenColorIO [0-9]"; then
    # The working space is the display transform's source: render values
    # taken as sRGB-encoded go to the sRGB display unchanged, as the Raw view
    # writes them.
    # shellcheck disable=SC2086
    run "$desk" $size --colorspace "sRGB Encoded Rec.709" -o "$work/cs-srgb.png" --stats
    cs_line=$(grep '^colour:' "$work/err")
    # shellcheck disable=SC2086
    "$hstrace" "$desk" $size --view Raw -o "$work/raw.png" 2>/dev/null
    # shellcheck disable=SC2086
    "$hstrace" "$desk" $size --ocio-config "$srcdir/data/ocio/config.ocio" -o "$work/ocio.png" 2>/dev/null
    colorspace_png() {
        status_is 0 && same_pixels "$work/cs-srgb.png" "$work/raw.png" && ! same_pixels "$work/cs-srgb.png" "$work/ocio.png"
    }
    check "--colorspace 'sRGB Encoded Rec.709': the PNG is the Raw view's, code for code, not the linear space's" colorspace_png
    check "--colorspace: --stats names the working space ($cs_line)" \
        grep -q "^colour: OpenColorIO.*working space 'sRGB Encoded Rec.709'" "$work/err"
    if [ -n "$exrheader" ]; then
        # shellcheck disable=SC2086
        run "$desk" $size --colorspace ACES2065-1 -o "$work/ap0.exr"
        red_x() { "$exrheader" "$1" | sed -n 's/^ *red *(\([0-9.]*\) .*/\1/p'; }
        ap0() { status_is 0 && [ "$(red_x "$work/half.exr")" = 0.64 ] && awk -v x="$(red_x "$work/ap0.exr")" 'BEGIN { exit !(x > 0.73 && x < 0.74) }'; }
        check "--colorspace ACES2065-1: the EXR's chromaticities are AP0's (red x $(red_x "$work/ap0.exr"); Rec.709's $(red_x "$work/half.exr") by default)" ap0
    else
        skip "--colorspace ACES2065-1: the EXR's chromaticities" "exrheader not installed (Debian package openexr)"
    fi
else
    skip "--colorspace: the working space" "built without OpenColorIO (tests/colour.sh checks the refusal)"
fi

# --- POV-Ray's +Qn, and the switches that change nothing -----------------------------
# +Q0-1 pigment colour only; 2-3 no shadows; 4-5 shadows; 6-7 also
# refraction; 8 and up also reflection.
cat >"$work/flat.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -3> look_at 0 }
light_source { <3, 2, -3> rgb 1 }
triangle { <-20, -20, 0>, <20, -20, 0>, <0, 20, 0> pigment { rgb <1, 0, 0> } }
POV
quality() { # SCENE Q: render at +Q, figures in $work/qQ.json
    # shellcheck disable=SC2086
    run "$1" $size "+Q$2" -o "$work/q$2.exr" --stats-json "$work/q$2.json"
}
rays() { sed -n "s/.*\"rays\": {.*\"$2\": \\([0-9]*\\).*/\\1/p" "$work/q$1.json"; }
run "$work/flat.pov" --width 8 --height 6 +Q1 -o "$work/flat1.exr"
run "$work/flat.pov" --width 8 --height 6 +Q9 -o "$work/flat9.exr"
flat() { status_is 0 && same_pixels "$work/flat1.exr" "$work/red.ppm" && ! same_pixels "$work/flat9.exr" "$work/red.ppm"; }
check "+Q1: the pigment's colour only (a red triangle is exactly red; shaded at +Q9)" flat
quality "$desk" 3
quality "$desk" 4
# shellcheck disable=SC2086
"$hstrace" "$desk" $size +Q4 --shadows none -o "$work/q4none.exr" 2>/dev/null
q3() { [ "$(json "$work/q3.json" queries)" = 0 ] && gt "$(json "$work/q4.json" queries)" 0 && same_pixels "$work/q3.exr" "$work/q4none.exr"; }
check "+Q3: no shadows (0 queries; $(json "$work/q4.json" queries) at +Q4), the image of +Q4 --shadows none" q3
quality "$desk" 7
quality "$desk" 8
q8() { [ "$(rays 7 reflected)" = 0 ] && gt "$(rays 8 reflected)" 0; }
check "+Q8 adds reflection: desk's reflected rays $(rays 7 reflected) at +Q7, $(rays 8 reflected) at +Q8" q8
quality "$srcdir/scenes/glasses.pov" 5
quality "$srcdir/scenes/glasses.pov" 6
q6() { [ "$(rays 5 refracted)" = 0 ] && gt "$(rays 6 refracted)" 0; }
check "+Q6 adds refraction: glasses' refracted rays $(rays 5 refracted) at +Q5, $(rays 6 refracted) at +Q6" q6
for sw in -A -D +D -V; do
    # shellcheck disable=SC2086
    run "$desk" $size $sw -o "$work/sw.exr"
    check "$sw is accepted and changes nothing (the same image)" rendered "$work/sw.exr" "$work/half.exr"
done
# shellcheck disable=SC2086
run "$desk" $size +A -o "$work/aa.exr"
aa_on() { status_is 0 && [ -s "$work/aa.exr" ] && ! same_pixels "$work/aa.exr" "$work/half.exr"; }
check "+A anti-aliases: exit status 0, another image than without it (tests/antialias.sh: POV-Ray's)" aa_on

# --- --version ------------------------------------------------------------------------
run --version
check "--version: hstrace VERSION and the OpenColorIO and Embree built in, or none ($(cat "$work/out"))" \
    grep -Eqx "hstrace [0-9]+\.[0-9]+\.[0-9]+ \((OpenColorIO [0-9][0-9.]*|no OpenColorIO .*); (Embree [0-9][0-9.]*|no Embree); (Open MPI|no MPI)\)" "$work/out"

# --- vs-povray: render options passed on, and refused ----------------------------------
mkdir "$work/tmp"
refused() { # OPTION: named in the message, nothing written
    status_is 1 && grep -q -- "^hstrace vs-povray: .*$1" "$work/err" && [ ! -e "$work/x.png" ] && [ ! -e "$work/x.json" ]
}
run vs-povray "$work/bg.pov" --output "$work/x.png"
check "vs-povray --output FILE: refused (exit status 1), nothing written" refused "--output"
run vs-povray "$work/bg.pov" "+O$work/x.png"
check "vs-povray +OFILE: refused (exit status 1), nothing written" refused "+O"
run vs-povray "$work/bg.pov" --stats
check "vs-povray --stats: refused (exit status 1)" refused "--stats"
run vs-povray "$work/bg.pov" --stats-json "$work/x.json"
check "vs-povray --stats-json FILE: refused (exit status 1), nothing written" refused "--stats-json"
povray=""
[ -n "${POVRAY:-}" ] && povray=$(command -v "$POVRAY" 2>/dev/null || true)
if [ -n "$povray" ]; then
    # A scene whose floor colour comes from col.inc: POV-Ray finds it only
    # through the include folders vs-povray gives it (status 5 otherwise).
    cat >"$work/vs.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
#include "col.inc"
camera { location <0, 2, -4> look_at 0 }
light_source { <2, 5, -3> rgb 1 }
plane { y, 0 pigment { Col } }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> pigment { rgb 1 } }
POV
    vs() { # vs-povray in $work, with relative folders; the table in $work/out
        (cd "$work" && HSTRACE_POVRAY="$povray" TMPDIR="$work/tmp" "$hstrace" vs-povray vs.pov --width 32 --height 24 \
            --methods hst --json "$@" >"$work/out" 2>"$work/err"); status=$?
    }
    vs_rendered() { status_is 0 && awk -v r="$(json "$work/out" rmse)" 'BEGIN { exit !(r != "" && r + 0 < 0.01) }'; }
    vs_missing() { status_is 3 && grep -q "vs.pov:3:10: cannot open include file 'col.inc'" "$work/err"; }
    vs
    check "vs-povray without an include folder: the include is not found (exit status 3, FILE:LINE:COLUMN)" vs_missing
    vs --include-path d1
    check "vs-povray --include-path DIR (relative) reaches hstrace and POV-Ray: both render, RMSE $(json "$work/out" rmse)" vs_rendered
    vs +Ld1
    check "vs-povray +LDIR (relative) reaches hstrace and POV-Ray: both render, RMSE $(json "$work/out" rmse)" vs_rendered
else
    for d in "vs-povray without an include folder" "vs-povray --include-path DIR" "vs-povray +LDIR"; do
        skip "$d" "povray not installed"
    done
fi
echo "1..$n"
