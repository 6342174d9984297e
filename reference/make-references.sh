#!/bin/sh
# Renders POV-Ray references for the scenes in scenes/: NAME.exr (full
# quality), NAME.q3.exr and NAME.q4.exr (for the shadow mask), linear half
# float EXR, no anti-aliasing, at the size given (default 320x240).
#
# usage: reference/make-references.sh [OUTDIR] [WIDTH HEIGHT] [SCENE...]
#   OUTDIR defaults to the folder of this script (the committed references).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
scenes=$(cd "$here/../scenes" && pwd)
out=${1:-$here}
width=${2:-320}
height=${3:-240}
[ $# -ge 3 ] && shift 3 || shift $#
povray=${POVRAY:-povray}
command -v "$povray" >/dev/null 2>&1 || { echo "make-references: povray not found (Debian package: povray)" >&2; exit 3; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
list=${*:-$(cd "$scenes" && ls *.pov)}
# POV-Ray only writes where its configuration permits (the current folder
# and /tmp), so it renders in a scratch folder and the files are moved.
work=$(mktemp -d "${TMPDIR:-/tmp}/povref.XXXXXX")
trap 'rm -rf "$work"' EXIT
for f in $list; do
    name=${f%.pov}
    cp "$scenes/$name.pov" "$work/"
    for q in 9 3 4; do
        suffix=$([ "$q" = 9 ] && echo "" || echo ".q$q")
        (cd "$work" && "$povray" "+I$name.pov" "+O$name$suffix.exr" +FE -A -D -GA +WT2 \
            "+W$width" "+H$height" "+Q$q" >/dev/null 2>"$name$suffix.log") || {
            echo "make-references: povray failed on $name (+Q$q):" >&2
            cat "$work/$name$suffix.log" >&2
            exit 1
        }
        mv "$work/$name$suffix.exr" "$out/$name$suffix.exr"
    done
done
