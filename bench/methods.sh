#!/bin/sh
# The shadow methods side by side on the project's scenes (the paper's
# Table 2): for each scene, conventional, cache, volume, hst (N_th from
# eq. 7, with pixel coherence), hst without pixel coherence and hst with a
# per-point N_th, rendered at 640x480 on one thread
# (so that the CPU-time split is clean). hyperfine times the whole runs in
# one interleaved session (wall medians); each method's --stats-json split
# (preprocessing, shadow testing, others) is the median of 5 further runs.
# Writes bench/methods.md.
#
# usage: bench/methods.sh [BUILDDIR]   (default: the current folder)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
command -v hyperfine >/dev/null || { echo "methods: hyperfine not found (Debian package: hyperfine)" >&2; exit 3; }
command -v python3 >/dev/null || { echo "methods: python3 not found (Debian package: python3)" >&2; exit 3; }
work=$(mktemp -d "${TMPDIR:-/tmp}/hstmethods.XXXXXX")
trap 'rm -rf "$work"' EXIT
out="$here/methods.md"
size="--width 640 --height 480 --threads 1"
variants="conventional cache volume light-buffer hst hst:auto:off hst:per-point planned"
{
    echo "# Shadow methods side by side"
    echo
    echo "Made by \`make bench\` (\`bench/methods.sh\`) on $(date -u +%Y-%m-%d), $(nproc) cores, $(uname -m)."
    echo "Each scene at 640x480, 1 thread, EXR output. *Wall* is hyperfine's median of 10 runs (2 warm-up),"
    echo "all methods of a scene interleaved in one session; the split (preprocessing incl. silhouettes,"
    echo "shadow-polygon registration and the cost-model calibration; shadow testing incl. filling shadow"
    echo "buckets; others) is the median of 5 runs of \`--stats-json\`. Ratios are to \`conventional\`."
    echo "Shadow-testing time is estimated by timing every 31st decision (see src/shadow/shadow_decide.h)."
    echo "The hst rows build every light's shadow volumes (\`--volumes always\`, as the paper does); *planned*"
    echo "is the default \`--shadows hst\`, which builds only those the cost model expects to pay (volume_plan.h)"
    echo "and hands the rest to the light buffers where they pay (shadow_hst_prepare.c). *ns / decision*: shadow"
    echo "testing over the decisions asked (issue 41's figure); the *buffer* columns are the light buffer's sub-schemes."
    echo
} >"$out"
for scene in "$src"/scenes/*.pov; do
    name=$(basename "$scene" .pov)
    set --
    for v in $variants; do
        m=${v%%:*}; rest=${v#"$m"}; rest=${rest#:}
        nth=${rest%%:*}; [ -n "$nth" ] || nth=auto
        coh=on; case $rest in *:off) coh=off ;; esac
        # hst with every light's volumes (the paper's algorithm); "planned"
        # is the default, where the cost model builds only those that pay.
        opts="--shadows $m --volumes always --nth $nth --pixel-coherence $coh"
        [ "$m" = planned ] && opts="--shadows hst --volumes auto"
        set -- "$@" "$build/hstrace $scene $size $opts -o $work/$name.exr"
        for i in 1 2 3 4 5; do
            # shellcheck disable=SC2086 # $size and $opts hold several options
            "$build/hstrace" "$scene" $size $opts -o "$work/$name.exr" --stats-json "$work/$name.$v.$i.json"
        done
    done
    hyperfine -N -w 2 -r 10 --export-json "$work/$name.hyperfine.json" "$@" >/dev/null 2>&1
    python3 - "$work" "$name" "$variants" >>"$out" <<'PY'
import json, statistics, sys
work, name, variants = sys.argv[1], sys.argv[2], sys.argv[3].split()
wall = [r["median"] for r in json.load(open(f"{work}/{name}.hyperfine.json"))["results"]]
rows = []
for v, w in zip(variants, wall):
    m, nth, coh = (v.split(":") + ["auto", "on"][len(v.split(":")) - 1:])[:3]
    runs = [json.load(open(f"{work}/{name}.{v}.{i}.json")) for i in range(1, 6)]
    med = lambda f: statistics.median(f(r) for r in runs)
    t = {k: med(lambda r: r["time"][k]) for k in ("preprocessing", "shadow_testing", "others", "total")}
    sch = runs[0]["shadows"]["schemes"]
    label = m if nth == "auto" else f"{m} (N_th {nth})"
    if coh == "off":
        label += " (no pixel coherence)"
    nthv = runs[0].get("nth", "")
    rows.append((label, t, w, sch, nthv, runs[0]))
base = rows[0]
print(f"## {name}\n")
print(f"{base[5]['polygons']} polygons, {base[5]['lights']} lights, grid {'x'.join(map(str, base[5]['grid']))}.\n")
print("| method | preprocessing (ms) | shadow testing (ms) | ns / decision | others (ms) | total (ms) | wall median (ms) | shadow / conv. | total / conv. | wall / conv. | sustain | self-shadow | volume (from the previous pixel) | conventional | cache hit | buffer lit | buffer cover | buffer list |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for label, t, w, sch, nthv, r in rows:
    ms = lambda x: f"{1000 * x:.1f}"
    q = r["shadows"]["queries"]
    ns = f"{1e9 * t['shadow_testing'] / q:.1f}" if q else "-"
    print(f"| {label} | {ms(t['preprocessing'])} | {ms(t['shadow_testing'])} | {ns} | {ms(t['others'])} | {ms(t['total'])} | {ms(w)} | "
          f"{t['shadow_testing'] / base[1]['shadow_testing']:.2f} | {t['total'] / base[1]['total']:.2f} | {w / base[2]:.2f} | "
          f"{sch['sustain']} | {sch['self-shadow']} | {sch['volume']} ({r['shadows'].get('coherent', 0)}) | {sch['conventional']} | {sch['cache hit']} | "
          f"{sch.get('buffer lit', 0)} | {sch.get('buffer cover', 0)} | {sch.get('buffer list', 0)} |")
hst = [r for r in rows if r[0] == "hst"][0][5]
c = hst.get("cost_model")
if c:
    print(f"\nCost model (hst run): C_s {c['c_s_ns']:.1f} ns, C_i {c['c_i_ns']:.1f} ns, C_c {c['c_c_ns']:.1f} ns, "
          f"C_o {c['c_o_ns']:.1f} ns, p {c['p']:.4f}, alpha {c['alpha']:.3f}, N_c {c['n_c']:.1f}, N_o {c['n_o']:.1f}, "
          f"N_th (eq. 7) " + (f"{c['nth_eq7']:.1f}" if c['nth_eq7'] is not None else "none (no finite optimum)") +
          f"; calibration {1000 * c['seconds']:.1f} ms.")
v = hst.get("volumes")
if v:
    sp = ", ".join(f"{l['shadow_polygons']} ({l['cell_registrations']} registrations)" for l in v["lights"])
    print(f"Shadow polygons per light: {sp}; built in {1000 * v['seconds']:.1f} ms.")
print()
PY
done
echo "wrote $out"
