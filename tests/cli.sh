#!/bin/sh
# The command line as a user meets it, in TAP: exit statuses, error messages
# with FILE:LINE:COLUMN, no partial output on failure, POV-Ray switches, and
# the same image for every thread count.
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstcli.XXXXXX")
trap 'rm -rf "$work"' EXIT
n=0
check() { # description, then a shell condition
    n=$((n + 1)); d=$1; shift
    if eval "$@"; then echo "ok $n - $d"; else echo "not ok $n - $d"; fi
}
run() { # runs hstrace, keeps stderr in $work/err and the status in $status
    "$hstrace" "$@" >"$work/out" 2>"$work/err"; status=$?
}

cat >"$work/bad.pov" <<'POV'
#version 3.7;
camera { location <0,1,-3> look_at 0 }
polygon { 4, <0,0>, <1,0> <1,1>, <0,0>
  pigment { color rgb 1 }
POV
run "$work/bad.pov" -o "$work/bad.png"
check "unterminated polygon: exit status 2" '[ $status -eq 2 ]'
check "error names FILE:LINE:COLUMN ($(head -1 "$work/err"))" 'grep -q "bad.pov:[0-9][0-9]*:[0-9][0-9]*: " "$work/err"'
check "no image left behind after a scene error" '[ ! -e "$work/bad.png" ] && [ -z "$(ls -A "$work" | grep -v -e bad.pov -e err -e out)" ]'

printf '#include "no-such-file.inc"\n' >"$work/inc.pov"
run "$work/inc.pov" -o "$work/inc.png"
check "missing include file: exit status 3" '[ $status -eq 3 ]'
check "message names the include file" 'grep -q "no-such-file.inc" "$work/err"'

printf 'sphere { 0, 1 pigment { rgb 1 } }\n' >"$work/sphere.pov"
run "$work/sphere.pov" -o "$work/sphere.png"
check "unsupported object: exit status 2" '[ $status -eq 2 ]'
check "message says what is unsupported, where ($(head -1 "$work/err"))" 'grep -q "sphere.pov:1:1: .*sphere.*not supported" "$work/err"'

run "$work/missing.pov"
check "missing scene file: exit status 3" '[ $status -eq 3 ]'
run "$srcdir/scenes/holes.pov" --width 0
check "impossible size: exit status 1" '[ $status -eq 1 ] && grep -q width "$work/err"'
run "$srcdir/scenes/holes.pov" --frobnicate
check "unknown option: exit status 1" '[ $status -eq 1 ]'
run "$srcdir/scenes/holes.pov" --shadows bogus
check "unknown shadow method lists the valid ones" '[ $status -eq 1 ] && grep -q conventional "$work/err"'
run "$srcdir/scenes/holes.pov" --pixel-coherence maybe
check "bad --pixel-coherence value: exit status 1, says what is valid" \
    '[ $status -eq 1 ] && grep -q "expected on or off" "$work/err"'
run "$srcdir/scenes/holes.pov" --tolerance 1
check "bad --tolerance value: exit status 1, says the range" '[ $status -eq 1 ] && grep -q "from 0 to 1e-3" "$work/err"'
run "$srcdir/scenes/holes.pov" --plane-precision half
check "bad --plane-precision value: exit status 1, names the valid ones" \
    '[ $status -eq 1 ] && grep -q "expected double, float or float-naive" "$work/err"'
run "$srcdir/scenes/holes.pov" --nth lots
check "bad --nth value: exit status 1, says what is valid" '[ $status -eq 1 ] && grep -q "per-point" "$work/err"'
run "$srcdir/scenes/holes.pov" -o "$work/no/such/folder/x.png" --width 16 --height 12
check "unwritable output: exit status 3" '[ $status -eq 3 ] && grep -q "no/such/folder" "$work/err"'
run --help
check "--help exits 0 and lists --shadows" '[ $status -eq 0 ] && grep -q -- --shadows "$work/out"'
run --version
check "--version exits 0" '[ $status -eq 0 ] && grep -q hstrace "$work/out"'

# POV-Ray's switches mean what they mean there.
run "+I$srcdir/scenes/holes.pov" +W40 +H30 "+O$work/pov.png" +Q4
check "POV-Ray switches +I +W +H +O +Q render" '[ $status -eq 0 ] && [ -s "$work/pov.png" ]'
run "$srcdir/scenes/holes.pov" --width 40 --height 30 -o "$work/gnu.png" +Q4
check "same image as with GNU-style options" 'cmp -s "$work/pov.png" "$work/gnu.png"'

# Determinism: the same image, bit for bit, for any thread count.
for t in 1 2 3 5; do
    "$hstrace" "$srcdir/scenes/desk.pov" --width 96 --height 72 --threads $t -o "$work/t$t.exr" 2>/dev/null
done
# The pixels, not the files: the EXR header records the thread count and timings.
same_pixels() { "$hstrace" compare "$1" "$2" --max-error 0 >/dev/null 2>&1; }
check "same image for 1, 2, 3 and 5 threads" 'same_pixels "$work/t1.exr" "$work/t2.exr" && same_pixels "$work/t1.exr" "$work/t3.exr" && same_pixels "$work/t1.exr" "$work/t5.exr"'

run "$srcdir/scenes/desk.pov" --width 32 --height 24 -o "$work/s.ppm" --stats --stats-json "$work/s.json"
check "--stats prints the Table 2 rows" 'grep -q "shadow testing" "$work/err" && grep -q preprocessing "$work/err"'
check "--stats-json writes JSON with the time split" 'grep -q "\"shadow_testing\"" "$work/s.json"'
check "PPM output is binary P6" '[ "$(head -c 2 "$work/s.ppm")" = P6 ]'

# Options keep their values whatever follows them.
run "$srcdir/scenes/desk.pov" --width 32 --height 24 -o "$work/o.png" --pixel-coherence off --tolerance 0 --nth auto \
    --stats-json "$work/o.json"
check "--pixel-coherence off and --tolerance 0 stay set after --nth auto" \
    '[ $status -eq 0 ] && grep -q "\"coherent\": 0," "$work/o.json" && grep -q "\"tolerance\": 0," "$work/o.json"'
echo "1..$n"
