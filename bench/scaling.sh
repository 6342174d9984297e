#!/bin/sh
# How cost grows with the work: the generated scene of scenes/make-mesh.sh at
# 10^2 to 10^6 triangles (x10 steps) and 1, 2, 4 and 8 lights, rendered by
# every shadow method of hstrace and by POV-Ray, one after the other for
# each scene. Per run: wall time, CPU time and peak memory (the process's
# maximum resident set, from wait4), and for hstrace the preprocessing and
# shadow-testing split of --stats-json. 320x240, 1 thread, EXR output;
# every figure is the median of RUNS runs, the programs interleaved within
# each round, each round in an order of its own (default 3 runs). Then hst
# against conventional in instructions (callgrind, when valgrind is there)
# on a few cells, a measure the machine's load does not move. hst is the default (only the volumes the cost model
# expects to pay), hst-always builds every light's. Then the biggest cell
# at 1280x960, and on 1 and 2 threads. Plots with gnuplot (Debian: gnuplot-nox) when present.
# Writes bench/scaling.md and bench/scaling.{svg,png}.
#
# usage: bench/scaling.sh [BUILDDIR]   (default: the current folder)
#   env: SCALING_TRIANGLES (default "100 1000 10000 100000 1000000"),
#        SCALING_LIGHTS (default "1 2 4 8"), SCALING_RUNS (default 3),
#        SCALING_CALLGRIND (cells TRIANGLES:LIGHTS, default
#        "10000:8 100000:1 100000:8 1000000:1 1000000:8"; "" for none)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
command -v python3 >/dev/null || { echo "scaling: python3 not found (Debian package: python3)" >&2; exit 3; }
work=$(mktemp -d "${TMPDIR:-/tmp}/hstscale.XXXXXX")
trap 'rm -rf "$work"' EXIT
triangles=${SCALING_TRIANGLES:-"100 1000 10000 100000 1000000"}
lights=${SCALING_LIGHTS:-"1 2 4 8"}
runs=${SCALING_RUNS:-3}
for n in $triangles; do
    for l in $lights; do
        sh "$src/scenes/make-mesh.sh" "$n" "$l" >"$work/mesh-$n-$l.pov"
    done
done
python3 - "$build/hstrace" "$work" "$here" "$triangles" "$lights" "$runs" <<'PY'
import json, os, random, re, shutil, statistics, subprocess, sys, time

hstrace, work, here, triangles, lights, runs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4].split(), sys.argv[5].split(), int(sys.argv[6])
# Every round takes the programs in an order of its own (medians_of).
methods = ["conventional", "hst", "cache", "volume", "hst-always"]
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


def hstrace_cmd(m, scene, extra):
    """The command of one of hstrace's columns: a method, or hst with every light's volumes built."""
    opts = ["--shadows", "hst", "--volumes", "always"] if m == "hst-always" else ["--shadows", m]
    return [hstrace, scene, *extra, *opts]


def measure(m, scene, extra, js):
    """One run: wall, CPU, peak KiB, and for hstrace parse + preprocessing and shadow-testing seconds."""
    if m == "povray":
        w, h = "320", "240"
        if "--width" in extra:
            w, h = extra[extra.index("--width") + 1], extra[extra.index("--height") + 1]
        threads = extra[extra.index("--threads") + 1] if "--threads" in extra else "1"
        cmd = [povray, f"+I{scene}", f"+O{work}/p.exr", "+FE", "-A", "-D", "-GA", f"+WT{threads}", f"+W{w}", f"+H{h}"]
        return run(cmd, work) + (None, None)
    cmd = hstrace_cmd(m, scene, extra) + ["-o", f"{work}/h.exr", "--stats-json", js]
    wall, cpu, rss = run(cmd, work)
    t = json.load(open(js))["time"]
    return wall, cpu, rss, t["parse"] + t["preprocessing"], t["shadow_testing"]


def medians_of(cases, scene, label):
    """Every case (key, method, options) measured RUNS times, interleaved
    (A B C A B C ...), so that a change of load falls on all of them alike;
    the medians by key. Each round takes the cases in an order of its own (a
    shuffle, the same for the same round in every bench run): on this kind
    of machine a big run that follows a long one (POV-Ray's, or a spell
    of idling) is up to 50% slower, its memory backed by the virtual
    machine's host again, and a fixed order, or a rotation of one, put that
    on the same case, conventional, in every round."""
    samples = {key: [] for key, _, _ in cases}
    for r in range(runs):
        order = list(cases)
        random.Random(7919 * (r + 1) + len(cases)).shuffle(order)
        for key, m, extra in order:
            samples[key].append(measure(m, scene, extra, f"{work}/{m}.json"))
    per = {}
    for key in samples:
        med = lambda i: statistics.median(s[i] for s in samples[key]) if samples[key][0][i] is not None else None
        per[key] = [med(i) for i in range(5)] + [[s[0] for s in samples[key]]]  # [5]: every run's wall time
    print(f"scaling: {label} done", file=sys.stderr)
    return per


def medians(columns, scene, extra, label):
    """medians_of for the columns (methods) on the same options."""
    return medians_of([(m, m, extra) for m in columns], scene, label)


rows = []
for n in triangles:
    for l in lights:
        scene = f"mesh-{n}-{l}.pov"
        with open(os.path.join(work, scene)) as f:
            exact = next(int(line.split()[-1]) for line in f if line.startswith("// triangles:"))
        per = medians(methods + (["povray"] if povray else []), scene, size, f"{exact} triangles, {l} lights")
        rows.append((exact, int(l), per))

# The biggest cell again where shadow testing weighs most (1280x960), and on
# 1 and 2 threads (the thread-scaling rows).
big_n, big_l = triangles[-1], lights[-1]
big = f"mesh-{big_n}-{big_l}.pov"
with open(os.path.join(work, big)) as f:
    big_exact = next(int(line.split()[-1]) for line in f if line.startswith("// triangles:"))
large = medians(["conventional", "hst", "hst-always"] + (["povray"] if povray else []), big,
                ["--width", "1280", "--height", "960", "--threads", "1"], f"{big_exact} triangles at 1280x960")
# 1 and 2 threads interleaved too: a slow spell of the machine falls on both.
by_threads = medians_of([(f"{m}@{t}", m, ["--width", "320", "--height", "240", "--threads", t])
                         for t in ("1", "2") for m in ("conventional", "hst", "hst-always")],
                        big, f"{big_exact} triangles on 1 and 2 threads")
threads = {t: {m: by_threads[f"{m}@{t}"] for m in ("conventional", "hst", "hst-always")} for t in ("1", "2")}

# The same comparison in instructions (callgrind), which the machine's load
# does not change: hst over conventional on one thread, for a few cells.
valgrind = shutil.which("valgrind")
counted = []
for cell in os.environ.get("SCALING_CALLGRIND", "10000:8 100000:1 100000:8 1000000:1 1000000:8").split():
    n, l = cell.split(":")
    scene = f"mesh-{n}-{l}.pov"
    if not valgrind or not os.path.exists(os.path.join(work, scene)):
        continue
    ir = {}
    for m in ("conventional", "hst"):
        proc = subprocess.run([valgrind, "--tool=callgrind", "--callgrind-out-file=/dev/null", *hstrace_cmd(m, scene, size),
                               "-o", f"{work}/h.exr", "--stats-json", f"{work}/cg.json"], cwd=work, capture_output=True,
                              text=True)
        found = re.search(r"Collected : (\d+)", proc.stderr)
        if proc.returncode != 0 or not found:
            sys.exit(f"scaling: callgrind failed on {scene} ({m})")
        ir[m] = int(found.group(1))
    # hst's cost model times what it weighs, under valgrind as natively: how many lights it built volumes for.
    built = sum(1 for x in json.load(open(f"{work}/cg.json")).get("volume_plan", {}).get("lights", []) if x["volumes"])
    with open(os.path.join(work, scene)) as f:
        exact = next(int(line.split()[-1]) for line in f if line.startswith("// triangles:"))
    counted.append((exact, int(l), ir["conventional"], ir["hst"], built))
    print(f"scaling: callgrind {exact} triangles, {l} lights done", file=sys.stderr)

have = methods + (["povray"] if povray else [])
out = os.path.join(here, "scaling.md")
with open(out, "w") as f:
    f.write("# Scaling: time and memory against triangles and lights\n\n")
    f.write(f"Made by `make bench` (`bench/scaling.sh`) on {time.strftime('%Y-%m-%d', time.gmtime())}, "
            f"{os.cpu_count()} cores. The scene of `scenes/make-mesh.sh TRIANGLES LIGHTS`, 320x240, 1 thread, "
            f"EXR output; median of {runs} run(s) per cell, the programs interleaved, each round in an order of its own. *Wall* and *peak memory* are the whole process's "
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
    f.write("**hst against conventional** (wall time and peak memory, hst over conventional; hst is the default, "
            "which builds only the volumes the cost model expects to pay, `hst-always` builds every light's)\n\n")
    f.write("| triangles | lights | hst wall | hst memory | hst-always wall | hst-always memory |\n|---|---|---|---|---|---|\n")
    for exact, l, per in rows:
        c = per["conventional"]
        f.write(f"| {exact} | {l} | {per['hst'][0] / c[0]:.3f} | {per['hst'][2] / c[2]:.3f} | "
                f"{per['hst-always'][0] / c[0]:.3f} | {per['hst-always'][2] / c[2]:.3f} |\n")
    worst = max(per["hst"][0] / per["conventional"][0] for _, _, per in rows)
    over = sum(1 for _, _, per in rows if per["hst"][0] > 1.02 * per["conventional"][0])
    f.write(f"\nWorst hst/conventional wall ratio (of the medians) {worst:.3f}; cells above 1.02: {over} of {len(rows)}.\n\n")
    # The same comparison run by run: hst over the conventional run of the
    # same round, the median of those ratios per cell (a slow spell of the
    # machine that falls on one round changes one pair).
    def paired(per):
        return statistics.median(h / c for h, c in zip(per["hst"][5], per["conventional"][5]))
    pworst = max(paired(per) for _, _, per in rows)
    pover = sum(1 for _, _, per in rows if paired(per) > 1.02)
    f.write("**hst against conventional, run by run** (the median over the rounds of hst's wall time over the "
            "conventional run of the same round)\n\n| triangles | lights | hst / conventional |\n|---|---|---|\n")
    for exact, l, per in rows:
        f.write(f"| {exact} | {l} | {paired(per):.3f} |\n")
    f.write(f"\nWorst paired ratio {pworst:.3f}; cells above 1.02: {pover} of {len(rows)}.\n\n")
    if counted:
        f.write("**hst against conventional in instructions** (`valgrind --tool=callgrind`, the whole run, "
                "1 thread, 320x240; the count does not depend on the machine's load, but hst's cost model "
                "decides by times it measures, here as valgrind runs the code: *volumes* says for how many "
                "lights it built them)\n\n"
                "| triangles | lights | conventional | hst | hst / conventional | volumes |\n|---|---|---|---|---|---|\n")
        for exact, l, c, h, b in counted:
            f.write(f"| {exact} | {l} | {c:,} | {h:,} | {h / c:.4f} | {b} of {l} |\n")
        f.write(f"\nWorst {max(h / c for _, _, c, h, _ in counted):.4f}.\n\n")
    f.write(f"**{big_exact} triangles, {big_l} lights at 1280x960, 1 thread** (median of {runs})\n\n")
    f.write("| program | wall (s) | CPU (s) | parse + preprocessing (s) | shadow testing (s) | peak (MiB) | wall / conventional |\n")
    f.write("|---|---|---|---|---|---|---|\n")
    for m, v in large.items():
        prep = f"{v[3]:.2f}" if v[3] is not None else "-"
        shadow = f"{v[4]:.2f}" if v[4] is not None else "-"
        f.write(f"| {m} | {v[0]:.2f} | {v[1]:.2f} | {prep} | {shadow} | {v[2] / 1024:.0f} | "
                f"{v[0] / large['conventional'][0]:.3f} |\n")
    f.write(f"\n**Threads: {big_exact} triangles, {big_l} lights, 320x240** (median of {runs}, 1 and 2 threads "
            "interleaved; speed-up = 1 thread over 2, of the medians and, run by run, the median of each round's ratio)\n\n")
    f.write("| method | wall 1 thread | wall 2 threads | speed-up | run by run | prep. 1 thread | prep. 2 threads | speed-up |\n")
    f.write("|---|---|---|---|---|---|---|---|\n")
    for m in ("conventional", "hst", "hst-always"):
        a, b = threads["1"][m], threads["2"][m]
        rbr = statistics.median(x / y for x, y in zip(a[5], b[5]))  # each round's 1-thread over its 2-thread run
        f.write(f"| {m} | {a[0]:.2f} | {b[0]:.2f} | {a[0] / b[0]:.2f} | {rbr:.2f} | {a[3]:.2f} | {b[3]:.2f} | "
                f"{a[3] / b[3]:.2f} |\n")
    f.write("\n")
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
