#!/bin/sh
# Survey of POV-Ray's own sample scenes (Debian package povray-examples):
# which of them hstrace renders unmodified, how their shadow masks compare
# with POV-Ray's, and for every other scene the line hstrace names and why.
# Writes bench/examples.md.
#
# Every scene is run in a private copy of the examples folder, because some
# of them #write files next to themselves. A scene "renders" when hstrace
# exits 0 and writes the image; for those, POV-Ray renders the scene too and
# `hstrace compare` measures the shadow masks (+Q3 against +Q4) by the rule
# of tests/povray-examples.sh (at most 0.1% of the pixels, none in the
# interior of a shadow). Every other scene is listed with hstrace's error
# message, grouped by its reason.
#
# usage: bench/examples.sh [BUILDDIR]   (default: the current folder)
# Environment: HST_POVRAY_EXAMPLES (default /usr/share/doc/povray/examples),
# POVRAY (default povray), HST_EXAMPLES_ONLY (an extended regular expression:
# survey only the scenes whose path matches it, for work on a few of them),
# HST_EXAMPLES_OUT (where the table goes; default bench/examples.md).
# A scene with an animation INI beside it (Initial_Frame before
# Final_Frame, naming no other scene: the portfolio's) is rendered, by both
# programs, through that INI at its first frame.
# Exit status: 0 done, 3 hstrace not built or the examples not installed.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
build=$(cd "${1:-.}" && pwd)
hstrace="$build/hstrace"
[ -x "$hstrace" ] || { echo "examples: build hstrace first (make)" >&2; exit 3; }
examples=${HST_POVRAY_EXAMPLES:-/usr/share/doc/povray/examples}
[ -d "$examples" ] || { echo "examples: $examples not found (Debian package povray-examples)" >&2; exit 3; }
povray=${POVRAY:-povray}
command -v "$povray" >/dev/null 2>&1 || povray=""
work=$(mktemp -d "${TMPDIR:-/tmp}/hstsurvey.XXXXXX")
trap 'rm -rf "$work"' EXIT
cp -R "$examples" "$work/examples"
out=${HST_EXAMPLES_OUT:-$here/examples.md}
width=160 height=120
rendered="$work/rendered" failed="$work/failed"
: >"$rendered"
: >"$failed"

# hstrace's error line: the first FILE:LINE:COLUMN: line that is neither a
# warning nor a note (#debug output of the scene may come before it)
error_line() {
    grep -E '^[^ ]+:[0-9]+:[0-9]+: ' "$1" | grep -v -E ': (warning|note): ' | head -1
}

# "a|b|c" lines as Markdown table rows
table_rows() { awk -F'|' '{ printf "|"; for (i = 1; i <= NF; i++) printf " %s |", $i; print "" }'; }

(cd "$work/examples" && find . -name '*.pov' | sed 's|^\./||' | sort |
    grep -E -- "${HST_EXAMPLES_ONLY:-.}") >"$work/scenes"
# ini_key BASE KEY: KEY's value in BASE.ini, if it has one
ini_key() {
    sed -n "s/^[[:space:]]*$2[[:space:]]*=[[:space:]]*\\([^[:space:];]*\\).*/\\1/p" "$dir/$1.ini" | head -1
}
# frame_of BASE: for a scene whose INI beside it (BASE.ini) makes it an
# animation of several frames and names no other scene, its first frame,
# which both programs render through that INI as a POV-Ray user would (the
# portfolio's scenes index their arrays by frame_number); else nothing
frame_of() {
    [ -f "$dir/$1.ini" ] || return 0
    first=$(ini_key "$1" Initial_Frame) last=$(ini_key "$1" Final_Frame) named=$(ini_key "$1" Input_File_Name)
    for n in "$first" "$last"; do
        case "$n" in '' | *[!0-9]*) return 0 ;; esac
    done
    [ "$last" -gt "$first" ] || return 0
    [ -z "$named" ] || [ "$named" = "$1.pov" ] || return 0
    echo "$first"
}
# image PREFIX: the one image a render named PREFIX.exr wrote (an
# animation's frame gets its number before the extension)
image() { for f in "$1".exr "$1"[0-9]*.exr; do [ -s "$f" ] && echo "$f" && return; done; echo "$1.exr"; }

while read -r scene; do
    dir="$work/examples/$(dirname "$scene")"
    base=$(basename "$scene" .pov)
    img="$work/$base"
    # the scene's own file, or its animation INI at its first frame (its
    # output type and anti-aliasing set as for every other scene)
    frame=$(frame_of "$base")
    input="$base.pov"
    [ -n "$frame" ] && input="$base.ini +SF$frame +EF$frame +FE -A"
    status=0
    # shellcheck disable=SC2086 # the input's words
    (cd "$dir" && timeout 120 "$hstrace" $input --width $width --height $height "+Q4" --threads 1 \
        -o "$img.h4.exr" >/dev/null 2>"$work/err") || status=$?
    h4=$(image "$img.h4")
    if [ $status -ne 0 ] || [ ! -s "$h4" ]; then
        line=$(error_line "$work/err")
        [ $status -eq 124 ] && line="(no answer within 120 s)"
        [ -n "$line" ] || line="(exit status $status: $(tail -1 "$work/err"))"
        # paths relative to the examples folder and to hstrace's source tree
        echo "$scene|$status|$(echo "$line" | sed "s|$work/examples/||g; s|$dir/||g; s|$src/||g; s|$build/||g")" >>"$failed"
        continue
    fi
    approx=$(grep ': warning: .* approximated: ' "$work/err" | sed 's/.*warning: //; s/ approximated: .*//' |
        sort -u | tr '\n' ',' | sed 's/,$//; s/,/, /g')
    figures="POV-Ray not installed"
    if [ -n "$povray" ]; then
        # shellcheck disable=SC2086 # the input's words
        (cd "$dir" && "$hstrace" $input --width $width --height $height "+Q3" --threads 1 \
            -o "$img.h3.exr" >/dev/null 2>&1) || true
        pov_input="+I$base.pov"
        [ -n "$frame" ] && pov_input="$base.ini +SF$frame +EF$frame"
        for q in 3 4; do
            # shellcheck disable=SC2086 # the input's words
            (cd "$dir" && "$povray" $pov_input "+O$img.p$q.exr" +FE +W$width +H$height -A -D -GA +WT1 \
                "+Q$q" >/dev/null 2>&1) || true
        done
        h3=$(image "$img.h3") p3=$(image "$img.p3") p4=$(image "$img.p4")
        if [ -s "$p3" ] && [ -s "$p4" ] && [ -s "$h3" ]; then
            report=$("$hstrace" compare "$p4" "$h4" --mask-a "$p3" "$p4" \
                --mask-b "$h3" "$h4" --max-mask-share 0.001 --max-interior 0 2>&1) &&
                verdict=agrees || verdict="**differs**"
            pixels=$(echo "$report" | sed -n 's/.*disagree on \([0-9]*\) px.*/\1/p')
            interior=$(echo "$report" | sed -n 's/.* \([0-9]*\) interior.*/\1/p')
            rmse=$(echo "$report" | sed -n 's/.*RMSE \([0-9.eE+-]*\),.*/\1/p' | head -1)
            figures="$verdict|${pixels:-?}|${interior:-?}|${rmse:-?}"
        else
            figures="POV-Ray did not render it|||"
        fi
    fi
    echo "$scene|$figures|${approx:--}" >>"$rendered"
    rm -f "$img".*
done <"$work/scenes"

total=$(wc -l <"$work/scenes")
nr=$(wc -l <"$rendered")
{
    echo "# POV-Ray's sample scenes in hstrace"
    echo
    echo "Made by \`bench/examples.sh\` on $(date -u +%Y-%m-%d) from the $total scenes of"
    echo "povray-examples $(dpkg-query -W -f '${Version}' povray-examples 2>/dev/null || echo '(version unknown)'),"
    echo "each run unmodified in a private copy of the examples folder at ${width}x${height}, 1 thread."
    echo
    echo "**$nr of $total render.** Their shadow masks (+Q3 against +Q4) are compared with POV-Ray's"
    echo "by the rule of \`tests/povray-examples.sh\`: at most 0.1% of the pixels differ, none in the"
    echo "interior of a shadow. *Approximated* lists what hstrace reported it approximated"
    echo "(\`--strict\` refuses those scenes instead)."
    echo
    echo "| scene | mask | pixels differing | of which interior | image RMSE | approximated |"
    echo "|---|---|---|---|---|---|"
    table_rows <"$rendered"
    echo
    echo "## The $((total - nr)) others, by reason"
    echo
    echo "The reason is hstrace's message (status 2 unless noted), the first thing in the scene that"
    echo "hstrace does not model; a scene may need more after it."
    echo
    echo "| scenes | reason |"
    echo "|---|---|"
    cut -d'|' -f3 "$failed" | sed -E 's/^[^ ]+:[0-9]+:[0-9]+: //; s/ \(declared at .*//' |
        sort | uniq -c | sort -k1,1nr -k2 | awk '{ n = $1; $1 = ""; sub(/^ /, ""); printf "| %d | %s |\n", n, $0 }'
    echo
    echo "### Every scene that does not render"
    echo
    echo "| scene | status | message |"
    echo "|---|---|---|"
    table_rows <"$failed"
} >"$out"
echo "wrote $out: $nr of $total render"
