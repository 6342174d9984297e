#!/bin/sh
# The seeds hstrace writes for the fuzz entry points that read its files,
# made from tests/fuzz/seeds/small.pov: for an image reader (exr, png, ppm,
# tga, bmp, jpg, hdr) six renders in that format at a few sizes and with
# a few options; for `stitch` partial renders (EXR) as the stitch entry
# point takes them: one part alone, or two divided by a line "%%part%%"
# (tests/fuzz/fuzz_stitch.c) -- parts that stitch, parts that overlap,
# parts of other channels and thread counts. Used by tests/fuzz/run.sh
# (`make fuzz`) and tests/fuzz-replay.sh (`make check`).
#
# usage: tests/fuzz/make-seeds.sh HSTRACE SRCDIR TARGET DIR
# Writes DIR/seed-*; prints nothing. A render that fails (an option set a
# format has not, such as --aov for PNG) leaves no seed: the caller counts
# what it got. Exit status 0, or 1 for a bad TARGET.
set -u
hstrace=${1:?usage: make-seeds.sh HSTRACE SRCDIR TARGET DIR}
src=${2:?usage: make-seeds.sh HSTRACE SRCDIR TARGET DIR}
target=${3:?usage: make-seeds.sh HSTRACE SRCDIR TARGET DIR}
dir=${4:?usage: make-seeds.sh HSTRACE SRCDIR TARGET DIR}
scene=$src/tests/fuzz/seeds/small.pov

# render NAME OPTION...: small.pov into DIR/NAME
render() {
    name=$1
    shift
    "$hstrace" "$scene" "$@" -o "$dir/$name" >/dev/null 2>&1 || rm -f "$dir/$name"
}

# join SEED PART...: the parts, divided by "\n%%part%%\n", into DIR/SEED
join() {
    seed=$1
    shift
    for part in "$@"; do [ -f "$dir/$part" ] || return; done
    first=1
    for part in "$@"; do
        [ "$first" = 1 ] || printf '\n%%%%part%%%%\n'
        cat "$dir/$part"
        first=0
    done >"$dir/$seed"
}

case $target in
stitch)
    size="--width 8 --height 6"
    # shellcheck disable=SC2086 # the options are words
    {
        render seed-whole.exr $size
        render part-top.exr $size +SR1 +ER3 --threads 1
        render part-bottom.exr $size +SR4 +ER6 --threads 2
        render part-rows.exr $size +SR2 +ER6
        render part-left.exr $size +SC1 +EC4 --aov all
        render part-right.exr $size +SC0.5 +EC1 --aov all
        render part-right-float.exr $size +SC5 +EC8 --aov all --exr-float
        render part-corner.exr $size +SR1 +ER3 +SC1 +EC4 --aov depth
        render part-aa.exr $size +SR1 +ER3 +A0.1 +AM1
    }
    join seed-rows.exr part-top.exr part-bottom.exr
    join seed-overlap.exr part-top.exr part-rows.exr
    join seed-columns.exr part-left.exr part-right.exr
    join seed-float.exr part-left.exr part-right-float.exr
    join seed-gap.exr part-corner.exr part-bottom.exr
    join seed-twice.exr part-top.exr part-top.exr
    join seed-aa.exr part-aa.exr part-bottom.exr
    for f in "$dir"/part-*; do [ -f "$f" ] && mv "$f" "$dir/seed-${f##*/}"; done
    ;;
exr | png | ppm | tga | bmp | jpg | hdr)
    i=0
    for opts in "--width 5 --height 3" "--width 7 --height 4 --exr-float" "--width 3 --height 9 --png16" \
        "--width 6 --height 5 --aov all" "--width 9 --height 2 +UA" "--width 40 --height 3 +UA +FC"; do
        i=$((i + 1))
        # shellcheck disable=SC2086 # the options are words
        render "seed-$i.$target" $opts
    done
    ;;
*)
    echo "make-seeds.sh: no seeds for '$target' (stitch, exr, png, ppm, tga, bmp, jpg, hdr)" >&2
    exit 1
    ;;
esac
exit 0
