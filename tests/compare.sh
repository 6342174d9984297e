#!/bin/sh
# `hstrace compare` as a user meets it, in TAP: figures on hand-made images
# (worked out below), the exit statuses 0/1/2 for every limit, the messages
# for unreadable and mismatched images, --json, --diff and --mask-map
# images, shadow masks split at edges and in the interior, and no output
# file left behind on bad input. The images are plain PPM (P3) with samples
# 0 and 255 only, which decode to exactly 0 and 1 in linear RGB.
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstcompare.XXXXXX") || bail "no temporary folder"
trap 'rm -rf "$work"' EXIT
[ -x "$hstrace" ] || bail "$hstrace is not built"
run() { # runs hstrace compare; stdout in $work/out, stderr in $work/err, status in $status
    "$hstrace" compare "$@" >"$work/out" 2>"$work/err"; status=$?
}
# json KEY: the value of the first line "KEY": VALUE[,] in $work/out (the
# output puts every key but the limits' on a line of its own).
json() {
    awk -v k="\"$1\":" '$1 == k { sub(/^[^:]*: /, ""); sub(/,$/, ""); print; exit }' "$work/out"
}
# json_is KEY VALUE [KEY VALUE...]: each KEY's value in $work/out is VALUE.
json_is() {
    while [ $# -ge 2 ]; do
        [ "$(json "$1")" = "$2" ] || { echo "\"$1\": $(json "$1"), expected $2"; return 1; }
        shift 2
    done
}
# near VALUE EXPECTED: equal within 1e-6 (the figures are exact arithmetic
# on 0s and 1s; 1e-6 only absorbs the printed digits, %.9g or better).
near() {
    awk -v v="$1" -v e="$2" 'BEGIN { d = v - e; exit !(v != "" && d < 1e-6 && d > -1e-6) }' ||
        { echo "$1, expected $2 within 1e-6"; return 1; }
}
# ppm FILE W H PIXEL...: a P3 image, each PIXEL one of k (black), w (white),
# r (red), c (cyan).
ppm() {
    f=$1 w=$2 h=$3; shift 3
    {
        printf 'P3\n%s %s\n255\n' "$w" "$h"
        for p in "$@"; do
            case $p in k) echo "0 0 0" ;; w) echo "255 255 255" ;; r) echo "255 0 0" ;; c) echo "0 255 255" ;; esac
        done
    } >"$f"
}

# A: 4x2, black. B: cyan at (3,0) (G and B off by 1), red at (2,1) (R off by
# 1). Over 24 samples the squared errors sum to 3: RMSE = sqrt(3/24) =
# 0.3535534, PSNR = 10 log10(24/3) = 9.0309 dB; the largest error, 1, first
# at (3,0); 2 of 8 pixels over the threshold: 0.25.
ppm "$work/a.ppm" 4 2 k k k k k k k k
ppm "$work/b.ppm" 4 2 k k k c k k r k
run "$work/a.ppm" "$work/b.ppm" --json
check_status "no limits given: exit status 0" "$status" 0
check "size 4x2" json_is width 4 height 2
check "RMSE = sqrt(3/24) = 0.3535534 ($(json rmse))" near "$(json rmse)" 0.35355339
check "PSNR = 10 log10(8) = 9.0309 dB ($(json psnr))" near "$(json psnr)" 9.03089987
check "max error 1 at (3,0) ($(json max_error) at $(json max_error_at))" json_is max_error 1 max_error_at "[3, 0]"
check "2 pixels over the default threshold 0.02: share 0.25" \
    json_is threshold 0.02 pixels_over_threshold 2 share_over_threshold 0.25
check "--json: no masks, no limits, within" json_is masks null exceeded "[]" within_limits true
one_object() { [ "$(head -c1 "$1")" = "{" ] && [ "$(tail -n1 "$1")" = "}" ]; }
check "--json output is one object" one_object "$work/out"
if command -v python3 >/dev/null 2>&1; then
    check "--json output parses as JSON" python3 -m json.tool "$work/out"
else
    skip "--json output parses as JSON" "python3 not installed (Debian package python3)"
fi
run "$work/a.ppm" "$work/b.ppm" --threshold 1
check_status "--threshold 1: exit status 0" "$status" 0
check "--threshold 1: errors of exactly 1 are not over it" grep -q "more than 1: 0 = 0.0000%" "$work/out"
run "$work/a.ppm" "$work/b.ppm"
check "text output: RMSE, PSNR, max error and where" grep -q "RMSE 0.353553, PSNR 9.03 dB, max error 1.000000 at (3,0)" "$work/out"
check "text output: the share over the threshold" grep -q "more than 0.02: 2 = 25.0000%" "$work/out"

# Every limit, just met (exit 0) and just missed (exit 1).
for case in "--max-rmse 0.36:0" "--max-rmse 0.35:1" "--min-psnr 9:0" "--min-psnr 9.1:1" "--max-error 1:0" \
            "--max-error 0.99:1" "--max-share 0.25:0" "--max-share=0.2:1" "--max-rmse 1 --max-share 0.1:1"; do
    limits=${case%:*} want=${case##*:}
    # shellcheck disable=SC2086 # $limits is options and values
    run "$work/a.ppm" "$work/b.ppm" $limits
    check_status "$limits: exit status $want ($(tail -n1 "$work/out"))" "$status" "$want"
done
run "$work/a.ppm" "$work/b.ppm" --max-rmse 0.35 --max-share 0.2 --max-error 1 --json
check "--json lists the limits exceeded" json_is exceeded '["max_rmse", "max_share"]' within_limits false
check "--json lists the limits given" grep -q '"limits": {"max_rmse": 0.35, "max_error": 1, "max_share": 0.2}' "$work/out"
run "$work/a.ppm" "$work/a.ppm" --max-error 0 --json
check_status "equal images: within --max-error 0" "$status" 0
check "equal images: PSNR null in JSON" json_is psnr null

# --diff: the heat map, black where equal and white where off by 1.
ppm "$work/expect.ppm" 4 2 k k k w k k w k
run "$work/a.ppm" "$work/b.ppm" --diff "$work/d.exr"
check_status "--diff d.exr: exit status 0" "$status" 0
run "$work/a.ppm" "$work/b.ppm" --diff "$work/d.png"
check_status "--diff d.png: exit status 0" "$status" 0
check "--diff writes an EXR" [ -s "$work/d.exr" ]
check "--diff writes a PNG" [ -s "$work/d.png" ]
check "EXR by extension" [ "$(head -c 4 "$work/d.exr" | od -An -tx1 | tr -d " ")" = 762f3101 ]
check "PNG by extension" [ "$(head -c 4 "$work/d.png" | tail -c 3)" = PNG ]
run "$work/d.exr" "$work/expect.ppm" --max-error 0
check "EXR heat map: 4x2, black where equal, white where off by 1" exited 0
run "$work/d.png" "$work/expect.ppm" --max-error 0
check "PNG heat map: the same" exited 0

# Bad input: exit status 2, a message naming the file, no output file.
ppm "$work/small.ppm" 3 2 k k k k k k
run "$work/a.ppm" "$work/small.ppm" --diff "$work/bad.png"
check_status "size mismatch: exit status 2" "$status" 2
check "size mismatch message ($(sed "s|$work/||g" "$work/err"))" \
    grep -qx "hstrace compare: $work/small.ppm: 3x2 pixels, but $work/a.ppm has 4x2" "$work/err"
run "$work/a.ppm" "$work/missing.png" --diff "$work/bad.png"
check "unreadable file: exit status 2, message ($(sed "s|$work/||g" "$work/err"))" \
    exited 2 "^hstrace compare: $work/missing.png: No such file or directory\$"
printf 'not an image at all\n' >"$work/junk.exr"
run "$work/junk.exr" "$work/a.ppm" --diff "$work/bad.png"
check "not an image: exit status 2, message ($(sed "s|$work/||g" "$work/err"))" \
    exited 2 "^hstrace compare: $work/junk.exr: "
head -c 20 "$work/d.png" >"$work/cut.png"
run "$work/cut.png" "$work/a.ppm" --diff "$work/bad.png"
check "truncated PNG: exit status 2" exited 2 "^hstrace compare: $work/cut.png: "
check "no diff image left behind on bad input" [ ! -e "$work/bad.png" ]
no_hidden() { for f in "$work"/.[!.]*; do [ ! -e "$f" ] || { echo "left behind: $f"; return 1; }; done; }
check "no temporary file left behind on bad input" no_hidden
run "$work/a.ppm" "$work/b.ppm" --diff "$work/no/such/folder/d.png"
check "unwritable --diff: exit status 2, names the file" exited 2 "no/such/folder/d.png: cannot write"

# Bad usage: exit status 2.
for args in "$work/a.ppm" "$work/a.ppm $work/b.ppm $work/b.ppm" "$work/a.ppm $work/b.ppm --frobnicate" \
            "$work/a.ppm $work/b.ppm --max-rmse lots" "$work/a.ppm $work/b.ppm --max-share 2" \
            "$work/a.ppm $work/b.ppm --max-interior 0" "$work/a.ppm $work/b.ppm --diff $work/d.gif" \
            "$work/a.ppm $work/b.ppm --mask-a $work/a.ppm" "$work/a.ppm $work/b.ppm --mask-a $work/a.ppm $work/a.ppm"; do
    # shellcheck disable=SC2086 # $args is several words
    run $args
    check "bad usage ($(sed "s|$work/||g" "$work/err")): exit status 2 and a message" exited 2 .
done
check "no image written for --diff with an unknown format" [ ! -e "$work/d.gif" ]
run --help
check_status "compare --help exits 0" "$status" 0
for opt in --max-rmse --min-psnr --max-error --max-share --max-mask-share --max-interior --mask-a; do
    check "compare --help lists $opt" grep -q -- "$opt" "$work/out"
done
"$hstrace" --help >"$work/out" 2>&1
check "hstrace --help mentions compare" grep -q "hstrace compare" "$work/out"

# Shadow masks, 6x6, no shadows (+Q3) white everywhere. A's +Q4: black on
# x 1..2, y 1..4. B's: the same one pixel to the right (x 2..3), and the
# pixel (5,5). Columns x = 1 (A only) and 3 (B only) lie on both shadows'
# edges: 8 disagreements at shadow edges. (5,5) is two pixels from A's
# nearest edge (x = 3): interior, or A's leak when allowed. 9 of 36 disagree.
q3() { ppm "$1" 6 6 w w w w w w  w w w w w w  w w w w w w  w w w w w w  w w w w w w  w w w w w w; }
q3 "$work/a3.ppm"
q3 "$work/b3.ppm"
ppm "$work/a4.ppm" 6 6 w w w w w w  w k k w w w  w k k w w w  w k k w w w  w k k w w w  w w w w w w
ppm "$work/b4.ppm" 6 6 w w w w w w  w w k k w w  w w k k w w  w w k k w w  w w k k w w  w w w w w k
masks="--mask-a $work/a3.ppm $work/a4.ppm --mask-b $work/b3.ppm $work/b4.ppm"
# shellcheck disable=SC2086 # $masks is options and files
run "$work/a4.ppm" "$work/b4.ppm" $masks --json --mask-map "$work/map.png"
check_status "masks, no limits: exit status 0" "$status" 0
check "masks: A 8 pixels, B 9, 9 disagree = 0.25" json_is a_pixels 8 b_pixels 9 disagree 9 share 0.25
check "masks: 8 at shadow edges, 0 at silhouettes, 1 interior at (5,5)" \
    json_is shadow_edge 8 silhouette 0 interior 1 first_interior_at "[5, 5]"
run "$work/map.png" "$work/a4.ppm" --json
check_status "--mask-map writes a readable image" "$status" 0
check "--mask-map: the masks' size (6x6)" json_is width 6 height 6
for case in "--max-interior 1:0" "--max-interior 0:1" "--max-interior 0 --allow-a-leaks:0" \
            "--max-mask-share 0.25:0" "--max-mask-share 0.24:1"; do
    limits=${case%:*} want=${case##*:}
    # shellcheck disable=SC2086 # options and files
    run "$work/a4.ppm" "$work/b4.ppm" $masks $limits
    check_status "masks, $limits: exit status $want ($(tail -n1 "$work/out"))" "$status" "$want"
done
# shellcheck disable=SC2086 # options and files
run "$work/a4.ppm" "$work/b4.ppm" $masks --allow-a-leaks
check "text output: the split, and A's leaks when allowed" \
    grep -q "8 at shadow edges, 0 at silhouettes, 0 interior, 1 where A lets more light through" "$work/out"
run "$work/a4.ppm" "$work/b4.ppm" --mask-a "$work/a3.ppm" "$work/a4.ppm" --mask-b "$work/b3.ppm" "$work/small.ppm"
check "a mask render of another size: exit status 2, named" exited 2 "small.ppm: 3x2 pixels, but"
tap_end
