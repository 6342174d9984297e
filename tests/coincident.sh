#!/bin/sh
# Coincident surfaces (trace_coincident_material), in TAP: two boxes whose
# tops lie in one plane where they overlap; a cylinder standing on a plane,
# seen from below and, made of glass, through its top. hstrace shows the object
# declared first there, in every pixel, and says on standard error that
# the image cannot be POV-Ray's (FILE:LINE:COLUMN of both objects, the
# camera rays counted as in --stats-json); POV-Ray's own render of the
# scene differs from it in that region (whichever its hierarchy meets
# first). One texture placed alike on both (a union's), and boxes that do
# not overlap, give no warning. The same for 1 and 2 threads.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (may be empty:
# the comparison with POV-Ray is skipped).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$(cd "$builddir" && pwd)/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
tap_work hstcoincident
[ -x "$hstrace" ] || bail "$hstrace is not built"
command -v python3 >/dev/null || bail "python3 is not installed"
cp "$srcdir"/tests/coincident/*.pov "$work/" || bail "cannot copy the scenes"
size="--width 48 --height 48"

# render NAME THREADS: NAME.pov to NAME-THREADS.ppm, its stderr and JSON beside
render() {
    # shellcheck disable=SC2086 # the size switches, one word each
    (cd "$work" && "$hstrace" "$1.pov" $size --threads "$2" -o "$1-$2.ppm" --stats-json "$1-$2.json" \
        >/dev/null 2>"$1-$2.err")
}

# coincident NAME [KEY]: the JSON's count of camera rays (or KEY's rays) on
# coincident surfaces
coincident() {
    python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["rays"][sys.argv[2]])' "$work/$1.json" \
        "${2:-coincident}"
}

# The PPM images' pixels, by tests/coincident/pixels.py:
#   pixels A B: "differing red-in-A blue-in-A red-in-B blue-in-B" over the
#     pixels where A and B differ
#   pixels A B P: at how many of those P is more than 32 levels off A (in
#     some channel)
pixels() { python3 "$srcdir/tests/coincident/pixels.py" "$@"; }

# starts TEXT PREFIX: TEXT begins with PREFIX
starts() { case "$1" in "$2"*) return 0 ;; *) return 1 ;; esac; }

for t in 1 2; do
    for s in red-first blue-first one-texture apart cylinder-below glass-on-plane; do
        render "$s" "$t"
        check_status "$s.pov renders on $t thread(s)" $? 0
    done
done

# The warning: where, how many, said alike for any number of threads.
warning=$(head -n 1 "$work/red-first-1.err")
n=$(coincident red-first-1)
check "red-first.pov: a warning at the first box, naming the second, counting the rays --stats-json counts ($warning)" \
    starts "$warning" "red-first.pov:5:1: warning: $n camera rays and 0 others met coincident surfaces of two objects, this one and red-first.pov:6:1 "
check "red-first.pov: the same warning on 2 threads" [ "$warning" = "$(head -n 1 "$work/red-first-2.err")" ]
check "red-first.pov: the same image on 2 threads" cmp -s "$work/red-first-1.ppm" "$work/red-first-2.ppm"
warning=$(head -n 1 "$work/blue-first-1.err")
check "blue-first.pov: the warning at the box declared first ($warning)" \
    starts "$warning" "blue-first.pov:4:1: warning: $(coincident blue-first-1) camera rays and 0 others met coincident surfaces of two objects, this one and blue-first.pov:5:1 "

# The region: where the two orders' images differ. Each shows its first box
# there, in every pixel; one camera ray a pixel, each counted.
# shellcheck disable=SC2046 # five numbers
set -- $(pixels "$work/red-first-1.ppm" "$work/blue-first-1.ppm")
check "the overlap is seen ($1 pixels)" [ "$1" -gt 20 ]
check "red-first.pov shows the red box in every pixel of it ($2 of $1)" same_count "$2" "$1"
check "blue-first.pov shows the blue box in every pixel of it ($5 of $1)" same_count "$5" "$1"
check "red-first.pov counts a camera ray per pixel of it ($n)" same_count "$n" "$1"
overlap=$1

# A curved object's surface in a plane: within 1e-9 of it, whichever the
# arithmetic puts nearer is shown. Seen by the camera (a base from below),
# and by the rays refracted into a glass standing on the plane.
warning=$(head -n 1 "$work/cylinder-below-1.err")
n=$(coincident cylinder-below-1)
check "cylinder-below.pov: a warning at the plane, naming the cylinder, counting the camera rays ($warning)" \
    starts "$warning" "cylinder-below.pov:6:1: warning: $n camera rays and 0 others met coincident surfaces of two objects, this one and cylinder-below.pov:7:1 "
check "cylinder-below.pov: some camera rays counted ($n)" [ "$n" -gt 0 ]
check "cylinder-below.pov: the same image on 2 threads" cmp -s "$work/cylinder-below-1.ppm" "$work/cylinder-below-2.ppm"
warning=$(head -n 1 "$work/glass-on-plane-1.err")
m=$(coincident glass-on-plane-1 coincident_secondary)
check "glass-on-plane.pov: a warning counting the refracted rays, none of the camera's ($warning)" \
    starts "$warning" "glass-on-plane.pov:5:1: warning: 0 camera rays and $m others met coincident surfaces of two objects, this one and glass-on-plane.pov:6:1 "
check "glass-on-plane.pov: some refracted rays counted ($m)" [ "$m" -gt 0 ]
check "glass-on-plane.pov: the same image on 2 threads" cmp -s "$work/glass-on-plane-1.ppm" "$work/glass-on-plane-2.ppm"

for s in one-texture apart; do
    check "$s.pov: no warning ($(head -n 1 "$work/$s-1.err"))" [ ! -s "$work/$s-1.err" ]
    check "$s.pov: no camera ray counted" same_count "$(coincident "$s-1")" 0
done

povray=""
if [ -n "${POVRAY:-}" ]; then povray=$(command -v "$POVRAY" 2>/dev/null || true); fi
if [ -z "$povray" ]; then
    skip "POV-Ray's image is not hstrace's in the overlap" "povray is not installed"
else
    (cd "$work" && "$povray" +W48 +H48 -D -GA +FP +Ired-first.pov +Opov.ppm >/dev/null 2>&1)
    check_status "POV-Ray renders red-first.pov" $? 0
    # POV-Ray's pixels where hstrace's two orders differ: how many are off
    # hstrace's (red-first.pov's) by more than 32 levels in some channel
    off=$(pixels "$work/red-first-1.ppm" "$work/blue-first-1.ppm" "$work/pov.ppm")
    check "POV-Ray's image is not hstrace's in the overlap ($off of $overlap pixels off)" [ "$off" -gt 0 ]
fi
tap_end
