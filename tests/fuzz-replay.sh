#!/bin/sh
# The fuzz entry points of tests/fuzz, replayed without libFuzzer (TAP):
# tests/fuzz_replay_scene hands the seed corpus make fuzz starts from (the
# project's scenes, the hard cases, tests/hostile and tests/fuzz/seeds) to
# the scene entry point one input at a time, which parses each and renders
# what parses at 4x3 pixels with hybrid shadow testing; the image readers'
# entry points (EXR, PNG, PPM, Targa, BMP, JPEG, HDR) get images hstrace
# writes of a small scene (tests/fuzz/make-seeds.sh) and the images fuzzing
# found (tests/hostile/images); the INI entry point the INI files and
# command lines of tests/fuzz/seeds/*.ini and those fuzzing found
# (tests/hostile/ini); the stitch entry point partial renders of the small
# scene, alone and in pairs (make-seeds.sh), and those fuzzing found
# (tests/hostile/stitch). Under the sanitizer build a
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
    mkdir "$work/$fmt" || bail "cannot make a temporary folder"
    sh "$srcdir/tests/fuzz/make-seeds.sh" "$build/hstrace" "$srcdir" "$fmt" "$work/$fmt"
    set --
    for f in "$work/$fmt"/seed-* "$srcdir"/tests/hostile/images/*."$fmt"; do
        [ -f "$f" ] && set -- "$@" "$f"
    done
    check "the $fmt reader's entry point reads the $# seed and hostile images" replayed "fuzz_replay_$fmt" "$@"
done

set --
for f in "$srcdir"/tests/fuzz/seeds/*.ini "$srcdir"/tests/hostile/ini/*.ini; do
    [ -f "$f" ] && set -- "$@" "$f"
done
check "the INI entry point reads the $# seed and hostile INI files and command lines" replayed fuzz_replay_ini "$@"

mkdir "$work/stitch" || bail "cannot make a temporary folder"
sh "$srcdir/tests/fuzz/make-seeds.sh" "$build/hstrace" "$srcdir" stitch "$work/stitch"
set --
for f in "$work/stitch"/seed-* "$srcdir"/tests/hostile/stitch/*.exr; do
    [ -f "$f" ] && set -- "$@" "$f"
done
check "the stitch entry point stitches the $# seed and hostile partial renders" replayed fuzz_replay_stitch "$@"
tap_end
