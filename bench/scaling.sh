#!/bin/sh
# How cost grows with the work: the generated scene of scenes/make-mesh.sh at
# 10^2 to 10^6 triangles (x10 steps) and 1, 2, 4 and 8 lights, rendered by
# every shadow method of hstrace and by POV-Ray, one after the other for
# each scene. Per run: wall time, CPU time and peak memory (the process's
# maximum resident set, from wait4), and for hstrace the preprocessing and
# shadow-testing split of --stats-json. 320x240, 1 thread, EXR output;
# every figure is the median of RUNS runs (default 1: the series shows growth,
# not small ratios). Plots with gnuplot (Debian: gnuplot-nox) when present.
# Writes bench/scaling.md and bench/scaling.{svg,png}.
#
# usage: bench/scaling.sh [BUILDDIR]   (default: the current folder)
#   env: SCALING_TRIANGLES (default "100 1000 10000 100000 1000000"),
#        SCALING_LIGHTS (default "1 2 4 8"), SCALING_RUNS (default 1)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
command -v python3 >/dev/null || { echo "scaling: python3 not found (Debian package: python3)" >&2; exit 3; }
work=$(mktemp -d "${TMPDIR:-/tmp}/hstscale.XXXXXX")
trap 'rm -rf "$work"' EXIT
triangles=${SCALING_TRIANGLES:-"100 1000 10000 100000 1000000"}
lights=${SCALING_LIGHTS:-"1 2 4 8"}
runs=${SCALING_RUNS:-1}
for n in $triangles; do
    for l in $lights; do
        sh "$src/scenes/make-mesh.sh" "$n" "$l" >"$work/mesh-$n-$l.pov"
    done
done
python3 - "$build/hstrace" "$work" "$here" "$triangles" "$lights" "$runs" <<'PY'
import json, os, shutil, statistics, subprocess, sys, time

hstrace, work, here, triangles, lights, runs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4].split(), sys.argv[5].split(), int(sys.argv[6])
methods = ["conventional", "cache", "volume", "hst"]
povray = shutil.which("povray")
size = ["--width", "320", "--height", "240", "--threads", "1"]


def run(cmd, cwd):
    """Wall seconds, CPU seconds (user + system) and peak resident KiB of one process."""
    start = time.monotonic()
    proc = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"scaling: failed: {' '.join(cmd)}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss


rows = []
for n in triangles:
    for l in lights:
        scene = f"mesh-{n}-{l}.pov"
        with open(os.path.join(work, scene)) as f:
            exact = next(int(line.split()[-1]) for line in f if line.startswith("// triangles:"))
        per = {}
        for m in methods + (["povray"] if povray else []):
            samples = []
            for r in range(runs):
                if m == "povray":
                    cmd = [povray, f"+I{scene}", f"+O{work}/p.exr", "+FE", "-A", "-D", "-GA", "+WT1", "+W320", "+H240"]
                    samples.append(run(cmd, work) + (None, None))
                else:
                    js = f"{work}/{m}.json"
                    cmd = [hstrace, scene, *size, "--shadows", m, "-o", f"{work}/h.exr", "--stats-json", js]
                    wall, cpu, rss = run(cmd, work)
                    t = json.load(open(js))["time"]
                    samples.append((wall, cpu, rss, t["parse"] + t["preprocessing"], t["shadow_testing"]))
            med = lambda i: statistics.median(s[i] for s in samples) if samples[0][i] is not None else None
            per[m] = [med(i) for i in range(5)]
        rows.append((exact, int(l), per))
        print(f"scaling: {exact} triangles, {l} lights done", file=sys.stderr)

have = methods + (["povray"] if povray else [])
out = os.path.join(here, "scaling.md")
with open(out, "w") as f:
    f.write("# Scaling: time and memory against triangles and lights\n\n")
    f.write(f"Made by `make bench` (`bench/scaling.sh`) on {time.strftime('%Y-%m-%d', time.gmtime())}, "
            f"{os.cpu_count()} cores. The scene of `scenes/make-mesh.sh TRIANGLES LIGHTS`, 320x240, 1 thread, "
            f"EXR output; median of {runs} run(s) per cell. *Wall* and *peak memory* are the whole process's "
            "(from wait4); *prep.* is hstrace's parse plus preprocessing (grid, silhouettes, shadow-polygon "
            "registration, cost-model calibration), *shadow* its shadow-testing time (--stats-json).")
    if not povray:
        f.write(" POV-Ray was not installed: its columns are missing.")
    f.write("\n\n")
    def table(title, cols, cell):
        f.write(f"{title}\n\n| triangles | lights |" + "".join(f" {c} |" for c in cols) + "\n")
        f.write("|" + "---|" * (2 + len(cols)) + "\n")
        for exact, l, per in rows:
            f.write(f"| {exact} | {l} |" + "".join(f" {cell(per[c])} |" for c in cols) + "\n")
        f.write("\n")
    table("**Wall time (s)**", have, lambda v: f"{v[0]:.2f}")
    table("**hstrace: parse + preprocessing / shadow testing (s)**", methods, lambda v: f"{v[3]:.2f} / {v[4]:.2f}")
    table("**Peak memory (MiB)**", have, lambda v: f"{v[2] / 1024:.0f}")
    # One data file per light count for the plot: wall time against triangles.
    for l in lights:
        with open(os.path.join(work, f"plot-{l}.dat"), "w") as d:
            for exact, ll, per in rows:
                if str(ll) == l:
                    d.write(f"{exact} " + " ".join(f"{per[m][0]:.4f}" for m in have) + "\n")
    with open(os.path.join(work, "methods.txt"), "w") as d:
        d.write(" ".join(have) + "\n")
    f.write("Plot: wall time against triangles, one panel per light count: `scaling.svg` / `scaling.png`.\n\n")
    f.write("![scaling](scaling.png)\n")
print(f"wrote {out}")
PY
if command -v gnuplot >/dev/null; then
    # shellcheck disable=SC2086 # one positional parameter per light count
    set -- $lights
    nl=$#
    methods=$(cat "$work/methods.txt")
    for fmt in svg png; do
        {
            if [ "$fmt" = svg ]; then echo "set terminal svg size 1000,$((300 * ((nl + 1) / 2))) dynamic"; else echo "set terminal pngcairo size 1000,$((300 * ((nl + 1) / 2)))"; fi
            echo "set output '$here/scaling.$fmt'"
            echo "set multiplot layout $(((nl + 1) / 2)),2"
            echo "set logscale xy; set key left top; set xlabel 'triangles'; set ylabel 'wall s'; set grid"
            for l in $lights; do
                echo "set title '$l light(s)'"
                printf 'plot '
                i=2
                sep=
                for m in $methods; do
                    printf "%s'%s' using 1:%d with linespoints title '%s'" "$sep" "$work/plot-$l.dat" "$i" "$m"
                    sep=', '
                    i=$((i + 1))
                done
                echo
            done
            echo "unset multiplot"
        } | gnuplot
    done
    echo "wrote $here/scaling.svg $here/scaling.png"
else
    echo "scaling: gnuplot not found (Debian package: gnuplot-nox); no plots" >&2
fi
