#!/bin/sh
# POV-Ray 3.7's INI keys and switches, every one, in TAP. The list below is
# POV-Ray 3.7.0's own (the INI key table and the switch table of its
# frontend/processrenderoptions.cpp: 111 keys, and each key's switch where
# it has one), with what hstrace must do with each: honoured, ignored (it
# cannot change the image or the files) or refused (refused-when-on: off,
# POV-Ray's default, is taken). Checked: `hstrace --povray-options` lists
# exactly these with these verdicts; no key is unknown to the INI reader;
# an ignored key renders; a refused one is an error at its INI line,
# naming the key and what it is about (exit status 1, no image); the
# switches, each form, likewise on the command line (one that takes no
# value given one is unknown); POV-Ray's Unix front end's -help, -?,
# -version, --V (honoured) and --benchmark (refused). And Version=3.7 (as
# Blender's exporter writes it) means +MV3.7: a scene without #version is a
# 3.7 scene, the PNG POV-Ray writes from the same INI file, code for code.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (path or name of
# povray; may be empty: the comparison is a TAP SKIP).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$(cd "$builddir" && pwd)/hstrace" # run in the test's folder
codes="$(cd "$builddir" && pwd)/tests/png_codes"
tap_work hstpovopts
[ -x "$hstrace" ] || bail "$hstrace is not built"
povray=""
if [ -n "${POVRAY:-}" ]; then povray=$(command -v "$POVRAY" 2>/dev/null || true); fi
run() { (cd "$work" && "$hstrace" "$@") >"$work/out" 2>"$work/err"; status=$?; }

# KEY  SWITCH  VERDICT
cat >"$work/keys" <<'KEYS'
All_Console              +GA   honoured
All_File                 -     refused
Antialias                +A    honoured
Antialias_Depth          +R    honoured
Antialias_Gamma          +AG   honoured
Antialias_Threshold      -     honoured
Append_File              +GP   ignored
Bits_Per_Color           -     honoured
Bits_Per_Colour          -     honoured
Bounding                 +B    ignored
Bounding_Method          +BM   ignored
Bounding_Threshold       +MB   ignored
BSP_BaseAccessCost       -     ignored
BSP_ChildAccessCost      -     ignored
BSP_ISectCost            -     ignored
BSP_MaxDepth             -     ignored
BSP_MissChance           -     ignored
Buffer_Output            -     ignored
Buffer_Size              -     ignored
Clock                    +K    honoured
Clockless_Animation      +KLA  refused-when-on
Compression              -     honoured
Continue_Trace           +C    ignored
Create_Histogram         -     ignored
Create_Ini               +GI   refused
Cyclic_Animation         +KC   honoured
Debug_Console            +GD   honoured
Debug_File               -     refused
Declare                  -     honoured
Display                  +D    ignored
Display_Gamma            -     honoured
Dither                   +TH   refused-when-on
Dither_Method            -     ignored
Draw_Vistas              +UD   ignored
End_Column               +EC   honoured
End_Row                  +ER   honoured
Fatal_Console            +GF   ignored
Fatal_Error_Command      -     refused
Fatal_Error_Return       -     ignored
Fatal_File               -     refused
Field_Render             +UF   refused-when-on
File_Gamma               -     honoured
Final_Clock              +KF   honoured
Final_Frame              +KFF  honoured
Frame_Step               +STP  honoured
Grayscale_Output         -     refused-when-on
Height                   +H    honoured
High_Reproducibility     +HR   ignored
Histogram_Grid_Size      -     ignored
Histogram_Name           -     ignored
Histogram_Type           -     ignored
Include_Header           +HI   refused
Include_Ini              -     honoured
Initial_Clock            +KI   honoured
Initial_Frame            +KFI  honoured
Input_File_Name          +I    honoured
Jitter                   +J    honoured
Jitter_Amount            -     honoured
Library_Path             +L    honoured
Light_Buffer             +UL   ignored
Max_Image_Buffer_Memory  +MI   ignored
Odd_Field                +UO   ignored
Output_Alpha             +UA   honoured
Output_File_Name         +O    honoured
Output_File_Type         +F    honoured
Output_To_File           -     honoured
Palette                  -     ignored
Pause_When_Done          +P    ignored
Post_Frame_Command       -     refused
Post_Frame_Return        -     ignored
Post_Scene_Command       -     refused
Post_Scene_Return        -     ignored
Pre_Frame_Command        -     refused
Pre_Frame_Return         -     ignored
Pre_Scene_Command        -     refused
Pre_Scene_Return         -     ignored
Preview_End_Size         +EP   ignored
Preview_Start_Size       +SP   ignored
Quality                  +Q    honoured
Radiosity_File_Name      +RF   ignored
Radiosity_From_File      +RFI  refused-when-on
Radiosity_To_File        +RFO  refused-when-on
Radiosity_Vain_Pretrace  +RVP  ignored
Real_Time_Raytracing     +RTR  refused-when-on
Remove_Bounds            +UR   ignored
Render_Block_Size        +BS   honoured
Render_Block_Step        +RS   ignored
Render_Console           +GR   honoured
Render_File              -     refused
Render_Pattern           +RP   ignored
Sampling_Method          +AM   honoured
Split_Unions             +SU   ignored
Start_Column             +SC   honoured
Start_Row                +SR   honoured
Statistic_Console        +GS   honoured
Statistic_File           -     refused
Subset_End_Frame         +EF   honoured
Subset_Start_Frame       +SF   honoured
Test_Abort               +X    ignored
Test_Abort_Count         -     ignored
User_Abort_Command       -     refused
User_Abort_Return        -     ignored
Verbose                  +V    ignored
Version                  +MV   honoured
Video_Mode               -     ignored
Vista_Buffer             +UV   ignored
Warning_Console          +GW   honoured
Warning_File             -     refused
Warning_Level            +WL   ignored
Width                    +W    honoured
Work_Threads             +WT   honoured
KEYS
check "the list holds POV-Ray 3.7's 111 keys" test "$(grep -c . "$work/keys")" = 111

# --- hstrace's own list: the same keys, switches and verdicts ---------------------
"$hstrace" --povray-options >"$work/listed" 2>"$work/err"
check "--povray-options: exit status 0" test $? = 0
awk '{ v = $3; sub(/:$/, "", v); if ($3 == "refused" && $4 == "when") v = "refused-when-on"; print $1, $2, v }' \
    "$work/listed" >"$work/got"
awk '{ print $1, $2, $3 }' "$work/keys" >"$work/want"
check "--povray-options lists POV-Ray 3.7's keys and switches with the verdicts above, and no other" \
    diff "$work/want" "$work/got"
# what a refused key is about, as --povray-options says it
what() { awk -v k="$1" '$1 == k { sub(/^[^:]*: /, ""); print; exit }' "$work/listed"; }

# --- each key in an INI file ---------------------------------------------------------
cat >"$work/scene.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -4> look_at 0 }
light_source { <2, 4, -3> rgb 1 }
box { -0.5, 0.5 pigment { rgb <0.9, 0.5, 0.2> } }
POV
nothing_written() { ! test -e "$work/k.png"; }
unknown=0
while read -r key sw verdict; do
    for value in on off; do
        [ "$value" = off ] && [ "$verdict" != refused-when-on ] && continue
        printf 'Width=8\n%s=%s\nHeight=6\n' "$key" "$value" >"$work/k.ini"
        rm -f "$work/k.png"
        run scene.pov k.ini -o k.png
        if grep -q "unknown INI key" "$work/err"; then
            unknown=$((unknown + 1))
            diag "$key=$value: $(cat "$work/err")"
        fi
        case $verdict/$value in
        ignored/* | refused-when-on/off)
            check "$key=$value ($verdict): accepted, the image rendered" exited 0
            ;;
        refused*/on)
            check "$key=$value ($verdict): exit status 1 at its line, naming it and what it is about" \
                exited 1 "^k.ini:2:1: $key: $(what "$key") is not supported by hstrace yet$"
            check "$key=$value ($verdict): no image written" nothing_written
            ;;
        esac
    done
done <"$work/keys"
check_status "no key of POV-Ray 3.7's is unknown to hstrace's INI reader (honoured ones given 'on': a value error at most)" \
    "$unknown" 0
run scene.pov +W8 +H6 Bogus_Key=1 -o k.png
check "a key POV-Ray does not know is unknown (exit status 1)" exited 1 "unknown INI key 'Bogus_Key'"
# A switch that takes no value, given one, is no switch (as in POV-Ray).
for sw in +B5 +UD1 +Vx -version2; do
    run scene.pov +W8 +H6 "$sw" -o k.png
    check "$sw: no switch of POV-Ray's, exit status 1" exited 1 "unknown POV-Ray switch '$sw'"
done
# POV-Ray's Unix front end's own options.
for o in -help '-?'; do
    run "$o"
    check "$o: hstrace's --help (exit status 0)" test "$status $(grep -c '^usage: hstrace' "$work/out")" = "0 1"
done
for o in -version --V; do
    run "$o"
    check "$o: hstrace's --version (exit status 0)" test "$status $(grep -c '^hstrace [0-9]' "$work/out")" = "0 1"
done
for o in --benchmark -benchmark; do
    run "$o"
    check "$o: refused, exit status 1, naming it" \
        exited 1 "'$o': POV-Ray's built-in benchmark scene is not supported by hstrace"
done

# --- each switch, in its forms -----------------------------------------------------------
# SWITCH|exit status|what it is about (refused)
while IFS='|' read -r sw want about; do
    rm -f "$work/k.png"
    run scene.pov +W8 +H6 "$sw" -o k.png
    if [ "$want" = 0 ]; then
        check "switch $sw: accepted, the image rendered" exited 0
    else
        check "switch $sw: refused, exit status 1, naming it: '$about'" exited 1 "^hstrace: '$sw': $about"
        check "switch $sw: no image written" nothing_written
    fi
done <<'SWITCHES'
+B|0|
-B|0|
+BM2|0|
+MB25|0|
-MB|0|
+SU|0|
+UR|0|
+UL|0|
+UV|0|
+UD|0|
+X|0|
+X100|0|
+WL1|0|
+MI128|0|
+RS1|0|
+RP3|0|
+UO|0|
+RFcache.rad|0|
+RVP|0|
+HR|0|
+C|0|
+V|0|
+SP8|0|
+EP2|0|
+AG1.5|0|
+AGx|1|the anti-aliasing gamma is a number from 0
+BS8|0|
+BS3|1|the render block size is a whole number from 4
+STP2|0|
+STPx|1|expected a whole number
+UF|1|field rendering is not supported by hstrace yet
-UF|0|
+TH|1|dithering is not supported by hstrace yet
+THFS|1|dithering is not supported by hstrace yet
-TH|0|
+RFI|1|radiosity files is not supported by hstrace yet
-RFI|0|
+RFO|1|radiosity files is not supported by hstrace yet
-RFO|0|
+RTR|1|real-time ray tracing (a display loop) is not supported by hstrace yet
-RTR|0|
+KLA|1|clockless animation (real-time ray tracing's) is not supported by hstrace yet
-KLA|0|
+HIheader.inc|1|an include file for every scene is not supported by hstrace yet
+GIout.ini|1|writing INI files is not supported by hstrace yet
SWITCHES

# --- Version=3.7, as Blender's exporter writes it --------------------------------------
# A scene without #version or assumed_gamma: POV-Ray 3.6's gamma rules,
# unless the version is set to 3.7 before its first line.
cat >"$work/blend.pov" <<'POV'
camera { location <0, 1, -4> look_at 0 }
light_source { <2, 4, -3> rgb 1 }
plane { y, -0.5 pigment { rgb 0.3 } }
box { -0.5, 0.5 pigment { rgb <0.9, 0.5, 0.2> } }
POV
# blender_ini NAME VERSION: an INI file in the style of Blender's exporter
blender_ini() {
    {
        [ -z "$2" ] || printf 'Version=%s\n' "$2"
        printf "Input_File_Name='blend.pov'\nOutput_File_Name='%s'\n" "$1"
        printf 'Width=40\nHeight=30\nBounding_Method=2\nDisplay=0\nPause_When_Done=0\nOutput_File_Type=N\nOutput_Alpha=0\n'
        printf 'Antialias=off\nSampling_Method=1\nAntialias_Depth=3\nAntialias_Threshold=0.3\nJitter=off\nAntialias_Gamma=2.5\n'
    } >"$work/$1.ini"
}
blender_ini v37 3.7
blender_ini none ""
blender_ini v36 3.6
run v37.ini +Ov37.h.png
check "Version=3.7 (Blender's INI file): accepted, the image rendered" exited 0
run none.ini +Onone.h.png
run none.ini +MV3.7 +Omv.h.png
check "Version=3.7 gives the PNG +MV3.7 gives, code for code" "$codes" "$work/mv.h.png" "$work/v37.h.png"
check_fails "... which is not the PNG without it (the scene is a 3.7 one)" "$codes" "$work/none.h.png" "$work/v37.h.png"
run v36.ini +Ov36.h.png
check "Version=3.6: refused at its line, exit status 1" \
    exited 1 "^v36.ini:1:1: Version=3.6: hstrace reads scenes as POV-Ray 3.7 does (+MV3.7 only, or Version=3.7)$"
if [ -z "$povray" ]; then
    skip "Version=3.7: POV-Ray's PNG from the same INI file" "povray not installed"
else
    (cd "$work" && { "$povray" v37.ini +Ov37.p.png -GA +WT1 || "$povray" v37.ini +Ov37.p.png -GA +WT1; }) >"$work/pov.log" 2>&1
    check "Version=3.7: POV-Ray renders the same INI file" test -s "$work/v37.p.png" &&
        check "Version=3.7: every sample has POV-Ray's code" "$codes" "$work/v37.p.png" "$work/v37.h.png"
fi
tap_end
