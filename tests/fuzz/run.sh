#!/bin/sh
# The fuzzers of tests/fuzz, built with clang's libFuzzer under
# AddressSanitizer and UBSan (float-cast-overflow included, no recovery)
# and run one after the other at the lowest priority: `scene` (the parser,
# and the engine on what parses), `exr`, `png` and `ppm` (the image readers
# of `hstrace compare`).
#
# Each target starts from a seed corpus -- for `scene` hstrace's scenes,
# the scenes of tests/hostile and the snippets of tests/fuzz/seeds; for the
# readers images hstrace writes of a small scene -- and a dictionary made
# from parser/keywords.def. An input that crashes, trips a sanitizer, leaks,
# runs over 10 s or takes over 2 GiB is a finding (resident memory: a single
# allocation may reserve up to 4.5 GiB, as the image readers do for the
# largest image they accept, 2^28 pixels of 16 bytes, calloc'd and touched
# only as pixels arrive: tests/hostile/images/exr-huge-reservation.exr
# reserves 2.3 GiB and peaks at 6 MiB); libFuzzer stops there and
# writes it to BUILDDIR/fuzz/findings-TARGET; it belongs in tests/hostile
# (a scene) or tests/test_image.c (an image) once fixed.
#
# usage: tests/fuzz/run.sh SRCDIR BUILDDIR [TARGET...]   (`make fuzz`)
# Environment: FUZZ_SECONDS per target (default 60), FUZZ_CC (default
# clang), FUZZ_ARGS (more libFuzzer options).
# Prints one line per target: seconds, executions, edges covered of those
# instrumented, corpus size, findings.
# Exit status: 0 no findings, 1 findings, 2 the fuzzers cannot be built
# (clang or its libFuzzer runtime missing: Debian packages clang and
# libclang-rt-dev).
set -u
src=$(cd "${1:?usage: run.sh SRCDIR BUILDDIR}" && pwd)
build=$(cd "${2:?usage: run.sh SRCDIR BUILDDIR}" && pwd)
shift 2
targets=${*:-scene exr png ppm tga bmp jpg hdr}
seconds=${FUZZ_SECONDS:-60}
cc=${FUZZ_CC:-clang}
out=$build/fuzz
mkdir -p "$out/obj" || exit 2

command -v "$cc" >/dev/null 2>&1 || { echo "fuzz: $cc not found (Debian package clang)" >&2; exit 2; }
san="-fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all"
cflags="-std=c11 -g -O1 -fno-omit-frame-pointer -ffp-contract=off -D_POSIX_C_SOURCE=200809L"
cflags="$cflags -DHST_DATADIR=\"$src/data\" -I$build -I$src/parser -I$src/parser/description"
cflags="$cflags -I$src/parser/tokens -I$src/parser/expressions -I$src/parser/grammar"
for room in "$src"/src/[0-7]-*; do cflags="$cflags -I$room"; done
pkgs="libpng libjpeg OpenEXR"
cflags="$cflags $(pkg-config --cflags $pkgs)"
libs="$(pkg-config --libs $pkgs) -lm -lpthread"
[ -f "$build/config.h" ] || { echo "fuzz: $build/config.h missing: configure first" >&2; exit 2; }
# Built with Embree (configure found it): its method is in the objects below.
grep -q '^#define HAVE_EMBREE 1' "$build/config.h" && libs="$libs -lembree3"

# Every C file of the parser and of rooms 0 to 7 (without OpenColorIO's C++),
# compiled once with the coverage instrumentation and the sanitizers; all of
# them again when any header has changed since (a struct that grew would
# otherwise be read with two layouts, and the fuzzer would see nothing).
headers=$(find "$src/parser" "$src/src" -name '*.h' -exec cksum {} + | sort | cksum)
if [ "$(cat "$out/obj/headers.sum" 2>/dev/null)" != "$headers" ]; then
    rm -f "$out"/obj/*.o
    printf '%s\n' "$headers" >"$out/obj/headers.sum"
fi
objects=""
for f in "$src"/parser/*/*.c "$src"/src/[0-7]-*/*.c; do
    o=$out/obj/$(echo "${f#"$src"/}" | tr / _ | sed 's/\.c$/.o/')
    if [ ! -f "$o" ] || [ "$f" -nt "$o" ] || [ "$src/parser/tokens/tokens.h" -nt "$o" ]; then
        # shellcheck disable=SC2086 # the flags are words
        nice -n 19 "$cc" $cflags $san -fsanitize=fuzzer-no-link -c "$f" -o "$o" || exit 2
    fi
    objects="$objects $o"
done
link() { # target, defines: the fuzzer
    # shellcheck disable=SC2086
    nice -n 19 "$cc" $cflags $san -fsanitize=fuzzer $2 "$3" $objects $libs -o "$out/fuzz-$1" || exit 2
}

# The dictionary: every reserved word, the directives, the punctuation.
{
    sed -n 's/^KW(\(.*\))$/"\1"/p' "$src/parser/tokens/keywords.def"
    for d in include declare local undef if ifdef ifndef elseif else end while for switch case range break \
        macro version debug warning error default fopen fclose read write; do
        echo "\"#$d\""
    done
    for p in '{' '}' '(' ')' '[' ']' '<' '>' ',' ';' '=' '+' '-' '*' '/' '.' '?' ':' '!' '&' '|' '<=' '>=' '!=' \
        '"' '//' '/*' '*/' '1e309' '1e308' '-1e10' '0.5' '1/0'; do
        printf '"%s"\n' "$(printf '%s' "$p" | sed 's/\\/\\\\/g; s/"/\\"/g')"
    done
} >"$out/scene.dict"

findings=0
for t in $targets; do
    corpus=$out/corpus-$t
    mkdir -p "$corpus" "$out/findings-$t"
    dict=""
    case $t in
    scene)
        link scene "-DFUZZ_INCLUDE_DIR=\"$src/data/include\"" "$src/tests/fuzz/fuzz_scene.c"
        for f in "$src"/scenes/*.pov "$src"/scenes/hard/*.pov "$src"/tests/hostile/*.pov "$src"/tests/fuzz/seeds/*.pov; do
            [ -f "$f" ] && cp "$f" "$corpus/seed-$(basename "$f")"
        done
        dict=-dict=$out/scene.dict
        max_len=16384
        ;;
    exr | png | ppm | tga | bmp | jpg | hdr)
        fmt=$(echo "$t" | tr a-z A-Z)
        link "$t" "-DFUZZ_$fmt" "$src/tests/fuzz/fuzz_image.c"
        if [ -x "$build/hstrace" ]; then
            i=0
            for opts in "--width 5 --height 3" "--width 7 --height 4 --exr-float" "--width 3 --height 9 --png16" \
                "--width 6 --height 5 --aov all" "--width 9 --height 2 +UA" "--width 40 --height 3 +UA +FC"; do
                i=$((i + 1))
                # shellcheck disable=SC2086
                "$build/hstrace" "$src/tests/fuzz/seeds/small.pov" $opts -o "$corpus/seed-$i.$t" >/dev/null 2>&1 || true
            done
        fi
        max_len=16384
        ;;
    *) echo "fuzz: no target '$t' (scene, exr, png, ppm, tga, bmp, jpg, hdr)" >&2; exit 2 ;;
    esac
    (cd "$out/findings-$t" && exec nice -n 19 "$out/fuzz-$t" "$corpus" $dict -max_total_time="$seconds" \
        -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=4608 -max_len=$max_len -print_final_stats=1 -artifact_prefix="$out/findings-$t/" \
        ${FUZZ_ARGS:-}) >"$out/$t.log" 2>&1
    status=$?
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/$t.log" | tail -1)
    edges=$(grep -o 'cov: [0-9]*' "$out/$t.log" | tail -1 | cut -d' ' -f2)
    total=$(sed -n 's/.*(\([0-9]*\) inline 8-bit counters).*/\1/p' "$out/$t.log" | head -1)
    units=$(find "$corpus" -type f | wc -l)
    found=$(find "$out/findings-$t" -type f | wc -l)
    findings=$((findings + found))
    echo "fuzz $t: ${seconds} s, ${execs:-?} executions, ${edges:-?} of ${total:-?} edges, corpus $units, findings $found (status $status; $out/$t.log)"
done
[ "$findings" -eq 0 ]
