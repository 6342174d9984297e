#!/bin/sh
# File_Gamma against POV-Ray 3.7, in TAP. PoseRay's *_POV_main.ini files set
# it (1, 1.0, 2.2, srgb seen); POV-Ray 3.7 encodes its PNG, PPM, Targa, BMP
# and JPEG files with it (a power law, 1 being none, or sRGB, the default),
# says it in PNG's gAMA chunk (and an sRGB chunk for sRGB), leaves EXR
# linear, and encodes a scene that turns gamma correction off with
# Display_Gamma instead. A ramp of 3600 linear values (flat patches, ambient
# 1, no light: each pixel is its pigment's value) is rendered from an INI
# file written as PoseRay writes one, by hstrace and by POV-Ray, and
# compared: every PNG sample's code (tests/png_codes, libpng alone), the
# gAMA and sRGB chunks (and the values they must have), the decoded pixels
# (`hstrace compare`), the other integer types' pixels, EXR's. Values POV-Ray
# refuses (bt709, which 3.7.0 lacks; 0; a negative; below 0.001) are
# refused by both, hstrace at the INI line. Without povray the comparisons
# are TAP SKIPs.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (path or name of
# povray; may be empty).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$(cd "$builddir" && pwd)/hstrace" # run from the INI file's folder
codes="$(cd "$builddir" && pwd)/tests/png_codes"
tap_work hstfilegamma
for tool in "$hstrace" "$codes"; do
    [ -x "$tool" ] || bail "$tool is not built"
done
unset OCIO OCIO_ACTIVE_DISPLAYS OCIO_ACTIVE_VIEWS OCIO_INACTIVE_COLORSPACES
povray=""
if [ -n "${POVRAY:-}" ]; then povray=$(command -v "$POVRAY" 2>/dev/null || true); fi

# The ramp: 40x30 patches, three values each, k/4096 (exact in single
# precision, as POV-Ray keeps colours) for k up to 3596, then 0.9375, 1 and
# 1.5 (clipped). PREAMBLE: the scene's first line(s).
width=40
height=30
ramp() {
    awk -v W=$width -v H=$height -v pre="$1" 'BEGIN {
        print pre
        printf "camera { orthographic location <%g, %g, -1> direction z right x*%d up y*%d }\n", W / 2, H / 2, W, H
        for (p = 0; p < W * H; p++) {
            x = p % W; y = H - 1 - int(p / W)
            printf "box { <%d, %d, 0>, <%d, %d, 1> pigment { rgb <%.17g, %.17g, %.17g> } finish { ambient 1 diffuse 0 } }\n",
                x, y, x + 1, y + 1, v(3 * p), v(3 * p + 1), v(3 * p + 2)
        }
    }
    function v(k) { return k < 3597 ? k / 4096 : k == 3597 ? 0.9375 : k == 3598 ? 1 : 1.5 }'
}
ramp "#version 3.7; global_settings { assumed_gamma 1 }" >"$work/ramp.pov"
# A scene that turns gamma correction off: neither #version nor assumed_gamma.
ramp "// no #version, no assumed_gamma" >"$work/old.pov"

# main_ini NAME SCENE TYPE GAMMA: an INI file as PoseRay writes one
# (NAME_POV_main.ini), with File_Gamma=GAMMA (none when empty).
main_ini() {
    {
        printf '; %s: rendered as POV-Ray renders it\n' "$1"
        printf 'Input_File_Name=%s\nOutput_File_Name=%s\nOutput_File_Type=%s\n' "$2" "$1" "$3"
        printf 'Width=%d\nHeight=%d\nAntialias=Off\nDisplay=Off\nPause_When_Done=Off\n' $width $height
        [ -z "$4" ] || printf 'File_Gamma=%s\n' "$4"
    } >"$work/${1}_POV_main.ini"
}
# hst NAME OUT [ARG...] / pov NAME OUT [ARG...]: each renderer from the INI
# file, in $work, the output named OUT; the status in $status, messages in
# $work/err.
hst() {
    n=$1 out=$2
    shift 2
    (cd "$work" && "$hstrace" "${n}_POV_main.ini" "+O$out" "$@") >"$work/out" 2>"$work/err"
    status=$?
}
pov() {
    n=$1 out=$2
    shift 2
    rm -f "$work/$out"
    # POV-Ray 3.7 can time out starting its threads on a loaded machine: one retry
    (cd "$work" && { "$povray" "${n}_POV_main.ini" "+O$out" -GA +WT1 "$@" || "$povray" "${n}_POV_main.ini" "+O$out" -GA +WT1 "$@"; }) \
        >"$work/pov.log" 2>&1
    [ -s "$work/$out" ] || { tail -3 "$work/pov.log"; return 1; }
}
# chunks PNG: its gAMA chunk's value and "sRGB" when it has that chunk.
chunks() {
    perl -e 'open(F, "<:raw", $ARGV[0]) or exit 1; read(F, my $sig, 8); my @o;
        while (read(F, my $h, 8) == 8) {
            my ($n, $t) = unpack("Na4", $h); read(F, my $d, $n); read(F, my $crc, 4);
            push(@o, "gAMA=" . unpack("N", $d)) if $t eq "gAMA"; push(@o, "sRGB") if $t eq "sRGB"; last if $t eq "IEND";
        }
        print join(" ", @o), "\n"' "$1"
}
# same_chunks A B: the two PNGs say the same gamma.
same_chunks() {
    a=$(chunks "$1") b=$(chunks "$2")
    [ "$a" = "$b" ] || { echo "'$a' against '$b'"; return 1; }
}
# pixels FILE OUT: a binary PPM's pixel bytes (after its header and comments)
pixels() { tail -c $((width * height * 3)) "$1" >"$2"; }
same_pixels() { pixels "$1" "$work/a.raw" && pixels "$2" "$work/b.raw" && cmp "$work/a.raw" "$work/b.raw"; }

# --- PNG, as PoseRay's INI files ask for it --------------------------------
# case|File_Gamma|the chunks POV-Ray 3.7 writes for it
while IFS='|' read -r name gamma want; do
    main_ini "$name" ramp.pov N "$gamma"
    hst "$name" "$name.h.png"
    check "File_Gamma=$gamma: hstrace renders from ${name}_POV_main.ini alone" exited 0
    check "File_Gamma=$gamma: the PNG's chunks say '$want'" test "$(chunks "$work/$name.h.png")" = "$want"
    if [ -z "$povray" ]; then
        skip "File_Gamma=$gamma: POV-Ray's codes, every one" "povray not installed"
        continue
    fi
    check "File_Gamma=$gamma: POV-Ray renders the same INI file" pov "$name" "$name.p.png" || continue
    check "File_Gamma=$gamma: every sample has POV-Ray's code" "$codes" "$work/$name.p.png" "$work/$name.h.png"
    check "File_Gamma=$gamma: the gAMA and sRGB chunks are POV-Ray's" same_chunks "$work/$name.p.png" "$work/$name.h.png"
    check "File_Gamma=$gamma: decoded by their chunks, the pixels are POV-Ray's (hstrace compare, max error 0)" \
        "$hstrace" compare "$work/$name.p.png" "$work/$name.h.png" --max-error 0
done <<'CASES'
one|1|gAMA=100000
one-point-zero|1.0|gAMA=100000
two-point-two|2.2|gAMA=45455
srgb|srgb|gAMA=45455 sRGB
srgb-upper|SRGB|gAMA=45455 sRGB
half|0.5|gAMA=200000
none||gAMA=45455 sRGB
CASES
# The comparisons see the gamma: File_Gamma=1's codes are not sRGB's.
check_fails "File_Gamma=1 and File_Gamma=srgb: png_codes tells their codes apart" \
    "$codes" "$work/one.h.png" "$work/srgb.h.png"
check "without File_Gamma: sRGB's codes (each type's default: sRGB for PNG)" \
    "$codes" "$work/srgb.h.png" "$work/none.h.png"

# --- the other types ----------------------------------------------------------
main_ini wide ramp.pov N 2.2
hst wide wide.h.png +FN16
check "File_Gamma=2.2, 16-bit PNG (+FN16): hstrace renders" exited 0
main_ini linear ramp.pov N 1
for t in "P ppm" "T tga" "B bmp" "J jpg" "E exr"; do
    type=${t%% *} ext=${t#* }
    hst linear "linear.h.$ext" "+F$type"
    check "File_Gamma=1, +F$type: hstrace renders" exited 0
done
hst srgb "srgb.h.exr" +FE
check "File_Gamma=srgb, +FE: hstrace renders" exited 0
check "EXR is linear: File_Gamma=1 and File_Gamma=srgb give the same EXR" \
    "$hstrace" compare "$work/linear.h.exr" "$work/srgb.h.exr" --max-error 0
if [ -z "$povray" ]; then
    skip "the other types as POV-Ray writes them" "povray not installed"
else
    pov wide wide.p.png +FN16 && check "File_Gamma=2.2, +FN16: every sample has POV-Ray's code" \
        "$codes" "$work/wide.p.png" "$work/wide.h.png"
    pov linear linear.p.ppm +FP && check "File_Gamma=1, +FP: the PPM's pixel bytes are POV-Ray's" \
        same_pixels "$work/linear.p.ppm" "$work/linear.h.ppm"
    for t in "T tga" "B bmp" "J jpg"; do
        type=${t%% *} ext=${t#* }
        pov linear "linear.p.$ext" "+F$type" &&
            check "File_Gamma=1, +F$type: the pixels are POV-Ray's (max error 0)" \
                "$hstrace" compare "$work/linear.p.$ext" "$work/linear.h.$ext" --max-error 0
    done
    pov linear linear.p.exr +FE && check "File_Gamma=1, +FE: POV-Ray's EXR, linear (RMSE <= 1e-5: half floats)" \
        "$hstrace" compare "$work/linear.p.exr" "$work/linear.h.exr" --max-rmse 1e-5
fi

# --- a scene that turns gamma correction off: Display_Gamma, not File_Gamma ---
main_ini old old.pov N 1
hst old old.h.png
check "no #version, no assumed_gamma, File_Gamma=1: hstrace renders" exited 0
main_ini old-plain old.pov N ""
hst old-plain old-plain.h.png
check "no #version, no assumed_gamma: File_Gamma=1 changes nothing (Display_Gamma, sRGB, decides)" \
    "$codes" "$work/old-plain.h.png" "$work/old.h.png"
if [ -z "$povray" ]; then
    skip "no #version, no assumed_gamma, File_Gamma=1: POV-Ray's codes" "povray not installed"
else
    pov old old.p.png && check "no #version, no assumed_gamma, File_Gamma=1: every sample has POV-Ray's code" \
        "$codes" "$work/old.p.png" "$work/old.h.png"
fi

# --- values POV-Ray 3.7 refuses ------------------------------------------------
for g in bt709 BT709 0 -2.2 0.0005 abc; do
    main_ini bad ramp.pov N "$g"
    rm -f "$work/bad.h.png"
    hst bad bad.h.png
    check "File_Gamma=$g: refused at its line, exit status 1" \
        exited 1 "^bad_POV_main.ini:10:1: File_Gamma=$g: expected sRGB or a power-law gamma from 0.001"
    check_fails "File_Gamma=$g: no image written" test -e "$work/bad.h.png"
    if [ -n "$povray" ] && [ "$g" != abc ]; then
        check_fails "File_Gamma=$g: POV-Ray refuses it too" pov bad bad.p.png
    fi
done
tap_end
