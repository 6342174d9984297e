#!/bin/sh
# Issue 41's figures: the light buffer and hst (which hands its shadow-ray
# decisions to it where it pays) against the shadow ray and Embree.
#   1. ns per shadow decision (shadow_testing / queries of --stats-json)
#      of every method on the paper's four scenes, 640x480, 1 thread: the
#      median of RUNS rounds, each round every method once, in turn
#      (interleaved, so that the machine's load falls on all alike); with
#      the light buffer's sub-scheme shares, cells, memory and build time.
#   2. make-mesh 10^5 triangles x 4 lights and 10^6 x 8, 640x480, 1 thread:
#      hst against conventional, CPU time (user + sys) medians of interleaved
#      runs and peak resident memory.
#   3. desk at 1280x960 on 2 threads: hst's CPU time against --shadows none
#      and POV-Ray 3.7's (-A +WT2), medians of interleaved runs.
# Writes bench/light-buffer.md.
#
# usage: bench/light-buffer.sh [BUILDDIR]   (default: the current folder)
# Environment: RUNS (default 5), MESH_RUNS (default 3), POVRAY (default povray).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
hstrace="$build/hstrace"
runs=${RUNS:-5}
mesh_runs=${MESH_RUNS:-3}
povray=${POVRAY:-povray}
command -v python3 >/dev/null || { echo "light-buffer: python3 not found (Debian package: python3)" >&2; exit 3; }
[ -x "$hstrace" ] || { echo "light-buffer: $hstrace is not built" >&2; exit 3; }
work=$(mktemp -d "${TMPDIR:-/tmp}/hstlb.XXXXXX")
trap 'rm -rf "$work"' EXIT
out="$here/light-buffer.md"
methods="conventional cache light-buffer hst none"
"$hstrace" --version 2>/dev/null | grep -q "Embree [0-9]" && methods="embree $methods"

# cpu CMD...: runs CMD, prints its user + sys seconds and peak KiB, from
# the kernel's resource usage to the microsecond (/usr/bin/time rounds to
# 10 ms: 2.5% of a 0.4 s render, more than the differences measured)
cpu() {
    python3 -c '
import os, subprocess, sys
p = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
_, status, ru = os.wait4(p.pid, 0)
p.returncode = status
if status != 0:
    sys.exit(1)
print(f"{ru.ru_utime + ru.ru_stime:.6f} {ru.ru_maxrss}")
' "$@"
}

# 1. ns per decision, interleaved rounds
for r in $(seq 1 "$runs"); do
    for scene in desk glasses stars cards; do
        for m in $methods; do
            (cd "$src/scenes" && "$hstrace" "$scene.pov" --width 640 --height 480 --threads 1 --shadows "$m" \
                -o "$work/$scene.exr" --stats-json "$work/$scene.$m.$r.json") >/dev/null 2>&1
        done
    done
done

# 2. the meshes
sh "$src/scenes/make-mesh.sh" 100000 4 >"$work/mesh-1e5.pov"
sh "$src/scenes/make-mesh.sh" 1000000 8 >"$work/mesh-1e6.pov"
for r in $(seq 1 "$mesh_runs"); do
    for mesh in mesh-1e5 mesh-1e6; do
        for m in conventional hst; do
            cpu "$hstrace" "$work/$mesh.pov" --width 640 --height 480 --threads 1 --shadows "$m" -o "$work/$mesh.exr" \
                --stats-json "$work/$mesh.$m.$r.json" >"$work/$mesh.$m.$r.cpu"
        done
    done
done

# 3. desk at 1280x960 on 2 threads, against none and POV-Ray
have_povray=0
command -v "$povray" >/dev/null 2>&1 && have_povray=1
for r in $(seq 1 "$mesh_runs"); do
    for m in hst none; do
        (cd "$src/scenes" && cpu "$hstrace" desk.pov --width 1280 --height 960 --threads 2 --shadows "$m" \
            -o "$work/desk-big.png") >"$work/big.$m.$r.cpu"
    done
    if [ $have_povray = 1 ]; then
        (cd "$src/scenes" && cpu "$povray" -D -A +WT2 +W1280 +H960 +Idesk.pov +O"$work/desk-pov.png") \
            >"$work/big.povray.$r.cpu" || have_povray=0
    fi
done

python3 - "$work" "$runs" "$mesh_runs" "$methods" "$have_povray" >"$out" <<'PY'
import json, os, statistics, sys, datetime, platform
work, runs, mesh_runs, methods, have_povray = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4].split(), sys.argv[5] == "1"
med = statistics.median
def load(path):
    return json.load(open(path))
cpu_model = ""
try:
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            cpu_model = line.split(":", 1)[1].strip()
            break
except OSError:
    pass
print("# The light buffer: ns per shadow decision, meshes, and whole renders")
print()
print(f"Made by `bench/light-buffer.sh` on {datetime.date.today()}, {os.cpu_count()} cores, {platform.machine()}"
      f" ({cpu_model}); load average {os.getloadavg()[0]:.2f} at the end.")
print(f"ns per decision is `--stats-json`'s shadow_testing / queries (every 31st decision timed, the clock's own read"
      f" taken out), the median of {runs} interleaved rounds (each round every method once, in turn);"
      f" 640x480, 1 thread. Ratios are to conventional's and embree's medians.")
print()
print("## ns per shadow decision")
print()
print("| scene | " + " | ".join(methods) + " | hst / conventional | hst / embree | light-buffer / conventional |")
print("|---|" + "---|" * (len(methods) + 3))
lb_rows = []
for scene in ["desk", "glasses", "stars", "cards"]:
    ns = {}
    for m in methods:
        vals = []
        for r in range(1, runs + 1):
            d = load(f"{work}/{scene}.{m}.{r}.json")
            vals.append(1e9 * d["time"]["shadow_testing"] / max(d["shadows"]["queries"], 1))
        ns[m] = med(vals)
    ratio = lambda a, b: f"{ns[a] / ns[b]:.2f}" if b in ns and ns[b] > 0 else "-"
    print(f"| {scene} | " + " | ".join(f"{ns[m]:.1f}" for m in methods) +
          f" | {ratio('hst', 'conventional')} | {ratio('hst', 'embree')} | {ratio('light-buffer', 'conventional')} |")
    d = load(f"{work}/{scene}.hst.1.json")
    lb_rows.append((scene, d))
print()
print("## The camera's hits and the secondary ones apart")
print()
print("ns per decision at the hits of camera rays and at those of reflected, refracted and transmitted rays"
      " (`time.shadow_testing_secondary` over `shadows.secondary_queries`), medians as above; the share of"
      " decisions at secondary hits in brackets.")
print()
print("| scene | " + " | ".join(f"{m} camera / secondary" for m in methods if m != "none") + " |")
print("|---|" + "---|" * (len(methods) - 1))
for scene in ["desk", "glasses", "stars", "cards"]:
    cells = []
    for m in methods:
        if m == "none":
            continue
        cam, sec, share = [], [], 0.0
        for r in range(1, runs + 1):
            d = load(f"{work}/{scene}.{m}.{r}.json")
            q, q2 = d["shadows"]["queries"], d["shadows"].get("secondary_queries", 0)
            t, t2 = d["time"]["shadow_testing"], d["time"].get("shadow_testing_secondary", 0.0)
            cam.append(1e9 * (t - t2) / max(q - q2, 1))
            if q2:
                sec.append(1e9 * t2 / q2)
            share = q2 / max(q, 1)
        cells.append(f"{med(cam):.1f} / " + (f"{med(sec):.1f} ({100 * share:.0f}%)" if sec else "- (0%)"))
    print(f"| {scene} | " + " | ".join(cells) + " |")
print()
print("## hst's sub-schemes and its light buffer (first round)")
print()
print("| scene | decisions | buffer lit | buffer cover | buffer list | cache hit | shadow ray | cells | MiB | build (ms) | candidates looked at / tested per decision |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for scene, d in lb_rows:
    s = d["shadows"]; sch = s["schemes"]; q = max(s["queries"], 1); lb = d.get("light_buffer", {})
    pct = lambda k: f"{100 * sch.get(k, 0) / q:.1f}%"
    print(f"| {scene} | {q} | {pct('buffer lit')} | {pct('buffer cover')} | {pct('buffer list')} | {pct('cache hit')} | "
          f"{pct('conventional')} | {lb.get('cells', 0)} | {lb.get('bytes', 0) / 1048576:.1f} | "
          f"{1000 * lb.get('build_seconds', 0):.1f} | {s.get('light_buffer_scanned', 0) / q:.2f} / "
          f"{s.get('light_buffer_candidates', 0) / q:.2f} |")
print()
print("## Meshes: hst against the shadow ray")
print()
print(f"`scenes/make-mesh.sh`, 640x480, 1 thread; CPU (user + sys) and peak resident memory, medians of {mesh_runs}"
      " interleaved runs.")
print()
print("| scene | conventional CPU (s) | hst CPU (s) | hst / conv. CPU | conventional peak (MiB) | hst peak (MiB) | hst / conv. peak | hst's light buffer |")
print("|---|---|---|---|---|---|---|---|")
for mesh, label in (("mesh-1e5", "10^5 triangles x 4 lights"), ("mesh-1e6", "10^6 x 8")):
    row = {}
    for m in ("conventional", "hst"):
        c = [open(f"{work}/{mesh}.{m}.{r}.cpu").read().split() for r in range(1, mesh_runs + 1)]
        row[m] = (med(float(x[0]) for x in c), med(int(x[1]) for x in c) / 1024)
    d = load(f"{work}/{mesh}.hst.1.json")
    lb = "cells " + str(d["light_buffer"]["cells"]) if "light_buffer" in d else "none (more than one polygon in 20 pixels)"
    print(f"| {label} | {row['conventional'][0]:.3f} | {row['hst'][0]:.3f} | {row['hst'][0] / row['conventional'][0]:.3f} | "
          f"{row['conventional'][1]:.0f} | {row['hst'][1]:.0f} | {row['hst'][1] / row['conventional'][1]:.3f} | {lb} |")
print()
print("## desk, 1280x960, 2 threads: CPU time")
print()
big = {}
for m in ["hst", "none"] + (["povray"] if have_povray else []):
    big[m] = med(float(open(f"{work}/big.{m}.{r}.cpu").read().split()[0]) for r in range(1, mesh_runs + 1))
line = f"hst {big['hst']:.3f} s, --shadows none {big['none']:.3f} s: hst / none {big['hst'] / big['none']:.2f}"
if have_povray:
    line += f"; POV-Ray 3.7 (`-A +WT2`) {big['povray']:.3f} s: hst / POV-Ray {big['hst'] / big['povray']:.2f}"
print(line + f" (medians of {mesh_runs} interleaved runs).")
PY
echo "wrote $out"
