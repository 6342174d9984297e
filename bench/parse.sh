#!/bin/sh
# Parse speed: scenes/make-mesh.sh scenes of 10^4, 10^5 and 10^6 triangles
# (one mesh2 each), parsed by hstrace (the "parse" time of --stats) and by
# POV-Ray 3.7 (the "Parse Time" of its statistics, which it prints on stderr
# without -GA). Both render a 1x1 image without shadows, so that the
# rendering costs nothing; hstrace's parse time excludes its preprocessing
# (grid), POV-Ray's excludes its bounding. Median of 3 runs, 1 thread.
# Writes bench/parse.md.
#
# usage: bench/parse.sh [BUILDDIR]   (default: the current folder)
# Exit status: 0 done, 3 hstrace not built.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
[ -x "$build/hstrace" ] || { echo "parse: build hstrace first (make)" >&2; exit 3; }
povray=${POVRAY:-povray}
command -v "$povray" >/dev/null 2>&1 || povray=""
work=$(mktemp -d "${TMPDIR:-/tmp}/hstparse.XXXXXX")
trap 'rm -rf "$work"' EXIT
out="$here/parse.md"
runs=3

median() { sort -n | awk '{ v[NR] = $1 } END { if (NR) print v[int((NR + 1) / 2)]; else print "-" }'; }

{
    echo "# Parse speed"
    echo
    echo "Made by \`make bench\` (\`bench/parse.sh\`) on $(date -u +%Y-%m-%d), $(nproc) cores, $(uname -m);"
    echo "load average before the runs: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)."
    echo "Scenes from \`scenes/make-mesh.sh N\`: one mesh2 of about N triangles, written as plain numbers."
    echo "*hstrace*: the parse time of \`--stats\` (reading and parsing the file into the scene description)."
    echo "*POV-Ray*: the \"Parse Time\" of POV-Ray 3.7's statistics (reading, parsing and building its objects)."
    echo "Both render 1x1 pixels with 1 thread; seconds, median of $runs runs."
    echo
    echo "| triangles | file MB | hstrace parse s | POV-Ray parse s | POV-Ray / hstrace |"
    echo "|---|---|---|---|---|"
} >"$out"

for n in 10000 100000 1000000; do
    scene="$work/mesh$n.pov"
    sh "$src/scenes/make-mesh.sh" "$n" >"$scene"
    tris=$(sed -n 's|^// triangles: ||p' "$scene")
    mb=$(awk -v b="$(wc -c <"$scene")" 'BEGIN { printf "%.1f", b / 1e6 }')
    h=$(for _ in $(seq $runs); do
        "$build/hstrace" "$scene" --width 1 --height 1 --threads 1 --shadows none --stats -o "$work/h.png" 2>&1 |
            sed -n 's/.*time (s) *parse \([0-9.]*\).*/\1/p'
    done | median)
    p="-"
    if [ -n "$povray" ]; then
        p=$(for _ in $(seq $runs); do
            "$povray" "+I$scene" +W1 +H1 -D +WT1 -GR -GW "+O$work/p.png" 2>&1 |
                sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p'
        done | median)
    fi
    ratio=$(awk -v h="$h" -v p="$p" 'BEGIN { if (h + 0 > 0 && p != "-" && p != "") printf "%.1f", p / h; else print "-" }')
    echo "| $tris | $mb | $h | ${p:--} | $ratio |" >>"$out"
done
[ -n "$povray" ] || echo "POV-Ray was not found (Debian package: povray): its column is empty." >>"$out"
echo "wrote $out"
