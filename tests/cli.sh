#!/bin/sh
# The command line as a user meets it, in TAP: exit statuses, error messages
# with FILE:LINE:COLUMN, no partial output on failure, POV-Ray switches, and
# the same image for every thread count.
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstcli.XXXXXX") || bail "no temporary folder"
trap 'rm -rf "$work"' EXIT
[ -x "$hstrace" ] || bail "$hstrace is not built"
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
check_status "unterminated polygon: exit status 2" "$status" 2
check "error names FILE:LINE:COLUMN ($(head -1 "$work/err"))" grep -q "bad.pov:[0-9][0-9]*:[0-9][0-9]*: " "$work/err"
# only_inputs: nothing in $work but the scene and run's two files
only_inputs() {
    for f in "$work"/* "$work"/.[!.]*; do
        case ${f#"$work"/} in bad.pov | err | out | '*' | '.[!.]*') ;; *) echo "left behind: $f"; return 1 ;; esac
    done
}
check "no image left behind after a scene error" only_inputs

printf '#include "no-such-file.inc"\n' >"$work/inc.pov"
run "$work/inc.pov" -o "$work/inc.png"
check_status "missing include file: exit status 3" "$status" 3
check "message names the include file" grep -q "no-such-file.inc" "$work/err"

printf 'ovus { 1, 0.5 pigment { rgb 1 } }\n' >"$work/ovus.pov"
run "$work/ovus.pov" -o "$work/ovus.png"
check_status "unsupported object: exit status 2" "$status" 2
check "message says what is unsupported, where ($(head -1 "$work/err"))" grep -q "ovus.pov:1:1: .*ovus.*not supported" "$work/err"

run "$work/missing.pov"
check_status "missing scene file: exit status 3" "$status" 3
run "$srcdir/scenes/holes.pov" --width 0
check "impossible size: exit status 1" exited 1 width
run "$srcdir/scenes/holes.pov" --frobnicate
check "unknown option: exit status 1, names it" exited 1 frobnicate
run "$srcdir/scenes/holes.pov" --shadows bogus
check "unknown shadow method lists the valid ones" exited 1 conventional
run "$srcdir/scenes/holes.pov" --pixel-coherence maybe
check "bad --pixel-coherence value: exit status 1, says what is valid" exited 1 "expected on or off"
run "$srcdir/scenes/holes.pov" --tolerance 1
check "bad --tolerance value: exit status 1, says the range" exited 1 "from 0 to 1e-3"
run "$srcdir/scenes/holes.pov" --plane-precision half
check "bad --plane-precision value: exit status 1, names the valid ones" \
    exited 1 "expected double, float or float-naive"
run "$srcdir/scenes/holes.pov" --nth lots
check "bad --nth value: exit status 1, says what is valid" exited 1 "per-point"
run "$srcdir/scenes/holes.pov" -o "$work/no/such/folder/x.png" --width 16 --height 12
check "unwritable output: exit status 3" exited 3 "no/such/folder"
run --help
check_status "--help exits 0" "$status" 0
check "--help lists --shadows" grep -q -- --shadows "$work/out"
for tool in compare vs-povray stitch; do
    check "--help's usage names hstrace $tool" grep -q "^ *hstrace $tool " "$work/out"
done
# --strict refuses what APPROXIMATIONS lists; area lights are rendered as
# POV-Ray renders them, so --help must not name them among the refused.
lacks() { ! grep -q -- "$1" "$2"; }
check "--help does not say --strict refuses area_light" lacks area_light "$work/out"
run --version
check_status "--version exits 0" "$status" 0
check "--version names hstrace" grep -q hstrace "$work/out"

# POV-Ray's switches mean what they mean there.
run "+I$srcdir/scenes/holes.pov" +W40 +H30 "+O$work/pov.png" +Q4
check_status "POV-Ray switches +I +W +H +O +Q: exit status 0" "$status" 0
check "POV-Ray switches +I +W +H +O +Q render" [ -s "$work/pov.png" ]
run "$srcdir/scenes/holes.pov" --width 40 --height 30 -o "$work/gnu.png" +Q4
check "same image as with GNU-style options" cmp "$work/pov.png" "$work/gnu.png"

# Determinism: the same image, bit for bit, for any thread count.
for t in 1 2 3 5; do
    "$hstrace" "$srcdir/scenes/desk.pov" --width 96 --height 72 --threads $t -o "$work/t$t.exr" 2>/dev/null
done
# The pixels, not the files: the EXR header records the thread count and timings.
same_pixels() { "$hstrace" compare "$1" "$2" --max-error 0; }
for t in 2 3 5; do
    check "same image for 1 and $t threads" same_pixels "$work/t1.exr" "$work/t$t.exr"
done

run "$srcdir/scenes/desk.pov" --width 32 --height 24 -o "$work/s.ppm" --stats --stats-json "$work/s.json"
check_status "--stats, --stats-json and a PPM: exit status 0" "$status" 0
check "--stats prints the Table 2 rows: shadow testing" grep -q "shadow testing" "$work/err"
check "--stats prints the Table 2 rows: preprocessing" grep -q preprocessing "$work/err"
check "--stats-json writes JSON with the time split" grep -q '"shadow_testing"' "$work/s.json"
check "PPM output is binary P6" [ "$(head -c 2 "$work/s.ppm")" = P6 ]
# The decisions at the hits of reflected and refracted rays counted apart:
# glasses refracts, cards has no mirror and no glass.
secondary() {
    python3 -c 'import json, sys
d = json.load(open(sys.argv[1])); q, q2 = d["shadows"]["queries"], d["shadows"]["secondary_queries"]
t, t2 = d["time"]["shadow_testing"], d["time"]["shadow_testing_secondary"]
ok = (0 < q2 < q and 0 < t2 < t) if sys.argv[2] == "some" else (q2 == 0 and t2 == 0)
sys.exit(0 if ok else 1)' "$1" "$2"
}
run "$srcdir/scenes/glasses.pov" --width 64 --height 48 -o "$work/g.ppm" --stats --stats-json "$work/g.json"
check "--stats-json: glasses' decisions at refracted rays' hits counted apart, with their time" secondary "$work/g.json" some
check "--stats: the decisions line gives both ns figures" grep -q "ns at secondary hits" "$work/err"
run "$srcdir/scenes/cards.pov" --width 64 --height 48 -o "$work/c.ppm" --stats-json "$work/c.json"
check "--stats-json: cards has no secondary hits, none counted" secondary "$work/c.json" none

# Options keep their values whatever follows them.
run "$srcdir/scenes/desk.pov" --width 32 --height 24 -o "$work/o.png" --volumes always --pixel-coherence off --tolerance 0 \
    --nth auto --stats-json "$work/o.json"
check_status "--pixel-coherence off --tolerance 0 --nth auto: exit status 0" "$status" 0
check "--pixel-coherence off stays set after --nth auto" grep -q '"coherent": 0,' "$work/o.json"
check "--tolerance 0 stays set after --nth auto" grep -q '"tolerance": 0,' "$work/o.json"

# A scene named without its extension, as "povray +Idesk" takes it.
case $hstrace in /*) abs=$hstrace ;; *) abs=$(pwd)/$hstrace ;; esac
cp "$srcdir/scenes/desk.pov" "$work/desk.pov"
(cd "$work" && "$abs" desk --width 8 --height 6 +D >"$work/out" 2>"$work/err"); status=$?
check_status "'hstrace desk' renders desk.pov: exit status 0" "$status" 0
check "... to desk.png, as POV-Ray names it" test -s "$work/desk.png"
check "+D: one note that there is no display window, not an error" test "$(grep -c "no display window" "$work/err")" = 1

# The progress line: on a terminal (a pseudo-terminal made by script(1)),
# rewritten in place with the pixels done, the share, the time spent and an
# estimate of what is left, and erased at the end; nothing when stderr is
# not a terminal.
if command -v script >/dev/null 2>&1; then
    (cd "$work" && script -qec "'$abs' desk.pov --width 2000 --height 1500 --threads 1 +GR -o pty.png" /dev/null \
        >pty.out 2>&1 </dev/null); status=$?
    check_status "under a pseudo-terminal: exit status 0" "$status" 0
    tr '\r' '\n' <"$work/pty.out" >"$work/pty.lines"
    check "under a pseudo-terminal: a progress line with pixels, share, time spent and left" \
        grep -Eq '^rendering: [0-9]+ of 3000000 pixels \( *[0-9]+%\), [0-9.hms]+ elapsed, about [0-9.hms]+ left' \
        "$work/pty.lines"
    # The last thing written is the line's erasure: carriage return, clear to the end.
    check "under a pseudo-terminal: the line erased at the end" \
        test "$(tail -c 4 "$work/pty.out" | od -An -tx1 | tr -d ' \n')" = 0d1b5b4b
    # -GR: POV-Ray's render stream off: no progress line.
    (cd "$work" && script -qec "'$abs' desk.pov --width 400 --height 300 --threads 1 -GR -o pty-gr.png" /dev/null \
        >pty-gr.out 2>&1 </dev/null); status=$?
    check "under a pseudo-terminal with -GR: exit status 0 and no progress line" \
        test "$status $(grep -c rendering: "$work/pty-gr.out")" = "0 0"
else
    skip "under a pseudo-terminal: a progress line" "script(1) not installed (Debian package bsdutils)"
    skip "under a pseudo-terminal: the line erased at the end" "script(1) not installed"
    skip "under a pseudo-terminal with -GR: no progress line" "script(1) not installed"
fi
run "$work/desk.pov" --width 2000 --height 1500 --threads 1 -o "$work/np.png"
check "no progress line when stderr is not a terminal (a file)" test ! -s "$work/err"
tap_end
