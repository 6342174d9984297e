#!/bin/sh
# Anti-aliased renders side by side, for issue 18: the paper's four scenes
# and POV-Ray's objects/chesmsh.pov (Debian package povray-examples) at
# +A0.3 (POV-Ray's default method and jitter), 1280x960, 2 threads: hstrace
# with each shadow method and POV-Ray 3.7, wall and CPU time of the whole
# process (user + system, from wait4), the median of RUNS runs with the
# programs interleaved run by run; and each hstrace image against POV-Ray's
# (RMSE and the share of pixels off by more than 0.02, `hstrace compare`).
# Writes bench/antialias.md. Run it under nice on a shared machine.
#
# usage: bench/antialias.sh [BUILDDIR]   (default: the current folder)
#   env: AA_RUNS (default 3), HST_POVRAY_EXAMPLES (default
#        /usr/share/doc/povray/examples), POVRAY (default povray)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
[ -x "$build/hstrace" ] || { echo "antialias: build hstrace first" >&2; exit 3; }
command -v python3 >/dev/null || { echo "antialias: python3 not found (Debian package: python3)" >&2; exit 3; }
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
[ -n "$povray" ] || { echo "antialias: povray not found (Debian package: povray)" >&2; exit 3; }
examples=${HST_POVRAY_EXAMPLES:-/usr/share/doc/povray/examples}
work=$(mktemp -d "${TMPDIR:-/tmp}/hstaabench.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir "$work/scenes"
for s in desk glasses stars cards; do cp "$src/scenes/$s.pov" "$work/scenes/"; done
[ -f "$examples/objects/chesmsh.pov" ] && cp -R "$examples/objects" "$work/objects"
python3 - "$build/hstrace" "$povray" "$work" "$here" "${AA_RUNS:-3}" <<'PY'
import json, os, statistics, subprocess, sys, time

hstrace, povray, work, here, runs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5])
version = subprocess.run([hstrace, "--version"], capture_output=True, text=True).stdout.strip()
methods = ["conventional", "cache", "volume", "hst", "hst-always"] + (["embree"] if "; Embree " in version else [])
scenes = [(s, os.path.join(work, "scenes"), s + ".pov") for s in ["desk", "glasses", "stars", "cards"]]
if os.path.isdir(os.path.join(work, "objects")):
    scenes.append(("chesmsh", os.path.join(work, "objects"), "chesmsh.pov"))
size = ["+W1280", "+H960", "+A0.3"]
loads = []


def run(cmd, cwd):
    loads.append(os.getloadavg()[0])
    start = time.monotonic()
    proc = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"antialias: failed: {' '.join(cmd)}")
    return time.monotonic() - start, usage.ru_utime + usage.ru_stime


def command(program, scene, out):
    label, folder, name = scene
    if program == "povray":
        return [povray, f"+I{name}", *size, "+WT2", "+FE", f"+O{out}", "-D", "-V", "-GA"]
    shadows = ["--shadows", "hst", "--volumes", "always"] if program == "hst-always" else ["--shadows", program]
    return [hstrace, name, *size, "--threads", "2", *shadows, "-o", out]


programs = methods + ["povray"]
times = {sc[0]: {p: [] for p in programs} for sc in scenes}
start_date = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
t0 = time.monotonic()
for r in range(runs):
    for sc in scenes:
        for p in programs:
            out = os.path.join(work, f"{sc[0]}.{p}.exr")
            times[sc[0]][p].append(run(command(p, sc, out), sc[1]))
    print(f"antialias: run {r + 1} of {runs} done", file=sys.stderr)
errors = {}
for sc in scenes:
    for p in methods:
        j = subprocess.run([hstrace, "compare", os.path.join(work, f"{sc[0]}.povray.exr"),
                            os.path.join(work, f"{sc[0]}.{p}.exr"), "--json"], capture_output=True, text=True)
        d = json.loads(j.stdout)
        errors[(sc[0], p)] = (d["rmse"], d["share_over_threshold"])
minutes = (time.monotonic() - t0) / 60
med = statistics.median
out = os.path.join(here, "antialias.md")
with open(out, "w") as o:
    o.write("# Anti-aliased renders against POV-Ray\n\n")
    o.write(f"Made by `make bench` (`bench/antialias.sh`) on {start_date}, in {minutes:.0f} minutes, {os.cpu_count()} "
            f"cores; {version}. Every scene at `+W1280 +H960 +A0.3` (POV-Ray's default method 1 and jitter), "
            f"2 threads (`--threads 2`, POV-Ray `+WT2`), EXR output; wall and CPU (user + system) of the whole "
            f"process, median of {runs} runs, programs interleaved run by run; 1-minute load average "
            f"{med(loads):.1f} (median, from {min(loads):.1f} to {max(loads):.1f}). *RMSE* and *off* (the share "
            "of pixels off by more than 0.02) are hstrace's image against POV-Ray's (`hstrace compare`). hst is "
            "the default method; hst-always builds every light's shadow volumes (`--volumes always`).\n\n")
    o.write("| scene | program | wall (s) | CPU (s) | CPU vs POV-Ray | RMSE | off |\n|---|---|---|---|---|---|---|\n")
    for sc in scenes:
        t = times[sc[0]]
        pov_cpu = med(x[1] for x in t["povray"])
        for p in programs:
            w, c = med(x[0] for x in t[p]), med(x[1] for x in t[p])
            rm, off = errors.get((sc[0], p), (None, None))
            o.write(f"| {sc[0]} | {'povray' if p == 'povray' else 'hstrace ' + p} | {w:.2f} | {c:.2f} | "
                    f"{c / pov_cpu:.2f} | {'-' if rm is None else f'{rm:.2e}'} | "
                    f"{'-' if off is None else f'{100 * off:.3f}%'} |\n")
    o.write("\nCommand: `hstrace SCENE +W1280 +H960 +A0.3 --threads 2 --shadows METHOD -o x.exr` against "
            "`povray +ISCENE +W1280 +H960 +A0.3 +WT2 +FE +Ox.exr -D -V -GA`, in a private copy of the scene's folder.\n")
print(f"wrote {out}")
PY
