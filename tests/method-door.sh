#!/bin/sh
# One door per shadow method (issue 40), in TAP: the test-only method
# every-point-lit (src/shadow/shadow_every_lit.c, one file and one row of
# the registry) goes through the real render loop -- the command line, the
# method's preparation, its per-thread state, the tile, pixel and segment
# hooks -- and must give what `none` gives: the same image (its answers are
# black wherever a hook is called out of step), on 1 and 2 threads and with
# anti-aliasing, and under --verify-shadows the same disagreements with the
# shadow ray, one for each decision the ray finds blocked or filtered. The
# registry hides it: --help does not list it.
# Environment: top_srcdir, top_builddir (default .).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace=$(cd "$builddir" && pwd)/hstrace
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
[ -x "$hstrace" ] || bail "$hstrace is not built"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstdoor.XXXXXX") || bail "cannot make a temporary folder"
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM

# render NAME ARGS...: desk at 64x48 into NAME.exr (float) and NAME.json
render() {
    name=$1
    shift
    (cd "$srcdir/scenes" && "$hstrace" desk.pov --width 64 --height 48 --exr-float -o "$work/$name.exr" \
        --stats-json "$work/$name.json" "$@") >"$work/$name.log" 2>&1
}
same_image() { "$hstrace" compare "$work/$1.exr" "$work/$2.exr" --max-error 0 >/dev/null 2>&1; }
# json NAME KEY: a number of NAME.json's "shadows" object
json() { sed -n "s/.*\"$2\": \([0-9]*\).*/\1/p" "$work/$1.json" | head -1; }

for threads in 1 2; do
    check "every-point-lit on $threads thread(s): renders" render "lit$threads" --shadows every-point-lit --threads $threads
    check "none on $threads thread(s): renders" render "none$threads" --shadows none --threads $threads
    check "every-point-lit on $threads thread(s): the image of none, bit for bit" same_image "lit$threads" "none$threads"
done
check "every-point-lit with anti-aliasing (+A0.1 +AM2): renders" render litaa --shadows every-point-lit +A0.1 +AM2 +R2
check "none with anti-aliasing: renders" render noneaa --shadows none +A0.1 +AM2 +R2
check "every-point-lit with anti-aliasing: the image of none" same_image litaa noneaa
check "every-point-lit --verify-shadows: renders" render litv --shadows every-point-lit --verify-shadows
check "none --verify-shadows: renders" render nonev --shadows none --verify-shadows
lit_dis=$(json litv disagreements) none_dis=$(json nonev disagreements)
check "every-point-lit: every decision verified ($(json litv verified) of $(json litv queries))" \
    [ "$(json litv verified)" = "$(json litv queries)" ]
same_positive() { [ -n "$1" ] && [ "$1" = "$2" ] && [ "$1" -gt 0 ]; }
check "every-point-lit: its disagreements with the shadow ray are none's ($lit_dis and $none_dis, above 0)" \
    same_positive "$lit_dis" "$none_dis"
"$hstrace" --help >"$work/help" 2>&1
lacks() { ! grep -q -- "$1" "$2"; }
check "--help does not list the test-only method" lacks every-point-lit "$work/help"
tap_end
