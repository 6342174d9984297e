#!/bin/sh
# `hstrace stitch PART... -o FULL`, in TAP: desk at 64x48 rendered whole
# and as partial renders (rows, columns, a mix of both, given in any order,
# on different thread counts), stitched, and every channel of the result
# held to the full render's, bit for bit, by tests/exr_channels (OpenEXR
# alone, none of hstrace's image code): plain, with every analysis channel
# (--aov all, for hst with volumes and for cache, whose analysis depends on
# the pixels before it in a tile), and in 32-bit floats. The header of the
# whole (the options line without the area, the parts named). Then every
# refusal, with its message and exit status (1: parts that do not make one
# image; 3: a file that cannot be read or is no hstrace render), and FULL
# never written, nor an existing one touched.
#
# Environment: top_builddir (default .).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
channels="$builddir/tests/exr_channels"
work=$(mktemp -d "${TMPDIR:-/tmp}/hststitch.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
[ -x "$channels" ] || { echo "Bail out! $channels is not built"; exit 1; }
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
case $channels in /*) ;; *) channels=$(cd "$(dirname "$channels")" && pwd)/$(basename "$channels") ;; esac
fails() { ! "$@"; }
# Every run ends within 120 s: a stitch that hangs fails its check (137).
run() { (cd "$work" && exec timeout -s KILL 120 "$hstrace" "$@") >"$work/out" 2>"$work/err"; status=$?; }
cp "$srcdir/scenes/desk.pov" "$work/desk.pov"
exrheader=$(command -v exrheader 2>/dev/null || true)
header() { # FILE ATTRIBUTE: the attribute's value as exrheader prints it
    "$exrheader" "$work/$1.exr" | sed -n "s/^$2 (type [a-z]*): //p" | sed 's/^"\(.*\)"$/\1/'
}

# render NAME SWITCH...: desk at 64x48 into NAME.exr; nothing when it fails
# (the checks that use the file then fail).
render() {
    name=$1
    shift
    (cd "$work" && "$hstrace" desk.pov +W64 +H48 "$@" -o "$name.exr") >"$work/render.log" 2>&1 ||
        { diag "render of $name failed:"; diag "$(cat "$work/render.log")"; rm -f "$work/$name.exr"; }
}
# same_pixels A B: every channel of A.exr and B.exr the same bits (and the
# same names and types); else the lines that differ.
same_pixels() {
    "$channels" "$work/$1.exr" >"$work/$1.channels" 2>&1 && "$channels" "$work/$2.exr" >"$work/$2.channels" 2>&1 &&
        diff "$work/$1.channels" "$work/$2.channels"
}
# channel_count FILE N: FILE.exr holds N channels.
channel_count() {
    n=$("$channels" "$work/$1.exr" | sed 1d | wc -l | tr -d ' ')
    [ "$n" = "$2" ] || { echo "$1.exr holds $n channels, expected $2"; return 1; }
}
# stitched NAME N PART...: `hstrace stitch` of the PARTs (.exr) into
# NAME.exr, which must then hold the full render's pixels; the checks of
# one stitch.
stitched() {
    name=$1 full=$2
    shift 2
    args=""
    for p in "$@"; do args="$args $p.exr"; done
    # shellcheck disable=SC2086 # the parts are words
    run stitch $args -o "$name.exr"
    check "$name: stitch of$args: exit status 0, the whole written" exited 0
    check "$name: every channel is the full render's, bit for bit" same_pixels "$full" "$name"
}

# --- rows, columns, both, in any order ------------------------------------------
render full --threads 2
render top +SR1 +ER16 --threads 1
render middle +SR17 +ER30 --threads 2
render bottom +SR31 +ER48 --threads 1
stitched rows full top middle bottom
check "rows: the report names the whole" grep -q "^rows.exr: 64x48 pixels, 4 channels, stitched from 3 parts$" "$work/out"
check "rows: a part alone is not the full render (the check can fail)" fails same_pixels full middle
check "rows: nor are two of three parts stitched by hand: the part left out shows" fails same_pixels full top
render left +SC1 +EC20
render centre +SC21 +EC41 --threads 1
render right +SC42 +EC64
stitched columns full right left centre
# Four parts, none on the 16-pixel tile grid: two corners, then the rest.
render nw +SR1 +ER21 +SC1 +EC27
render ne +SR1 +ER21 +SC28 +EC64
render south +SR22 +ER48
stitched mixed full south ne nw
stitched single full full
check "a part that is the whole image stitches to itself" grep -q "stitched from 1 part$" "$work/out"
check "hstrace compare agrees: RGB off by 0 (it compares RGB only)" \
    "$hstrace" compare "$work/full.exr" "$work/mixed.exr" --max-error 0

# --- the header of the whole ---------------------------------------------------------
if [ -n "$exrheader" ]; then
    full_options=$(header full hstrace.options)
    check "header: hstrace.options is the full render's without --threads (the parts used 1 and 2)" \
        same_count "$(header rows hstrace.options)" "$(echo "$full_options" | sed 's/ --threads 2//')"
    render t1 +SR1 +ER24 --threads 1
    render t2 +SR25 +ER48 --threads 1
    run stitch t1.exr t2.exr -o same-threads.exr
    check "header: with one thread count in every part, hstrace.options keeps it" \
        same_count "$(header same-threads hstrace.options)" "$(echo "$full_options" | sed 's/ --threads 2/ --threads 1/')"
    check "header: the parts named with their areas" same_count "$(header rows hstrace.stitch)" \
        "3 parts: top.exr +SR1 +ER16 +SC1 +EC64; middle.exr +SR17 +ER30 +SC1 +EC64; bottom.exr +SR31 +ER48 +SC1 +EC64"
    check "header: hstrace.stitch.parts 3" same_count "$(header rows hstrace.stitch.parts)" 3
    check "header: the scene's hash kept" same_count "$(header rows hstrace.sceneHash)" "$(header full hstrace.sceneHash)"
    check "header: the command line is the stitch's" same_count "$(header rows hstrace.commandLine)" \
        "$hstrace stitch top.exr middle.exr bottom.exr -o rows.exr"
    no_timings() { ! "$exrheader" "$work/rows.exr" | grep -q 'hstrace\.time\.\|hstrace\.threads'; }
    check "header: no timings or thread count of one part (they differ)" no_timings
    check "header: the parts' chromaticities kept" same_count "$("$exrheader" "$work/rows.exr" | grep -A4 '^chromaticities')" \
        "$("$exrheader" "$work/full.exr" | grep -A4 '^chromaticities')"
else
    skip "the header of the whole" "exrheader not installed (Debian package openexr)"
fi

# --- every analysis channel -------------------------------------------------------
# hst with volumes: sub-scheme codes, depth counts and costs depend on pixel
# coherence, which carries the neighbour's count within a tile; N_th fixed,
# since --nth auto times each run.
aov="--aov all --volumes always --nth 4"
# shellcheck disable=SC2086 # the options are words
{
    render aov-full $aov --threads 2
    render aov-a $aov +SR1 +ER13 +SC1 +EC40 --threads 1
    render aov-b $aov +SR1 +ER13 +SC41 +EC64
    render aov-c $aov +SR14 +ER37
    render aov-d $aov +SR38 +ER48 --threads 1
}
stitched aov aov-full aov-d aov-c aov-b aov-a
check "aov: all 25 channels (R G B A, Z, N and P, per light of 3 shadow, hst and depth, shadow.loss, 2 costs)" \
    channel_count aov 25
# cache: the last blockers carry from pixel to pixel within a tile.
render cache-full --aov all --shadows cache
render cache-a --aov all --shadows cache +SC1 +EC23
render cache-b --aov all --shadows cache +SC24 +EC64
stitched cache cache-full cache-b cache-a
# 32-bit floats: the parts' type is the whole's.
render float-full --exr-float --aov shadow
render float-a --exr-float --aov shadow +SR1 +ER7
render float-b --exr-float --aov shadow +SR8 +ER48
stitched float float-full float-a float-b
float_rgb() { grep -q '^R float ' "$work/float.channels"; }
check "float: R is float in the whole" float_rgb

# --- anti-aliasing method 1: 32-pixel blocks from the area's corner -------------------
render aa-full +A0.3
render aa-a +A0.3 +SR1 +ER32
render aa-b +A0.3 +SR33 +ER48
stitched aa aa-full aa-a aa-b
check "+AM1, areas on the 32-pixel grid: no warning" fails grep -q warning "$work/err"
render aa-c +A0.3 +SR1 +ER20
render aa-d +A0.3 +SR21 +ER48
run stitch aa-c.exr aa-d.exr -o aa-off.exr
check "+AM1, areas off the grid: written (exit 0) with a warning naming the part" \
    exited 0 "warning: aa-c.exr (rows 1-20, columns 1-64): anti-aliasing method 1 (+AM1) works in 32-pixel blocks"
# +BS16: its own blocks, recorded in the parts' options.
render bs-full +A0.3 +BS16
render bs-a +A0.3 +BS16 +SR1 +ER16
render bs-b +A0.3 +BS16 +SR17 +ER48
stitched bs bs-full bs-a bs-b
check "+AM1 +BS16, areas on the 16-pixel grid: no warning" fails grep -q warning "$work/err"
render bs-c +A0.3 +BS16 +SR1 +ER20
render bs-d +A0.3 +BS16 +SR21 +ER48
run stitch bs-c.exr bs-d.exr -o bs-off.exr
check "+AM1 +BS16, areas off the grid: the warning names its 16-pixel blocks" \
    exited 0 "warning: bs-c.exr (rows 1-20, columns 1-64): anti-aliasing method 1 (+AM1) works in 16-pixel blocks"
render aa-e +A0.3 +SR17 +ER48
run stitch bs-a.exr aa-e.exr -o bs-mixed.exr
check "a +BS16 part and a default one: refused (exit status 1), their options differ" exited 1 "+BS16"

# --- analysis channels from parts whose N_th was timed apart ------------------------
render timed-a --aov all --volumes always +SR1 +ER20
render timed-b --aov all --volumes always +SR21 +ER48
run stitch timed-a.exr timed-b.exr -o timed.exr
if [ -n "$exrheader" ] && [ "$(header timed-a hstrace.nth)" = "$(header timed-b hstrace.nth)" ]; then
    skip "--nth auto timed apart: a warning" "both parts timed the same N_th"
else
    check "--nth auto timed apart: written (exit 0) with a warning that hst.* and cost.* are each part's" \
        exited 0 "warning: timed-b.exr: another hstrace.nth than timed-a.exr's: its analysis channels hst"
fi

# --- refusals ---------------------------------------------------------------------
# refused DESC STATUS PATTERN PART...: stitch exits STATUS with PATTERN in
# its message, and writes nothing (no.exr absent, no file left beside it).
refused() {
    desc=$1 want=$2 pattern=$3
    shift 3
    rm -f "$work/no.exr"
    before=$(find "$work" -maxdepth 1 | wc -l)
    run stitch "$@" -o no.exr
    check "$desc: exit status $want, '$pattern'" exited "$want" "$pattern"
    nothing_written() { [ ! -e "$work/no.exr" ] && [ "$(find "$work" -maxdepth 1 | wc -l)" = "$before" ]; }
    check "$desc: nothing written" nothing_written
}
# Parts sharing an hstrace attribute of 40 bytes: OpenEXR's writer refuses a
# name of 32 or more, and its error handler used to wait on the writer's own
# lock: hstrace stitch never ended and left its hidden temporary (issue 39).
if command -v python3 >/dev/null 2>&1; then
    for p in top middle bottom; do
        python3 "$srcdir/tests/exr-long-attribute.py" "$work/$p.exr" "$work/$p-long.exr"
    done
    refused "an attribute name of 40 bytes" 3 \
        "^hstrace stitch: cannot write 'no.exr': .*'hstrace.a-name-of-forty-bytes-for-writer' too long" \
        top-long.exr middle-long.exr bottom-long.exr
    rm -f "$work"/*-long.exr
else
    skip "an attribute name of 40 bytes" "python3 not installed"
    skip "an attribute name of 40 bytes: nothing written" "python3 not installed"
fi
render overlapping +SR10 +ER30
refused "overlap" 1 "^hstrace stitch: top.exr and overlapping.exr overlap: rows 10-16, columns 1-64 are in both$" \
    top.exr overlapping.exr bottom.exr
refused "overlap of a full part" 1 "top.exr and full.exr overlap: rows 1-16, columns 1-64 are in both" \
    top.exr full.exr
refused "a part given twice" 1 "^hstrace stitch: middle.exr is given twice$" top.exr middle.exr bottom.exr middle.exr
refused "a gap of rows" 1 \
    "^hstrace stitch: no part holds rows 17-30, columns 1-64 of the 64x48 image (a part rendered with +SR17 +ER30 +SC1 +EC64 is missing)$" \
    top.exr bottom.exr
refused "a gap of columns" 1 "no part holds rows 1-48, columns 21-41 of the 64x48 image (a part rendered with +SR1 +ER48 +SC21 +EC41" \
    left.exr right.exr
refused "a gap in a corner" 1 "no part holds rows 1-21, columns 28-64 of the 64x48 image" nw.exr south.exr
# The same pixels from a scene with one more comment: only the hash tells.
{ cat "$work/desk.pov"; echo "// one more line"; } >"$work/desk2.pov"
(cd "$work" && "$hstrace" desk2.pov +W64 +H48 +SR17 +ER30 -o other-scene.exr) >/dev/null 2>&1
check "another scene's part renders the same pixels (the refusal below is the header's)" \
    "$hstrace" compare "$work/middle.exr" "$work/other-scene.exr" --max-error 0
refused "another scene" 1 "^hstrace stitch: other-scene.exr: rendered from another scene than top.exr (desk2.pov, hstrace.sceneHash fnv1a64:[0-9a-f]*; top.exr has desk.pov, fnv1a64:[0-9a-f]*)$" \
    top.exr other-scene.exr bottom.exr
render q4 +Q4 +SR17 +ER30
refused "other options: +Q4" 1 "^hstrace stitch: q4.exr: rendered with other options than top.exr: '+Q4', where top.exr has '+Q9' (hstrace.options)$" \
    top.exr q4.exr bottom.exr
render cache-part --shadows cache +SR17 +ER30
refused "other options: --shadows cache" 1 "'--shadows cache', where top.exr has '--shadows hst'" \
    top.exr cache-part.exr bottom.exr
render aa-part +A0.3 +SR17 +ER30
refused "other options: anti-aliasing" 1 "aa-part.exr: rendered with other options than top.exr: with '+A0.3', which top.exr has not" \
    top.exr aa-part.exr bottom.exr
render clock-part +K0.5 +SR17 +ER30
refused "other options: another frame's clock, first" 1 "top.exr: rendered with other options than clock-part.exr: without '+K0.5', which clock-part.exr has" \
    clock-part.exr top.exr bottom.exr
render declare-part Declare=Shift=2 +SR17 +ER30
refused "other options: Declare=" 1 "with 'Declare=Shift=2'" top.exr declare-part.exr bottom.exr
render small +W32 +H24 +SR1 +ER10
refused "another size" 1 "^hstrace stitch: small.exr: 32x24 pixels, but top.exr has 64x48$" top.exr small.exr
render z-part --aov Z +SR17 +ER30
refused "another channel set" 1 "^hstrace stitch: z-part.exr: channel 'Z', which top.exr has not (other --aov?)$" \
    top.exr z-part.exr bottom.exr
refused "a channel missing" 1 "^hstrace stitch: top.exr: no channel 'Z', which z-part.exr has (other --aov?)$" \
    z-part.exr top.exr bottom.exr
render float-part --exr-float +SR17 +ER30
refused "another channel type" 1 "float-part.exr: channel 'A' is float, in top.exr half (other --exr-float?)" \
    top.exr float-part.exr bottom.exr
"$hstrace" compare "$work/full.exr" "$work/top.exr" --diff "$work/heat.exr" >/dev/null 2>&1
refused "an EXR hstrace did not render (compare's heat map)" 3 \
    "^hstrace stitch: heat.exr: not an EXR rendered by hstrace: its header has no hstrace.options$" top.exr heat.exr
(cd "$work" && "$hstrace" desk.pov +W64 +H48 +SR17 +ER30 -o middle.png) >/dev/null 2>&1
refused "a PNG" 3 "^hstrace stitch: middle.png: not an EXR file$" top.exr middle.png bottom.exr
refused "a missing part" 3 "^hstrace stitch: nosuch.exr: No such file or directory$" top.exr nosuch.exr bottom.exr
mkdir "$work/sub"
refused "a folder given as a part" 3 "^hstrace stitch: sub: Is a directory$" top.exr sub bottom.exr
head -c 3000 "$work/middle.exr" >"$work/truncated.exr"
refused "a truncated part (a job still writing)" 3 "^hstrace stitch: truncated.exr: " top.exr truncated.exr bottom.exr
printf 'v/1\001 not really an EXR header at all' >"$work/garbage.exr"
refused "a file with EXR's magic number and nothing else" 3 "^hstrace stitch: garbage.exr: " top.exr garbage.exr bottom.exr
cp "$work/rows.exr" "$work/existing.exr"
run stitch top.exr bottom.exr -o existing.exr
check "a refusal leaves an existing FULL as it was" cmp "$work/rows.exr" "$work/existing.exr"

# --- the command line -------------------------------------------------------------
run stitch top.exr middle.exr bottom.exr
check "no output: exit status 1" exited 1 "^hstrace stitch: no output given: hstrace stitch PART.exr... -o FULL.exr (see --help)$"
run stitch -o no.exr
check "no parts: exit status 1" exited 1 "^hstrace stitch: no parts given"
run stitch top.exr bottom.exr middle.exr -o no.png
check "-o FILE.png: exit status 1, EXR only" exited 1 "^hstrace stitch: -o 'no.png': the stitched image is an EXR file"
run stitch top.exr middle.exr bottom.exr -o top.exr
check "-o naming a part: exit status 1" exited 1 "^hstrace stitch: -o 'top.exr' is also given as a part$"
run stitch top.exr middle.exr bottom.exr -o whole.exr -o again.exr
check "-o twice: exit status 1" exited 1 "-o given twice"
run stitch --frobnicate top.exr -o no.exr
check "an unknown option: exit status 1" exited 1 "unknown option '--frobnicate' (see hstrace stitch --help)"
run stitch top.exr middle.exr bottom.exr -o no-such-folder/whole.exr
check "an unwritable FULL: exit status 3" exited 3 "^hstrace stitch: cannot write 'no-such-folder/whole.exr': No such file or directory$"
run stitch --help
check "--help: exit status 0" exited 0
check "--help: the usage line" grep -q "^usage: hstrace stitch PART.exr... -o FULL.exr$" "$work/out"
run stitch --output=dashes.exr top.exr middle.exr -- bottom.exr
check "--output=FULL and -- before the parts" exited 0
check "... the whole written" same_pixels full dashes
tap_end
