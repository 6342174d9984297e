#!/bin/sh
# POV-Ray 3.7's output types (+FT +FC +FB +FJ +FH, beside +FN +FE +FP), in
# TAP: each written as POV-Ray writes it (against the installed POV-Ray's
# file at the same switches: BMP byte for byte, Targa's pixel bytes, and the
# decoded pixels of all), read back by hstrace's own readers as the PNG
# reader reads the same render, +Oname without an extension given the
# type's, JPEG's quality from the INI key Compression, alpha in Targa and BMP
# under +UA; and the mistakes: types hstrace does not write, a name for
# another type, damaged files given to `hstrace compare`.
#
# Environment: top_builddir (default .), POVRAY (path or name of povray;
# default povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstfmt.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
run() { (cd "$work" && "$hstrace" "$@") >"$work/out" 2>"$work/err"; status=$?; }
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
pov() { (cd "$work" && "$povray" "$@" -D -GA +WT1 >/dev/null 2>&1); }
cp "$srcdir/scenes/desk.pov" "$work/desk.pov"
W=64 H=48

# byte FILE OFFSET: the unsigned byte at OFFSET.
byte() { od -An -tu1 -j "$2" -N1 "$1" | tr -d ' '; }
# is VALUE WANT: the same number, or say what it is.
is() { [ "$1" = "$2" ] || { echo "got '$1', want '$2'"; return 1; }; }
# compare_exact A B: hstrace compare finds the same pixels (RMSE 0).
compare_exact() { "$hstrace" compare "$1" "$2" --max-error 0; }

# --- each type, named by its extension, with its header -------------------------
run desk.pov +W$W +H$H +FN -o desk-N.png
check "+FN: the PNG the others are held against" exited 0
while IFS='|' read -r sw ext; do
    run desk.pov +W$W +H$H "$sw" "+Odesk-$sw"
    check "$sw +Odesk-$sw writes desk-$sw$ext (the type's extension added)" test "$status" = 0 -a -s "$work/desk-$sw$ext"
done <<'TYPES'
+FT|.tga
+FC|.tga
+FB|.bmp
+FJ|.jpg
+FH|.hdr
TYPES
t=$work/desk-+FT.tga c=$work/desk-+FC.tga b=$work/desk-+FB.bmp j=$work/desk-+FJ.jpg h=$work/desk-+FH.hdr
check "+FT: Targa type 2 (uncompressed), 24 bits, rows from the top" \
    is "$(byte "$t" 2) $(byte "$t" 16) $(byte "$t" 17)" "2 24 32"
check "+FT: 18 + 64 x 48 x 3 bytes of header and pixels, the TGA 2.0 extension area and footer" \
    is "$(wc -c <"$t" | tr -d ' ') $(tail -c 18 "$t" | head -c 17)" "$((18 + W * H * 3 + 495 + 26)) TRUEVISION-XFILE."
check "+FC: Targa type 10 (run-length encoded), smaller than +FT's" \
    test "$(byte "$c" 2)" = 10 -a "$(wc -c <"$c")" -lt "$(wc -c <"$t")"
check "+FB: BMP, 24 bits, 54 + 64 x 48 x 3 bytes" \
    is "$(head -c 2 "$b") $(byte "$b" 28) $(wc -c <"$b" | tr -d ' ')" "BM 24 $((54 + W * H * 3))"
check "+FJ: JPEG with a comment naming hstrace" \
    test "$(byte "$j" 0) $(byte "$j" 1)" = "255 216" -a "$(grep -c 'Software: hstrace' "$j")" -ge 1
check "+FH: Radiance HDR, -Y 48 +X 64" test "$(head -n 1 "$h")" = "#?RADIANCE" -a "$(grep -ac '^-Y 48 +X 64$' "$h")" = 1

# --- read back: the same pixels as the PNG (HDR and JPEG within their precision) -
for f in "$t" "$c" "$b"; do
    check "$(basename "$f") read back: the PNG's pixels exactly" compare_exact "$work/desk-N.png" "$f"
done
run desk.pov +W$W +H$H +FE --exr-float -o desk-E.exr
check "HDR read back: the float EXR's pixels to RGBE's precision (RMSE <= 0.002)" \
    "$hstrace" compare "$work/desk-E.exr" "$h" --max-rmse 0.002 --max-share 0
# quality 85 on a 64x48 image: RMSE 0.026 measured (linear light); a reader
# that swapped or shifted channels would be far off
check "JPEG read back: the PNG's pixels to quality 85 (RMSE <= 0.04)" \
    "$hstrace" compare "$work/desk-N.png" "$j" --max-rmse 0.04
check_fails "a JPEG is not a PNG: the comparison sees the loss" compare_exact "$work/desk-N.png" "$j"

# --- against POV-Ray's files -----------------------------------------------------
if [ -n "$povray" ]; then
    for sw in +FT +FC +FB +FJ +FH; do
        pov +Idesk.pov +W$W +H$H "$sw" "+Opov$sw" -A
        ours=$(ls "$work/desk-$sw".*)
        theirs=$(ls "$work/pov$sw".* 2>/dev/null)
        check "$sw: the pixels of POV-Ray's file exactly" compare_exact "$theirs" "$ours"
    done
    check "+FB: POV-Ray's BMP byte for byte" cmp "$work/pov+FB.bmp" "$b"
    check "+FT: POV-Ray's Targa header and pixel bytes byte for byte" cmp -n $((18 + W * H * 3)) "$work/pov+FT.tga" "$t"
    printf 'Compression=50\n' >"$work/q50.ini"
    pov q50.ini +Idesk.pov +W$W +H$H +FJ +Opov-q50.jpg -A
    run q50.ini desk.pov +W$W +H$H +FJ +Oq50.jpg
    check "Compression=50: POV-Ray's JPEG at quality 50, the same pixels" compare_exact "$work/pov-q50.jpg" "$work/q50.jpg"
    check_fails "Compression=50 is not quality 85" compare_exact "$work/q50.jpg" "$j"
else
    skip "the types against POV-Ray's files" "povray not installed"
fi

# --- alpha: 32 bits with +UA ----------------------------------------------------
cat >"$work/alpha.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -3> color rgb 1 }
polygon { 4, <-2,0,-1>, <2,0,-1>, <2,0,3>, <-2,0,3> pigment { color rgb <0.8,0.7,0.6> } }
triangle { <-1.6,0.1,0>, <-0.4,0.1,0>, <-1,1.4,0> pigment { color rgbt <1,0.2,0.2,0.6> } }
EOF
run alpha.pov +W$W +H$H +FT +UA +Oalpha
check "+FT +UA: 32-bit Targa with 8 alpha bits" \
    is "$(byte "$work/alpha.tga" 16) $(byte "$work/alpha.tga" 17)" "32 40"
run alpha.pov +W$W +H$H +FB +UA +Oalpha
check "+FB +UA: 32-bit BMP" is "$(byte "$work/alpha.bmp" 28)" 32
run alpha.pov +W$W +H$H +FN +UA +Oalpha
check "+UA read back: Targa and PNG hold the same premultiplied pixels" compare_exact "$work/alpha.png" "$work/alpha.tga"
check "+UA read back: BMP and PNG hold the same premultiplied pixels" compare_exact "$work/alpha.png" "$work/alpha.bmp"
if [ -n "$povray" ]; then
    pov +Ialpha.pov +W$W +H$H +FT +UA +Opov-alpha.tga -A
    pov +Ialpha.pov +W$W +H$H +FB +UA +Opov-alpha.bmp -A
    check "+FT +UA: POV-Ray's Targa pixel bytes, alpha included" \
        cmp -n $((18 + W * H * 4)) "$work/pov-alpha.tga" "$work/alpha.tga"
    check "+FB +UA: POV-Ray's BMP byte for byte, alpha included" cmp "$work/pov-alpha.bmp" "$work/alpha.bmp"
else
    skip "alpha against POV-Ray's files" "povray not installed"
fi

# --- names and mistakes -----------------------------------------------------------
run desk.pov +W8 +H6 +FJ -o named.jpeg
check "+FJ -o named.jpeg: JPEG's other extension is accepted" test "$status" = 0 -a -s "$work/named.jpeg"
run desk.pov +W8 +H6 +FT -o wrong.png
check "+FT -o wrong.png: refused, status 1, nothing written" \
    test "$status" = 1 -a ! -e "$work/wrong.png" -a "$(grep -c "+FT asks for tga, but the output 'wrong.png' is named for another type" "$work/err")" = 1
run desk.pov +W8 +H6 -o plain.tga
check "-o plain.tga without +F: an uncompressed Targa" is "$status $(byte "$work/plain.tga" 2)" "0 2"
while IFS='|' read -r sw message; do
    run desk.pov +W8 +H6 "$sw"
    check "$sw: refused with status 1 ($message)" exited 1 "$message"
done <<'BAD'
+FS|the system's own image type is not supported
+FX|'+FX': unknown output type
+FNG|greyscale output is not supported
+FP16|16-bit PPM output is not supported
+FT99|bits per colour must be 1 to 16
BAD
printf 'Width=8\nHeight=6\nCompression=300\n' >"$work/badq.ini"
run badq.ini desk.pov
check "Compression=300: refused with the INI file's line" exited 1 "badq.ini:3:.*Compression=300: expected 0 to 255"

# --- damaged files, read by hstrace compare: a message and status 2 --------------
for f in "$t" "$c" "$b" "$j" "$h"; do
    ext=${f##*.}
    head -c 300 "$f" >"$work/short.$ext"
    (cd "$work" && "$hstrace" compare "$f" "short.$ext") >"$work/out" 2>"$work/err"
    status=$?
    check "$(basename "$f") cut to 300 bytes: status 2 and why" exited 2 "short.$ext: .*\(truncated\|Premature end\|corrupt\)"
done
printf 'BM' >"$work/tiny.bmp"
(cd "$work" && "$hstrace" compare "$b" tiny.bmp) >"$work/out" 2>"$work/err"
status=$?
check "a 2-byte BMP: status 2 and why" exited 2 "tiny.bmp: not a BMP file"
printf '#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 2 +X 2\n' >"$work/xyze.hdr"
(cd "$work" && "$hstrace" compare "$h" xyze.hdr) >"$work/out" 2>"$work/err"
status=$?
check "an XYZE HDR: status 2 and why" exited 2 "unsupported HDR format '32-bit_rle_xyze'"
tap_end
