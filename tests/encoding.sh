#!/bin/sh
# POV-Ray's display encoding, code for code, in TAP: a scene of 3000 flat
# patches (ambient 1, diffuse 0, no lights: each pixel is its pigment's
# linear colour) rendered by POV-Ray (+FN, +FN16, +FP) and by hstrace at the
# same settings, without any OCIO config; the PNGs are read back with libpng
# by tests/png_codes (none of hstrace's image code) and every sample must
# carry the same code, the PPMs' pixel bytes must be the same bytes.
#
# The linear values, 8863 of them, three to a pixel, all exact in single
# precision (POV-Ray keeps colours as floats, hstrace as doubles, so they are
# the same numbers in both): a ramp k/4096; for every 8-bit code c, the 8
# consecutive floats around the linear value that sRGB-encodes to
# (c + 0.5)/255, where rounding decides between c and c + 1 (POV-Ray's own
# boundary, computed in float, lies among them for 250 of the 255 codes);
# the same for every 193rd 16-bit code (332 of 340); both sides of
# 0.0031308, where the sRGB curve changes formula; 0, a tiny value, 1 and
# values above 1 (clipped). Without povray, a TAP SKIP.
#
# Environment: top_builddir (default .), POVRAY (path or name of povray;
# default povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
codes="$builddir/tests/png_codes"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstencoding.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
unset OCIO OCIO_ACTIVE_DISPLAYS OCIO_ACTIVE_VIEWS OCIO_INACTIVE_COLORSPACES
for tool in "$hstrace" "$codes"; do
    [ -x "$tool" ] || { echo "Bail out! $tool is not built"; exit 1; }
done

width=60
height=50
awk -v W=$width -v H=$height 'BEGIN {
    n = 0
    for (k = 0; k < 4096; k++) v[n++] = k / 4096
    for (c = 0; c < 255; c++) { t = decode((c + 0.5) / 255); for (d = -4; d < 4; d++) v[n++] = below(t) + d * ulp(t) }
    for (c = 0; c < 65535; c += 193) {
        t = decode((c + 0.5) / 65535)
        for (d = -4; d < 4; d++) v[n++] = below(t) + d * ulp(t)
    }
    t = 0.0031308; v[n++] = below(t); v[n++] = below(t) + ulp(t)
    v[n++] = 0; v[n++] = 1e-7; v[n++] = 1; v[n++] = 1.5; v[n++] = 2
    print "#version 3.7;"
    print "global_settings { assumed_gamma 1 }"
    printf "camera { orthographic location <%g, %g, -1> direction z right x*%d up y*%d }\n", W / 2, H / 2, W, H
    print "#declare Flat = finish { ambient 1 diffuse 0 }"
    for (p = 0; p < W * H; p++) {
        x = p % W; y = H - 1 - int(p / W)
        printf "box { <%d, %d, 0>, <%d, %d, 1> pigment { rgb <%.17g, %.17g, %.17g> } finish { Flat } }\n",
            x, y, x + 1, y + 1, value(3 * p), value(3 * p + 1), value(3 * p + 2)
    }
    if (n > 3 * W * H) print "#error \"too many values for the image\""
}
function value(k) { return k < n ? v[k] : 0 }
# The inverse of the sRGB curve, to find where rounding changes code.
function decode(e) { return e <= 0.04045 ? e / 12.92 : ((e + 0.055) / 1.055) ^ 2.4 }
# A float step at x (x > 0: 24 significant bits), and the float at or below x.
function ulp(x,   e) { e = 0; while (2 ^ e > x) e--; while (2 ^ (e + 1) <= x) e++; return 2 ^ (e - 23) }
function below(x,   u) { u = ulp(x); return int(x / u) * u }' >"$work/ramp.pov"

povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
# pov FORMAT OUT: POV-Ray's render of ramp.pov, in $work (POV-Ray may write there).
pov() {
    # POV-Ray 3.7 can time out starting its threads on a loaded machine: one retry
    (cd "$work" && { "$povray" +Iramp.pov "+O$2" "+F$1" "+W$width" "+H$height" -A -D -GA +WT1 >pov.log 2>&1 ||
        "$povray" +Iramp.pov "+O$2" "+F$1" "+W$width" "+H$height" -A -D -GA +WT1 >pov.log 2>&1; }) ||
        { tail -3 "$work/pov.log"; return 1; }
}
hst() { "$hstrace" "$work/ramp.pov" --width $width --height $height "$@"; }
# the pixel bytes of a binary PPM of this size (after its header, comments and all)
pixels() { tail -c $((width * height * 3)) "$1" >"$2"; }
same_pixels() { pixels "$1" "$work/a.raw" && pixels "$2" "$work/b.raw" && cmp "$work/a.raw" "$work/b.raw"; }

check "hstrace writes the ramp as 8-bit PNG" hst -o "$work/h8.png"
check "hstrace writes the ramp as 16-bit PNG" hst --png16 -o "$work/h16.png"
check "hstrace writes the ramp as PPM" hst -o "$work/h8.ppm"
if [ -z "$povray" ]; then
    skip "8-bit PNG: POV-Ray's codes, every one" "povray not installed"
    skip "16-bit PNG: POV-Ray's codes, every one" "povray not installed"
    skip "PPM: POV-Ray's pixel bytes" "povray not installed"
else
    check "POV-Ray writes the ramp as 8-bit PNG (+FN)" pov N p8.png &&
        check "8-bit PNG: every sample has POV-Ray's code" "$codes" "$work/p8.png" "$work/h8.png"
    # The comparison sees one sample: the first patch's red made 0.5.
    sed '5s/rgb <0,/rgb <0.5,/' "$work/ramp.pov" >"$work/one.pov"
    "$hstrace" "$work/one.pov" --width $width --height $height -o "$work/one.png" 2>"$work/err"
    "$codes" "$work/p8.png" "$work/one.png" >"$work/one.cmp" 2>&1
    check "png_codes finds the one sample changed on purpose" grep "1 of 9000 samples differ" "$work/one.cmp"
    check "POV-Ray writes the ramp as 16-bit PNG (+FN16)" pov N16 p16.png &&
        check "16-bit PNG: every sample has POV-Ray's code" "$codes" "$work/p16.png" "$work/h16.png"
    check "POV-Ray writes the ramp as PPM (+FP)" pov P p8.ppm &&
        check "PPM: the pixel bytes are POV-Ray's" same_pixels "$work/p8.ppm" "$work/h8.ppm"
fi
tap_end
