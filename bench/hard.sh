#!/bin/sh
# Speed against error on the hard cases (scenes/hard/): for every scene,
# shadow method and numeric setting (--tolerance: the default margin 1e-9,
# none at all, and a thousand times wider; for volume and hst also
# --plane-precision float and float-naive), the shadow-testing time, the
# disagreements with the conventional shadow ray (--verify-shadows, at every
# shading point, reflected and refracted ones included), the method's and
# the shadow ray's errors against the long-double reference
# (--verify-reference, where it is not a tie), the decisions left
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
if [ ! -x "$build/hstrace" ] || [ ! -x "$build/tests/test_agreement" ]; then
    echo "hard: build the test programs first (make check)" >&2
    exit 3
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/hsthard.XXXXXX")
trap 'rm -rf "$work"' EXIT
out="$here/hard.md"
size="--width 320 --height 240 --threads 1"
methods="conventional cache volume hst"
tolerances="1e-9 0 1e-6"
# A numeric setting: name=hstrace options (spaces as commas).
settings="margin_1e-9=--tolerance,1e-9 margin_0=--tolerance,0 margin_1e-6=--tolerance,1e-6 float_planes=--plane-precision,float float_planes_naive=--plane-precision,float-naive"
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
    echo "*Setting*: margin R is \`--tolerance R\`, the margin of every shadow test relative to the scene's"
    echo "coordinates (1e-9 is the default); float planes is \`--plane-precision float\` (volume and hst test the"
    echo "shadow polygons' planes in float with a margin widened for float's rounding), naive is"
    echo "\`--plane-precision float-naive\` (float with the double margin)."
    echo "*Reference*: \`--verify-reference\`, the decisions against a brute-force long-double reference where it"
    echo "can tell (not a tie, i.e. no polygon within 1e-12 of the scene's size of a border or an end): the"
    echo "method's wrong decisions / the shadow ray's own / ties. hst builds every light's volumes here"
    echo "(\`--volumes always\`): the point is its counting, not whether the cost model would build them."
    echo
    echo "| scene | method | setting | shadow ms | disagree | reference: method wrong / ray wrong / ties | to the ray | mask: edges | mask: elsewhere | mask: POV-Ray leaks |"
    echo "|---|---|---|---|---|---|---|---|---|---|"
} >"$out"
for scene in "$src"/scenes/hard/*.pov; do
    name=$(basename "$scene" .pov)
    ref="$src/reference/hard/$name"
    leaks=""
    grep -q '^// hstrace-regress: povray-leaks' "$scene" && leaks="--allow-a-leaks"
    # shellcheck disable=SC2086 # $size holds several options
    "$build/hstrace" "$scene" $size +Q3 -o "$work/$name.q3.exr"
    for m in $methods; do
        for setting in $settings; do
            label=$(echo "${setting%%=*}" | tr _ ' ')
            opts=$(echo "${setting#*=}" | tr , ' ')
            case $m:$label in conventional:float* | cache:float*) continue ;; esac # no shadow polygons
            for i in 1 2 3; do
                # shellcheck disable=SC2086 # $opts is options and values
                "$build/hstrace" "$scene" $size --shadows "$m" --volumes always $opts --verify-shadows \
                    --stats-json "$work/$name.$m.$i.json" -o "$work/x.exr"
            done
            # shellcheck disable=SC2086
            "$build/hstrace" "$scene" --width 320 --height 240 --threads 2 --shadows "$m" --volumes always $opts --verify-reference \
                --stats-json "$work/$name.$m.ref.json" -o "$work/x.exr"
            # shellcheck disable=SC2086
            "$build/hstrace" "$scene" $size +Q4 --shadows "$m" --volumes always $opts -o "$work/$name.q4.exr"
            # shellcheck disable=SC2086 # $leaks is one option, or nothing
            mask=$("$build/hstrace" compare "$ref.q4.exr" "$work/$name.q4.exr" --json \
                   --mask-a "$ref.q3.exr" "$ref.q4.exr" --mask-b "$work/$name.q3.exr" "$work/$name.q4.exr" $leaks || true)
            python3 - "$work" "$name" "$m" "$label" "$mask" >>"$out" <<'PY'
import json, statistics, sys
work, name, m, label, mask = sys.argv[1:6]
runs = [json.load(open(f"{work}/{name}.{m}.{i}.json")) for i in (1, 2, 3)]
ref = json.load(open(f"{work}/{name}.{m}.ref.json"))["shadows"]
sh = runs[0]["shadows"]
ms = 1000 * statistics.median(r["time"]["shadow_testing"] for r in runs)
to_ray = sum(sh.get(k, 0) for k in ("unsure", "touching", "in_plane"))
try:
    mk = json.loads(mask)["masks"]
    edge_total, elsewhere = mk["shadow_edge"] + mk["silhouette"], mk["interior"]
    leaks = mk["a_leaks"] if mk["allow_a_leaks"] else "-"
except (ValueError, KeyError, TypeError):
    edge_total = elsewhere = leaks = "?"
reference = f"{ref['reference_wrong']} / {ref['reference_ray_wrong']} / {ref['reference_ties']}"
print(f"| {name} | {m} | {label} | {ms:.1f} | {sh['disagreements']} of {sh['verified']} | {reference} | {to_ray} | {edge_total} | {elsewhere} | {leaks} |")
PY
        done
    done
done
# The frontier: per method and setting, summed over the hard scenes.
# shellcheck disable=SC2094 # python reads the whole table before it appends
python3 - "$out" >>"$out" <<'PY'
import collections, sys
rows = [l.split("|")[1:-1] for l in open(sys.argv[1]) if l.startswith("| ") and not l.startswith("| scene")]
tot = collections.OrderedDict()
for r in rows:
    name, m, setting, ms, dis, ref = (c.strip() for c in r[:6])
    t = tot.setdefault((m, setting), [0.0, 0, 0, 0, 0])
    t[0] += float(ms)
    t[1] += int(dis.split(" of ")[0])
    t[2] += int(dis.split(" of ")[1])
    t[3] += int(ref.split(" / ")[0])
    t[4] += int(ref.split(" / ")[1])
print()
print("## Summed over the hard scenes")
print()
print("| method | setting | shadow ms | disagree with the shadow ray | wrong against the reference (method / ray) |")
print("|---|---|---|---|---|")
for (m, setting), t in tot.items():
    print(f"| {m} | {setting} | {t[0]:.1f} | {t[1]} of {t[2]} | {t[3]} / {t[4]} |")
PY
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
