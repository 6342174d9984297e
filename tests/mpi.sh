#!/bin/sh
# A render spread over Open MPI's ranks (mpirun -n N hstrace ...), in TAP,
# on this machine only (shared memory and loopback): the image and every
# analysis channel bit for bit those of one process (tests/exr_channels
# hashes each channel with OpenEXR alone), for 1 to 4 ranks of 1 and 2
# threads, on the paper's four scenes and one with reflection and
# refraction, for every shadow method, with anti-aliasing, for a partial
# render; an animation of 5 frames on 2 ranks (spread by frames) and of 2
# frames on 3 (by tiles) frame by frame; the statistics of all ranks adding
# up; a scene error said once with its status; a rank that dies ends the
# job with its status and no image. Skipped without Open MPI in the build
# or without mpirun.
#
# Environment: top_builddir (default .), MPIRUN (default mpirun).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
channels="$builddir/tests/exr_channels"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstmpi.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
mpirun=$(command -v "${MPIRUN:-mpirun}" 2>/dev/null || true)
if ! "$hstrace" --version | grep -q "Open MPI"; then
    skip "renders across ranks" "hstrace built without Open MPI (configure found no libopenmpi-dev)"
    tap_end
    exit 0
fi
if [ -z "$mpirun" ]; then
    skip "renders across ranks" "mpirun not installed (Debian package openmpi-bin)"
    tap_end
    exit 0
fi
# As root (CI), on one machine with more ranks than cores, shared memory only.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMPI_MCA_btl=self,vader OMPI_MCA_oob_tcp_if_include=lo
# Under the sanitizer build, LeakSanitizer finds what Open MPI's own
# components leave allocated at MPI_Finalize (in modules it has unloaded by
# then, so no suppression can name them): leak detection is off for the
# ranks, AddressSanitizer's and UBSan's other checks stay on. The same code
# run as one process is leak-checked by every other test.
mpi_env="ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
mpi() { # RANKS ARGS...: mpirun -n RANKS hstrace ARGS in $work; $status, $work/err
    n=$1
    shift
    (cd "$work" && env "$mpi_env" "$mpirun" -n "$n" "$hstrace" "$@") >"$work/out" 2>"$work/err"
    status=$?
}
run() { (cd "$work" && "$hstrace" "$@") >"$work/out" 2>"$work/err"; status=$?; }
# same A B: every channel of two EXRs the same bits. same_rgba A B: the
# colour and alpha channels alone.
same() {
    "$channels" "$1" >"$work/a.ch" && "$channels" "$2" >"$work/b.ch" || return 1
    cmp -s "$work/a.ch" "$work/b.ch" || { diff "$work/a.ch" "$work/b.ch" | head -n 8; return 1; }
}
same_rgba() {
    "$channels" "$1" | grep -E '^[RGBA] ' >"$work/a.ch" && "$channels" "$2" | grep -E '^[RGBA] ' >"$work/b.ch" || return 1
    if [ "$(wc -l <"$work/a.ch")" != 4 ] || ! cmp -s "$work/a.ch" "$work/b.ch"; then
        diff "$work/a.ch" "$work/b.ch"
        return 1
    fi
}
# hst's N_th and volume plan are measured (timings) afresh by every run, so
# two runs, of one process or many, may hand decisions to other sub-schemes
# (the same decisions, other analysis channels). The runs compared channel
# for channel fix them: every light's volumes, N_th 2.
hst="--shadows hst --volumes always --nth 2"
for s in desk glasses stars cards; do cp "$srcdir/scenes/$s.pov" "$work/"; done
cat >"$work/mirrors.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -3> color rgb 1 }
light_source { <-4, 3, -2> color rgb 0.5 }
polygon { 4, <-2,0,-1>, <2,0,-1>, <2,0,3>, <-2,0,3> pigment { color rgb <0.8,0.7,0.6> } }
triangle { <-1.6,0.1,0>, <-0.4,0.1,0>, <-1,1.4,0> pigment { color rgbt <1,0.2,0.2,0.6> } }
triangle { <1,0.1,0.5>, <2,0.1,0.5>, <1.5,1.5,0.5> pigment { color rgb 0.5 } finish { reflection 0.5 } }
triangle { <-0.3,0.1,-0.5>, <0.9,0.1,-0.5>, <0.3,1.6,-0.5> pigment { color rgbf <1,1,1,0.9> } interior { ior 1.3 } }
EOF
W=96 H=72

# --- 1 to 4 ranks, 1 and 2 threads: the single process's image -----------------
for s in desk glasses stars cards mirrors; do
    # shellcheck disable=SC2086 # $hst is several words
    run "$s.pov" +W$W +H$H --aov all $hst --threads 1 -o "$s-one.exr"
    check "$s: the single-process render" exited 0
    for n in 1 2 3 4; do
        for t in 1 2; do
            # shellcheck disable=SC2086
            mpi $n "$s.pov" +W$W +H$H --aov all $hst --threads $t -o "$s-$n-$t.exr"
            check "$s, $n ranks x $t threads: every channel as one process's" same "$work/$s-one.exr" "$work/$s-$n-$t.exr"
        done
    done
    run "$s.pov" +W$W +H$H -o "$s-default-one.exr"
    mpi 3 "$s.pov" +W$W +H$H -o "$s-default-3.exr"
    check "$s with the default options on 3 ranks: the single process's colours and alpha" \
        same_rgba "$work/$s-default-one.exr" "$work/$s-default-3.exr"
done

# --- every shadow method, anti-aliasing, a partial render -------------------------
for method in conventional cache volume hst-always none embree; do
    case $method in
    hst-always) set -- --shadows hst --volumes always --nth 2 ;;
    volume) set -- --shadows volume --nth 2 ;;
    embree) "$hstrace" --version | grep -q "; Embree" || { skip "embree on 3 ranks" "built without Embree"; continue; }
        set -- --shadows embree ;;
    *) set -- --shadows "$method" ;;
    esac
    run desk.pov +W$W +H$H --aov all "$@" -o "m-$method-one.exr"
    mpi 3 desk.pov +W$W +H$H --aov all --threads 2 "$@" -o "m-$method-3.exr"
    check "desk --shadows $method on 3 ranks: every channel as one process's" same "$work/m-$method-one.exr" "$work/m-$method-3.exr"
done
run desk.pov +W$W +H$H +A0.3 -o aa-one.exr
mpi 3 desk.pov +W$W +H$H +A0.3 -o aa-3.exr
check "desk +A0.3 on 3 ranks: the single process's image" same "$work/aa-one.exr" "$work/aa-3.exr"
run mirrors.pov +W$W +H$H +AM2 +A0.1 +R2 -o aa2-one.exr
mpi 4 mirrors.pov +W$W +H$H +AM2 +A0.1 +R2 -o aa2-4.exr
check "mirrors +AM2 +A0.1 on 4 ranks: the single process's image" same "$work/aa2-one.exr" "$work/aa2-4.exr"
run desk.pov +W$W +H$H +SR10 +ER50 +SC5 +EC70 --aov all -o part-one.exr
mpi 2 desk.pov +W$W +H$H +SR10 +ER50 +SC5 +EC70 --aov all -o part-2.exr
check "a partial render (+SR10 +ER50 +SC5 +EC70) on 2 ranks: as one process's" same "$work/part-one.exr" "$work/part-2.exr"
run desk.pov +W$W +H$H -o png-one.png
mpi 3 desk.pov +W$W +H$H -o png-3.png
check "a PNG written by rank 0 of 3: one process's, byte for byte" cmp "$work/png-one.png" "$work/png-3.png"

# --- animations ------------------------------------------------------------------
cat >"$work/spin.pov" <<'EOF'
#version 3.7;
camera { location <0, 1, -4> look_at 0 }
light_source { <3, 5, -3> color rgb 1 }
polygon { 4, <-2,-1,-1>, <2,-1,-1>, <2,-1,3>, <-2,-1,3> pigment { color rgb 0.8 } }
triangle { <-1,-0.5,0>, <1,-0.5,0>, <0,1,0> rotate y*clock*90 pigment { color rgb <1,0.3,0.2> } }
EOF
run spin.pov +W48 +H36 +KFI1 +KFF5 -o one.exr
mpi 2 spin.pov +W48 +H36 +KFI1 +KFF5 -o two.exr
check "5 frames on 2 ranks: the run ends well" exited 0
for f in 1 2 3 4 5; do
    check "5 frames on 2 ranks (by frames): frame $f as one process's" same "$work/one$f.exr" "$work/two$f.exr"
done
run spin.pov +W48 +H36 +KFI1 +KFF2 -o pair.exr
mpi 3 spin.pov +W48 +H36 +KFI1 +KFF2 -o trio.exr
for f in 1 2; do
    check "2 frames on 3 ranks (by tiles): frame $f as one process's" same "$work/pair$f.exr" "$work/trio$f.exr"
done

# --- statistics ------------------------------------------------------------------
mpi 3 desk.pov +W$W +H$H --threads 1 --stats-json stats.json -o st.png
sum_pixels() { awk -F'"pixels": ' '/"rank":/ { split($2, a, ","); n += a[1] } END { print n }' "$work/stats.json"; }
check "--stats-json on 3 ranks: 3 ranks, each one's pixels adding up to $((W * H))" \
    test "$(json_value ranks "$work/stats.json") $(grep -c '"rank":' "$work/stats.json") $(sum_pixels)" = "3 3 $((W * H))"

# --- faults ----------------------------------------------------------------------
printf 'camera { location <0,0,-3> look_at 0 }\ntriangle { <0,0,0>, <1,0,0> }\n' >"$work/broken.pov"
mpi 3 broken.pov +W8 +H6 -o broken.png
check "a scene error on 3 ranks: status 2, said once, no image" \
    test "$status $(grep -c '^broken.pov:2:' "$work/err") $([ -e "$work/broken.png" ] && echo image || echo none)" = "2 1 none"
# shellcheck disable=SC2016 # the rank's own shell expands its rank
(cd "$work" && env "$mpi_env" "$mpirun" -n 3 sh -c '[ "$OMPI_COMM_WORLD_RANK" = 2 ] && exit 7; exec "$0" desk.pov +W64 +H48 -o died.png' \
    "$hstrace") >"$work/out" 2>"$work/err"
status=$?
check "a rank that dies: the job ends with its status (7), mpirun says so, and no image" \
    test "$status $(grep -c 'non-zero' "$work/err" | sed 's/^[1-9][0-9]*$/said/') $([ -e "$work/died.png" ] && echo image || echo none)" = "7 said none"
tap_end
