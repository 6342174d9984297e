#!/bin/sh
# `hstrace vs-povray` as a user meets it, in TAP. On a small scene (a floor,
# a box, one light; 64x48) rendered by POV-Ray and hstrace: a row per shadow
# method with a speed-up above 0, an RMSE below 0.01 and no interior
# shadow-mask disagreement against POV-Ray; --json with its keys; --report
# DIR writing index.html whose PNGs exist and decode and whose table holds
# the printed figures; render options (size, threads) reaching both
# programs. Without POV-Ray: the message and exit status 4 (PATH without
# povray, or HSTRACE_POVRAY naming nothing), POV-Ray's failure (a stand-in
# script) shown with status 5, a termination signal stopping the renders,
# usage errors with status 1; the private temporary folder removed every
# time. The checks that need POV-Ray are skipped when it is not installed.
set -u
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstvspov.XXXXXX") || { echo "Bail out! no temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
# vs-povray's private folders go here, so the tests can see them removed.
mkdir "$work/tmp"
TMPDIR="$work/tmp"
export TMPDIR
n=0
check() { # description, then a shell condition
    n=$((n + 1)); d=$1; shift
    if eval "$@"; then echo "ok $n - $d"; else echo "not ok $n - $d"; fi
}
skip() { # description: a check that needs POV-Ray
    n=$((n + 1)); echo "ok $n - $1 # SKIP povray not installed"
}
run() { # hstrace vs-povray ARGS: stdout in $work/out, stderr in $work/err, status in $status
    "$hstrace" vs-povray "$@" >"$work/out" 2>"$work/err"; status=$?
}
clean_tmp() { [ -z "$(ls -A "$work/tmp")" ]; }
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
check "--help: exit status 0, names the options and exit statuses" \
    '[ $status -eq 0 ] && grep -q -- "--methods" "$work/out" && grep -q "4 POV-Ray not found" "$work/out"'
run "$work/box.pov" --report "$work/no/such/folder"
check "--report in a folder that does not exist: exit status 3 before any render" \
    '[ $status -eq 3 ] && grep -q "no/such/folder" "$work/err" && [ ! -e "$work/no" ]'
run "$work/box.pov" --methods hst,bogus
check "unknown method: exit status 1, lists the valid ones" '[ $status -eq 1 ] && grep -q "bogus.*valid: hst" "$work/err"'
run "$work/box.pov" --runs 0
check "--runs 0: exit status 1" '[ $status -eq 1 ] && grep -q "runs" "$work/err"'
run "$work/box.pov" -o "$work/x.png"
check "an output image is refused: exit status 1" '[ $status -eq 1 ] && [ ! -e "$work/x.png" ]'
run "$work/box.pov" --shadows hst
check "--shadows is refused (--methods chooses): exit status 1" '[ $status -eq 1 ] && grep -q -- "--methods" "$work/err"'
run "$work/box.pov" +Q4
check "+Q4 is refused: exit status 1" '[ $status -eq 1 ]'
run "$work/box.pov" --width 0
check "a render option's bad value: exit status 1, as when rendering" '[ $status -eq 1 ] && grep -q width "$work/err"'
run
check "no scene: exit status 1" '[ $status -eq 1 ] && grep -q "no scene" "$work/err"'
run "$work/missing.pov"
check "missing scene: exit status 3, names it" '[ $status -eq 3 ] && grep -q "missing.pov" "$work/err"'

mkdir "$work/empty"
(unset HSTRACE_POVRAY; PATH="$work/empty" "$hstrace" vs-povray "$work/box.pov" >"$work/out" 2>"$work/err"); status=$?
check "no povray in PATH: exit status 4 ($(cat "$work/err"))" \
    '[ $status -eq 4 ] && [ "$(cat "$work/err")" = "hstrace vs-povray: povray not found; install the Debian package povray" ]'
HSTRACE_POVRAY=/nonexistent "$hstrace" vs-povray "$work/box.pov" >"$work/out" 2>"$work/err"; status=$?
check "HSTRACE_POVRAY=/nonexistent: exit status 4, the message names the Debian package" \
    '[ $status -eq 4 ] && grep -q "povray not found; install the Debian package povray" "$work/err" && [ ! -s "$work/out" ]'

# A stand-in POV-Ray that fails as POV-Ray does on a parse error.
printf '#!/bin/sh\necho "Persistence of Vision(tm) Ray Tracer Version 3.7 banner" >&2\necho "==== [Parsing...] ====" >&2\necho "File '"'"'x.pov'"'"' line 3: Parse Error: stand-in failure" >&2\necho "Render failed" >&2\nexit 1\n' \
    >"$work/failing-povray"
chmod +x "$work/failing-povray"
HSTRACE_POVRAY="$work/failing-povray" "$hstrace" vs-povray "$work/box.pov" --width 16 --height 12 \
    >"$work/out" 2>"$work/err"; status=$?
check "POV-Ray fails on the scene: exit status 5" '[ $status -eq 5 ]'
check "... its message and the end of its output are shown, not its banner" \
    'grep -q "POV-Ray failed on .*box.pov" "$work/err" && grep -q "line 3: Parse Error: stand-in failure" "$work/err" && ! grep -q banner "$work/err"'
check "... no table, and the temporary folder is gone" '[ ! -s "$work/out" ] && clean_tmp'

# A stand-in POV-Ray that takes its time: a termination signal stops it.
printf '#!/bin/sh\nexec sleep 30\n' >"$work/slow-povray"
chmod +x "$work/slow-povray"
HSTRACE_POVRAY="$work/slow-povray" "$hstrace" vs-povray "$work/box.pov" --width 16 --height 12 \
    >"$work/out" 2>"$work/err" &
pid=$!
i=0
while [ $i -lt 100 ] && clean_tmp; do sleep 0.1; i=$((i + 1)); done   # until the renders have begun
sleep 0.5
kill -TERM $pid
{ wait $pid; } 2>/dev/null; status=$?
check "SIGTERM while rendering: ends by that signal (status $status)" '[ $status -eq 143 ]'
check "... and the temporary folder is gone" 'clean_tmp'

# --- with POV-Ray ------------------------------------------------------------
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
if [ -z "$povray" ]; then
    echo "# povray not installed: the comparisons are skipped"
    for d in "syntax error: exit status 2" "syntax error: FILE:LINE:COLUMN" "a row per method" \
             "speed-ups above 0" "RMSE below 0.01" "no interior mask pixels" "size and threads" "--report files" \
             "--report PNGs decode" "--report table values" "--report provenance" "--json keys" \
             "--runs, --methods and POV-Ray switches" "--json parses" "--methods hst,embree" "temporary folder removed"; do
        skip "$d"
    done
    echo "1..$n"
    exit 0
fi
HSTRACE_POVRAY=$povray
export HSTRACE_POVRAY

run "$work/bad.pov" --report "$work/badreport"
check "syntax error: exit status 2" '[ $status -eq 2 ]'
check "... the message names FILE:LINE:COLUMN ($(grep -m1 "bad.pov:" "$work/err")); no report folder made" \
    'grep -q "bad.pov:[0-9][0-9]*:[0-9][0-9]*: " "$work/err" && [ ! -e "$work/badreport" ]'

run "$work/box.pov" --width 64 --height 48 --threads 2 --report "$work/report"
cp "$work/out" "$work/table"
sed 's/^/# /' "$work/table"
methods="conventional cache volume hst"
ok_rows=1 ok_speed=1 ok_rmse=1 ok_interior=1
for m in $methods; do
    [ -n "$(row $m)" ] || ok_rows=0
    awk -v s="$(field $m 5)" 'BEGIN { exit !(s + 0 > 0) }' || ok_speed=0
    awk -v r="$(field $m 6)" 'BEGIN { exit !(r != "" && r + 0 < 0.01) }' || ok_rmse=0
    [ "$(field $m 8)" = 0 ] || ok_interior=0
done
check "exit status 0, a row for POV-Ray and for each of $methods" \
    '[ $status -eq 0 ] && [ -n "$(row povray)" ] && [ $ok_rows = 1 ]'
check "every speed-up against POV-Ray is above 0" '[ $ok_speed = 1 ]'
check "every method's RMSE against POV-Ray is below 0.01" '[ $ok_rmse = 1 ]'
check "no method has interior shadow-mask pixels against POV-Ray" '[ $ok_interior = 1 ]'
check "64x48 pixels and 2 threads for both programs" 'grep -q "64x48 pixels, 2 threads" "$work/out"'

check "--report: index.html and vs-povray.json written" '[ -s "$work/report/index.html" ] && [ -s "$work/report/vs-povray.json" ]'
pngs=$(sed -n 's/.*<img src="\([^"]*\)".*/\1/p' "$work/report/index.html")
npng=0 ok_png=1
for p in $pngs; do
    npng=$((npng + 1))
    # hstrace compare decodes both; an image equal to itself compares within limits.
    "$hstrace" compare "$work/report/$p" "$work/report/$p" --max-error 0 >/dev/null 2>&1 || ok_png=0
    case $p in *.png) ;; *) ok_png=0 ;; esac
done
check "--report: the page shows 13 PNGs (POV-Ray, 4 renders, 4 heat maps, 4 mask maps), all present and decoding" \
    '[ $npng -eq 13 ] && [ $ok_png = 1 ]'
ok_values=1
for m in povray $methods; do
    for k in 2 3 4 5 6 7 8; do
        grep -q "<td>$(field $m $k)</td>" "$work/report/index.html" || ok_values=0
    done
done
check "--report: the page's table holds the printed figures" '[ $ok_values = 1 ]'
check "--report: the page names the command, both versions, the date and the machine" \
    'grep -q "vs-povray .*box.pov --width 64" "$work/report/index.html" && grep -q "POV-Ray 3\.7" "$work/report/index.html" &&
     grep -q "hstrace [0-9]" "$work/report/index.html" && grep -q "<dt>Date</dt><dd>20" "$work/report/index.html" &&
     grep -q "<dt>Machine</dt><dd>.*core" "$work/report/index.html"'

run "$work/box.pov" +W64 +H48 +WT1 --methods hst,conventional --runs 2 --json
for k in scene width height threads runs povray_version povray methods method wall cpu shadow_testing speedup \
         rmse mask edge interior; do
    grep -q "\"$k\":" "$work/out" || { echo "# key $k missing"; ok_keys=0; }
done
check "--json: exit status 0, every key present" '[ $status -eq 0 ] && [ "${ok_keys:-1}" = 1 ]'
check "--runs 2, --methods hst,conventional and POV-Ray's switches +W64 +H48 +WT1 reach both programs" \
    'grep -q "\"runs\": 2," "$work/out" && grep -q "\"threads\": 1," "$work/out" && grep -q "\"width\": 64," "$work/out" &&
     [ "$(grep -c "\"method\":" "$work/out")" = 2 ]'
if command -v python3 >/dev/null 2>&1; then
    check "--json parses: hst then conventional, speed-up above 0, RMSE below 0.01, no interior mask pixels" \
        'python3 -c "
import json, sys
r = json.load(open(sys.argv[1]))
m = r[\"methods\"]
assert [x[\"method\"] for x in m] == [\"hst\", \"conventional\"]
assert r[\"runs\"] == 2 and r[\"threads\"] == 1 and (r[\"width\"], r[\"height\"]) == (64, 48)
assert all(x[\"speedup\"] > 0 and x[\"rmse\"] < 0.01 and x[\"mask\"][\"interior\"] == 0 for x in m)
" "$work/out"'
else
    check "--json is one object (python3 missing: not parsed)" '[ "$(head -c1 "$work/out")" = "{" ]'
fi
# embree is not exact: its disagreements with the shadow ray are measured
# (one more render with --verify-shadows) and shown; the exact methods' not.
if "$hstrace" --version | grep -q "Embree [0-9]"; then
    run "$work/box.pov" --width 64 --height 48 --threads 2 --methods hst,embree --json
    cp "$work/out" "$work/embree.json"
    run "$work/box.pov" --width 64 --height 48 --threads 2 --methods hst,embree
    check "--methods hst,embree: embree's disagreements with the shadow ray counted in the JSON and the table ($(row embree | awk '{ print $9, $10, $11 }')), none for the exact hst" \
        '[ $status -eq 0 ] && grep -q "vs shadow ray" "$work/out" && [ "$(field hst 9)" = - ] &&
         row embree | grep -Eq " [0-9]+ of [1-9][0-9]*$" &&
         { ! command -v python3 >/dev/null 2>&1 || python3 -c "
import json, sys
m = {x[\"method\"]: x for x in json.load(open(sys.argv[1]))[\"methods\"]}
assert m[\"hst\"][\"verified\"] is None and m[\"hst\"][\"disagreements\"] is None
assert m[\"embree\"][\"verified\"] > 0 and 0 <= m[\"embree\"][\"disagreements\"] <= m[\"embree\"][\"verified\"]
" "$work/embree.json"; }'
else
    n=$((n + 1)); echo "ok $n - --methods hst,embree # SKIP embree not built"
fi
check "the temporary folder is removed after every run" 'clean_tmp'
echo "1..$n"
