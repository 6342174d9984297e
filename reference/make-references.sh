#!/bin/sh
# Renders POV-Ray references for the scenes in scenes/: NAME.exr (full
# quality, +Q9), NAME.q3.exr and NAME.q4.exr (+Q3: no shadows, +Q4: shadows;
# they differ exactly on the pixels shadowed at the primary hit), as linear
# half-float OpenEXR without anti-aliasing.
#
# usage: make-references.sh OUTDIR [WIDTH HEIGHT] [SCENE...]
#   OUTDIR   folder to write into (created if missing). Nothing is written
#            anywhere else, so to refresh the committed references name the
#            folder explicitly: reference/make-references.sh reference
#   WIDTH HEIGHT  image size, default 320 240
#   SCENE    scene names (desk, holes.pov ...), default every scenes/*.pov
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
mkdir -p "$out"
out=$(cd "$out" && pwd)
if [ $# -eq 0 ]; then
    set -- $(cd "$scenes" && ls *.pov)
fi
# POV-Ray only writes where its configuration permits (the current folder
# and /tmp), so it renders in a scratch folder from which the files are moved.
work=$(mktemp -d "${TMPDIR:-/tmp}/povref.XXXXXX")
trap 'rm -rf "$work"' EXIT
for f in "$@"; do
    name=$(basename "$f" .pov)
    [ -f "$scenes/$name.pov" ] || { echo "make-references: no scene $scenes/$name.pov" >&2; exit 2; }
    cp "$scenes/$name.pov" "$work/"
    for q in 9 3 4; do
        suffix=$([ "$q" = 9 ] && echo "" || echo ".q$q")
        (cd "$work" && "$povray" "+I$name.pov" "+O$name$suffix.exr" +FE -A -D -GA +WT2 \
            "+W$width" "+H$height" "+Q$q" >"$name$suffix.log" 2>&1) || {
            echo "make-references: povray failed on $name (+Q$q):" >&2
            cat "$work/$name$suffix.log" >&2
            exit 1
        }
        mv "$work/$name$suffix.exr" "$out/$name$suffix.exr"
    done
done
