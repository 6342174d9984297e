#!/bin/sh
# scenes/make-mesh.sh, in TAP: it refuses bad arguments, writes the number
# of triangles it was asked for (within 2% from 600 up, 4% from 60 up), a
# mesh2 whose counts agree with its lists, the lights asked for, and a scene
# that hstrace renders and POV-Ray parses (when $POVRAY names an installed
# povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
gen="$srcdir/scenes/make-mesh.sh"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstmesh.XXXXXX") || bail "cannot make a temporary folder"
trap 'rm -rf "$work"' EXIT
[ -x "$hstrace" ] || bail "$hstrace is not built"

for bad in "" "0" "12x" "-5" "100 0" "100 9" "100 2 3" "1000000000"; do
    # shellcheck disable=SC2086 # each case is a list of arguments
    sh "$gen" $bad >"$work/bad.pov" 2>"$work/err"; status=$?
    check "make-mesh.sh $bad: exit status 2 with a usage message" exited 2 usage
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
check "make-mesh.sh 1500 2 exits 0" exited 0
check "... nothing on stderr" [ ! -s "$work/err" ]
# between VALUE LOW HIGH: LOW <= VALUE <= HIGH (integers)
between() {
    if [ "$1" -ge "$2" ] && [ "$1" -le "$3" ]; then return 0; fi
    echo "$1 is not in $2..$3"
    return 1
}
# The generator promises (scenes/make-mesh.sh) the count within 2% from 600
# triangles up and within 4% from 60 up. Its counts are exact (no
# randomness); measured 2026-11: 1500 asked, 1496 written (0.27% off:
# the 2% window is 7.5x that); 60 asked, 60 written (0 off: the 4%
# window, 58..62, is the promise under test, not a measured limit).
# shellcheck disable=SC2046 # counts prints seven numbers
set -- $(counts "$work/mesh.pov")
said=$1 nv=$2 gv=$3 nf=$4 gf=$5 top=$6 lights=$7
check "about 1500 triangles, within 2% ($said)" between "$said" 1470 1530
check_status "face_indices declares $said triangles" "$nf" "$said"
check_status "face_indices lists $said triangles" "$gf" "$said"
check_status "vertex_vectors lists the $nv vertices it declares" "$gv" "$nv"
check "every vertex index in range (largest $top, $nv vertices)" [ "$top" -lt "$nv" ]
check_status "2 lights" "$lights" 2
mkdir "$work/here"
gen_abs=$(cd "$(dirname "$gen")" && pwd)/make-mesh.sh
(cd "$work/here" && sh "$gen_abs" 1500 2 >"$work/again.pov")
check "the same arguments write the same scene" cmp "$work/mesh.pov" "$work/again.pov"
check "no file written but standard output" [ -z "$(ls -A "$work/here")" ]
# shellcheck disable=SC2046 # counts prints seven numbers
set -- $(sh "$gen" 60 | counts -)
said60=$1 lights60=$7
check "60 triangles asked: $said60 written, within 4%" between "$said60" 58 62
check_status "3 lights by default" "$lights60" 3
# shellcheck disable=SC2046 # counts prints seven numbers
set -- $(sh "$gen" 1 8 | counts -)
said1=$1 lights1=$7
check_status "1 triangle asked: the smallest rock, 6 triangles" "$said1" 6
check_status "8 lights asked: 8 written" "$lights1" 8

"$hstrace" "$work/mesh.pov" --width 64 --height 48 -o "$work/mesh.ppm" --stats 2>"$work/err"; status=$?
check "hstrace renders it" exited 0
check "... an image" [ -s "$work/mesh.ppm" ]
check "hstrace reads $said triangles and the floor" grep -q "scene *$((said + 1)) polygons" "$work/err"

povray=""
if [ -n "${POVRAY:-}" ]; then
    povray=$(command -v "$POVRAY" 2>/dev/null || true)
fi
if [ -n "$povray" ] && [ -x "$povray" ]; then
    # POV-Ray writes only where its configuration permits: the current folder.
    (cd "$work" && "$povray" +Imesh.pov +Omesh.png +W16 +H12 -D -GA >povray.log 2>&1); status=$?
    check_status "POV-Ray parses and renders it" "$status" 0
    [ $status -eq 0 ] || sed 's/^/# /' "$work/povray.log"
    check "... an image" [ -s "$work/mesh.png" ]
else
    skip "POV-Ray parses and renders it" "povray not installed (Debian package povray)"
    skip "... an image" "povray not installed (Debian package povray)"
fi
tap_end
