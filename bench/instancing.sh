#!/bin/sh
# Issue 42's instancing figures: an LDraw-style model (scenes/ldraw-model.sh:
# PLACEMENTS parts of about 400 to 2,100 triangles each, declared once and
# placed by matrix, on a baseplate placed once) rendered at 1280x960 on 2
# threads with anti-aliasing (+A0.3) by hstrace with instancing (the
# default), by hstrace with --instancing off (every copy flattened) and by
# POV-Ray 3.7 (povray -D +WT2), each RUNS times, interleaved in a shuffled
# order per round so that the machine's load falls on all alike. Medians of
# the whole process's wall time, CPU time (user + sys) and peak resident
# memory (/usr/bin/time -f %M), and the ratios to POV-Ray's.
# Writes bench/instancing.md.
#
# usage: bench/instancing.sh [BUILDDIR]   (default: the current folder)
# Environment: RUNS (default 7), PLACEMENTS (default 400), POVRAY (default povray).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
hstrace="$build/hstrace"
runs=${RUNS:-7}
placements=${PLACEMENTS:-400}
povray=${POVRAY:-povray}
command -v python3 >/dev/null || { echo "instancing: python3 not found (Debian package: python3)" >&2; exit 3; }
[ -x "$hstrace" ] || { echo "instancing: $hstrace is not built" >&2; exit 3; }
command -v "$povray" >/dev/null 2>&1 || { echo "instancing: $povray not found (Debian package: povray)" >&2; exit 3; }
work=$(mktemp -d "${TMPDIR:-/tmp}/hstinst.XXXXXX")
trap 'rm -rf "$work"' EXIT
out="$here/instancing.md"
sh "$src/scenes/ldraw-model.sh" "$placements" >"$work/model.pov"
size="+W1280 +H960 +A0.3"

# timed NAME CMD...: runs CMD in $work, appends "wall cpu peak_kib" to NAME.times
timed() {
    name=$1
    shift
    (cd "$work" && /usr/bin/time -f "%e %U %S %M" -o "$work/time" "$@" >/dev/null 2>&1) || {
        echo "instancing: $name failed" >&2
        exit 1
    }
    awk '{ printf "%.3f %.3f %d\n", $1, $2 + $3, $4 }' "$work/time" >>"$work/$name.times"
}

# The stats of each hstrace build of the world, once.
# shellcheck disable=SC2086 # the size switches, one word each
(
    cd "$work" && "$hstrace" model.pov $size --threads 2 -o inst.png --stats-json inst.json &&
        "$hstrace" model.pov $size --threads 2 -o flat.png --stats-json flat.json --instancing off
) >/dev/null 2>&1
for r in $(seq 1 "$runs"); do
    # a shuffled order of the three, from the round's number
    case $((r % 6)) in
    0) order="inst flat pov" ;; 1) order="flat pov inst" ;; 2) order="pov inst flat" ;;
    3) order="inst pov flat" ;; 4) order="flat inst pov" ;; *) order="pov flat inst" ;;
    esac
    for who in $order; do
        # shellcheck disable=SC2086 # the size switches, one word each
        case $who in
        inst) timed inst "$hstrace" model.pov $size --threads 2 -o inst.png ;;
        flat) timed flat "$hstrace" model.pov $size --threads 2 -o flat.png --instancing off ;;
        pov) timed pov "$povray" -D +WT2 $size +Imodel.pov +Opov.png ;;
        esac
    done
done
"$hstrace" compare "$work/pov.png" "$work/inst.png" --json >"$work/cmp-inst.json" 2>/dev/null || true
"$hstrace" compare "$work/flat.png" "$work/inst.png" --json >"$work/cmp-flat.json" 2>/dev/null || true
pov_version=$("$povray" --version 2>&1 | grep -m 1 "^POV-Ray" || echo "version unknown")
cpu_model=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
load=$(cut -d ' ' -f 1-3 /proc/loadavg)

python3 - "$work" "$runs" "$placements" "$pov_version" "$cpu_model" "$load" >"$out" <<'PY'
import json, statistics, sys, datetime
work, runs, placements, pov_version, cpu_model, load = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5], sys.argv[6]
med = statistics.median
def times(name):
    rows = [tuple(float(x) for x in line.split()) for line in open(f"{work}/{name}.times")]
    return [med(r[i] for r in rows) for i in range(3)], rows
def stats(name):
    return json.load(open(f"{work}/{name}.json"))
(iw, ic, im), irows = times("inst")
(fw, fc, fm), frows = times("flat")
(pw, pc, pm), prows = times("pov")
si, sf = stats("inst"), stats("flat")
def cmp(name):
    try:
        return json.load(open(f"{work}/cmp-{name}.json"))
    except Exception:
        return {}
ci, cf = cmp("inst"), cmp("flat")
print("# Instancing: an LDraw-style model against POV-Ray 3.7 (issue 42)")
print()
print(f"Made by `bench/instancing.sh` on {datetime.date.today()} ({runs} rounds, each round the three "
      f"commands once in a shuffled order; medians). Machine: {cpu_model}, 2 cores; load average at the end "
      f"{load}. POV-Ray: {pov_version}.")
print()
print(f"Scene: `sh scenes/ldraw-model.sh {placements}` (parts of 396 to 2,076 triangles, studs of 32 segments, "
      f"declared once as unions of meshes and placed by `matrix`, two lights, a baseplate placed once, an "
      f"infinite plane). Rendered at 1280x960, 2 threads, `+A0.3`:")
print()
print("- hstrace: `hstrace model.pov +W1280 +H960 +A0.3 --threads 2 -o inst.png` (instancing auto, the default)")
print("- flattened: the same with `--instancing off`")
print("- POV-Ray: `povray -D +WT2 +W1280 +H960 +A0.3 +Imodel.pov +Opov.png`")
print()
print("Whole processes, timed by `/usr/bin/time -f \"%e %U %S %M\"`: CPU is user + sys, memory the peak resident set.")
print()
print("| | wall (s) | CPU (s) | CPU / POV-Ray | peak memory (MiB) | memory / POV-Ray |")
print("|---|---:|---:|---:|---:|---:|")
for label, w, c, m in (("hstrace, instancing", iw, ic, im), ("hstrace, --instancing off", fw, fc, fm),
                       ("POV-Ray 3.7", pw, pc, pm)):
    print(f"| {label} | {w:.2f} | {c:.2f} | {c / pc:.2f} | {m / 1024:.1f} | {m / pm:.2f} |")
print()
def world(s):
    return (f"{s['polygons']} world polygons, {s['instances']} instances of {s['prototypes']} meshes "
            f"({s['prototype_polygons']} polygons kept once, placing {s['instanced_polygons']})")
print(f"- instancing: {world(si)}")
print(f"- flattened: {sf['polygons']} world polygons")
for label, c in (("hstrace (instancing) against POV-Ray's PNG", ci), ("instancing against flattened", cf)):
    if c:
        print(f"- {label}: RMSE {c.get('rmse')}, largest channel error {c.get('max_error')}")
print()
print("Each run (wall s, CPU s, peak KiB):")
print()
for label, rows in (("instancing", irows), ("flattened", frows), ("POV-Ray", prows)):
    print(f"- {label}: " + "; ".join(f"{r[0]:.2f} {r[1]:.2f} {int(r[2])}" for r in rows))
PY
echo "wrote $out"
