#!/bin/sh
# Speed side by side, for issue 16: on the paper's four scenes, POV-Ray's
# objects/chesmsh.pov (Debian package povray-examples) and the make-mesh
# scenes of 10^5 and 10^6 triangles with 3 lights:
#   - ns per camera ray: bench/camera_rays, a dedicated timer (the nearest-hit
#     query alone through every pixel centre at 640x480, one thread, thread
#     CPU clock, median pass of RUNS), with the ray/polygon tests per ray;
#   - ns per shadow decision for each method (conventional, cache, volume,
#     hst, embree; none for the fixed cost of a decision): shadow-testing
#     time over shadow queries of --stats-json, 640x480, 1 thread (shadow
#     testing is timed on every 31st decision and scaled); with conventional's
#     ray/polygon tests per shadow ray, and embree's disagreements with the
#     exact shadow ray from one more render with --verify-shadows;
#   - the whole render at 1280x960 on 2 threads, every method and POV-Ray 3.7
#     (povray -A +WT2, the same size, PNG out): wall time and CPU time (user +
#     system of the process, from wait4);
#   - hst (the default) on 1 thread against 2 at 1280x960, and the speed-up.
# Every figure is the median of RUNS runs; the programs and methods are
# interleaved (each run renders every scene with every program once, in
# turn), so a change of load falls on all of them alike. The 1-minute load
# average is sampled before every render and reported in the header.
# Writes bench/speed.md. Run it under nice on a shared machine.
#
# usage: bench/speed.sh [BUILDDIR]   (default: the current folder)
#   env: SPEED_RUNS (default 3), SPEED_SCENES (default all: desk glasses
#        stars cards chesmsh mesh-1e5 mesh-1e6), HST_POVRAY_EXAMPLES
#        (default /usr/share/doc/povray/examples), POVRAY (default povray)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
if ! [ -x "$build/hstrace" ] || ! [ -x "$build/bench/camera_rays" ]; then
    echo "speed: build hstrace and bench/camera_rays first (make bench)" >&2
    exit 3
fi
command -v python3 >/dev/null || { echo "speed: python3 not found (Debian package: python3)" >&2; exit 3; }
runs=${SPEED_RUNS:-3}
examples=${HST_POVRAY_EXAMPLES:-/usr/share/doc/povray/examples}
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
work=$(mktemp -d "${TMPDIR:-/tmp}/hstspeed.XXXXXX")
trap 'rm -rf "$work"' EXIT
# Private copies: POV-Ray writes only where its configuration permits (the
# current folder), and chesmsh.pov needs its examples folder's chess.inc.
mkdir "$work/scenes"
for s in desk glasses stars cards; do cp "$src/scenes/$s.pov" "$work/scenes/"; done
sh "$src/scenes/make-mesh.sh" 100000 3 >"$work/scenes/mesh-1e5.pov"
sh "$src/scenes/make-mesh.sh" 1000000 3 >"$work/scenes/mesh-1e6.pov"
if [ -f "$examples/objects/chesmsh.pov" ]; then
    cp -R "$examples/objects" "$work/objects"
fi
python3 - "$build" "$work" "$here" "$runs" "$povray" <<'PY'
import json, os, platform, re, shutil, statistics, subprocess, sys, time

build, work, here, runs, povray = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
hstrace = os.path.join(build, "hstrace")
camera_rays = os.path.join(build, "bench", "camera_rays")
version = subprocess.run([hstrace, "--version"], capture_output=True, text=True).stdout.strip()
have_embree = "; Embree " in version
# hst is the default (volumes only where the cost model expects them to pay);
# hst-always builds every light's, as the paper does.
methods = ["conventional", "cache", "volume", "hst", "hst-always"] + (["embree"] if have_embree else [])

scenes = []  # (label, folder, file)
for s in ["desk", "glasses", "stars", "cards"]:
    scenes.append((s, os.path.join(work, "scenes"), s + ".pov"))
if os.path.isdir(os.path.join(work, "objects")):
    scenes.append(("chesmsh", os.path.join(work, "objects"), "chesmsh.pov"))
scenes.append(("make-mesh 10^5", os.path.join(work, "scenes"), "mesh-1e5.pov"))
scenes.append(("make-mesh 10^6", os.path.join(work, "scenes"), "mesh-1e6.pov"))
if os.environ.get("SPEED_SCENES"):
    wanted = os.environ["SPEED_SCENES"].split()
    scenes = [sc for sc in scenes if sc[2][:-4] in wanted]

loads = []


def run(cmd, cwd, retry_povray=False):
    """Wall and CPU (user + system) seconds of one process."""
    for attempt in range(3):
        loads.append(os.getloadavg()[0])
        start = time.monotonic()
        with open(os.path.join(work, "log"), "w") as log:
            proc = subprocess.Popen(cmd, cwd=cwd, stdout=log, stderr=subprocess.STDOUT)
            _, status, usage = os.wait4(proc.pid, 0)
        wall = time.monotonic() - start
        if os.waitstatus_to_exitcode(status) == 0:
            return wall, usage.ru_utime + usage.ru_stime
        text = open(os.path.join(work, "log")).read()
        # POV-Ray 3.7 can give up before its threads start on a loaded machine.
        if not (retry_povray and "Timed out waiting for worker thread startup" in text):
            break
    sys.exit(f"speed: failed: {' '.join(cmd)}\n{text[-2000:]}")


def hst(scene, method, width, height, threads, extra=()):
    label, folder, name = scene
    js = os.path.join(work, "stats.json")
    shadows = ["--shadows", "hst", "--volumes", "always"] if method == "hst-always" else ["--shadows", method]
    cmd = [hstrace, name, *shadows, "--width", str(width), "--height", str(height),
           "--threads", str(threads), "-o", os.path.join(work, "h.png"), "--stats-json", js, *extra]
    wall, cpu = run(cmd, folder)
    with open(js) as f:
        return wall, cpu, json.load(f)


def pov(scene, width, height, threads):
    label, folder, name = scene
    cmd = [povray, f"+I{name}", f"+O{os.path.join(work, 'p.png')}", "+FN", "-A", f"+WT{threads}",
           f"+W{width}", f"+H{height}", "-D", "-V", "-GA"]
    return run(cmd, folder, retry_povray=True)


med = statistics.median
start_date = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
t_start = time.monotonic()
load_start = os.getloadavg()

# Camera rays, by the dedicated timer (one process per scene, RUNS passes).
camera = {}
for sc in scenes:
    loads.append(os.getloadavg()[0])
    out = subprocess.run([camera_rays, sc[2], "640", "480", str(runs)], cwd=sc[1], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"speed: bench/camera_rays failed on {sc[2]}: {out.stderr}")
    camera[sc[0]] = json.loads(out.stdout)
print("speed: camera rays timed", file=sys.stderr)

# Per decision: 640x480, 1 thread, every method, interleaved.
decide = {sc[0]: {m: [] for m in ["none"] + methods} for sc in scenes}
for r in range(runs):
    for sc in scenes:
        for m in ["none"] + methods:
            wall, cpu, j = hst(sc, m, 640, 480, 1)
            q = j["shadows"]["queries"]
            decide[sc[0]][m].append({
                "ns": j["time"]["shadow_testing"] / q * 1e9 if q else float("nan"),
                "queries": q, "shadow_rays": j["shadows"]["shadow_rays"],
                "shadow_tests": j["shadows"]["polygon_tests"], "j": j})
    print(f"speed: per-decision run {r + 1} of {runs} done", file=sys.stderr)

# embree's disagreements with the exact shadow ray (untimed).
disagree = {}
if have_embree:
    for sc in scenes:
        _, _, j = hst(sc, "embree", 640, 480, 2, ["--verify-shadows"])
        disagree[sc[0]] = (j["shadows"]["disagreements"], j["shadows"]["verified"])

# Whole renders at 1280x960: 2 threads, every method and POV-Ray; hst on 1
# thread too. Interleaved.
programs = ["none"] + methods + (["povray"] if povray else [])
big = {sc[0]: {p: [] for p in programs + ["hst-1"]} for sc in scenes}
for r in range(runs):
    for sc in scenes:
        for p in programs + ["hst-1"]:
            if p == "povray":
                big[sc[0]][p].append(pov(sc, 1280, 960, 2))
            elif p == "hst-1":
                big[sc[0]][p].append(hst(sc, "hst", 1280, 960, 1)[:2])
            else:
                big[sc[0]][p].append(hst(sc, p, 1280, 960, 2)[:2])
    print(f"speed: 1280x960 run {r + 1} of {runs} done", file=sys.stderr)

minutes = (time.monotonic() - t_start) / 60
load_end = os.getloadavg()
cores = os.cpu_count()
cpu_model = platform.processor() or platform.machine()
try:
    with open("/proc/cpuinfo") as f:
        cpu_model = next(l.split(":", 1)[1].strip() for l in f if l.startswith("model name"))
except (OSError, StopIteration):
    pass
pov_version = "not installed"
if povray:
    banner = subprocess.run([povray, "--version"], capture_output=True, text=True)
    line = next((l for l in (banner.stdout + banner.stderr).splitlines() if l.startswith("POV-Ray")), "POV-Ray")
    pov_version = line.strip()


def f(x, fmt="{:.0f}"):
    return "-" if x is None or x != x else fmt.format(x)


out = os.path.join(here, "speed.md")
with open(out, "w") as o:
    o.write("# Speed: camera rays, shadow decisions and whole renders against POV-Ray\n\n")
    o.write(f"Made by `make bench` (`bench/speed.sh`) on {start_date}, in {minutes:.0f} minutes: {cpu_model}, "
            f"{cores} cores, {platform.machine()}; {version}; {pov_version}. Every figure is the median of "
            f"{runs} runs (`SPEED_RUNS`), programs and methods interleaved run by run.\n\n")
    lo, hi = min(loads), max(loads)
    o.write(f"Machine load (1-minute load average, sampled before each of {len(loads)} measurements): "
            f"{load_start[0]:.1f} at the start, median {med(loads):.1f}, from {lo:.1f} to {hi:.1f}, "
            f"{load_end[0]:.1f} at the end, on {cores} cores.")
    if med(loads) > cores * 0.75:
        o.write(f" **The machine was busy**: a load average of {med(loads):.1f} on {cores} cores means other work "
                "competed for the processors throughout. Wall times are inflated (2-thread renders most, so the "
                "thread speed-ups understate what an idle machine gives), CPU times less so (caches and "
                "frequency are shared), and the ratios between programs measured side by side hold better "
                "than the absolute figures.")
    o.write("\n\n")

    o.write("## Camera rays and polygon tests\n\n")
    o.write("*Camera ray*: `bench/camera_rays SCENE 640 480 RUNS`, the nearest-hit query alone (hierarchy, then "
            "the watertight double test) through every pixel centre, one thread, no shading; the median pass. "
            "*Tests per camera ray* and *nodes per camera ray* are its counts; *tests per shadow ray* is "
            "conventional's ray/polygon tests over its shadow rays (`--stats-json`, 640x480). *Embree 1* and "
            "*Embree 8*: the same rays as Embree's nearest-hit queries on the scene `--shadows embree` builds, in "
            "float, one at a time (`rtcIntersect1`) and in coherent packets of 4x2 pixels (`rtcIntersect8`), the "
            "median pass of the same process; *hstrace / Embree 1* is the issue's goal (<= 1). Embree's scene "
            "holds no infinite planes, no_shadow polygons or polygons with holes as triangles, so it may hit "
            "fewer (*Embree hits*).\n\n")
    o.write("| scene | polygons | lights | ns per camera ray | Embree 1 | Embree 8 | hstrace / Embree 1 "
            "| hits | Embree hits | tests per camera ray | nodes per camera ray "
            "| tests per shadow ray |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for sc in scenes:
        c = camera[sc[0]]
        conv = decide[sc[0]]["conventional"][0]
        j = conv["j"]
        per_shadow = conv["shadow_tests"] / conv["shadow_rays"] if conv["shadow_rays"] else float("nan")
        e1, e8, eh = c.get("embree_ns_per_ray"), c.get("embree_packet_ns_per_ray"), c.get("embree_hits")
        e1_text = "-" if e1 is None else f"{e1:.0f}"
        e8_text = "-" if e8 is None else f"{e8:.0f}"
        ratio_text = "-" if e1 is None else f"{c['ns_per_ray'] / e1:.2f}"
        o.write(f"| {sc[0]} | {j['polygons']} | {j['lights']} | {c['ns_per_ray']:.0f} | {e1_text} | {e8_text} | "
                f"{ratio_text} | {c['hits']} | {'-' if eh is None else eh} | "
                f"{c['polygon_tests_per_ray']:.2f} | {c['nodes_per_ray']:.1f} | {f(per_shadow, '{:.2f}')} |\n")

    o.write("\n## Shadow decisions (640x480, 1 thread)\n\n")
    o.write("Nanoseconds per shadow decision: shadow-testing time over shadow queries (`--stats-json`; the "
            "time is taken on every 31st decision and scaled). *none* decides nothing and measures the fixed "
            "cost of a decision (the call and the clock). "
            + (f"*embree* is Embree {re.search(r'Embree ([0-9.]+)', version).group(1)}'s `rtcOccluded1` with the shadow "
               "ray's rules; *embree vs ray* is how many of its decisions differ from the exact shadow ray's "
               "(`--verify-shadows`, 640x480, 2 threads). " if have_embree else
               "This hstrace was built without Embree: no embree column. ")
            + "*queries* are the decisions per render (the same for every method).\n\n")
    cols = ["none"] + methods
    o.write("| scene | queries | " + " | ".join(cols) + (" | embree vs ray |" if have_embree else " |")
            + "\n|---|---|" + "---|" * len(cols) + ("---|" if have_embree else "") + "\n")
    for sc in scenes:
        d = decide[sc[0]]
        row = [f(med(x["ns"] for x in d[m])) for m in cols]
        extra = ""
        if have_embree:
            dis, ver = disagree[sc[0]]
            extra = f" {dis} of {ver} |"
        o.write(f"| {sc[0]} | {d['conventional'][0]['queries']} | " + " | ".join(row) + " |" + extra + "\n")
    if "embree" in methods:
        o.write("\nRatios to embree (ns per decision over embree's):\n\n")
        o.write("| scene | " + " | ".join(m for m in methods if m != "embree") + " |\n|---|"
                + "---|" * (len(methods) - 1) + "\n")
        for sc in scenes:
            d = decide[sc[0]]
            e = med(x["ns"] for x in d["embree"])
            o.write(f"| {sc[0]} | " + " | ".join(f(med(x["ns"] for x in d[m]) / e, "{:.2f}")
                                                for m in methods if m != "embree") + " |\n")

    o.write("\n## Whole renders (1280x960, 2 threads)\n\n")
    o.write("Wall and CPU time of the whole process (parse, preprocessing, render, PNG output; CPU is user + "
            "system from wait4), hstrace with each `--shadows` method (hst is the default) and POV-Ray 3.7 as "
            "`povray +ISCENE +Ox.png +FN -A +WT2 +W1280 +H960 -D -V -GA` (its wall time includes a start-up "
            "wait of its own of about 0.6 s); *hst-always* is hst with `--volumes always`. *CPU vs POV-Ray* is the "
            "row's CPU time over POV-Ray's.\n\n")
    o.write("| scene | program | wall (s) | CPU (s) | CPU vs POV-Ray |\n|---|---|---|---|---|\n")
    for sc in scenes:
        b = big[sc[0]]
        pov_cpu = med(x[1] for x in b["povray"]) if povray else None
        for p in programs:
            w, c = med(x[0] for x in b[p]), med(x[1] for x in b[p])
            ratio = c / pov_cpu if pov_cpu else None
            name = p if p == "povray" else f"hstrace {p}"
            o.write(f"| {sc[0]} | {name} | {w:.2f} | {c:.2f} | {f(ratio, '{:.2f}')} |\n")

    o.write("\n## Threads (1280x960, hst)\n\n")
    o.write("The default method on 1 thread and on 2 (the 2-thread figures are those of the table above); "
            "*speed-up* is the 1-thread wall time over the 2-thread one.\n\n")
    o.write("| scene | wall 1 thread (s) | wall 2 threads (s) | speed-up | CPU 1 thread (s) | CPU 2 threads (s) |\n"
            "|---|---|---|---|---|---|\n")
    for sc in scenes:
        b = big[sc[0]]
        w1, c1 = med(x[0] for x in b["hst-1"]), med(x[1] for x in b["hst-1"])
        w2, c2 = med(x[0] for x in b["hst"]), med(x[1] for x in b["hst"])
        o.write(f"| {sc[0]} | {w1:.2f} | {w2:.2f} | {w1 / w2:.2f} | {c1:.2f} | {c2:.2f} |\n")
    o.write("\nCommands: `hstrace SCENE --shadows METHOD --width W --height H --threads T -o x.png --stats-json "
            "s.json` in a private copy of the scene's folder; make-mesh scenes from `scenes/make-mesh.sh "
            "100000 3` and `scenes/make-mesh.sh 1000000 3`; chesmsh.pov in a copy of the examples' "
            "`objects` folder.\n")
print(f"wrote {out}")
PY
