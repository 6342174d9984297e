#!/bin/sh
# POV-Ray's INI files, Declare= and +F, in TAP: an INI file with comments,
# a section chosen by name, switches in it and a Declare, rendered by hstrace
# and by POV-Ray from the same INI file and compared by `hstrace compare`
# (POV-Ray's image as A; the limits those of tests/lights.sh, a little above
# what half-float EXR's rounding alone gives); the Declare seen (without it
# the image is outside the limits); later settings winning; the values a
# Declare gives the scene as POV-Ray 3.7 gives them (6 significant digits,
# the first of two declarations); and every mistake with its FILE:LINE:COLUMN,
# its exit status and no image written. Without povray the comparisons are
# TAP SKIPs.
#
# Environment: top_builddir (default .), POVRAY (path or name of povray;
# default povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstini.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
fails() { ! "$@"; }
# run ARG...: hstrace in $work; stderr in $work/err, the status in $status.
run() { (cd "$work" && "$hstrace" "$@") >"$work/out" 2>"$work/err"; status=$?; }

# The box moves by Shift, declared in the INI file (0 without it).
cat >"$work/scene.pov" <<'POV'
#version 3.7;
#ifndef (Shift) #declare Shift = 0; #end
global_settings { assumed_gamma 1 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> right x*image_width/image_height }
light_source { <-2, 5, -3> rgb 1 }
plane { y, 0 pigment { rgb 0.9 } }
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> pigment { rgb <1, 0.8, 0.6> } translate x*Shift }
POV
cat >"$work/render.ini" <<'INI'
; settings for scene.pov
Input_File_Name=scene.pov   ; the scene
Width=64
Height = 48
Declare=Shift=1.25
# switches, two on a line
-D -V

[Small]
Width=80
Height=60
+FE +Osmall-hst

[Large]
Width=640
Height=480
INI

# --- against POV-Ray ------------------------------------------------------
run "render.ini[small]" +WT1
check "an INI file's [Small] section (named in another case) renders: exit status 0" exited 0
check "+FE and +Osmall-hst in the section: an EXR named small-hst.exr" test -s "$work/small-hst.exr"
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
pov() { # ARG...: POV-Ray in $work (one retry: it can time out starting its threads on a loaded machine)
    (cd "$work" && { "$povray" "$@" -A -GA +WT1 >pov.log 2>&1 || "$povray" "$@" -A -GA +WT1 >pov.log 2>&1; }) ||
        { tail -3 "$work/pov.log"; return 1; }
}
if [ -n "$povray" ]; then
    check "POV-Ray renders the same INI file and section" pov "render.ini[Small]" +Osmall-pov.exr
    check "the INI file's image as POV-Ray renders it (80x60, the box shifted by the Declare; RMSE <= 1e-5, max error <= 0.0005)" \
        "$hstrace" compare "$work/small-pov.exr" "$work/small-hst.exr" --max-rmse 1e-5 --max-error 0.0005
    run scene.pov +W80 +H60 +FE +Onoshift
    check "the scene without the Declare renders" exited 0
    check "without the Declare the image is outside those limits (the comparison sees it)" \
        fails "$hstrace" compare "$work/small-pov.exr" "$work/noshift.exr" --max-rmse 1e-5 --max-error 0.0005
else
    skip "the INI file's image as POV-Ray renders it" "povray not installed"
    skip "without the Declare the image is outside those limits" "povray not installed"
fi

# --- settings in order -------------------------------------------------------
run render.ini +W40 +H30 --stats-json s.json -o later.png
size_is() { grep -q "\"width\": $1," "$work/s.json" && grep -q "\"height\": $2," "$work/s.json"; }
check "render.ini then +W40 +H30: the later switches win (40x30)" size_is 40 30
run +W40 +H30 render.ini --stats-json s.json -o earlier.png
check "+W40 +H30 then render.ini: the INI file's settings win (64x48; no section: [Small] and [Large] ignored)" \
    size_is 64 48
cat >"$work/values.pov" <<'POV'
#debug concat("X=", str(X, 0, 9), " Y=", str(Y, 0, 3), " S=", S, "\n")
camera { location <0, 0, -5> look_at 0 }
POV
run values.pov Declare=X=1.23456789 Declare=Y=2 Declare=Y=3 'Declare=S="a b"' --width 4 --height 3 -o v.png
check "Declare=X=1.23456789 gives the scene 1.23457 (single precision, 6 significant digits, as POV-Ray 3.7)" \
    grep -q "X=1.234570000 " "$work/err"
check "Declare=Y=2 then Declare=Y=3: the first stands (as POV-Ray 3.7)" grep -q " Y=2.000 " "$work/err"
check "Declare=S=\"a b\": a string" grep -q " S=a b$" "$work/err"

# --- mistakes ----------------------------------------------------------------
nothing_written() { ! ls "$work"/bad*.png >/dev/null 2>&1; }
mistake() { # NAME STATUS PATTERN DESC LINES...: an INI file of LINES, run, its message and status
    name=$1 want=$2 pattern=$3 desc=$4
    shift 4
    printf '%s\n' "$@" >"$work/$name.ini"
    run "$name.ini" scene.pov -o "bad-$name.png"
    check "$desc: exit status $want, '$pattern'" exited "$want" "$pattern"
    check "$desc: no image written" nothing_written
}
mistake key 1 "^key.ini:2:1: unknown INI key 'Bogus_Key'$" "an unknown key" "Width=64" "Bogus_Key=1"
mistake novalue 1 "^novalue.ini:1:1: Width= has no value$" "a key without a value" "Width="
mistake section 1 "^section.ini:2:1: a \\[section\\] header without its ']'$" "an unclosed section header" \
    "Width=64" "[Small"
mistake quote 1 "^quote.ini:1:1: a string opened with \" is not closed on its line$" "an unclosed quote" \
    'Output_File_Name="out.png'
mistake width 1 "^width.ini:1:5: '+W0': width must be 1 to 32768$" "a bad switch in an INI file" "-D  +W0"
mistake field 1 "^field.ini:1:1: Field_Render: field rendering is not supported by hstrace yet$" \
    "a POV-Ray key hstrace does not support yet" "Field_Render=on"
mistake declare 1 "Declare=X=abc: the value must be a number" "a Declare whose value is no number" "Declare=X=abc"
# Hostile INI files: each an error with its status, no crash and no hang
# (the suite runs under AddressSanitizer and UBSan in CI's second build).
printf 'Width=64\n\000\001\377garbage\n' >"$work/nul.ini"
run nul.ini scene.pov -o bad-nul.png
check "a NUL byte in an INI file: exit status 1, says so" exited 1 "NUL byte"
printf 'Include_Ini=self.ini\n' >"$work/self.ini"
run self.ini scene.pov -o bad-self.png
check "an INI file that includes itself: exit status 1 at 16 deep, no hang" exited 1 "more than 16 deep"
awk 'BEGIN { printf "Output_File_Name="; for (i = 0; i < 70000; i++) printf "x"; printf "\n" }' >"$work/long.ini"
run long.ini scene.pov --width 4 --height 3
check "a 70000-character value: read whole; as an output name without an extension it is refused (exit status 1)" \
    exited 1 "unknown image format"
head -c 1100000 /dev/zero | tr '\0' ';' >"$work/big.ini"
run big.ini scene.pov -o bad-big.png
check "an INI file over 1 MiB: exit status 3, too big" exited 3 "too big for an INI file"
printf '[Unclosed' >"$work/eof.ini"
run eof.ini scene.pov -o bad-eof.png
check "a section header cut by the end of the file: exit status 1" exited 1 "without its ']'"
run missing.ini scene.pov -o bad-missing.png
check "an INI file that cannot be read: exit status 3, says which" exited 3 "cannot open INI file 'missing.ini'"
mistake include 3 "^include.ini:2:1: cannot open INI file 'gone.ini'" \
    "an INI file that includes one that cannot be read: where it was named" "Width=64" "Include_Ini=gone.ini"
mistake word 3 "^word.ini:2:3: cannot open INI file 'gone.ini'" \
    "an INI file that names one that cannot be read: where it was named (found by fuzzing)" "Width=64" "  gone.ini"
printf 'Width=24\nHeight=18\n' >"$work/more.ini"
run Include_Ini=more.ini scene.pov --stats-json s.json -o included.png
check "Include_Ini=more.ini on the command line: the key, as POV-Ray takes it, not a file of that name (24x18)" \
    size_is 24 18
run scene.pov Declare=clock=1 -o bad-clock.png
check "Declare of a reserved word: a scene error, exit status 2" exited 2 "'clock' is a reserved word"
printf 'Width=64\n' >"$work/noscene.ini"
run noscene.ini -o bad-noscene.png
check "an INI file without Input_File_Name and no scene: exit status 1" exited 1 "no scene file given"
run scene.pov +FE -o bad-type.png
check "+FE with an output named .png: refused, exit status 1" exited 1 "+FE asks for exr"
check "... and nothing written" nothing_written

# --- +F output types -----------------------------------------------------------
run scene.pov +W8 +H6 +FN16 +Ofn16
png_depth() { [ "$(od -An -tu1 -j24 -N1 "$work/fn16.png" | tr -d ' ')" = 16 ]; }
check "+FN16 +Ofn16: a 16-bit PNG named fn16.png" png_depth
run scene.pov +W8 +H6 +FP +Ofp
check "+FP +Ofp: a binary PPM named fp.ppm" test "$(head -c 2 "$work/fp.ppm" 2>/dev/null)" = P6
run scene.pov +W8 +H6 +FE
exr_magic() { [ "$(od -An -tx1 -N4 "$work/scene.exr" | tr -d ' ')" = 762f3101 ]; }
check "+FE without +O: the scene's name with .exr, an OpenEXR file" exr_magic
run scene.pov +W8 +H6 +FN +Ofn8
png_depth8() { [ "$(od -An -tu1 -j24 -N1 "$work/fn8.png" | tr -d ' ')" = 8 ]; }
check "+FN +Ofn8: an 8-bit PNG named fn8.png" png_depth8
# kind FILE: what the file's first bytes say it is.
kind() {
    case $(od -An -tu1 -N3 "$1" 2>/dev/null | tr -s ' ' | sed 's/^ //') in
    "0 0 2") echo Targa ;;
    "0 0 10") echo "RLE Targa" ;;
    "66 77 "*) echo BMP ;;
    "255 216 255") echo JPEG ;;
    "35 63 82") echo HDR ;;
    *) echo "unknown" ;;
    esac
}
for t in "T tga Targa" "C tga RLE Targa" "B bmp BMP" "J jpg JPEG" "H hdr HDR"; do
    type=${t%% *} rest=${t#* }
    ext=${rest%% *} want=${rest#* }
    printf 'Output_File_Type=%s\nOutput_File_Name=type-%s\nWidth=8\nHeight=6\n' "$type" "$type" >"$work/type-$type.ini"
    run "type-$type.ini" scene.pov
    check "Output_File_Type=$type: writes type-$type.$ext, a $want file" test "$status $(kind "$work/type-$type.$ext")" = "0 $want"
done

# --- Antialias=on turned off later, -F ----------------------------------------
printf 'Width=64\nHeight=48\nAntialias=on\n' >"$work/aa.ini"
run aa.ini scene.pov -o aa-on.png
run aa.ini scene.pov -A -o aa-off.png
run scene.pov +W64 +H48 -o plain.png
aa_later() { "$hstrace" compare "$work/aa-off.png" "$work/plain.png" --max-error 0 >/dev/null &&
    ! "$hstrace" compare "$work/aa-on.png" "$work/plain.png" --max-error 0 >/dev/null 2>&1; }
check "Antialias=on anti-aliases; then -A on the command line turns it off again (the plain image)" aa_later
run scene.pov -F -o nofile.png --width 8 --height 6
check "-F: renders, exit status 0" exited 0
check "-F: writes no image" fails test -e "$work/nofile.png"

# --- POV-Ray's console streams (+G.. -G..) and +P ----------------------------
cat >"$work/streams.pov" <<'EOF'
#debug "debug-text\n"
#warning "warning-text"
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
triangle { <-1,-1,0>, <1,-1,0>, <0,1,0> pigment { color rgb 1 } }
EOF
# shown SWITCHES...: which of the two streams reach the standard error.
shown() {
    run streams.pov +W8 +H6 -o streams.png "$@"
    [ "$status" = 0 ] || { echo "exit status $status"; cat "$work/err"; return 1; }
    printf '%s%s' "$(grep -q debug-text "$work/err" && echo D)" "$(grep -q 'warning: warning-text' "$work/err" && echo W)"
}
while IFS='|' read -r switches want; do
    # shellcheck disable=SC2086 # the switches are words
    got=$(shown $switches)
    check "streams ${switches:-(none)}: ${want:-nothing} shown" test "$got" = "$want"
done <<'STREAMS'
|DW
-GD|W
-GW|D
-GA|
-GA +GW|W
+GA -GD +GP|W
-GA +GD +GS|D
+GF -GW|D
STREAMS
run streams.pov +W8 +H6 -o streams.png --stats
stats_lines=$(grep -c '' "$work/err")
run streams.pov +W8 +H6 -o streams.png --stats -GS
check "-GS: --stats prints nothing (only the two streams' lines are left)" \
    test "$status $(grep -c '' "$work/err") $(above "$stats_lines" 10 >/dev/null && echo many)" = "0 2 many"
printf 'Debug_Console=off\n' >"$work/nodebug.ini"
check "Debug_Console=off in an INI file: the debug stream off" test "$(shown nodebug.ini)" = W
printf 'All_Console=off\nWarning_Console=on\n' >"$work/warnonly.ini"
check "All_Console=off then Warning_Console=on: warnings only" test "$(shown warnonly.ini)" = W
printf 'camera { location <0,0,-3> look_at 0 }\nsphere { 0, 1 pigment { colour rgb 1 } } }\n' >"$work/broken.pov"
run broken.pov +W8 +H6 -GA -GF -o broken.png
check "-GA -GF: a scene error is still shown (status 2, FILE:LINE:COLUMN)" exited 2 "broken.pov:2:"
run streams.pov +W8 +H6 +GWwarnings.txt -o streams.png
check "+GWwarnings.txt: refused (hstrace writes to the standard error), status 1" exited 1 "standard error only"
run streams.pov +W8 +H6 +GIout.ini -o streams.png
check "+GIout.ini: refused (no INI files written), status 1" exited 1 "writing INI files is not supported"
run streams.pov +W8 +H6 +P -o streams.png
check "+P: accepted, with a note that there is nothing to pause on" exited 0 "note: +P: hstrace has no display window to pause on"
printf 'Pause_When_Done=on\n' >"$work/pause.ini"
run pause.ini streams.pov +W8 +H6 -o streams.png
check "Pause_When_Done=on: the same note" exited 0 "note: +P:"
run streams.pov +W8 +H6 -P -o streams.png
check "-P: accepted without a note" test "$status $(grep -c 'note: +P' "$work/err")" = "0 0"
tap_end
