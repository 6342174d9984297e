#!/bin/sh
# Renders POV-Ray references for the scenes in scenes/ and scenes/hard/:
# NAME.exr (full quality, +Q9), NAME.q3.exr and NAME.q4.exr (+Q3: no
# shadows, +Q4: shadows; they differ exactly on the pixels shadowed at the
# primary hit), as linear half-float OpenEXR without anti-aliasing. Images of
# scenes/NAME.pov go to OUTDIR/, those of scenes/hard/NAME.pov (the hard
# cases) to OUTDIR/hard/.
#
# usage: make-references.sh OUTDIR [WIDTH HEIGHT] [SCENE...]
#   OUTDIR   folder to write into (created if missing). Nothing is written
#            anywhere else, so to refresh the committed references name the
#            folder explicitly: reference/make-references.sh reference
#   WIDTH HEIGHT  image size, default 320 240
#   SCENE    scene names, with or without .pov and a leading folder: desk,
#            holes.pov, scenes/mesh2.pov; hard/grazing or
#            scenes/hard/grazing.pov for a hard case (a bare name found only
#            in scenes/hard/ is taken from there too). Default: every
#            scenes/*.pov, then every scenes/hard/*.pov
# POV-Ray is given the scene's own folder as a library path (+L, as
# `hstrace vs-povray` gives it), so that the includes and pictures a scene
# names relative to its folder (scenes/oldcolors.inc, scenes/textures/) are
# found from the scratch folder it renders in, as hstrace finds them from
# any current folder.
# A scene may carry one line "// povray-reference-options: OPTIONS": extra
# povray options for its reference (far-coordinates.pov renders its
# reference at the origin with Declare=Offset=0, where POV-Ray is exact).
# Works from any folder. POVRAY names the povray program (default: povray).
# Exit status: 0 done, 1 a render failed, 2 bad usage, 3 povray missing.
set -eu
usage() { echo "usage: $0 OUTDIR [WIDTH HEIGHT] [SCENE...]" >&2; exit 2; }
[ $# -ge 1 ] || usage
here=$(cd "$(dirname "$0")" && pwd)
scenes=$(cd "$here/../scenes" && pwd)
out=$1
shift
width=320
height=240
if [ $# -ge 2 ]; then
    case "$1$2" in
        *[!0-9]*) ;;                       # not a size: scene names follow
        *) width=$1; height=$2; shift 2 ;;
    esac
fi
povray=${POVRAY:-povray}
command -v "$povray" >/dev/null 2>&1 || { echo "make-references: povray not found (Debian package: povray)" >&2; exit 3; }
if [ $# -eq 0 ]; then
    set -- $(cd "$scenes" && ls *.pov)
    if [ -d "$scenes/hard" ]; then
        set -- "$@" $(cd "$scenes" && ls hard/*.pov 2>/dev/null || true)
    fi
fi
# Resolve every name before rendering anything: "hard/NAME" (the folder
# that holds the scene is called hard) is scenes/hard/NAME.pov, any other
# name scenes/NAME.pov, or scenes/hard/NAME.pov when only that exists.
list=""
for f in "$@"; do
    name=$(basename "$f" .pov)
    sub=""
    if [ "$(basename "$(dirname "$f")")" = hard ]; then
        sub=hard/
    elif [ ! -f "$scenes/$name.pov" ] && [ -f "$scenes/hard/$name.pov" ]; then
        sub=hard/
    fi
    [ -f "$scenes/$sub$name.pov" ] || { echo "make-references: no scene $scenes/$sub$name.pov" >&2; exit 2; }
    list="$list $sub$name"
done
mkdir -p "$out"
out=$(cd "$out" && pwd)
# POV-Ray only writes where its configuration permits (the current folder
# and /tmp), so it renders in a scratch folder from which the files are moved.
work=$(mktemp -d "${TMPDIR:-/tmp}/povref.XXXXXX")
trap 'rm -rf "$work"' EXIT
for scene in $list; do
    name=$(basename "$scene")
    sub=${scene%"$name"}                   # "" or "hard/"
    mkdir -p "$work/$sub" "$out/$sub"
    cp "$scenes/$scene.pov" "$work/$sub"
    extra=$(sed -n 's|^// povray-reference-options: *||p' "$scenes/$scene.pov" | head -1)
    for q in 9 3 4; do
        suffix=$([ "$q" = 9 ] && echo "" || echo ".q$q")
        # On a loaded machine POV-Ray 3.7 can give up before its render
        # threads start ("Timed out waiting for worker thread startup"):
        # that, and only that, is tried again, up to twice.
        for attempt in 1 2 3; do
            # shellcheck disable=SC2086 # $extra holds separate options
            if (cd "$work/$sub" && "$povray" "+I$name.pov" "+O$name$suffix.exr" +FE -A -D -GA +WT1 \
                "+L$scenes/$sub" "+W$width" "+H$height" "+Q$q" $extra >"$name$suffix.log" 2>&1); then
                break
            fi
            if [ $attempt = 3 ] || ! grep -q "Timed out waiting for worker thread startup" "$work/$sub$name$suffix.log"; then
                echo "make-references: povray failed on $scene (+Q$q):" >&2
                cat "$work/$sub$name$suffix.log" >&2
                exit 1
            fi
        done
        mv "$work/$sub$name$suffix.exr" "$out/$sub$name$suffix.exr"
    done
done
