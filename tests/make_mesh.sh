#!/bin/sh
# scenes/make-mesh.sh, in TAP: it refuses bad arguments, writes the number
# of triangles it was asked for (within 4% from 60 up), a mesh2 whose counts
# agree with its lists, the lights asked for, and a scene that hstrace
# renders and POV-Ray parses (when $POVRAY names an installed povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
gen="$srcdir/scenes/make-mesh.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstmesh.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
n=0
check() { # description, then a shell condition
    n=$((n + 1)); d=$1; shift
    if eval "$@"; then echo "ok $n - $d"; else echo "not ok $n - $d"; fi
}

for bad in "" "0" "12x" "-5" "100 0" "100 9" "100 2 3" "1000000000"; do
    # shellcheck disable=SC2086 # each case is a list of arguments
    sh "$gen" $bad >"$work/bad.pov" 2>"$work/err"; status=$?
    check "make-mesh.sh $bad: exit status 2 with a usage message" '[ $status -eq 2 ] && grep -q usage "$work/err"'
done

# The counts in a generated scene: "// triangles: N", the declared sizes of
# vertex_vectors and face_indices, the vectors actually listed, the largest
# vertex index and the lights.
counts() {
    awk '
        /^\/\/ triangles: / { said = $3 }
        /vertex_vectors/ { list = "v"; sub(/.*vertex_vectors \{ */, ""); nv = $0 + 0 }
        /face_indices/ { list = "f"; sub(/.*face_indices \{ */, ""); nf = $0 + 0 }
        /^  \}/ { list = "" }
        /^light_source/ { lights++ }
        list == "v" { gv += gsub(/<[^>]*>/, "&") }
        list == "f" {
            s = $0
            while (match(s, /<[0-9]+, [0-9]+, [0-9]+>/)) {
                gf++
                t = substr(s, RSTART + 1, RLENGTH - 2); split(t, idx, ", ")
                for (k = 1; k <= 3; k++) if (idx[k] + 0 > top) top = idx[k] + 0
                s = substr(s, RSTART + RLENGTH)
            }
        }
        END { printf "%d %d %d %d %d %d %d\n", said, nv, gv, nf, gf, top, lights }' "$1"
}

sh "$gen" 1500 2 >"$work/mesh.pov" 2>"$work/err"; status=$?
check "make-mesh.sh 1500 2 exits 0, nothing on stderr" '[ $status -eq 0 ] && [ ! -s "$work/err" ]'
set -- $(counts "$work/mesh.pov")
said=$1 nv=$2 gv=$3 nf=$4 gf=$5 top=$6 lights=$7
check "about 1500 triangles ($said)" '[ "$said" -ge 1440 ] && [ "$said" -le 1560 ]'
check "face_indices declares and lists $said triangles ($nf, $gf)" '[ "$nf" -eq "$said" ] && [ "$gf" -eq "$said" ]'
check "vertex_vectors declares and lists $nv vertices, every index in range ($gv, largest $top)" \
    '[ "$gv" -eq "$nv" ] && [ "$top" -lt "$nv" ]'
check "2 lights" '[ "$lights" -eq 2 ]'
mkdir "$work/here"
gen_abs=$(cd "$(dirname "$gen")" && pwd)/make-mesh.sh
(cd "$work/here" && sh "$gen_abs" 1500 2 >"$work/again.pov")
check "the same arguments write the same scene" 'cmp -s "$work/mesh.pov" "$work/again.pov"'
check "no file written but standard output" '[ -z "$(ls -A "$work/here")" ]'
set -- $(sh "$gen" 60 | counts -)
said60=$1 lights60=$7
check "60 triangles asked: $said60 written, within 4%; 3 lights by default ($lights60)" \
    '[ "$said60" -ge 58 ] && [ "$said60" -le 62 ] && [ "$lights60" -eq 3 ]'
set -- $(sh "$gen" 1 8 | counts -)
said1=$1 lights1=$7
check "1 triangle asked: the smallest rock, 6 triangles; 8 lights ($said1, $lights1)" '[ "$said1" -eq 6 ] && [ "$lights1" -eq 8 ]'

"$hstrace" "$work/mesh.pov" --width 64 --height 48 -o "$work/mesh.ppm" --stats 2>"$work/err"; status=$?
check "hstrace renders it" '[ $status -eq 0 ] && [ -s "$work/mesh.ppm" ]'
check "hstrace reads $said triangles and the floor" 'grep -q "scene *$((said + 1)) polygons" "$work/err"'

povray=""
if [ -n "${POVRAY:-}" ]; then
    povray=$(command -v "$POVRAY" 2>/dev/null || true)
fi
if [ -n "$povray" ] && [ -x "$povray" ]; then
    # POV-Ray writes only where its configuration permits: the current folder.
    (cd "$work" && "$povray" +Imesh.pov +Omesh.png +W16 +H12 -D -GA >povray.log 2>&1); status=$?
    check "POV-Ray parses and renders it" '[ $status -eq 0 ] && [ -s "$work/mesh.png" ]'
    [ $status -eq 0 ] || sed 's/^/# /' "$work/povray.log"
else
    n=$((n + 1)); echo "ok $n - # SKIP povray not installed"
fi
echo "1..$n"
