#!/bin/sh
# A render spread over Open MPI's ranks, for issue 21: on this machine (2
# cores), desk and make-mesh 10^5 (4 lights) at 1280x960, wall and CPU time
# (user + system of the whole job, from wait4) of 1 process x 1 thread,
# 1 process x 2 threads, 2 ranks x 1 thread and 2 ranks x 2 threads (more
# threads than cores), the median of RUNS runs with the four interleaved run
# by run: strong scaling, and what MPI costs
# against threads alone, and what starting MPI costs (mpirun -n 2 of a
# 16x12 render against one process's). Then an estimate, not a measurement,
# for 16 and 64 ranks of one thread each: the 1x1 run's own tile times
# (--stats-json's tile_seconds) handed out as rank 0 hands them out (single
# tiles to its own thread, guided runs to the others, each request paying
# a round trip), every rank repeating parse and preprocessing, rank 0
# gathering the others' tiles (one image's worth) at the 2-rank run's speed,
# plus the start; the round trip as the 2-rank run measured it (its tile requests'
# waits); the same model for 2 ranks beside the measured run, as a check.
# Writes bench/mpi.md. Run it under nice on an idle machine.
#
# usage: bench/mpi.sh [BUILDDIR]   (default: the current folder)
#   env: MPI_RUNS (default 3), MPIRUN (default mpirun)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
[ -x "$build/hstrace" ] || { echo "mpi: build hstrace first" >&2; exit 3; }
"$build/hstrace" --version | grep -q "Open MPI" || { echo "mpi: hstrace is built without Open MPI" >&2; exit 3; }
mpirun=$(command -v "${MPIRUN:-mpirun}" 2>/dev/null) || { echo "mpi: mpirun not found (Debian package openmpi-bin)" >&2; exit 3; }
command -v python3 >/dev/null || { echo "mpi: python3 not found (Debian package: python3)" >&2; exit 3; }
work=$(mktemp -d "${TMPDIR:-/tmp}/hstmpibench.XXXXXX")
trap 'rm -rf "$work"' EXIT
cp "$src/scenes/desk.pov" "$work/"
sh "$src/scenes/make-mesh.sh" 100000 4 >"$work/mesh-1e5.pov"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
python3 - "$build/hstrace" "$mpirun" "$work" "$here" "${MPI_RUNS:-3}" <<'PY'
import heapq, json, os, statistics, subprocess, sys, time

hstrace, mpirun, work, here, runs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5])
size = ["+W1280", "+H960"]
configs = [("1 process x 1 thread", 1, 1), ("1 process x 2 threads", 1, 2), ("2 ranks x 1 thread", 2, 1),
           ("2 ranks x 2 threads (4 threads on 2 cores)", 2, 2)]

def timed(cmd):
    t0 = time.time()
    p = subprocess.Popen(cmd, cwd=work, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.time() - t0
    err = p.stderr.read().decode(errors="replace")
    if status != 0:
        sys.exit("mpi: %s failed: %s" % (" ".join(cmd), err[-500:]))
    return wall, ru.ru_utime + ru.ru_stime

def command(scene, ranks, threads, json_path):
    base = [hstrace, scene] + size + ["--threads", str(threads), "--stats-json", json_path, "-o", "out.png"]
    return ([mpirun, "-n", str(ranks)] + base) if ranks > 1 else base

loads = []
rows = []
# What starting MPI costs: a tiny render under mpirun -n 2 and alone.
starts = []
for r in range(runs):
    a, _ = timed([mpirun, "-n", "2", hstrace, "desk.pov", "+W16", "+H12", "-o", "tiny.png"])
    b, _ = timed([hstrace, "desk.pov", "+W16", "+H12", "-o", "tiny.png"])
    starts.append(a - b)
start = max(0.0, statistics.median(starts))

def simulate(tiles, ranks, prep, latency, gather):
    """The wall time of ranks x 1 thread: rank 0's thread takes single tiles,
    the others guided runs (what is left over twice the threads), each run
    paying one round trip; then rank 0 gathers the other ranks' tiles, one
    image's worth in all (gather: the time for a whole image)."""
    free = [(prep, i) for i in range(ranks)]
    heapq.heapify(free)
    k, n = 0, len(tiles)
    while k < n:
        at, i = heapq.heappop(free)
        count = 1 if i == 0 else max(1, (n - k) // (2 * ranks))
        at += sum(tiles[k:k + count]) + (latency if i else 0.0)
        k += count
        heapq.heappush(free, (at, i))
    return max(at for at, _ in free) + gather * (ranks - 1) / ranks + start

for scene in ["desk.pov", "mesh-1e5.pov"]:
    walls = {c[0]: [] for c in configs}
    cpus = {c[0]: [] for c in configs}
    for r in range(runs):
        loads.append(os.getloadavg()[0])
        for name, ranks, threads in configs:
            w, c = timed(command(scene, ranks, threads, "%s-%d-%d.json" % (scene, ranks, threads)))
            walls[name].append(w)
            cpus[name].append(c)
    med = {n: (statistics.median(walls[n]), statistics.median(cpus[n])) for n in walls}
    one = json.load(open(os.path.join(work, "%s-1-1.json" % scene)))
    two = json.load(open(os.path.join(work, "%s-2-1.json" % scene)))
    tiles = one["tile_seconds"]
    prep = one["time"]["parse"] + one["time"]["preprocessing"]
    t1 = med["1 process x 1 thread"][0]
    t2 = med["2 ranks x 1 thread"][0]
    # A whole image's gathering, from the 2-rank run's (which gathered the
    # other rank's share of the pixels).
    share = two["per_rank"][1]["pixels"] / float(sum(p["pixels"] for p in two["per_rank"]))
    per_image = two["gather_seconds"] / share if share > 0 else two["gather_seconds"]
    # A request's round trip as the 2-rank run measured it (its ranks'
    # tile_wait_seconds over their tile_requests).
    asked = sum(p["tile_requests"] for p in two["per_rank"])
    latency = sum(p["tile_wait_seconds"] for p in two["per_rank"]) / asked if asked else 0.0
    model2 = simulate(tiles, 2, prep, latency, per_image)

    def estimate(n):
        wall = simulate(tiles, n, prep, latency, per_image)
        return wall, t1 / (n * wall)

    rows.append((scene, med, t1, prep, sum(tiles), len(tiles), latency, per_image, estimate, model2, t2))

# A job of the size this is for: desk at 3840x2160 with +A0.3, its tiles
# (anti-aliasing's 32-pixel blocks) timed by one 1x1 run; the round trip
# and the gathering speed (per pixel) are desk's above.
big_json = "big.json"
timed([hstrace, "desk.pov", "+W3840", "+H2160", "+A0.3", "--threads", "1", "--stats-json", big_json, "-o", "big.png"])
big = json.load(open(os.path.join(work, big_json)))
d = rows[0]
big_tiles = big["tile_seconds"]
big_prep = big["time"]["parse"] + big["time"]["preprocessing"]
big_t1 = big["time"]["wall"]
big_gather = d[7] * (3840 * 2160) / (1280 * 960)

def big_estimate(n):
    wall = simulate(big_tiles, n, big_prep, d[6], big_gather)
    return wall, big_t1 / (n * wall)

out = []
out.append("# Renders across Open MPI's ranks (bench/mpi.sh)\n")
out.append("Command: `bench/mpi.sh` (MPI_RUNS=%d), this machine's 2 cores, Open MPI over shared memory; "
           "load average during the runs %.1f-%.1f. Median of %d runs, the configurations interleaved.\n"
           % (runs, min(loads), max(loads), runs))
out.append("## Measured: strong scaling and MPI's cost against threads\n")
out.append("| scene, 1280x960 | configuration | wall s | CPU s | speed-up (wall) against 1x1 |")
out.append("|---|---|---|---|---|")
for scene, med, t1, *_ in rows:
    for name, _, _ in configs:
        w, c = med[name]
        out.append("| %s | %s | %.3f | %.3f | %.2f |" % (scene, name, w, c, t1 / w))
out.append("")
out.append("| scene | 2 ranks x 1 thread against 1 process x 2 threads (wall) | (CPU) |")
out.append("|---|---|---|")
for scene, med, *_ in rows:
    a, b = med["2 ranks x 1 thread"], med["1 process x 2 threads"]
    out.append("| %s | %.3f | %.3f |" % (scene, a[0] / b[0], a[1] / b[1]))
out.append("")
out.append("## Estimated, not measured: 16 and 64 ranks of one thread\n")
out.append("A model, from this machine's figures: the 1x1 run's tiles (%s) at their measured times, handed "
           "out as rank 0 hands them out (single tiles to its own thread, guided runs to the others, each "
           "request paying a round trip); every rank first repeats parse and preprocessing; rank 0 gathers "
           "the other ranks' tiles (packed: one image's worth in all, whatever N) at the 2-rank run's speed; and starting MPI costs %.3f s (mpirun -n 2 of a 16x12 "
           "render against one process's, median). The round trip is the 2-rank run's own (its tile requests' "
           "waits over their number). The model's 2-rank wall time stands beside the measured one as a check. "
           "It assumes identical machines and a network as fast as shared "
           "memory, so real clusters do worse on the gathering." % (", ".join(str(r[5]) for r in rows), start))
out.append("")
out.append("| scene | parse + preprocessing s | tiles' CPU s | round trip per request ms | a whole image gathered s "
           "| 2 ranks: model s (measured s) | 16 ranks: wall s (efficiency) | 64 ranks: wall s (efficiency) |")
out.append("|---|---|---|---|---|---|---|---|")
for scene, med, t1, prep, total, n, latency, per_image, estimate, model2, t2 in rows:
    w16, e16 = estimate(16)
    w64, e64 = estimate(64)
    out.append("| %s | %.3f | %.3f | %.3f | %.4f | %.3f (%.3f) | %.3f (%.0f%%) | %.3f (%.0f%%) |"
               % (scene, prep, total, latency * 1e3, per_image, model2, t2, w16, 100 * e16, w64, 100 * e64))
w16, e16 = big_estimate(16)
w64, e64 = big_estimate(64)
out.append("| desk.pov 3840x2160 +A0.3 (one 1x1 run: %.2f s) | %.3f | %.3f | %.3f (desk's) | %.4f (desk's, per pixel) | - "
           "| %.3f (%.0f%%) | %.3f (%.0f%%) |" % (big_t1, big_prep, sum(big_tiles), d[6] * 1e3, big_gather, w16, 100 * e16,
                                                w64, 100 * e64))
out.append("")
out.append("Where the model's 2-rank figure falls short of the measured one, the rest is what it leaves "
           "out (two ranks and rank 0's scheduler sharing 2 cores, MPI's own threads); the 16- and 64-rank "
           "estimates are optimistic by at least that. Every rank repeats parse and preprocessing and MPI "
           "takes its time to start, which bounds the efficiency: with S to start, P of preparation, R of "
           "rendering and G to gather an image, N ranks take at least S + P + R/N + G(N-1)/N. A 1280x960 "
           "frame is far too small a job for 16 ranks; large frames, anti-aliasing and many lights are what "
           "this is for.")
open(os.path.join(here, "mpi.md"), "w").write("\n".join(out) + "\n")
print("\n".join(out))
PY
