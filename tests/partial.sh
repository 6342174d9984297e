#!/bin/sh
# Partial renders (+SR +ER +SC +EC and their INI keys), in TAP: the rows and
# columns rendered for pixel numbers and fractions, as POV-Ray 3.7.0.10
# renders them (measured, written below; and against the installed POV-Ray's
# image at the same switches); the rendered pixels byte for byte those of the
# full render, so that two partial renders spliced together are the full
# image; and the mistakes.
#
# Environment: top_builddir (default .), POVRAY (path or name of povray;
# default povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstpart.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
fails() { ! "$@"; }
run() { (cd "$work" && "$hstrace" "$@") >"$work/out" 2>"$work/err"; status=$?; }
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
cp "$srcdir/scenes/desk.pov" "$work/desk.pov"

# rows FILE.ppm: the rows (from 0) holding a pixel that is not black, and
# the columns likewise, as "rows R0-R1 columns C0-C1".
lit() {
    od -An -v -tu1 -j "$(head -c 15 "$1" | awk 'NR <= 3 { n += length($0) + 1 } END { print n }')" "$1" |
        tr -s ' ' '\n' | awk -v w=16 'NF { v[i++] = $1 } END {
            r0 = c0 = 1e9; r1 = c1 = -1
            for (p = 0; p < i / 3; p++) if (v[3 * p] + v[3 * p + 1] + v[3 * p + 2] > 0) {
                y = int(p / w); x = p % w
                if (y < r0) r0 = y; if (y > r1) r1 = y; if (x < c0) c0 = x; if (x > c1) c1 = x }
            printf "rows %d-%d columns %d-%d\n", r0, r1, c0, c1 }'
}
# The area of each set of switches at 16x12 (POV-Ray 3.7.0.10's, measured).
while IFS='|' read -r switches want; do
    name=$(echo "$switches" | tr -d ' +.')
    # shellcheck disable=SC2086 # the switches are words
    run desk.pov +W16 +H12 $switches -o "$name.ppm"
    got=$(lit "$work/$name.ppm" 2>/dev/null)
    check "$switches: POV-Ray 3.7 renders $want (hstrace: $got)" test "$got" = "$want"
    if [ -n "$povray" ]; then
        # shellcheck disable=SC2086
        (cd "$work" && "$povray" +Idesk.pov +W16 +H12 $switches "+O$name-pov.png" -A -D -GA +WT1 >/dev/null 2>&1)
        check "$switches: the same pixels as the installed POV-Ray's image (RMSE <= 0.002)" \
            "$hstrace" compare "$work/$name-pov.png" "$work/$name.ppm" --max-rmse 0.002
    else
        skip "$switches: the same pixels as the installed POV-Ray's image" "povray not installed"
    fi
done <<'AREAS'
+SR4 +ER8 +SC3 +EC10|rows 3-7 columns 2-9
+SR0.25 +ER0.5|rows 3-5 columns 0-15
+SR0.1 +ER0.9|rows 1-9 columns 0-15
+SR0.3 +ER1|rows 3-11 columns 0-15
+SR2 +ER0.5|rows 1-5 columns 0-15
+SR5 +ER5|rows 4-4 columns 0-15
AREAS

# --- two halves spliced are the full render, byte for byte --------------------
run desk.pov +W64 +H48 -o full.ppm --threads 2
check "the full render" exited 0
run desk.pov +W64 +H48 +SR1 +ER20 -o top.ppm --threads 1
check "rows 1-20" exited 0
printf 'Input_File_Name=desk.pov\nWidth=64\nHeight=48\nStart_Row=21\nEnd_Row=48\nOutput_File_Name=bottom.ppm\n' \
    >"$work/bottom.ini"
run bottom.ini --threads 2
check "rows 21-48 from an INI file's Start_Row and End_Row" exited 0
header=$(head -c 15 "$work/full.ppm" | awk 'NR <= 3 { n += length($0) + 1 } END { print n }')
{
    head -c "$((header + 20 * 64 * 3))" "$work/top.ppm"
    tail -c "$((28 * 64 * 3))" "$work/bottom.ppm"
} >"$work/spliced.ppm"
check "the two partial renders spliced are the full render, byte for byte" cmp "$work/spliced.ppm" "$work/full.ppm"
check "a partial render leaves the rest black: it is not the full render" fails cmp "$work/top.ppm" "$work/full.ppm"

# --- mistakes -------------------------------------------------------------------
run desk.pov +W16 +H12 +SR5 +ER20 -o bad.ppm
check "an end row beyond the image: exit status 1" exited 1 "beyond the image's 12"
run desk.pov +W16 +H12 +SR8 +ER4 -o bad.ppm
check "an empty area: exit status 1" exited 1 "the render area is empty"
run desk.pov +W16 +H12 +SC-1 -o bad.ppm
check "+SC-1: exit status 1" exited 1 "'+SC-1': expected a row or column (or fraction) from 0 to 32768"
check "... and nothing written" fails test -e "$work/bad.ppm"
tap_end
