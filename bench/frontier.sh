#!/bin/sh
# Speed against error on the paper's scenes (desk, glasses, stars, cards):
# every shadow method, and for hst and conventional the settings that trade
# speed for error or for nothing (grid resolution, N_th, plane precision,
# the tolerance margin), each as one point of the frontier. Per point:
# shadow-testing and total time (medians of RUNS runs of --stats-json), the
# decisions that differ from the conventional shadow ray (--verify-shadows),
# the image against conventional's and against POV-Ray's (RMSE, by
# `hstrace compare`), and the shadow mask against POV-Ray's (+Q3/+Q4 pairs:
# pixels at edges or silhouettes / in the interior). POV-Ray's renders are
# the committed references in reference/ (320x240, the size used here).
# 1 thread. Writes bench/frontier.md.
#
# usage: bench/frontier.sh [BUILDDIR]   (default: the current folder)
#   env: FRONTIER_RUNS (default 3), FRONTIER_SCENES (default "desk glasses stars cards")
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
command -v python3 >/dev/null || { echo "frontier: python3 not found (Debian package: python3)" >&2; exit 3; }
work=$(mktemp -d "${TMPDIR:-/tmp}/hstfrontier.XXXXXX")
trap 'rm -rf "$work"' EXIT
python3 - "$build/hstrace" "$src" "$work" "$here/frontier.md" "${FRONTIER_RUNS:-3}" \
    "${FRONTIER_SCENES:-desk glasses stars cards}" <<'PY'
import json, os, statistics, subprocess, sys, time

hstrace, src, work, out, runs, scenes = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5]), sys.argv[6].split()
size = ["--width", "320", "--height", "240", "--threads", "1"]
# (label, options): the methods, then the settings of hst and conventional.
points = [
    ("conventional", ["--shadows", "conventional"]),
    ("cache", ["--shadows", "cache"]),
    ("volume", ["--shadows", "volume"]),
    ("hst", ["--shadows", "hst", "--volumes", "always"]),
    ("hst as planned (the default)", ["--shadows", "hst"]),
    ("hst, N_th 16", ["--shadows", "hst", "--volumes", "always", "--nth", "16"]),
    ("hst, N_th 1024", ["--shadows", "hst", "--volumes", "always", "--nth", "1024"]),
    ("hst, N_th per point", ["--shadows", "hst", "--volumes", "always", "--nth", "per-point"]),
    ("hst, no pixel coherence", ["--shadows", "hst", "--volumes", "always", "--pixel-coherence", "off"]),
    ("hst, grid 16", ["--shadows", "hst", "--volumes", "always", "--grid", "16"]),
    ("hst, grid 64", ["--shadows", "hst", "--volumes", "always", "--grid", "64"]),
    ("conventional, grid 16", ["--shadows", "conventional", "--grid", "16"]),
    ("conventional, grid 64", ["--shadows", "conventional", "--grid", "64"]),
    ("hst, float planes", ["--shadows", "hst", "--volumes", "always", "--plane-precision", "float"]),
    ("hst, float planes, double margin", ["--shadows", "hst", "--volumes", "always", "--plane-precision", "float-naive"]),
    ("hst, margin 0", ["--shadows", "hst", "--volumes", "always", "--tolerance", "0"]),
    ("hst, margin 1e-6", ["--shadows", "hst", "--volumes", "always", "--tolerance", "1e-6"]),
    ("volume, margin 0", ["--shadows", "volume", "--tolerance", "0"]),
]


def render(scene, opts, image, stats=None, extra=()):
    cmd = [hstrace, scene, *size, *opts, *extra, "-o", image]
    if stats:
        cmd += ["--stats-json", stats]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return json.load(open(stats)) if stats else None


def compare(a, b, masks=None):
    cmd = [hstrace, "compare", a, b, "--json"]
    if masks:
        cmd += ["--mask-a", *masks[0], "--mask-b", *masks[1]]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode not in (0, 1):
        sys.exit(f"frontier: compare failed: {r.stderr}")
    return json.loads(r.stdout)


with open(out, "w") as f:
    f.write("# Speed against error on the paper's scenes\n\n")
    f.write(f"Made by `make bench` (`bench/frontier.sh`) on {time.strftime('%Y-%m-%d', time.gmtime())}, "
            f"{os.cpu_count()} cores. 320x240, 1 thread. Times are medians of {runs} runs (`--stats-json`); "
            "*shadow / conv.* is against the `conventional` row of the same scene. *Decisions differing* "
            "are counted by `--verify-shadows` (the conventional shadow ray fired beside the method at every "
            "decision). *RMSE vs conv.* compares the images; *vs POV-Ray* compares with `reference/SCENE.exr`, "
            "and the mask with POV-Ray's +Q3/+Q4 pair (pixels at shadow edges or silhouettes / interior, the "
            "real errors). Grid N is N cells per axis; the default grid is chosen from the polygon count.\n\n")
    for name in scenes:
        scene = os.path.join(src, "scenes", name + ".pov")
        ref = os.path.join(src, "reference", name)
        if not os.path.exists(scene) or not os.path.exists(ref + ".q4.exr"):
            continue
        q3 = os.path.join(work, f"{name}.q3.exr")
        render(scene, ["+Q3"], q3)
        conv_image = os.path.join(work, f"{name}.conventional.exr")
        rows, conv_shadow = [], None
        for label, opts in points:
            tag = f"{name}.{len(rows)}"
            image = conv_image if label == "conventional" else os.path.join(work, f"{tag}.exr")
            stats = [render(scene, opts, image, os.path.join(work, f"{tag}.{r}.json")) for r in range(runs)]
            med = lambda k: statistics.median(s["time"][k] for s in stats)
            shadow, total = med("shadow_testing"), med("total")
            if label == "conventional":
                conv_shadow = shadow
            verify = render(scene, opts, os.path.join(work, f"{tag}.v.exr"), os.path.join(work, f"{tag}.v.json"),
                            ["--verify-shadows"])
            q4 = os.path.join(work, f"{tag}.q4.exr")
            render(scene, opts, q4, extra=["+Q4"])
            vs_conv = compare(conv_image, image)
            vs_pov = compare(ref + ".q4.exr", q4, ((ref + ".q3.exr", ref + ".q4.exr"), (q3, q4)))
            vs_pov_full = compare(ref + ".exr", image)
            m = vs_pov["masks"]
            rows.append((label, shadow, total, verify["shadows"]["disagreements"], verify["shadows"]["queries"],
                         vs_conv["rmse"], vs_pov_full["rmse"], m["shadow_edge"] + m["silhouette"], m["interior"],
                         "x".join(map(str, stats[0]["grid"]))))
            print(f"frontier: {name}: {label} done", file=sys.stderr)
        f.write(f"## {name}\n\n")
        f.write("| setting | grid | shadow ms | shadow / conv. | total ms | decisions differing (of) | RMSE vs conv. | "
                "RMSE vs POV-Ray | mask vs POV-Ray: edge / interior |\n|---|---|---|---|---|---|---|---|---|\n")
        for label, shadow, total, dis, queries, rc, rp, edge, interior, grid in rows:
            f.write(f"| {label} | {grid} | {1000 * shadow:.1f} | {shadow / conv_shadow:.2f} | {1000 * total:.1f} | "
                    f"{dis} ({queries}) | {rc:.2e} | {rp:.2e} | {edge} / {interior} |\n")
        f.write("\n")
print(f"wrote {out}")
PY
