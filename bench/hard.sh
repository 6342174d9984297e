#!/bin/sh
# Speed against error on the hard cases (scenes/hard/): for every scene,
# shadow method and numeric margin (--tolerance: the default 1e-9, none at
# all, and a thousand times wider), the shadow-testing time, the
# disagreements with the conventional shadow ray (--verify-shadows, at every
# shading point, reflected and refracted ones included), the decisions left
# to the shadow ray as too close to call, and the shadow mask against
# POV-Ray's (by the hard-case rule of tests/regress.sh: disagreements at
# edges are ties; elsewhere they are errors, or POV-Ray's leaks through
# shared edges where the scene is marked so). Then the randomized agreement
# test against its long-double reference at each margin. 320x240, 1 thread.
# Writes bench/hard.md.
#
# usage: bench/hard.sh [BUILDDIR]   (default: the current folder)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
command -v python3 >/dev/null || { echo "hard: python3 not found (Debian package: python3)" >&2; exit 3; }
[ -x "$build/hstrace" ] && [ -x "$build/tests/test_agreement" ] ||
    { echo "hard: build the test programs first (make check)" >&2; exit 3; }
work=$(mktemp -d "${TMPDIR:-/tmp}/hsthard.XXXXXX")
trap 'rm -rf "$work"' EXIT
out="$here/hard.md"
size="--width 320 --height 240 --threads 1"
methods="conventional cache volume hst"
tolerances="1e-9 0 1e-6"
{
    echo "# The hard cases: speed against error"
    echo
    echo "Made by \`make bench\` (\`bench/hard.sh\`) on $(date -u +%Y-%m-%d), $(nproc) cores, $(uname -m)."
    echo "320x240, 1 thread. *Shadow ms*: shadow-testing time, median of 3 runs with \`--verify-shadows\`"
    echo "(the check itself is not timed). *Disagree*: decisions that differ from the conventional shadow ray."
    echo "*To the ray*: decisions the method left to the shadow ray as too close to call (unsure crossings,"
    echo "points on a second polygon, segments in their start polygon's plane; pixel-coherence counts given up"
    echo "for the count from the eye are not among them). *Mask vs POV-Ray*: pixels whose shadow differs from POV-Ray's at +Q4, at edges (ties,"
    echo "allowed) / elsewhere (errors) / POV-Ray's leaks through shared edges (marked scenes only)."
    echo "*Tolerance*: \`--tolerance\`, the margin of every shadow test relative to the scene's coordinates."
    echo
    echo "| scene | method | tolerance | shadow ms | disagree | to the ray | mask: edges | mask: elsewhere | mask: POV-Ray leaks |"
    echo "|---|---|---|---|---|---|---|---|---|"
} >"$out"
for scene in "$src"/scenes/hard/*.pov; do
    name=$(basename "$scene" .pov)
    ref="$src/reference/hard/$name"
    leaks=""
    grep -q '^// hstrace-regress: povray-leaks' "$scene" && leaks="--allow-a-leaks"
    "$build/hstrace" "$scene" $size +Q3 -o "$work/$name.q3.exr"
    for m in $methods; do
        for tol in $tolerances; do
            for i in 1 2 3; do
                "$build/hstrace" "$scene" $size --shadows "$m" --tolerance "$tol" --verify-shadows \
                    --stats-json "$work/$name.$m.$tol.$i.json" -o "$work/x.exr"
            done
            "$build/hstrace" "$scene" $size +Q4 --shadows "$m" --tolerance "$tol" -o "$work/$name.q4.exr"
            # shellcheck disable=SC2086 # $leaks is one option, or nothing
            mask=$("$build/hstrace" compare "$ref.q4.exr" "$work/$name.q4.exr" --json \
                   --mask-a "$ref.q3.exr" "$ref.q4.exr" --mask-b "$work/$name.q3.exr" "$work/$name.q4.exr" $leaks || true)
            python3 - "$work" "$name" "$m" "$tol" "$mask" >>"$out" <<'PY'
import json, statistics, sys
work, name, m, tol, mask = sys.argv[1:6]
runs = [json.load(open(f"{work}/{name}.{m}.{tol}.{i}.json")) for i in (1, 2, 3)]
sh = runs[0]["shadows"]
ms = 1000 * statistics.median(r["time"]["shadow_testing"] for r in runs)
to_ray = sum(sh.get(k, 0) for k in ("unsure", "touching", "in_plane"))
try:
    mk = json.loads(mask)["masks"]
    edge_total, elsewhere = mk["shadow_edge"] + mk["silhouette"], mk["interior"]
    leaks = mk["a_leaks"] if mk["allow_a_leaks"] else "-"
except (ValueError, KeyError, TypeError):
    edge_total = elsewhere = leaks = "?"
print(f"| {name} | {m} | {tol} | {ms:.1f} | {sh['disagreements']} of {sh['verified']} | {to_ray} | {edge_total} | {elsewhere} | {leaks} |")
PY
        done
    done
done
{
    echo
    echo "## Random scenes against the long-double reference"
    echo
    echo "\`tests/test_agreement --scenes 5000 --tolerance T\` (the default seed): every method's decisions on"
    echo "random lattice scenes (shared edges and vertices, coplanar polygons, rays through vertices and along"
    echo "edges) against brute force in long double. Clear cases must all agree; at ties (within 1e-12 of the"
    echo "scene size of a border) the methods must agree with the shadow ray."
    echo
    echo "| tolerance | decisions | ties | wrong on clear cases (all methods) | differ from the ray at ties |"
    echo "|---|---|---|---|---|"
} >>"$out"
for tol in $tolerances; do
    "$build/tests/test_agreement" --scenes 5000 --tolerance "$tol" >"$work/agree.$tol.txt" || true
    python3 - "$work/agree.$tol.txt" "$tol" >>"$out" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
head = re.search(r"(\d+) decisions, (\d+) ties", text)
wrong = sum(int(x) for x in re.findall(r"clear case \((\d+) wrong", text))
ties = sum(int(x) for x in re.findall(r"on every tie \((\d+) differ", text))
print(f"| {sys.argv[2]} | {head[1]} | {head[2]} | {wrong} | {ties} |")
PY
done
echo "wrote $out"
