#!/bin/sh
# The fuzz entry points of tests/fuzz, replayed without libFuzzer (TAP):
# tests/fuzz_replay_scene hands the seed corpus make fuzz starts from (the
# project's scenes, the hard cases, tests/hostile and tests/fuzz/seeds) to
# the scene entry point one input at a time, which parses each and renders
# what parses at 4x3 pixels with hybrid shadow testing; the image readers'
# entry points (EXR, PNG, PPM, Targa, BMP, JPEG, HDR) get images hstrace writes of a small scene and the
# images fuzzing found (tests/hostile/images). Under the sanitizer build a
# report ends the program (no recovery): the check fails. So the entry
# points keep building with the tree, and every finding kept in the tree
# runs in both builds.
# Environment: top_srcdir, top_builddir (default .).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
build=$(cd "$builddir" && pwd)
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstreplay.XXXXXX") || bail "cannot make a temporary folder"
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM

# replayed PROGRAM FILE...: every file went through and was reported.
replayed() {
    program=$1
    shift
    "$build/tests/$program" "$@" >"$work/out" 2>&1 || { cat "$work/out"; return 1; }
    n=$(grep -c '^ok ' "$work/out")
    [ "$n" -eq $# ] || { echo "$n of $# inputs replayed"; cat "$work/out"; return 1; }
}

set --
for f in "$srcdir"/scenes/*.pov "$srcdir"/scenes/hard/*.pov "$srcdir"/tests/hostile/*.pov "$srcdir"/tests/fuzz/seeds/*.pov; do
    [ -f "$f" ] && set -- "$@" "$f"
done
check "the scene entry point parses and renders the $# seed scenes" replayed fuzz_replay_scene "$@"

for fmt in exr png ppm tga bmp jpg hdr; do
    set --
    i=0
    for opts in "--width 5 --height 3" "--width 7 --height 4 --exr-float" "--width 3 --height 9 --png16" \
        "--width 6 --height 5 --aov all" "--width 9 --height 2 +UA" "--width 40 --height 3 +UA +FC"; do
        i=$((i + 1))
        # shellcheck disable=SC2086 # the options are words
        "$build/hstrace" "$srcdir/tests/fuzz/seeds/small.pov" $opts -o "$work/seed-$i.$fmt" >/dev/null 2>&1 &&
            set -- "$@" "$work/seed-$i.$fmt"
    done
    for f in "$srcdir"/tests/hostile/images/*."$fmt"; do
        [ -f "$f" ] && set -- "$@" "$f"
    done
    check "the $fmt reader's entry point reads the $# seed and hostile images" replayed "fuzz_replay_$fmt" "$@"
done
tap_end
