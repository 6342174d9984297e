#!/bin/sh
# The fuzzers of tests/fuzz, built with clang's libFuzzer under
# AddressSanitizer and UBSan (float-cast-overflow included, no recovery)
# and run one after the other at the lowest priority: `scene` (the parser,
# and the engine on what parses), `ini` (INI files and KEY=VALUE command
# lines through the option parser: fuzz_ini.c), `stitch` (partial renders
# joined: fuzz_stitch.c), and `exr`, `png`, `ppm`, `tga`, `bmp`, `jpg`
# and `hdr` (the image readers of `hstrace compare` and of scenes' image
# maps).
#
# Each target starts from a seed corpus -- for `scene` hstrace's scenes,
# the scenes of tests/hostile and the snippets of tests/fuzz/seeds; for
# `ini` tests/fuzz/seeds/*.ini and tests/hostile/ini; for `stitch` and the
# readers files hstrace writes of a small scene (tests/fuzz/make-seeds.sh)
# and those of tests/hostile/stitch and tests/hostile/images -- and, for
# `scene`, `ini` and `stitch`, a dictionary (parser/tokens/keywords.def; the INI
# keys and switches of options_table.c; the EXR header attributes hstrace
# writes). An input that crashes, trips a sanitizer, leaks, runs over 10 s
# or takes over 2 GiB is a finding (resident memory: a single allocation
# may reserve up to 4.5 GiB, as the image readers do for the largest image
# they accept, 2^28 pixels of 16 bytes, calloc'd and touched only as
# pixels arrive: tests/hostile/images/exr-huge-reservation.exr reserves
# 2.3 GiB and peaks at 6 MiB); libFuzzer stops there and writes it to
# BUILDDIR/fuzz/findings-TARGET; it belongs in tests/hostile (a scene),
# tests/hostile/ini, tests/hostile/stitch or tests/hostile/images once
# fixed, where tests/fuzz-replay.sh replays it.
#
# usage: tests/fuzz/run.sh SRCDIR BUILDDIR [TARGET[:SECONDS]...]   (`make fuzz`)
# Without targets, all of them: scene ini stitch exr png ppm tga bmp jpg hdr.
# Environment: FUZZ_SECONDS per target without its own :SECONDS (default
# 60), FUZZ_CC (default clang), FUZZ_ARGS (more libFuzzer options, after
# the defaults, which they override: -timeout=20 -rss_limit_mb=4096),
# FUZZ_CONTINUE=1 (after a finding, start the target again from its
# corpus until its time is used, rather than stop it there).
# Prints one line per target as it ends, and a table of them all at the
# end: seconds run, libFuzzer runs, executions (the sum of each run's
# stat::number_of_executed_units), coverage (the last cov: and ft:, of the
# edges instrumented), corpus size, findings (the files in
# findings-TARGET, by kind) and the last run's status.
# Exit status: 0 no findings, 1 findings (or a fuzzer that ended in
# failure), 2 the fuzzers cannot be built (clang or its libFuzzer runtime
# missing: Debian packages clang and libclang-rt-dev).
set -u
src=$(cd "${1:?usage: run.sh SRCDIR BUILDDIR}" && pwd)
build=$(cd "${2:?usage: run.sh SRCDIR BUILDDIR}" && pwd)
shift 2
targets=${*:-scene ini stitch exr png ppm tga bmp jpg hdr}
seconds=${FUZZ_SECONDS:-60}
cc=${FUZZ_CC:-clang}
out=$build/fuzz
mkdir -p "$out/obj" || exit 2

command -v "$cc" >/dev/null 2>&1 || { echo "fuzz: $cc not found (Debian package clang)" >&2; exit 2; }
san="-fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all"
cflags="-std=c11 -g -O1 -fno-omit-frame-pointer -ffp-contract=off -D_POSIX_C_SOURCE=200809L"
cflags="$cflags -DHST_DATADIR=\"$src/data\" -I$build -I$src/parser -I$src/parser/description"
cflags="$cflags -I$src/parser/tokens -I$src/parser/expressions -I$src/parser/grammar"
# every room of the engine but the command line's (its main.c is hstrace)
for room in "$src"/src/*/; do
    case $room in */cli/) ;; *) cflags="$cflags -I${room%/}" ;; esac
done
pkgs="libpng libjpeg OpenEXR"
cflags="$cflags $(pkg-config --cflags $pkgs)"
libs="$(pkg-config --libs $pkgs) -lm -lpthread"
[ -f "$build/config.h" ] || { echo "fuzz: $build/config.h missing: configure first" >&2; exit 2; }
# Built with Embree (configure found it): its method is in the objects below.
grep -q '^#define HAVE_EMBREE 1' "$build/config.h" && libs="$libs -lembree3"

# Every C file of the parser and of those rooms (without OpenColorIO's C++),
# compiled once with the coverage instrumentation and the sanitizers; all of
# them again when any header has changed since (a struct that grew would
# otherwise be read with two layouts, and the fuzzer would see nothing).
headers=$(find "$src/parser" "$src/src" -name '*.h' -exec cksum {} + | sort | cksum)
if [ "$(cat "$out/obj/headers.sum" 2>/dev/null)" != "$headers" ]; then
    rm -f "$out"/obj/*.o
    printf '%s\n' "$headers" >"$out/obj/headers.sum"
fi
objects=""
for f in "$src"/parser/*/*.c "$src"/src/*/*.c; do
    case $f in "$src"/src/cli/*) continue ;; esac
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

# The INI dictionary: the keys the options' table knows, its switches and long
# options, the words of values, the entry point's own divisions and names.
{
    grep -o '\.ini = "[A-Za-z_]*"' "$src/src/options/options_table.c" | sed 's/^\.ini = "\(.*\)"$/"\1="/' | sort -u
    for w in +W +H +Q +WT +F +FN +FN16 +FE +FP +FT +FC +FB +FJ +FH +L +I +O +A +AM +R +J +UA +MV +D +P +C \
        +GA +GD +GW +GR +GS +KFI +KFF +KI +KF +KC +K +SF +EF +SR +ER +SC +EC -F -J -D -A -GA \
        on off true false yes no 0.5 1e300 -1 2147483648 "%%" "[" "]" "=" ";" "#" "," "'" \
        fuzz.ini inc.ini "fuzz.ini[" "inc.ini[" scene.pov; do
        printf '"%s"\n' "$w"
    done
    printf '"\\""\n' # a double quote
    printf '"\\x0a%%%%\\x0a"\n'
    grep -o '"--[a-z0-9-]*"' "$src/src/options/options_table.c" | sort -u
} >"$out/ini.dict"

# The stitch dictionary: the header hstrace writes (attributes, their
# types, the options line's words) and the entry point's division.
{
    for w in hstrace.options hstrace.sceneHash hstrace.scene hstrace.version hstrace.commandLine hstrace.volumes \
        hstrace.nth hstrace.time.render hstrace.stitch hstrace.stitch.parts string int float double box2i chlist \
        compression dataWindow displayWindow lineOrder pixelAspectRatio screenWindowCenter screenWindowWidth \
        chromaticities channels R G B A Z depth.L1 hst.L1 cost.total "--width " "--height " "--threads " \
        "--aov " "--exr-float" "+SR" "+ER" "+SC" "+EC" "+AM1" "+A0.1"; do
        printf '"%s"\n' "$w"
    done
    printf '"\\x0a%%%%part%%%%\\x0a"\n'
} >"$out/stitch.dict"

findings=0
failed=0
table=""
for word in $targets; do
    t=${word%%:*}
    secs=$seconds
    [ "$t" = "$word" ] || secs=${word#*:}
    case $secs in '' | *[!0-9]*) echo "fuzz: '$word': expected TARGET or TARGET:SECONDS" >&2; exit 2 ;; esac
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
        ;;
    ini)
        link ini "" "$src/tests/fuzz/fuzz_ini.c"
        for f in "$src"/tests/fuzz/seeds/*.ini "$src"/tests/hostile/ini/*.ini; do
            [ -f "$f" ] && cp "$f" "$corpus/seed-$(basename "$f")"
        done
        dict=-dict=$out/ini.dict
        ;;
    stitch)
        link stitch "" "$src/tests/fuzz/fuzz_stitch.c"
        [ -x "$build/hstrace" ] && sh "$src/tests/fuzz/make-seeds.sh" "$build/hstrace" "$src" stitch "$corpus"
        for f in "$src"/tests/hostile/stitch/*.exr; do
            [ -f "$f" ] && cp "$f" "$corpus/seed-$(basename "$f")"
        done
        dict=-dict=$out/stitch.dict
        ;;
    exr | png | ppm | tga | bmp | jpg | hdr)
        fmt=$(echo "$t" | tr a-z A-Z)
        link "$t" "-DFUZZ_$fmt" "$src/tests/fuzz/fuzz_image.c"
        [ -x "$build/hstrace" ] && sh "$src/tests/fuzz/make-seeds.sh" "$build/hstrace" "$src" "$t" "$corpus"
        for f in "$src"/tests/hostile/images/*."$t"; do
            [ -f "$f" ] && cp "$f" "$corpus/seed-$(basename "$f")"
        done
        ;;
    *) echo "fuzz: no target '$t' (scene, ini, stitch, exr, png, ppm, tga, bmp, jpg, hdr)" >&2; exit 2 ;;
    esac
    # libFuzzer stops at a finding; with FUZZ_CONTINUE=1 it starts again
    # from the corpus (the finding kept) until the target's time is used.
    began=$(date +%s)
    left=$secs
    execs=0
    runs=0
    status=0
    : >"$out/$t.log"
    while [ "$left" -gt 0 ]; do
        runs=$((runs + 1))
        # shellcheck disable=SC2086 # $dict and FUZZ_ARGS are words
        (cd "$out/findings-$t" && exec nice -n 19 "$out/fuzz-$t" "$corpus" $dict -max_total_time="$left" \
            -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=4608 -max_len=16384 -print_final_stats=1 \
            -artifact_prefix="$out/findings-$t/" ${FUZZ_ARGS:-}) >"$out/$t.run.log" 2>&1
        status=$?
        cat "$out/$t.run.log" >>"$out/$t.log"
        # the run's final statistics (printed at a finding too)
        n=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/$t.run.log" | tail -1)
        execs=$((execs + ${n:-0}))
        if [ "$status" -eq 0 ] || [ "${FUZZ_CONTINUE:-0}" != 1 ]; then
            break
        fi
        left=$((secs - ($(date +%s) - began)))
    done
    rm -f "$out/$t.run.log"
    elapsed=$(($(date +%s) - began))
    [ "$status" -eq 0 ] || failed=$((failed + 1))
    edges=$(grep -o 'cov: [0-9]*' "$out/$t.log" | tail -1 | cut -d' ' -f2)
    features=$(grep -o 'ft: [0-9]*' "$out/$t.log" | tail -1 | cut -d' ' -f2)
    total=$(sed -n 's/.*(\([0-9]*\) inline 8-bit counters).*/\1/p' "$out/$t.log" | head -1)
    units=$(find "$corpus" -type f | wc -l)
    # findings by kind: crash (a signal or a sanitizer's report), timeout, oom, leak
    kinds=""
    for k in crash timeout oom leak; do
        kinds="$kinds/$(find "$out/findings-$t" -type f -name "$k-*" | wc -l)"
    done
    found=$(find "$out/findings-$t" -type f | wc -l)
    findings=$((findings + found))
    echo "fuzz $t: $elapsed s in $runs run(s), $execs executions, cov ${edges:-?} ft ${features:-?} (of ${total:-?} edges), corpus $units, findings $found (crash/timeout/oom/leak ${kinds#/}; status $status; $out/$t.log)"
    table="$table$(printf '%-7s %8s %5s %12s %7s %7s %7s %9s %16s %6s' "$t" "$elapsed" "$runs" "$execs" "${edges:-?}" \
        "${features:-?}" "$units" "$found" "${kinds#/}" "$status")
"
done
echo
printf '%-7s %8s %5s %12s %7s %7s %7s %9s %16s %6s\n' target seconds runs executions cov ft corpus findings crash/tmo/oom/leak status
printf '%s' "$table"
[ "$findings" -eq 0 ] && [ "$failed" -eq 0 ]
