#!/bin/sh
# Issue 22's hostile inputs, each measured through the hstrace command: its
# exit status, its first message, its wall time and its peak memory
# (/usr/bin/time), 16x12 pixels, one thread. The inputs are those the issue
# lists (stack overflows from deep nesting, double-to-integer conversions
# out of range, memory and time without bound, NaN and infinite values,
# bytes that are not UTF-8): the scenes of tests/hostile, and the deep and
# the long ones generated here. Run it on a plain build and on one
# configured with --enable-sanitizers (the issue's bound: every input ends
# within 5 s with status 2, or renders where POV-Ray would, under the
# sanitizers, within the memory budget).
# Writes bench/hostile.md, or the file named by HOSTILE_OUT.
#
# usage: bench/hostile.sh [BUILDDIR]   (default: the current folder)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
[ -x "$build/hstrace" ] || { echo "hostile: build hstrace first" >&2; exit 3; }
[ -x /usr/bin/time ] || { echo "hostile: /usr/bin/time not found (Debian package: time)" >&2; exit 3; }
out=${HOSTILE_OUT:-$here/hostile.md}
work=$(mktemp -d "${TMPDIR:-/tmp}/hsthostile.XXXXXX")
trap 'rm -rf "$work"' EXIT
cp -R "$src/tests/hostile" "$work/scenes"
scenes=$work/scenes

# repeat N TEXT: TEXT N times
repeat() { awk -v n="$1" -v s="$2" 'BEGIN { for (i = 0; i < n; i++) printf "%s", s }'; }
# nested NAME N OPEN MIDDLE CLOSE [BEFORE [AFTER]]: a scene with OPEN N
# times, MIDDLE, CLOSE N times, between BEFORE and AFTER
nested() {
    {
        printf '%s' "${6:-}"
        repeat "$2" "$3"
        printf '%s' "$4"
        repeat "$2" "$5"
        printf '%s\n' "${7:-}"
    } >"$scenes/$1.pov"
}
d=15000
nested concat-$d $d 'concat(' '"x"' ')' '#declare S = ' ';'
nested strupr-$d $d 'strupr(' '"x"' ')' '#declare S = ' ';'
nested substr-$d $d 'substr(' '"xyz"' ', 1, 1)' '#declare S = ' ';'
nested vstr-$d $d 'vstr(2, <1, 2>, ' '","' ', 0, 0)' '#declare S = ' ';'
nested macro-args-$d $d 'M(' '1' ')' '#macro M(A) (A) #end
#declare V = ' ';'
nested transform-$d $d 'transform { ' 'scale 1' ' }' '#declare T = transform { ' ' }'
nested pigment-map-$d $d 'gradient x pigment_map { [0 ' 'rgb 1' '] }' '#declare P = pigment { ' ' }'
nested checker-$d $d 'checker pigment { ' 'rgb 1' ' }' '#declare P = pigment { ' ' }'
nested color-map-$d $d 'gradient x pigment_map { [0 gradient y color_map { [0 rgb 1] } ' 'rgb 1' '] }' \
    '#declare P = pigment { ' ' }'
# Memory: a one-argument macro called 1M times; 1M passes over a
# 1000-character literal under a false #if; the same with strings made anew.
printf '#macro M(A) #local B = A; #end\n#for (I, 1, 1000000) M(I) #end\n' >"$scenes/macro-1M-calls.pov"
lit=$(repeat 1000 x)
printf '#for (I, 1, 1000000) #if (0) #declare S = "%s"; #end #end\n' "$lit" >"$scenes/literal-1M-false-if.pov"
printf '#for (I, 1, 1000000) #declare S = concat("a", str(I, 0, 0)); #end\n' >"$scenes/strings-1M.pov"
printf '#include "/dev/zero"\n' >"$scenes/include-dev-zero.pov"
printf '#fopen F "/dev/zero" read\n#read (F, X)\n' >"$scenes/fopen-dev-zero.pov"
# NaN and infinities in geometry; a message that quotes bytes not UTF-8.
printf 'triangle { <0, 0, 0>, <1, 1/0, 0>, <0, 1, 0> }\n' >"$scenes/geometry-1-over-0.pov"
printf 'triangle { <0, 0, 0>, <1e309, 1, 0>, <0, 1, 0> }\n' >"$scenes/geometry-1e309.pov"
printf 'triangle { 0, x, y \377\376 }\n' >"$scenes/bytes-not-utf8.pov"

# A row of the table: the input's status, seconds, peak MiB, first message.
row() { # NAME FILE-OR-PATH
    name=$1
    target=$2
    (cd "$scenes" && exec /usr/bin/time -o "$work/time" -f '%e %M' "$build/hstrace" "$target" --width 16 --height 12 \
        --threads 1 -o "$work/out.png") >/dev/null 2>"$work/err" && status=0 || status=$?
    # the last line: GNU time writes "Command exited with ..." before it
    seconds=$(tail -1 "$work/time" | cut -d' ' -f1)
    kib=$(tail -1 "$work/time" | cut -d' ' -f2)
    message=$(grep -v '^Command exited' "$work/err" | head -1 | cut -c1-150 | sed 's/|/\\|/g')
    rm -f "$work/out.png"
    printf '| %s | %s | %s | %s | %s |\n' "$name" "$status" "$seconds" "$((kib / 1024))" "${message:-(none)}"
}

{
    echo "# Hostile inputs (issue 22)"
    echo
    kind="a plain build"
    grep -q -e '--enable-sanitizers' "$build/config.log" 2>/dev/null && kind="the sanitizer build (--enable-sanitizers)"
    echo "Made by \`bench/hostile.sh\` on $(date -u '+%Y-%m-%d %H:%M') UTC, with $kind of hstrace $("$build/hstrace" --version 2>/dev/null | head -1 | sed 's/^hstrace //');"
    echo "load average $(cut -d' ' -f1 /proc/loadavg) on $(nproc) cores. Each input once, 16x12 pixels, one thread,"
    echo "the default budgets (memory: a quarter of the physical memory). *MiB* is the peak resident memory of the"
    echo "whole process. Status 2: an error in the scene, with its position; 3: a file that cannot be read; 0: rendered."
    echo
    echo "| input | status | seconds | MiB | first message |"
    echo "|---|---|---|---|---|"
    for f in "$scenes"/*.pov; do
        b=${f##*/}
        row "${b%.pov}" "$b"
    done
    row "hstrace /dev/zero" /dev/zero
} | sed "s|$work/scenes/||g; s|$work/||g" >"$out"
echo "hostile: wrote $out"
