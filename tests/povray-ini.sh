#!/bin/sh
# POV-Ray's povray.ini, in TAP: hstrace reads the one POV-Ray 3.7 reads on
# Unix before its command line, the first of $POVINI, ./povray.ini,
# ~/.povray/3.7/povray.ini, the system's (/etc/povray/3.7/povray.ini),
# ~/.povrayrc and the old system one, and no other. Each place here holds a
# povray.ini of its own width (the system's, and those after it, a height
# too), removed one after the other: the size --stats-json reports says
# which was read, and that only one was. --no-povray-ini reads none; the
# command line overrides what it says; its Library_Path (for include files
# and INI files), Output_File_Type, Input_File_Name and Display mean what
# the man page says; a mistake in it
# is named at its FILE:LINE:COLUMN. With povray installed, POV-Ray renders
# at the size hstrace does with the same $POVINI, folder and $HOME, and
# with the machine's own system povray.ini (when there is one).
#
# The system folder is the test's own ($HSTRACE_POVRAY_SYSCONFDIR) but in
# the last checks, which read the machine's.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (path or name of
# povray; may be empty).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$(cd "$builddir" && pwd)/hstrace" # run from the test's folders
tap_work hstpovrayini
[ -x "$hstrace" ] || bail "$hstrace is not built"
povray=""
if [ -n "${POVRAY:-}" ]; then povray=$(command -v "$POVRAY" 2>/dev/null || true); fi

home="$work/home" sys="$work/sys" here="$work/here"
mkdir -p "$home/.povray/3.7" "$sys/povray/3.7" "$here" "$work/lib" "$work/empty-home" "$work/empty-here" ||
    bail "cannot make the folders"
cat >"$here/scene.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -4> look_at 0 right x*image_width/image_height }
light_source { <2, 4, -3> rgb 1 }
plane { y, -1 pigment { rgb 0.8 } }
box { -0.5, 0.5 pigment { rgb <0.9, 0.5, 0.2> } }
POV
cp "$here/scene.pov" "$work/empty-here/scene.pov"
# place FILE WIDTH [HEIGHT]: a povray.ini of that size
place() { { printf 'Width=%s\n' "$2"; [ -z "${3:-}" ] || printf 'Height=%s\n' "$3"; } >"$1"; }
place "$work/povini.ini" 11
place "$here/povray.ini" 12
place "$home/.povray/3.7/povray.ini" 13
place "$sys/povray/3.7/povray.ini" 14 7
place "$home/.povrayrc" 15
place "$sys/povray.ini" 16 7

# hst DIR ARG...: hstrace in DIR, $POVINI as $povini (unset when empty),
# $HOME as $myhome, the system folder the test's; --stats-json into
# $work/s.json; the status in $status, messages in $work/err.
povini="" myhome=$home
hst() {
    d=$1
    shift
    rm -f "$work/s.json"
    (
        cd "$d" || exit 99
        unset POVINI
        if [ -n "$povini" ]; then POVINI=$povini && export POVINI; fi
        HOME=$myhome HSTRACE_POVRAY_SYSCONFDIR=$sys exec "$hstrace" "$@" --stats-json "$work/s.json"
    ) >"$work/out" 2>"$work/err"
    status=$?
}
# size_from WIDTH HEIGHT FILE: the last run rendered at that size after
# reading FILE ("null": none)
size_from() {
    [ "$status" = 0 ] || { echo "exit status $status:"; cat "$work/err"; return 1; }
    got="$(json_value width "$work/s.json")x$(json_value height "$work/s.json") $(json_value povray_ini "$work/s.json")"
    want="$1x$2 $([ "$3" = null ] && echo null || echo "\"$3\"")"
    [ "$got" = "$want" ] || { echo "rendered ${got:-nothing}, expected $want"; return 1; }
}

# --- the first found, and only that one ------------------------------------
povini="$work/povini.ini"
hst "$here" scene.pov -o a.png
check "all six places hold one, \$POVINI set: \$POVINI's alone (11x240: no other's height)" \
    size_from 11 240 "$work/povini.ini"
povini=""
hst "$here" scene.pov -o a.png
check "\$POVINI unset: the current folder's povray.ini (12x240)" size_from 12 240 "./povray.ini"
povini="$work/missing.ini"
hst "$here" scene.pov -o a.png
check "\$POVINI names a file that cannot be opened: the current folder's is read (12x240)" \
    size_from 12 240 "./povray.ini"
check "... with a warning naming it, as POV-Ray's" \
    grep -q "warning: \$POVINI: cannot open '$work/missing.ini': No such file or directory" "$work/err"
povini=""
rm "$here/povray.ini"
hst "$here" scene.pov -o a.png
check "none in the current folder: the user's ~/.povray/3.7/povray.ini (13x240)" \
    size_from 13 240 "$home/.povray/3.7/povray.ini"
myhome=""
hst "$here" scene.pov -o a.png
check "HOME empty: no user's file is looked for; the system's (14x7)" size_from 14 7 "$sys/povray/3.7/povray.ini"
myhome=$home
rm "$home/.povray/3.7/povray.ini"
hst "$here" scene.pov -o a.png
check "no user's: the system's povray/3.7/povray.ini (14x7)" size_from 14 7 "$sys/povray/3.7/povray.ini"
hst "$here" scene.pov -o a.png --stats
check "--stats names the file read and which it is" \
    grep -q "^  povray.ini  $sys/povray/3.7/povray.ini (the system's povray.ini)$" "$work/err"
rm "$sys/povray/3.7/povray.ini"
hst "$here" scene.pov -o a.png
check "no system's: the user's ~/.povrayrc, POV-Ray 3.6's (15x240)" size_from 15 240 "$home/.povrayrc"
rm "$home/.povrayrc"
hst "$here" scene.pov -o a.png
check "no ~/.povrayrc: the system's povray.ini of POV-Ray 3.6 (16x7)" size_from 16 7 "$sys/povray.ini"
rm "$sys/povray.ini"
hst "$here" scene.pov -o a.png --stats
check "none anywhere: hstrace's defaults (320x240), povray_ini null" size_from 320 240 null
check "... and --stats says none was found" grep -q "^  povray.ini  none (none where POV-Ray looks for one)$" "$work/err"

# --- --no-povray-ini and the command line's order ---------------------------
place "$here/povray.ini" 12 9
hst "$here" scene.pov -o a.png --no-povray-ini --stats
check "--no-povray-ini: none read (320x240)" size_from 320 240 null
check "--no-povray-ini: --stats says so" grep -q "^  povray.ini  none (--no-povray-ini)$" "$work/err"
hst "$here" --no-povray-ini scene.pov -o a.png
check "--no-povray-ini before the scene: the same" size_from 320 240 null
hst "$here" scene.pov -o a.png
check "a povray.ini setting Width and Height: hstrace scene.pov renders at that size (12x9)" \
    size_from 12 9 "./povray.ini"
png_size() { # FILE: "WxH" from a PNG's header
    od -An -tu1 -j16 -N8 "$1" | awk '{ printf "%dx%d", $1 * 16777216 + $2 * 65536 + $3 * 256 + $4, $5 * 16777216 + $6 * 65536 + $7 * 256 + $8 }'
}
check "... and the PNG written is 12x9" test "$(png_size "$here/a.png")" = 12x9
hst "$here" +W20 scene.pov -o a.png
check "+W20 on the command line, before the scene: it overrides povray.ini's Width (20x9)" size_from 20 9 "./povray.ini"
printf 'Height=21\n' >"$here/mine.ini"
hst "$here" scene.pov mine.ini -o a.png
check "an INI file on the command line overrides povray.ini (12x21)" size_from 12 21 "./povray.ini"
hst "$here" scene.pov Width=30 -o a.png
check "Width=30 on the command line overrides it (30x9)" size_from 30 9 "./povray.ini"

# --- what it may say -----------------------------------------------------------
printf '#declare Mine = 1;\n' >"$work/lib/mine.inc"
printf '#include "mine.inc"\n' >"$here/lib.pov"
cat "$here/scene.pov" >>"$here/lib.pov"
printf 'Width=12\nHeight=9\nLibrary_Path="%s"\n' "$work/lib" >"$here/povray.ini"
hst "$here" lib.pov -o lib.png
check "Library_Path in povray.ini: the include is found there" exited 0
hst "$here" lib.pov -o lib.png --no-povray-ini
check "... and not without it (--no-povray-ini: cannot open, exit status 3)" exited 3 "cannot open include file 'mine.inc'"
# INI files named by the command line (or Include_Ini) are looked for in
# the library paths too, as POV-Ray finds Debian's quickres.ini; a name
# without extension gets .ini.
printf 'Width=33\nHeight=22\n' >"$work/lib/size.ini"
printf '[Small]\nWidth=34\nHeight=23\n' >"$work/lib/sections.ini"
hst "$here" scene.pov size.ini -o a.png
check "an INI file named on the command line, not in the current folder: found in povray.ini's Library_Path (33x22)" \
    size_from 33 22 "./povray.ini"
hst "$here" scene.pov "sections.ini[small]" -o a.png
check "... with a section (34x23)" size_from 34 23 "./povray.ini"
hst "$here" scene.pov Include_Ini=size -o a.png
check "Include_Ini=size: size.ini, found in the library path (33x22)" size_from 33 22 "./povray.ini"
hst "$here" scene.pov size.ini -o a.png --no-povray-ini
check "... and not without povray.ini's Library_Path (cannot open, exit status 3)" exited 3 "cannot open INI file 'size.ini'"
printf 'Width=12\nHeight=9\nOutput_File_Type=E\n' >"$here/povray.ini"
rm -f "$here/scene.exr" "$here/scene.png"
hst "$here" scene.pov
check "Output_File_Type=E in povray.ini: the default output is scene.exr" test "$status $(od -An -tx1 -N4 "$here/scene.exr" 2>/dev/null | tr -d ' ')" = "0 762f3101"
hst "$here" scene.pov -o typed.png
check "... and -o typed.png, a PNG's name, writes a PNG (the name's type wins over povray.ini's)" \
    test "$status $(od -An -tu1 -j1 -N3 "$here/typed.png" 2>/dev/null | tr -d ' ')" = "0 807871"
hst "$here" scene.pov +FE -o typed.png
check "... but +FE given on the command line with -o typed.png is refused (exit status 1)" exited 1 "+FE asks for exr"
printf 'Width=12\nHeight=9\nInput_File_Name=scene.pov\nOutput_File_Name=named.png\n' >"$here/povray.ini"
rm -f "$here/named.png"
hst "$here"
check "Input_File_Name and Output_File_Name in povray.ini: hstrace alone renders them" \
    test "$status $(png_size "$here/named.png" 2>/dev/null)" = "0 12x9"
cp "$here/scene.pov" "$here/other.pov"
hst "$here" other.pov
check "... a scene on the command line is rendered instead (not two scenes)" \
    test "$status $(json_value scene "$work/s.json")" = '0 "other.pov"'
printf 'Width=12\nHeight=9\nDisplay=On\nPause_When_Done=On\nVerbose=On\nBounding_Threshold=3\n' >"$here/povray.ini"
hst "$here" scene.pov -o a.png
check "Display=On, Pause_When_Done=On in povray.ini (as Debian's): no note" \
    test "$status $(grep -c 'note:' "$work/err")" = "0 0"
printf 'Display=On\n' >"$here/display.ini"
hst "$here" scene.pov display.ini -o a.png
check "Display=On in an INI file of the command line: the note" exited 0 "note: +D"
printf 'Width=12\nField_Render=on\n' >"$here/povray.ini"
hst "$here" scene.pov -o a.png
check "a key refused in povray.ini: exit status 1 at its FILE:LINE:COLUMN, named as povray.ini" \
    exited 1 "^./povray.ini:2:1: Field_Render: field rendering is not supported by hstrace yet (read as the current folder's povray.ini, before the command line; --no-povray-ini reads none)$"
hst "$here" scene.pov -o a.png --no-povray-ini
check "... --no-povray-ini renders all the same" exited 0
hst "$here" --help
check "... --help does not read it (exit status 0)" exited 0
rm "$here/povray.ini"

# --- against POV-Ray ------------------------------------------------------------
# pov_size DIR [ARG...]: POV-Ray's render of scene.pov in DIR, with $POVINI
# and $HOME as hst's; prints the PNG's size.
pov_size() {
    d=$1
    shift
    rm -f "$d/pov.png"
    (
        cd "$d" || exit 99
        unset POVINI
        if [ -n "$povini" ]; then POVINI=$povini && export POVINI; fi
        HOME=$myhome "$povray" +Iscene.pov "$@" +Opov.png +FN -A -D -GA +WT1 ||
            HOME=$myhome "$povray" +Iscene.pov "$@" +Opov.png +FN -A -D -GA +WT1
    ) >"$work/pov.log" 2>&1
    png_size "$d/pov.png"
}
# as_povray DESC DIR: hstrace and POV-Ray render scene.pov in DIR at one size
as_povray() {
    hst "$2" scene.pov -o hst.png
    h=$(png_size "$2/hst.png" 2>/dev/null) p=$(pov_size "$2")
    check "$1: POV-Ray renders at hstrace's size ($h)" test "${p:-none}" = "$h"
}
if [ -z "$povray" ]; then
    skip "POV-Ray reads the same povray.ini" "povray not installed"
else
    place "$work/povini.ini" 24 18
    place "$here/povray.ini" 26 19
    place "$home/.povray/3.7/povray.ini" 28 20
    povini="$work/povini.ini"
    as_povray "\$POVINI" "$here"
    povini="$work/missing.ini"
    as_povray "\$POVINI cannot be opened: the current folder's" "$here"
    povini=""
    as_povray "the current folder's" "$here"
    printf 'Library_Path="%s"\n' "$work/lib" >>"$here/povray.ini"
    hst "$here" scene.pov size.ini -o hst.png
    h=$(png_size "$here/hst.png" 2>/dev/null) p=$(pov_size "$here" size.ini)
    check "an INI file found in povray.ini's Library_Path: POV-Ray renders at hstrace's size (${h:-none})" \
        test "${p:-none}" = "${h:-no image}"
    rm "$here/povray.ini"
    as_povray "the user's" "$here"
    # The machine's own system povray.ini, both reading it.
    if [ -f /etc/povray/3.7/povray.ini ]; then
        myhome="$work/empty-home"
        rm -f "$work/empty-here/hst.png"
        (cd "$work/empty-here" && unset POVINI && HOME=$myhome "$hstrace" scene.pov -o hst.png) >"$work/out" 2>"$work/err"
        h=$(png_size "$work/empty-here/hst.png" 2>/dev/null) p=$(pov_size "$work/empty-here")
        check "the machine's /etc/povray/3.7/povray.ini: POV-Ray renders at hstrace's size (${h:-none})" \
            test "${p:-none}" = "${h:-no image}"
    else
        skip "the machine's system povray.ini" "no /etc/povray/3.7/povray.ini here"
    fi
fi
tap_end
