#!/bin/sh
# hstrace against POV-Ray on the project's scenes, side by side in one run:
# same scene, same size (320x240), same thread count (2), EXR output, timed
# by hyperfine (Debian package hyperfine). Writes bench/vs-povray.md.
#
# usage: bench/vs-povray.sh [BUILDDIR]   (default: the current folder)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
command -v hyperfine >/dev/null || { echo "vs-povray: hyperfine not found (Debian package: hyperfine)" >&2; exit 3; }
command -v povray >/dev/null || { echo "vs-povray: povray not found (Debian package: povray)" >&2; exit 3; }
work=$(mktemp -d "${TMPDIR:-/tmp}/hstbench.XXXXXX")
trap 'rm -rf "$work"' EXIT
# with what the scenes include and map (oldcolors.inc, textures/)
cp "$src"/scenes/*.pov "$src"/scenes/*.inc "$work/"
cp -R "$src/scenes/textures" "$work/"
out="$here/vs-povray.md"
{
    echo "# hstrace against POV-Ray"
    echo
    echo "Made by \`bench/vs-povray.sh\` on $(date -u +%Y-%m-%d), $(nproc) cores, $(povray --version 2>&1 | grep -m1 POV-Ray)."
    echo "Each row: 320x240, 2 threads, EXR output, conventional shadows; hyperfine, 2 warm-up runs, 10 timed runs."
    echo "Wall time includes POV-Ray's fixed start-up cost; user CPU time is the fairer comparison of the work done."
    echo
    echo "| scene | POV-Ray wall (ms) | hstrace wall (ms) | wall ratio POV/hst | POV-Ray user CPU (ms) | hstrace user CPU (ms) | CPU ratio POV/hst |"
    echo "|---|---|---|---|---|---|---|"
} >"$out"
cd "$work"
for f in *.pov; do
    s=${f%.pov}
    hyperfine -N -w 2 -r 10 --export-json "$work/$s.json" \
        "povray +I$s.pov +O$work/${s}_p.exr +FE -A -D -GA +WT2 +W320 +H240" \
        "$build/hstrace $s.pov -o $work/${s}_h.exr --threads 2 --width 320 --height 240 --shadows conventional" >/dev/null 2>&1
    python3 - "$work/$s.json" "$s" >>"$out" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["results"]
p, h = r[0], r[1]
ms = lambda x: 1000 * x
print(f"| {sys.argv[2]} | {ms(p['median']):.1f} | {ms(h['median']):.1f} | {p['median']/h['median']:.2f} | "
      f"{ms(p['user']):.1f} | {ms(h['user']):.1f} | {p['user']/h['user']:.2f} |")
PY
done
echo >>"$out"
echo "Wall times are medians; CPU times are means over the runs." >>"$out"
cat "$out"
