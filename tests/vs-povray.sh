#!/bin/sh
# `hstrace vs-povray` as a user meets it, in TAP. On a small scene (a floor,
# a box, one light; 64x48) rendered by POV-Ray and hstrace: a row per shadow
# method with a speed-up above 0, an RMSE of at most 1e-5 and no shadow-mask
# disagreement against POV-Ray (the figures measured: 0); --json with its
# keys; --report DIR writing index.html whose PNGs exist and decode and
# whose table holds the printed figures; render options (size, threads)
# reaching both programs. Without POV-Ray: the message and exit status 4
# (PATH without povray, or HSTRACE_POVRAY naming nothing), POV-Ray's failure
# (a stand-in script) shown with status 5, a termination signal stopping the
# renders, usage errors with status 1; the private temporary folder removed
# every time. The checks that need POV-Ray are skipped when it is not
# installed.
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstvspov.XXXXXX") || bail "no temporary folder"
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || bail "$hstrace is not built"
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
# vs-povray's private folders go here, so the tests can see them removed.
mkdir "$work/tmp"
TMPDIR="$work/tmp"
export TMPDIR
run() { # hstrace vs-povray ARGS: stdout in $work/out, stderr in $work/err, status in $status
    "$hstrace" vs-povray "$@" >"$work/out" 2>"$work/err"; status=$?
}
empty_tmp() { [ -z "$(ls -A "$work/tmp")" ]; }
clean_tmp() { empty_tmp || { echo "left in the temporary folder:"; ls -A "$work/tmp"; return 1; }; }
# The table's row for a method: "method wall cpu shadows speed-up rmse edge interior".
row() { awk -v m="$1" '$1 == m { print; exit }' "$work/out"; }
field() { row "$1" | awk -v k="$2" '{ print $k }'; }

cat >"$work/box.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -5> look_at <0, 0.5, 0> angle 50 right x*4/3 }
light_source { <-3, 6, -4> color rgb 1 }
polygon { 4, <-4, 0, -4>, <4, 0, -4>, <4, 0, 4>, <-4, 0, 4> pigment { color rgb <0.8, 0.8, 0.7> } }
box { <-0.7, 0, -0.7>, <0.7, 1.2, 0.7> rotate y*30 pigment { color rgb <0.7, 0.2, 0.2> } }
POV
cat >"$work/bad.pov" <<'POV'
#version 3.7;
camera { location <0,1,-3> look_at 0 }
polygon { 4, <0,0>, <1,0> <1,1>, <0,0>
  pigment { color rgb 1 }
POV

# --- without POV-Ray ---------------------------------------------------------
run --help
check_status "--help: exit status 0" "$status" 0
check "--help names the options" grep -q -- "--methods" "$work/out"
check "--help names the exit statuses" grep -q "4 POV-Ray not found" "$work/out"
run "$work/box.pov" --report "$work/no/such/folder"
check "--report in a folder that does not exist: exit status 3" exited 3 "no/such/folder"
check "... before any render" [ ! -e "$work/no" ]
run "$work/box.pov" --methods hst,bogus
check "unknown method: exit status 1, lists the valid ones" exited 1 "bogus.*valid: hst"
run "$work/box.pov" --runs 0
check "--runs 0: exit status 1" exited 1 "runs"
run "$work/box.pov" -o "$work/x.png"
check "an output image is refused: exit status 1" exited 1
check "... and not written" [ ! -e "$work/x.png" ]
run "$work/box.pov" --shadows hst
check "--shadows is refused (--methods chooses): exit status 1" exited 1 "--methods"
run "$work/box.pov" +Q4
check "+Q4 is refused: exit status 1" exited 1
run "$work/box.pov" --width 0
check "a render option's bad value: exit status 1, as when rendering" exited 1 width
run
check "no scene: exit status 1" exited 1 "no scene"
run "$work/missing.pov"
check "missing scene: exit status 3, names it" exited 3 "missing.pov"

mkdir "$work/empty"
(unset HSTRACE_POVRAY; PATH="$work/empty" "$hstrace" vs-povray "$work/box.pov" >"$work/out" 2>"$work/err"); status=$?
check "no povray in PATH: exit status 4 ($(cat "$work/err"))" \
    exited 4 "^hstrace vs-povray: povray not found; install the Debian package povray\$"
check "... that one line only" [ "$(wc -l <"$work/err")" -eq 1 ]
HSTRACE_POVRAY=/nonexistent "$hstrace" vs-povray "$work/box.pov" >"$work/out" 2>"$work/err"; status=$?
check "HSTRACE_POVRAY=/nonexistent: exit status 4, the message names the Debian package" \
    exited 4 "povray not found; install the Debian package povray"
check "... and no table" [ ! -s "$work/out" ]

# A stand-in POV-Ray that fails as POV-Ray does on a parse error.
printf '#!/bin/sh\necho "Persistence of Vision(tm) Ray Tracer Version 3.7 banner" >&2\necho "==== [Parsing...] ====" >&2\necho "File '"'"'x.pov'"'"' line 3: Parse Error: stand-in failure" >&2\necho "Render failed" >&2\nexit 1\n' \
    >"$work/failing-povray"
chmod +x "$work/failing-povray"
HSTRACE_POVRAY="$work/failing-povray" "$hstrace" vs-povray "$work/box.pov" --width 16 --height 12 \
    >"$work/out" 2>"$work/err"; status=$?
check "POV-Ray fails on the scene: exit status 5, says so" exited 5 "POV-Ray failed on .*box.pov"
check "... the end of its output is shown" grep -q "line 3: Parse Error: stand-in failure" "$work/err"
check_fails "... not its banner" grep -q banner "$work/err"
check "... no table" [ ! -s "$work/out" ]
check "... and the temporary folder is gone" clean_tmp

# A stand-in POV-Ray that takes its time: a termination signal stops it.
printf '#!/bin/sh\nexec sleep 30\n' >"$work/slow-povray"
chmod +x "$work/slow-povray"
HSTRACE_POVRAY="$work/slow-povray" "$hstrace" vs-povray "$work/box.pov" --width 16 --height 12 \
    >"$work/out" 2>"$work/err" &
pid=$!
i=0
while [ $i -lt 100 ] && empty_tmp; do sleep 0.1; i=$((i + 1)); done   # until the renders have begun
sleep 0.5
kill -TERM $pid
{ wait $pid; } 2>/dev/null; status=$?
check_status "SIGTERM while rendering: ends by that signal (status $status)" "$status" 143
check "... and the temporary folder is gone" clean_tmp

# --- with POV-Ray ------------------------------------------------------------
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
if [ -z "$povray" ]; then
    for d in "syntax error: exit status 2" "syntax error: FILE:LINE:COLUMN" "a row per method" \
             "speed-ups above 0" "RMSE within the measured limits" "no interior mask pixels" "size and threads" "--report files" \
             "--report PNGs decode" "--report table values" "--report provenance" "--json keys" \
             "--runs, --methods and POV-Ray switches" "--json parses" "--methods hst,embree" "temporary folder removed"; do
        skip "$d" "povray not installed (Debian package povray)"
    done
    tap_end
    exit 0
fi
HSTRACE_POVRAY=$povray
export HSTRACE_POVRAY

run "$work/bad.pov" --report "$work/badreport"
check "syntax error: exit status 2, the message names FILE:LINE:COLUMN ($(grep -m1 "bad.pov:" "$work/err"))" \
    exited 2 "bad.pov:[0-9][0-9]*:[0-9][0-9]*: "
check "... no report folder made" [ ! -e "$work/badreport" ]

run "$work/box.pov" --width 64 --height 48 --threads 2 --report "$work/report"
cp "$work/out" "$work/table"
sed 's/^/# /' "$work/table"
check_status "vs-povray --report: exit status 0" "$status" 0
check "a row for POV-Ray" [ -n "$(row povray)" ]
# The limits, measured on this scene (2026-11, POV-Ray 3.7.0.10, both
# renders 64x48): every method's RMSE is 0 (the JSON prints 0: the half
# floats agree bit for bit) and no mask pixel disagrees, at edges or inside.
# So the RMSE limit is the floor 1e-5 (the table prints 6 decimals) and the
# edge count's is 0, like the interior's.
max_rmse=1e-5 max_edge=0
methods="conventional cache volume hst"
for m in $methods; do
    check "$m: a row" [ -n "$(row "$m")" ]
    check "$m: speed-up against POV-Ray above 0 ($(field "$m" 5))" awk -v s="$(field "$m" 5)" 'BEGIN { exit !(s + 0 > 0) }'
    check "$m: RMSE against POV-Ray $(field "$m" 6) <= $max_rmse" at_most "$(field "$m" 6)" $max_rmse
    check "$m: shadow-mask pixels at edges against POV-Ray $(field "$m" 7) <= $max_edge" at_most "$(field "$m" 7)" $max_edge
    check_status "$m: no interior shadow-mask pixels against POV-Ray" "$(field "$m" 8)" 0
done
check "64x48 pixels and 2 threads for both programs" grep -q "64x48 pixels, 2 threads" "$work/out"

check "--report: index.html written" [ -s "$work/report/index.html" ]
check "--report: vs-povray.json written" [ -s "$work/report/vs-povray.json" ]
pngs=$(sed -n 's/.*<img src="\([^"]*\)".*/\1/p' "$work/report/index.html")
npng=0
for p in $pngs; do npng=$((npng + 1)); done
check_status "--report: the page shows 13 images (POV-Ray, 4 renders, 4 heat maps, 4 mask maps)" $npng 13
# decodes FILE: a PNG that hstrace compare reads (equal to itself within --max-error 0)
decodes() {
    case $1 in *.png) ;; *) echo "not a PNG: $1"; return 1 ;; esac
    "$hstrace" compare "$1" "$1" --max-error 0
}
all_decode() {
    [ -n "$pngs" ] || { echo "the page shows no image"; return 1; }
    for p in $pngs; do decodes "$work/report/$p" >/dev/null || { echo "$p does not decode"; return 1; }; done
}
check "--report: every image is present and decodes as a PNG" all_decode
# in_page METHOD: the report page's table holds the figures printed for METHOD
in_page() {
    for k in 2 3 4 5 6 7 8; do
        grep -q -F -- "<td>$(field "$1" $k)</td>" "$work/report/index.html" || { echo "no <td>$(field "$1" $k)</td>"; return 1; }
    done
}
for m in povray $methods; do
    check "--report: the page's table holds the figures printed for $m" in_page "$m"
done
for pattern in "vs-povray .*box.pov --width 64" "POV-Ray 3\.7" "hstrace [0-9]" "<dt>Date</dt><dd>20" "<dt>Machine</dt><dd>.*core"; do
    check "--report: the page names the command, both versions, the date and the machine: $pattern" \
        grep -q "$pattern" "$work/report/index.html"
done

run "$work/box.pov" +W64 +H48 +WT1 --methods hst,conventional --runs 2 --json
check_status "--json: exit status 0" "$status" 0
for k in scene width height threads runs povray_version povray methods method wall cpu shadow_testing speedup \
         rmse mask edge interior; do
    check "--json: key $k present" grep -q "\"$k\":" "$work/out"
done
check "--runs 2 reaches both programs" grep -q '"runs": 2,' "$work/out"
check "POV-Ray's switch +WT1 reaches both programs" grep -q '"threads": 1,' "$work/out"
check "POV-Ray's switches +W64 +H48 reach both programs" grep -q '"width": 64,' "$work/out"
check_status "--methods hst,conventional: two methods" "$(grep -c '"method":' "$work/out")" 2
check "--json is one object" [ "$(head -c1 "$work/out")" = "{" ]
if command -v python3 >/dev/null 2>&1; then
    check "--json parses: hst then conventional, speed-up above 0, RMSE <= $max_rmse, at most $max_edge edge and no interior mask pixels" \
        python3 -c "
import json, sys
r = json.load(open(sys.argv[1]))
m = r['methods']
assert [x['method'] for x in m] == ['hst', 'conventional'], m
assert r['runs'] == 2 and r['threads'] == 1 and (r['width'], r['height']) == (64, 48), r
for x in m:
    assert x['speedup'] > 0 and x['rmse'] <= float(sys.argv[2]), x
    assert x['mask']['edge'] <= int(sys.argv[3]) and x['mask']['interior'] == 0, x
" "$work/out" $max_rmse $max_edge
else
    skip "--json parses" "python3 not installed (Debian package python3)"
fi
# embree is not exact: its disagreements with the shadow ray are measured
# (one more render with --verify-shadows) and shown; the exact methods' not.
embree_counted() {
    [ "$status" -eq 0 ] && grep -q "vs shadow ray" "$work/out" && [ "$(field hst 9)" = - ] &&
        row embree | grep -Eq " [0-9]+ of [1-9][0-9]*$" &&
        { ! command -v python3 >/dev/null 2>&1 || python3 -c "
import json, sys
m = {x[\"method\"]: x for x in json.load(open(sys.argv[1]))[\"methods\"]}
assert m[\"hst\"][\"verified\"] is None and m[\"hst\"][\"disagreements\"] is None
assert m[\"embree\"][\"verified\"] > 0 and 0 <= m[\"embree\"][\"disagreements\"] <= m[\"embree\"][\"verified\"]
" "$work/embree.json"; }
}
if "$hstrace" --version | grep -q "Embree [0-9]"; then
    run "$work/box.pov" --width 64 --height 48 --threads 2 --methods hst,embree --json
    cp "$work/out" "$work/embree.json"
    run "$work/box.pov" --width 64 --height 48 --threads 2 --methods hst,embree
    check "--methods hst,embree: embree's disagreements with the shadow ray counted in the JSON and the table ($(row embree | awk '{ print $9, $10, $11 }')), none for the exact hst" \
        embree_counted
else
    skip "--methods hst,embree" "embree not built"
fi
check "the temporary folder is removed after every run" clean_tmp
tap_end
