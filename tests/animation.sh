#!/bin/sh
# POV-Ray's animations, in TAP: the values a scene sees (clock, clock_on,
# clock_delta, initial_clock, final_clock, frame_number, initial_frame,
# final_frame) for a still, +K, +KFI/+KFF, +KI/+KF, +KC, +SF/+EF and +STP
# (Frame_Step), against
# what POV-Ray 3.7.0.10 prints for the same switches (measured, written
# below; and against POV-Ray itself when it is installed); the frames'
# file names; an animation of 3 frames whose box moves with clock, from
# switches and from an INI file, frame by frame against POV-Ray's frames
# (`hstrace compare`, POV-Ray's image as A; the limits those of
# tests/lights.sh); and a frame that fails ending the run with its status,
# the frames before it written and none after. (Partial renders: partial.sh.)
#
# Environment: top_builddir (default .), POVRAY (path or name of povray;
# default povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstanim.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
fails() { ! "$@"; }
run() { (cd "$work" && "$hstrace" "$@") >"$work/out" 2>"$work/err"; status=$?; }
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
pov() { # ARG...: POV-Ray in $work (one retry: it can time out starting its threads on a loaded machine)
    (cd "$work" && { "$povray" "$@" -A -D +WT1 >pov.log 2>&1 || "$povray" "$@" -A -D +WT1 >pov.log 2>&1; }) ||
        { tail -3 "$work/pov.log"; return 1; }
}

cat >"$work/values.pov" <<'POV'
#debug concat("C=", str(clock,0,12), " CO=", str(clock_on,0,0), " CD=", str(clock_delta,0,12), " IC=", str(initial_clock,0,6), " FC=", str(final_clock,0,6), " FN=", str(frame_number,0,0), " IF=", str(initial_frame,0,0), " FF=", str(final_frame,0,0), "\n")
camera { location <0, 0, -5> look_at 0 }
POV
# name, switches; then the lines POV-Ray 3.7.0.10 prints, one per frame.
expect() { # NAME SWITCHES LINE...
    name=$1 switches=$2
    shift 2
    printf '%s\n' "$@" >"$work/$name.want"
    # shellcheck disable=SC2086 # the switches are words
    run values.pov --width 4 --height 3 -o "$name.png" $switches
    grep '^C=' "$work/err" >"$work/$name.got"
    check "$name ($switches): the scene sees what POV-Ray 3.7 gives it" diff "$work/$name.want" "$work/$name.got"
    if [ -n "$povray" ]; then
        # shellcheck disable=SC2086
        (cd "$work" && "$povray" +Ivalues.pov +W4 +H3 "+O$name-pov.png" -D -GS -GR -GW $switches 2>&1) |
            grep '^C=' >"$work/$name.pov"
        check "$name ($switches): ... and what the installed POV-Ray gives it" diff "$work/$name.pov" "$work/$name.got"
    else
        skip "$name ($switches): ... and what the installed POV-Ray gives it" "povray not installed"
    fi
}
expect still "" \
    "C=0.000000000000 CO=0 CD=0.000000000000 IC=0.000000 FC=0.000000 FN=0 IF=0 FF=0"
expect clock "+K0.3" \
    "C=0.300000011921 CO=1 CD=0.000000000000 IC=0.000000 FC=0.000000 FN=0 IF=0 FF=0"
expect seven "+KFI1 +KFF7" \
    "C=0.000000000000 CO=1 CD=0.166667000000 IC=0.000000 FC=1.000000 FN=1 IF=1 FF=7" \
    "C=0.166666671634 CO=1 CD=0.166667000000 IC=0.000000 FC=1.000000 FN=2 IF=1 FF=7" \
    "C=0.333333343267 CO=1 CD=0.166667000000 IC=0.000000 FC=1.000000 FN=3 IF=1 FF=7" \
    "C=0.500000000000 CO=1 CD=0.166667000000 IC=0.000000 FC=1.000000 FN=4 IF=1 FF=7" \
    "C=0.666666686535 CO=1 CD=0.166667000000 IC=0.000000 FC=1.000000 FN=5 IF=1 FF=7" \
    "C=0.833333313465 CO=1 CD=0.166667000000 IC=0.000000 FC=1.000000 FN=6 IF=1 FF=7" \
    "C=1.000000000000 CO=1 CD=0.166667000000 IC=0.000000 FC=1.000000 FN=7 IF=1 FF=7"
expect clocks "+KFI2 +KFF4 +KI1 +KF2" \
    "C=1.000000000000 CO=1 CD=0.500000000000 IC=1.000000 FC=2.000000 FN=2 IF=2 FF=4" \
    "C=1.500000000000 CO=1 CD=0.500000000000 IC=1.000000 FC=2.000000 FN=3 IF=2 FF=4" \
    "C=2.000000000000 CO=1 CD=0.500000000000 IC=1.000000 FC=2.000000 FN=4 IF=2 FF=4"
expect cyclic "+KFI1 +KFF3 +KC" \
    "C=0.000000000000 CO=1 CD=0.333333000000 IC=0.000000 FC=1.000000 FN=1 IF=1 FF=4" \
    "C=0.333333343267 CO=1 CD=0.333333000000 IC=0.000000 FC=1.000000 FN=2 IF=1 FF=4" \
    "C=0.666666686535 CO=1 CD=0.333333000000 IC=0.000000 FC=1.000000 FN=3 IF=1 FF=4"
expect subset "+KFI1 +KFF10 +SF0.5 +EF0.7" \
    "C=0.444444447756 CO=1 CD=0.111111000000 IC=0.000000 FC=1.000000 FN=5 IF=1 FF=10" \
    "C=0.555555582047 CO=1 CD=0.111111000000 IC=0.000000 FC=1.000000 FN=6 IF=1 FF=10" \
    "C=0.666666686535 CO=1 CD=0.111111000000 IC=0.000000 FC=1.000000 FN=7 IF=1 FF=10"
expect step "+KFI1 +KFF7 +STP3" \
    "C=0.000000000000 CO=1 CD=0.166667000000 IC=0.000000 FC=1.000000 FN=1 IF=1 FF=7" \
    "C=0.500000000000 CO=1 CD=0.166667000000 IC=0.000000 FC=1.000000 FN=4 IF=1 FF=7" \
    "C=1.000000000000 CO=1 CD=0.166667000000 IC=0.000000 FC=1.000000 FN=7 IF=1 FF=7"
expect step-subset "+KFI1 +KFF10 +SF2 +EF9 Frame_Step=4" \
    "C=0.111111111939 CO=1 CD=0.111111000000 IC=0.000000 FC=1.000000 FN=2 IF=1 FF=10" \
    "C=0.555555582047 CO=1 CD=0.111111000000 IC=0.000000 FC=1.000000 FN=6 IF=1 FF=10"
step_names() {
    [ -s "$work/step1.png" ] && [ -s "$work/step4.png" ] && [ -s "$work/step7.png" ] || return 1
    for f in "$work"/step?.png; do
        case $f in */step[147].png) ;; *) echo "also $f"; return 1 ;; esac
    done
}
check "+STP3 of frames 1 to 7: step1.png, step4.png and step7.png written, as POV-Ray names them, and no other" step_names
names() { [ -s "$work/subset05.png" ] && [ -s "$work/subset06.png" ] && [ -s "$work/subset07.png" ] &&
    [ ! -e "$work/subset04.png" ] && [ ! -e "$work/subset08.png" ] && [ ! -e "$work/subset.png" ]; }
check "+KFF10: frames 5 to 7 written as subset05.png .. subset07.png, padded to the final frame's digits" names
check "+KFF7: frames written as seven1.png .. seven7.png" test -s "$work/seven1.png" -a -s "$work/seven7.png"

# --- a moving box, 3 frames, against POV-Ray ------------------------------------
cat >"$work/move.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> right x*4/3 }
light_source { <-2, 5, -3> rgb 1 }
plane { y, 0 pigment { rgb 0.9 } }
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> pigment { rgb <1, 0.8, 0.6> } rotate y*90*clock translate x*(2*clock - 1) }
POV
printf 'Input_File_Name=move.pov\nInitial_Frame=1\nFinal_Frame=3\nWidth=80\nHeight=60\nOutput_File_Type=E\nOutput_File_Name=ini-hst\n' \
    >"$work/move.ini"
run move.pov +W80 +H60 +KFI1 +KFF3 +FE +Omove-hst
check "3 frames from switches render: exit status 0" exited 0
run move.ini
check "3 frames from an INI file render: exit status 0" exited 0
for f in 1 2 3; do
    check "frame $f: the switches' and the INI file's frames are the same image" \
        "$hstrace" compare "$work/move-hst$f.exr" "$work/ini-hst$f.exr" --max-error 0
done
check "the frames differ (the box moves with clock)" \
    fails "$hstrace" compare "$work/move-hst1.exr" "$work/move-hst3.exr" --max-rmse 1e-5
if [ -n "$povray" ]; then
    check "POV-Ray renders the 3 frames" pov +Imove.pov +W80 +H60 +KFI1 +KFF3 +FE +Omove-pov -GA
    for f in 1 2 3; do
        check "frame $f as POV-Ray renders it (RMSE <= 1e-5, max error <= 0.0005)" \
            "$hstrace" compare "$work/move-pov$f.exr" "$work/move-hst$f.exr" --max-rmse 1e-5 --max-error 0.0005
    done
else
    skip "the 3 frames as POV-Ray renders them" "povray not installed"
fi

# --- mistakes -------------------------------------------------------------------
cat >"$work/breaks.pov" <<'POV'
#if (frame_number = 2) #error "frame 2 breaks" #end
camera { location <0, 0, -5> look_at 0 }
POV
run breaks.pov --width 4 --height 3 +KFI1 +KFF3 -o breaks.png
check "a frame that fails ends the run with its status (2)" exited 2 "frame 2 breaks"
check "... the frame before it written, it and those after not" \
    test -s "$work/breaks1.png" -a ! -e "$work/breaks2.png" -a ! -e "$work/breaks3.png"
run values.pov +KFIx -o bad.png
check "+KFIx: exit status 1, says what is expected" exited 1 "'+KFIx': expected a frame number"
run values.pov +KFI1 +KFF3 +SF5 -o bad.png
check "+SF beyond the final frame: no frame to render, exit status 1" exited 1 "no frame to render"
check "... and nothing written" fails test -e "$work/bad.png"
tap_end
