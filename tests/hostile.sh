#!/bin/sh
# Hostile input through the hstrace command, in TAP: every scene under
# tests/hostile/ (the inputs of issue 22 and what fuzzing found) ends within
# its time with the status and the message its header promises, and leaves
# no image behind when it fails; scenes whose numbers run to the ends of
# the doubles render.
#
# Then paths that are no regular files -- a FIFO (which would wait for a
# writer for ever), a directory, a device (/dev/zero, read for 4 GB
# before) -- as the scene, an #include and an #fopen: refused at once, with
# status 3 and the position of the name; as an image_map's picture (a
# FIFO hung the parse before), a text object's font (so did a FIFO) and
# to `hstrace compare`: refused at once,
# status 2; the images fuzzing found and the damaged ones of issue 20
# (tests/hostile/images; make-bad-images.py there writes the latter),
# which `hstrace compare` refuses with a message; and the budgets'
# options given something that is no budget.
#
# A scene's header says what it must do, in comment lines:
#   // expect: status N
#   // expect: error FILE:LINE:COLUMN: MESSAGE   (the first error line)
#   // expect: option ARGS                  (more hstrace arguments)
# Environment: top_srcdir, top_builddir (default .).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace=$(cd "$builddir" && pwd)/hstrace
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/hsthostile.XXXXXX") || bail "cannot make a temporary folder"
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
# The scenes run in a copy: some write files next to themselves.
cp -R "$srcdir/tests/hostile" "$work/scenes" || bail "cannot copy the scenes"
scenes=$work/scenes
[ -x "$hstrace" ] || bail "$hstrace is not built"
# says PATTERN: some line of hstrace's messages matches PATTERN.
says() { grep -q -- "$1" "$work/err"; }
# Sanitizer builds run several times slower: every scene must end within
# 10 s there (the issue's bound is 5 s; plain builds take well under 1 s).
limit=10

for f in "$scenes"/*.pov; do
    b=${f##*/}
    want_status=$(sed -n 's|^// expect: status \([0-9]*\)$|\1|p' "$f")
    want_error=$(sed -n 's|^// expect: error \(.*\)$|\1|p' "$f")
    options=$(sed -n 's|^// expect: option \(.*\)$|\1|p' "$f")
    rm -f "$work/out.png"
    # shellcheck disable=SC2086 # the options are words
    (cd "$scenes" && exec timeout -s KILL $limit "$hstrace" "$b" --width 16 --height 12 --threads 1 \
        -o "$work/out.png" $options) >/dev/null 2>"$work/err"
    status=$?
    got=$(grep -v -E ': (warning|note): ' "$work/err" | grep -E '^[^ ]*:[0-9]+:[0-9]+: ' | head -1)
    if [ "$status" -eq 137 ]; then
        not_ok "$b: ends within $limit s"
        continue
    fi
    check_status "$b: status $want_status ($(head -1 "$work/err"))" "$status" "$want_status"
    if [ -n "$want_error" ]; then
        check "$b: $want_error" same_count "$got" "$want_error"
    fi
    if [ "$want_status" = 0 ]; then
        check "$b: renders an image" [ -s "$work/out.png" ]
    else
        check "$b: no image left behind" [ ! -e "$work/out.png" ]
    fi
done

run() { # hstrace on scene $1 in $work/files; sets status, keeps stderr in $work/err
    rm -f "$work/out.png"
    (cd "$work/files" && exec timeout -s KILL $limit "$hstrace" "$1" --width 16 --height 12 --threads 1 \
        -o "$work/out.png") >/dev/null 2>"$work/err"
    status=$?
}
mkdir "$work/files" "$work/files/folder.pov"
if mkfifo "$work/files/fifo.pov" 2>/dev/null; then fifo=fifo.pov; else fifo=""; fi
for target in $fifo folder.pov /dev/zero; do
    case $target in
    fifo.pov) kind="a FIFO" ;;
    folder.pov) kind="a directory" ;;
    *) kind="a device" ;;
    esac
    run "$target"
    check_status "$target as the scene: status 3 within $limit s" "$status" 3
    check "$target as the scene: '$target' is $kind ($(head -1 "$work/err"))" \
        says "^$target: '$target' is $kind, not a file to read\$"
    printf '#declare A = 1;\n#include "%s"\n' "$target" >"$work/files/inc.pov"
    run inc.pov
    check_status "#include \"$target\": status 3" "$status" 3
    check "#include \"$target\": at the name ($(head -1 "$work/err"))" \
        says "^inc.pov:2:10: '$target' is $kind, not a file to read\$"
    printf '#fopen F "%s" read\n' "$target" >"$work/files/fopen.pov"
    run fopen.pov
    check_status "#fopen F \"$target\" read: status 3" "$status" 3
    check "#fopen F \"$target\" read: at the name ($(head -1 "$work/err"))" \
        says "^fopen.pov:1:10: '$target' is $kind, not a file to read\$"
    case $target in
    fifo.pov) why="a FIFO, not a regular file" ;;
    folder.pov) why="Is a directory" ;;
    *) why="a device, not a regular file" ;;
    esac
    printf 'triangle { 0, x, y pigment { image_map { png "%s" } } }\n' "$target" >"$work/files/picture.pov"
    run picture.pov
    check_status "image_map { png \"$target\" }: status 2 within $limit s" "$status" 2
    check "image_map { png \"$target\" }: at the name ($(head -1 "$work/err"))" \
        says "^picture.pov:1:46: image_map: cannot read '[./]*$target': $why\$"
    # FreeType's own open of a FIFO waited for a writer for ever.
    printf 'text { ttf "%s" "a" 0.1, 0 }\n' "$target" >"$work/files/font.pov"
    run font.pov
    if says "built without FreeType"; then
        skip "text { ttf \"$target\" }" "hstrace built without FreeType"
    else
        check_status "text { ttf \"$target\" }: status 2 within $limit s" "$status" 2
        check "text { ttf \"$target\" }: at the name ($(head -1 "$work/err"))" \
            says "^font.pov:1:12: cannot read the font file '[./]*$target': $why\$"
    fi
    (cd "$work/files" && exec timeout -s KILL $limit "$hstrace" compare "$target" "$target") >/dev/null 2>"$work/err"
    status=$?
    check_status "hstrace compare $target $target: status 2 within $limit s" "$status" 2
    check "hstrace compare $target $target: says so ($(head -1 "$work/err"))" says "^hstrace compare: $target: $why\$"
    printf '#fopen F "%s" write\n#write (F, "x")\n' "$target" >"$work/files/fwrite.pov"
    run fwrite.pov
    check_status "#fopen F \"$target\" write: status 3" "$status" 3
    check "#fopen F \"$target\" write: at the name ($(head -1 "$work/err"))" \
        says "^fwrite.pov:1:10: cannot open '$target' for writing: "
done

# A regular file whose size says 0 (a /proc file) is read as it grows.
if [ -r /proc/self/status ]; then
    printf '#fopen F "/proc/self/status" read\n#read (F, S)\n' >"$work/files/proc.pov"
    run proc.pov
    check_status "a /proc file, of size 0, is read: status 2" "$status" 2
    check "a /proc file: its data is no scene data ($(head -1 "$work/err"))" \
        says "^/proc/self/status:1:1: expected a float, a vector or a string"
fi

# Images the fuzzers of tests/fuzz found hostile, and the damaged ones of
# issue 20 (truncated in their data, declaring 0x0 pixels or more than the
# readers take: 65536 a side, 2^28 in all, refused from the header before
# anything is allocated; an interlaced PNG, reserved whole, whose file
# cannot inflate to its size), all in tests/hostile/images, and a missing file,
# read by `hstrace compare`: an error with a message, status 2, quickly,
# and no memory used beyond what the file holds (the pixels of an image
# are reserved up front, calloc'd, and touched only as its data arrives:
# exr-huge-reservation.exr reserves 2.3 GiB and peaks at 6 MiB). With a
# memory budget that lets every size a reader takes through: what is tested
# here is the readers' own defence, not the budget's (below).
while IFS='|' read -r image message; do
    "$hstrace" compare "$scenes/images/$image" "$scenes/images/$image" --max-memory 1T >/dev/null 2>"$work/err"
    status=$?
    check_status "images/$image: status 2" "$status" 2
    check "images/$image: '$message' ($(head -1 "$work/err"))" says "$message"
done <<'IMAGES'
ppm-huge-header.ppm|PPM pixel data is truncated (2677x55595 pixels need 446483445 bytes, 1 are left)
png-huge-truncated.png|Not enough image data
exr-huge-window.exr|truncated EXR file: its 2051x65536 data window needs 4096 chunks, the file holds 460 bytes
exr-huge-reservation.exr|Invalid size 50331649
jpg-arithmetic-bomb.jpg|JPEG data of 238 bytes is too small for 1801x44267 pixels
png-truncated.png|PNG data is truncated (the file ends early)
png-0x0.png|unsupported PNG size 0x0
png-100000x100000.png|unsupported PNG size 100000x100000
png-interlaced-16384x16384.png|interlaced PNG data of [0-9]* bytes is too small for 16384x16384 pixels
jpg-truncated.jpg|Premature end of JPEG file
jpg-0x0.jpg|Empty JPEG image (DNL not supported)
jpg-65535x65535.jpg|Maximum supported image dimension is 65500 pixels
jpg-65500x65500.jpg|unsupported JPEG size 65500x65500
no-such-image.png|No such file or directory
IMAGES

# Switches and INI keys of issue 39, whose numbers name no row, column or
# frame (a float-to-int overflow, then a write out of bounds or the wrong
# frames rendered with status 0): bad usage, status 1, at the INI line when
# an INI file says it.
# opt_refused DESCRIPTION MESSAGE ARG...: status 1 within the limit, MESSAGE
# (a pattern) the first line, no image.
opt_refused() {
    desc=$1 message=$2
    shift 2
    rm -f "$work/out.png"
    (cd "$work/files" && exec timeout -s KILL $limit "$hstrace" ok.pov --width 16 --height 12 --threads 1 \
        -o "$work/out.png" "$@") >/dev/null 2>"$work/err"
    status=$?
    check_status "$desc: status 1 within $limit s" "$status" 1
    check "$desc: '$message' ($(head -1 "$work/err"))" says "$message"
    check "$desc: no image" [ ! -e "$work/out.png" ]
}
printf 'triangle { 0, x, y }\n' >"$work/files/ok.pov"
for sw in +SR1e300 +SR2147483649 +SC3e9 +ER1e300 +EC-1; do
    opt_refused "$sw" "^hstrace: '$sw': expected a" "$sw"
done
opt_refused "+SR13 of 12 rows" "^hstrace: the render area's start row (13) is not within the image's 12\$" +SR13
printf 'Start_Row=1e300\n' >"$work/files/start-row.ini"
opt_refused "Start_Row=1e300 in an INI file" "^start-row.ini:1:1: '+SR1e300': expected a row or column" start-row.ini
for sw in +SF1e300 +EF3e9; do
    opt_refused "+KFI1 +KFF3 $sw" "^hstrace: '$sw': expected a frame number" +KFI1 +KFF3 "$sw"
done
printf 'Initial_Frame=1\nFinal_Frame=3\nSubset_End_Frame=3e9\n' >"$work/files/subset.ini"
opt_refused "Subset_End_Frame=3e9 in an INI file" "^subset.ini:3:1: '+EF3e9': expected a frame number" subset.ini

# INI files that include the next one ten times, sixteen deep (10^16 reads;
# only depth was bounded): refused once 1000 files have been read, at the
# line that would read one more.
i=0
while [ $i -lt 16 ]; do
    n=$((i + 1))
    for k in 1 2 3 4 5 6 7 8 9 10; do echo "fan$n.ini ; $k"; done >"$work/files/fan$i.ini"
    i=$n
done
echo "Width=8" >"$work/files/fan16.ini"
opt_refused "INI files including each other 10 times, 16 deep" \
    "^fan[0-9]*.ini:[0-9]*:1: 'fan[0-9]*.ini': INI files read 1000 times, .* in all: more than the 1000 files" fan0.ini

# A FIFO as an INI file, as an INI file's include and Include_Ini, and as
# the colour configuration (each waited for a writer for ever): refused at
# once, status 3.
if [ -n "$fifo" ]; then
    mkfifo "$work/files/fifo.ini"
    printf 'fifo.ini\n' >"$work/files/names-fifo.ini"
    printf 'Width=8\nInclude_Ini=fifo.ini\n' >"$work/files/includes-fifo.ini"
    for how in "fifo.ini|^hstrace: cannot read INI file 'fifo.ini': not a regular file\$" \
        "names-fifo.ini|^names-fifo.ini:1:1: cannot read INI file 'fifo.ini': not a regular file\$" \
        "includes-fifo.ini|^includes-fifo.ini:2:1: cannot read INI file 'fifo.ini': not a regular file\$" \
        "--ocio-config fifo.ini|^hstrace: cannot read colour configuration 'fifo.ini' (from --ocio-config): not a regular file\$"; do
        args=${how%%|*} message=${how#*|}
        rm -f "$work/out.png"
        # shellcheck disable=SC2086 # the arguments are words
        (cd "$work/files" && exec timeout -s KILL $limit "$hstrace" ok.pov --width 16 --height 12 --threads 1 \
            -o "$work/out.png" $args) >/dev/null 2>"$work/err"
        status=$?
        check_status "$args (a FIFO): status 3 within $limit s" "$status" 3
        check "$args (a FIFO): says so ($(head -1 "$work/err"))" says "$message"
    done
fi

# An include not found names each folder it searched once ("." was named
# twice: the current folder and the scene's).
printf '#include "no-such.inc"\n' >"$work/files/missing-inc.pov"
run missing-inc.pov
check "a missing include: each folder searched named once ($(head -1 "$work/err"))" \
    says "^missing-inc.pov:1:10: cannot open include file 'no-such.inc' (searched: \., [^.]"

# Pictures held to the memory budget from their headers, before a pixel is
# decoded (issue 39): a PNG of 260 KB declaring 16384x16384 pixels took
# 40 s and 8.2 GB as an image_map, and with --max-memory 256M was refused
# only once decoded (4.1 GB); `hstrace compare` decoded both images before
# saying that their sizes differ. Every reader's format, at 256x256 (2.1
# MiB with the parser's copy) against a budget of 1 MiB: status 2 at the
# picture's name, nothing decoded; compare refuses the same from the
# headers, and a file of another size before reading either.
bomb=$work/files/bomb.png
if "$builddir/tests/make_big_png" 16384 16384 "$bomb"; then
    printf 'plane { z, 0 pigment { image_map { png "bomb.png" } } }\n' >"$work/files/bomb.pov"
    rm -f "$work/out.png"
    (cd "$work/files" && exec timeout -s KILL $limit "$hstrace" bomb.pov --width 8 --height 6 --threads 1 \
        --max-memory 1G -o "$work/out.png") >/dev/null 2>"$work/err"
    status=$?
    check_status "a 16384x16384 PNG of 260 KB as an image_map, --max-memory 1G: status 2 within $limit s" "$status" 2
    check "... refused from its header, at its name ($(head -1 "$work/err"))" \
        says "^bomb.pov:1:40: image_map: cannot read '[./]*bomb.png': its 16384x16384 pixels would take 8.5 GiB, more than the [0-9.]* [MG]iB left of the memory budget (--max-memory sets it)\$"
    check "... no image left behind" [ ! -e "$work/out.png" ]
    (cd "$work/files" && exec timeout -s KILL $limit "$hstrace" compare bomb.png bomb.png --max-memory 1G) \
        >/dev/null 2>"$work/err"
    status=$?
    check_status "hstrace compare bomb.png bomb.png --max-memory 1G: status 2 within $limit s" "$status" 2
    check "... refused from the headers ($(head -1 "$work/err"))" \
        says "^hstrace compare: bomb.png: 16384x16384 pixels: comparing would take 8 GiB, more than the memory budget of 1 GiB (--max-memory sets it)\$"
    # Only the first 100 bytes of it: the sizes are told apart from the
    # headers, before the damage is found by decoding.
    head -c 100 "$bomb" >"$work/files/bomb-head.png"
    printf 'background { rgb 1 }\n' >"$work/files/white.pov"
    (cd "$work/files" && "$hstrace" white.pov --width 8 --height 6 -o small.png) >/dev/null 2>&1
    (cd "$work/files" && exec timeout -s KILL $limit "$hstrace" compare small.png bomb-head.png) >/dev/null 2>"$work/err"
    status=$?
    check_status "hstrace compare with a 16384x16384 header of another size: status 2" "$status" 2
    check "... the sizes told apart before decoding ($(head -1 "$work/err"))" \
        says "^hstrace compare: bomb-head.png: 16384x16384 pixels, but small.png has 8x6\$"
else
    not_ok "tests/make_big_png writes a 16384x16384 PNG"
fi
printf 'background { rgb 0.5 }\n' >"$work/files/grey.pov"
for ext in png jpg exr tga bmp ppm hdr; do
    (cd "$work/files" && "$hstrace" grey.pov --width 256 --height 256 --threads 1 -o "pic.$ext") >/dev/null 2>&1 ||
        { not_ok "a 256x256 .$ext to read"; continue; }
    printf 'plane { z, 0 pigment { image_map { "pic.%s" } } }\n' "$ext" >"$work/files/pic-$ext.pov"
    rm -f "$work/out.png"
    (cd "$work/files" && exec timeout -s KILL $limit "$hstrace" "pic-$ext.pov" --width 8 --height 6 --threads 1 \
        --max-memory 1M -o "$work/out.png") >/dev/null 2>"$work/err"
    status=$?
    check_status "a 256x256 .$ext as an image_map, --max-memory 1M: status 2" "$status" 2
    check "... refused from its header ($(head -1 "$work/err"))" \
        says "^pic-$ext.pov:1:36: image_map: cannot read '[./]*pic.$ext': its 256x256 pixels would take 2.1 MiB, more than the [0-9.]* KiB left of the memory budget"
    check "... no image left behind" [ ! -e "$work/out.png" ]
    (cd "$work/files" && exec timeout -s KILL $limit "$hstrace" "pic-$ext.pov" --width 8 --height 6 --threads 1 \
        --max-memory 4M -o "$work/out.png") >/dev/null 2>"$work/err"
    check_status "... and with --max-memory 4M it renders" "$?" 0
    (cd "$work/files" && exec timeout -s KILL $limit "$hstrace" compare "pic.$ext" "pic.$ext" --max-memory 1M) \
        >/dev/null 2>"$work/err"
    check_status "hstrace compare pic.$ext pic.$ext --max-memory 1M: status 2" "$?" 2
    check "... refused from the headers ($(head -1 "$work/err"))" \
        says "^hstrace compare: pic.$ext: 256x256 pixels: comparing would take 2 MiB, more than the memory budget of 1 MiB"
done

# The render's time budget: the message names the scene and the option.
rm -f "$work/out.png"
(cd "$scenes" && exec timeout -s KILL $limit "$hstrace" mirrors-filtering.pov --width 16 --height 12 --threads 2 \
    --max-render-seconds 0.5 --max-tree-rays 0 -o "$work/out.png") >/dev/null 2>"$work/err"
check_status "mirrors-filtering.pov, --max-render-seconds 0.5 on 2 threads: status 2 within $limit s" "$?" 2
check "... says so ($(head -1 "$work/err"))" \
    says "^mirrors-filtering.pov: the render ran for more than 0.5 s (--max-render-seconds); no image written\$"
check "... no image written" [ ! -e "$work/out.png" ]

# The ray tree's budget, on by default (a tree that splits at every level
# of 256 never ends): deterministic, the same message on 1 and 2 threads;
# --max-tree-rays 0 turns it off (then the render budget must stop it), and
# a tree held within it renders.
for threads in 1 2; do
    rm -f "$work/out.png"
    (cd "$scenes" && exec timeout -s KILL $limit "$hstrace" mirrors-filtering-tree.pov --width 16 --height 12 \
        --threads $threads -o "$work/out.png") >/dev/null 2>"$work/err"
    check_status "mirrors-filtering-tree.pov on $threads thread(s), no option: status 2 within $limit s" "$?" 2
    check "... says so ($(head -1 "$work/err"))" \
        says "^mirrors-filtering-tree.pov: a camera ray's tree of reflected and transmitted rays held more than 1048576 rays (max_trace_level 256, adc_bailout 0): lower max_trace_level, raise adc_bailout, or raise --max-tree-rays; no image written\$"
    check "... no image written" [ ! -e "$work/out.png" ]
done
(cd "$scenes" && exec timeout -s KILL $limit "$hstrace" mirrors-filtering-tree.pov --width 16 --height 12 \
    --max-tree-rays 0 --max-render-seconds 0.5 -o "$work/out.png") >/dev/null 2>"$work/err"
check_status "--max-tree-rays 0 turns the tree's budget off: the render budget stops it, status 2" "$?" 2
check "... by the render budget ($(head -1 "$work/err"))" says "(--max-render-seconds); no image written\$"
(cd "$scenes" && exec timeout -s KILL $limit "$hstrace" mirrors-256.pov --width 16 --height 12 \
    --max-tree-rays 256 -o "$work/out.png") >/dev/null 2>"$work/err"
check_status "--max-tree-rays 256: two facing mirrors' tree of 256 rays renders" "$?" 0
(cd "$scenes" && exec timeout -s KILL $limit "$hstrace" mirrors-256.pov --width 16 --height 12 \
    --max-tree-rays 255 -o "$work/out.png") >/dev/null 2>"$work/err"
check_status "--max-tree-rays 255: ... and one ray fewer is refused, status 2" "$?" 2

# The output (issue 39): a read-only file in a writable folder was replaced
# by the rename; POV-Ray cannot open it, and hstrace now refuses it too,
# status 3, the file as it was. SIGTERM or SIGINT while the image is written
# left the hidden temporary (.NAME.XXXXXX) beside it: the signal's handler
# removes it, and the process ends by the signal.
mkdir "$work/out"
printf 'kept' >"$work/out/ro.png"
chmod 444 "$work/out/ro.png"
(cd "$work/files" && exec timeout -s KILL $limit "$hstrace" white.pov --width 8 --height 6 -o "$work/out/ro.png") \
    >/dev/null 2>"$work/err"
check_status "-o a read-only file: status 3" "$?" 3
check "... refused ($(head -1 "$work/err"))" \
    says "^hstrace: cannot write '.*/ro.png': Permission denied (the file is read-only: it is left as it is)\$"
check "... the file as it was, nothing beside it" [ "$(cat "$work/out/ro.png")" = kept ] && [ "$(ls -A "$work/out")" = ro.png ]
rm -f "$work/out/ro.png"
# A shell starts a background command with SIGINT ignored: env puts its
# default action back (GNU env; without it SIGINT is not tried).
if env --default-signal=INT true 2>/dev/null; then sigs="TERM INT"; else sigs=TERM; fi
for sig in $sigs; do
    # A 3000x2000 PNG of one colour: rendered in a moment, written in about a
    # second, long enough to see the temporary and signal the writer.
    (cd "$work/files" && if [ "$sig" = INT ]; then set -- env --default-signal=INT; else set --; fi &&
        exec "$@" "$hstrace" white.pov --width 3000 --height 2000 --threads 2 -o "$work/out/big.png") \
        >/dev/null 2>&1 &
    pid=$!
    i=0
    seen=""
    while [ $i -lt 3000 ] && kill -0 $pid 2>/dev/null; do
        for f in "$work/out"/.big.png.*; do [ -e "$f" ] && seen=$f; done
        [ -n "$seen" ] && break
        sleep 0.01
        i=$((i + 1))
    done
    kill -s "$sig" "$pid" 2>/dev/null
    wait $pid
    status=$?
    if [ -z "$seen" ]; then
        not_ok "SIG$sig while the image is written: the temporary was seen (the writer ended before)"
        continue
    fi
    case $sig in TERM) want=143 ;; *) want=130 ;; esac
    check_status "SIG$sig while the image is written: ended by the signal" "$status" $want
    left=$(find "$work/out" -mindepth 1 | tr '\n' ' ')
    check "... no temporary left, no image ($left)" [ -z "$left" ]
    rm -f "$work/out"/.big.png.* "$work/out/big.png"
done

# The budgets' options, given something that is no budget: bad usage.
for bad in "--max-memory 12Q" "--max-memory 0" "--max-parse-seconds -1" "--max-render-seconds 0" "--max-tree-rays -1" "--max-tree-rays x" "--max-repeated-tokens 0" \
    "--max-macro-calls 1.5" "--max-loop-iterations x"; do
    # shellcheck disable=SC2086 # the option and its value are two words
    (cd "$work/files" && exec "$hstrace" ok.pov -o "$work/out.png" $bad) >/dev/null 2>"$work/err"
    status=$?
    check_status "$bad: status 1" "$status" 1
    check "$bad: the message names the option ($(head -1 "$work/err"))" says "^hstrace: ${bad%% *} "
done

tap_end
