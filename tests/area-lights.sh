#!/bin/sh
# Area lights (issue 19), in TAP, against the installed POV-Ray.
#
# 1. Each kind of area light, one at a time, over a box, a polygon with a
#    hole and a see-through pane on a floor: point, spotlight, cylinder and
#    parallel lights; adaptive 0, 1, 2 and the default (every sample);
#    circular, orient, area_illumination, fading; the same image as
#    POV-Ray's (no jitter: the samples are where POV-Ray puts them, so the
#    images agree to rounding). Each must differ from its +Q4 render
#    (where both renderers take the light as a point at its centre), so
#    that an area light sampled as a point cannot pass; the +Q4 render
#    matches POV-Ray's +Q4 too. The RMSEs measured on 2026-12-02 (64x48,
#    half-float EXR) are in the table.
# 2. Jitter: POV-Ray's jitter comes from a random number generator, so two
#    of its renders differ; hstrace's image of scenes/soft.pov and
#    scenes/spot.pov with Jitter=1 must be no farther from one POV-Ray
#    render than 1.5 times the distance between two (RMSE), and the same
#    image for 1 and 2 threads and every run.
# 3. Every shadow method decides every sample as the shadow ray does:
#    --verify-shadows with anti-aliasing, 0 disagreements (hst's beams
#    included: where they prove a point lit or in umbra, each sample is
#    still checked); the same image from every method; --stats reports the
#    samples, the lights' plans and the beams, which must keep proving.
# 4. Random scenes (seeded) of occluders under random area lights of every
#    kind: hst's beams against every sample's shadow ray, 0 disagreements.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (path or name of
# povray; default povray).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
hstrace="$builddir/hstrace"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstarea.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
case $hstrace in /*) ;; *) hstrace=$(cd "$(dirname "$hstrace")" && pwd)/$(basename "$hstrace") ;; esac
scenes=$(cd "$srcdir/scenes" && pwd)
run() { (cd "$work" && "$hstrace" "$@") >"$work/out" 2>"$work/err"; status=$?; }
povray=$(command -v "${POVRAY:-povray}" 2>/dev/null || true)
pov() { povray_threads 1 "$@"; }
povray_threads() { # N ARGS...: POV-Ray on N threads
    (t=$1 && shift && cd "$work" && "$povray" "$@" -D -GA "+WT$t" </dev/null >/dev/null 2>&1)
}
# json_number FILE KEY: the first number after "KEY": in FILE.
json_number() { sed -n "s/.*\"$2\": \([0-9][0-9.]*\).*/\1/p" "$1" | head -1; }
# rmse_of A B: the RMSE hstrace compare prints for images A and B.
rmse_of() { "$hstrace" compare "$1" "$2" | awk '$1 == "RMSE" { sub(/,$/, "", $2); print $2 }'; }

# --- 1. each kind of area light ------------------------------------------------
probe() {
    cat <<EOF
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -6> look_at <0, 0.3, 0> angle 50 }
light_source { $1 }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.8 } }
box { <-1, 0.5, -1>, <0.5, 0.7, 0.5> pigment { rgb <0.9, 0.2, 0.2> } finish { phong 0.5 specular 0.3 } }
polygon { 10, <-2, 1>, <2, 1>, <2, 2>, <-2, 2>, <-2, 1>, <-1, 1.3>, <1, 1.3>, <1, 1.7>, <-1, 1.7>, <-1, 1.3>
    rotate 90*x translate 1.5*y pigment { rgb 0.7 } }
triangle { <1, 0.2, -2>, <2, 0.2, -2>, <1.5, 1.2, -1.5> pigment { rgbf <0.2, 0.4, 0.9, 0.6> } }
EOF
}
n=0
while IFS='|' read -r light measured; do
    n=$((n + 1))
    probe "$light" >"$work/p$n.pov"
    run "p$n.pov" +W64 +H48 -o "p$n.exr"
    if [ "$status" != 0 ]; then
        not_ok "light_source { $light }: renders ($(head -n 1 "$work/err"))"
        continue
    fi
    run "p$n.pov" +W64 +H48 +Q4 -o "p$n-q4.exr"
    # shellcheck disable=SC2016 # the inner shell expands its arguments
    check "light_source { $light }: soft shadows (differs from its +Q4 point light by RMSE > 0.003)" \
        sh -c '! "$1" compare "$2" "$3" --max-rmse 0.003 >/dev/null' sh "$hstrace" "$work/p$n.exr" "$work/p$n-q4.exr"
    if [ -n "$povray" ]; then
        pov "+Ip$n.pov" +W64 +H48 +FE "+Op$n-pov.exr"
        check "light_source { $light }: POV-Ray's samples (RMSE $measured measured; limit 1e-5, no pixel off)" \
            "$hstrace" compare "$work/p$n-pov.exr" "$work/p$n.exr" --max-rmse 1e-5 --max-share 0
        pov "+Ip$n.pov" +W64 +H48 +Q4 +FE "+Op$n-q4-pov.exr"
        check "... and at +Q4, a point light at the centre, as POV-Ray" \
            "$hstrace" compare "$work/p$n-q4-pov.exr" "$work/p$n-q4.exr" --max-rmse 1e-5 --max-share 0
    else
        skip "light_source { $light }: POV-Ray's samples" "povray not installed"
        skip "... and at +Q4, a point light at the centre, as POV-Ray" "povray not installed"
    fi
done <<'LIGHTS'
<2, 5, -2> rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 5, 5|below 5e-7
<2, 5, -2> rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 9, 9 adaptive 0|below 5e-7
<2, 5, -2> rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 6, 4 adaptive 1|below 5e-7
<2, 5, -2> rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 17, 17 adaptive 2|below 5e-7
<2, 5, -2> rgb <0.3, 0.2, 0.1> area_light <2, 0, 0>, <0, 0, 2>, 9, 9 adaptive 0|below 5e-7
<2, 5, -2> rgb 1 area_light <2, 0, 1>, <0, 1, 0>, 1, 7|below 5e-7
<2, 5, -2> rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 8, 8 circular orient adaptive 1|below 5e-7
<-2, 3, -3> rgb 1 area_light <3, 0, 0>, <0, 0, 1>, 5, 3 orient|2e-6
<2, 5, -2> rgb 1.5 spotlight point_at <0, 0, 0> radius 20 falloff 30 tightness 5 area_light <1, 0, 0>, <0, 0, 1>, 6, 4 fade_distance 3 fade_power 2|below 5e-7
<2, 5, -2> rgb 1 parallel point_at <0, 0, 0> area_light <0.5, 0, 0>, <0, 0, 0.5>, 5, 5|below 5e-7
<2, 5, -2> rgb 1 cylinder point_at <0, 0, 0> radius 2 falloff 3 area_light <0.5, 0, 0>, <0, 0, 0.5>, 5, 5 adaptive 1|below 5e-7
<2, 5, -2> rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 5, 5 area_illumination|below 5e-7
<2, 3, -2> rgb 1 spotlight point_at <0, 0, 0> radius 15 falloff 25 area_light <2, 0, 0>, <0, 0, 2>, 4, 4 area_illumination on fade_distance 2 fade_power 1|below 5e-7
<2, 5, -2> rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 5, 5 rotate 30*y translate <-1, 0, 0>|below 5e-7
LIGHTS

# --- 2. jitter ---------------------------------------------------------------------
for scene in soft spot; do
    run "$scenes/$scene.pov" +W320 +H240 Declare=Jitter=1 -o "$scene-j.exr"
    check "$scene.pov with jitter: renders" exited 0
    run "$scenes/$scene.pov" +W320 +H240 Declare=Jitter=1 +WT1 -o "$scene-j1.exr"
    check "$scene.pov with jitter: 1 thread gives the same image as 2" \
        "$hstrace" compare "$work/$scene-j.exr" "$work/$scene-j1.exr" --max-error 0
    if [ -n "$povray" ]; then
        # On one thread POV-Ray draws the same random numbers in every run;
        # on two, which thread renders which block decides them.
        pov "+I$scenes/$scene.pov" +W320 +H240 Declare=Jitter=1 +FE "+O$scene-pov1.exr"
        povray_threads 2 "+I$scenes/$scene.pov" +W320 +H240 Declare=Jitter=1 +FE "+O$scene-pov2.exr"
        between=$(rmse_of "$work/$scene-pov1.exr" "$work/$scene-pov2.exr")
        ours=$(rmse_of "$work/$scene-pov1.exr" "$work/$scene-j.exr")
        check "$scene.pov with jitter: POV-Ray's two runs differ (RMSE $between > 0.001)" above "$between" 0.001
        check "$scene.pov with jitter: RMSE against POV-Ray $ours, at most 1.5 x its runs' $between" \
            within "$ours" "$(awk -v b="$between" 'BEGIN { print 1.5 * b }')"
    else
        skip "$scene.pov with jitter: POV-Ray's two runs differ" "povray not installed"
        skip "$scene.pov with jitter: RMSE against POV-Ray" "povray not installed"
    fi
done

# --- 3. every method, every sample -------------------------------------------------
methods=$("$hstrace" --help 2>&1 | sed -n 's/.*--shadows METHOD.*(\(.*\)).*/\1/p' | head -n 1)
for method in conventional cache volume hst embree; do
    run "$scenes/spot.pov" +W96 +H72 --shadows "$method" -o "m-$method.exr"
    if [ "$status" = 0 ]; then
        :
    elif grep -q "embree" "$work/err" && [ "$method" = embree ]; then
        skip "--shadows embree on area lights" "built without Embree"
        continue
    fi
    check "spot.pov, --shadows $method: renders" exited 0
    [ "$method" = conventional ] ||
        check "spot.pov, --shadows $method: the shadow ray's image" \
            "$hstrace" compare "$work/m-conventional.exr" "$work/m-$method.exr" --max-error 0
    run "$scenes/soft.pov" +W64 +H48 +A0.1 +R2 --shadows "$method" --verify-shadows --stats-json "v-$method.json" \
        -o "v-$method.exr"
    check "soft.pov with anti-aliasing, --shadows $method: renders" exited 0
    if command -v python3 >/dev/null 2>&1; then
        # a method with no volumes to time (volume here) once wrote N_th as "inf"
        check "... its --stats-json is JSON" python3 -m json.tool "$work/v-$method.json"
    else
        skip "... its --stats-json is JSON" "python3 not installed"
    fi
    samples=$(json_number "$work/v-$method.json" area_samples)
    check "... every sample verified: 0 disagreements (of $samples samples)" \
        same_count "$(json_number "$work/v-$method.json" disagreements)" 0
    check "... the samples counted (more than 10 per shading point of an area light)" \
        above "${samples:-0}" "$((10 * $(json_number "$work/v-$method.json" area_points)))"
done
: "$methods"
# --- 4. random scenes: the beams' proofs against every sample's ray ---------------
# Random occluders (a strip of triangles sharing edges, a polygon with a
# hole, boxes, a see-through pane, triangles in the light's plane) under a
# random area light of every kind; hst's answers against the shadow ray's
# for every sample (--verify-shadows), and the beams must prove some points.
proved=0
for seed in 1 2 3 4 5 6 7 8 9 10 11 12; do
    awk -v seed="$seed" 'BEGIN {
        srand(seed)
        kinds[0] = ""; kinds[1] = "jitter"; kinds[2] = "circular"; kinds[3] = "circular orient"
        kinds[4] = "adaptive 0"; kinds[5] = "adaptive 1 jitter"; kinds[6] = "orient circular jitter"
        n1 = 2 + int(rand() * 7); n2 = 2 + int(rand() * 7)
        k = kinds[int(rand() * 7)]
        if (k ~ /circular/) { n2 = n1 }
        lx = rand() * 4 - 2; ly = 3 + rand() * 3; lz = rand() * 4 - 3
        s1 = 0.3 + rand() * 1.5; s2 = 0.3 + rand() * 1.5
        printf "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
        printf "camera { location <0, 3, -5> look_at <0, 0.5, 0> angle 55 }\n"
        kind = rand()
        printf "light_source { <%.4f, %.4f, %.4f> rgb 1 ", lx, ly, lz
        if (kind < 0.2) printf "parallel point_at <0, 0, 0> "
        else if (kind < 0.35) printf "spotlight point_at <0, 0, 0> radius 25 falloff 40 "
        printf "area_light <%.4f, 0, %.4f>, <%.4f, %.4f, %.4f>, %d, %d %s }\n", s1, rand() - 0.5, rand() - 0.5, rand() * 0.5, s2, n1, n2, k
        printf "plane { y, 0 pigment { rgb 0.8 } }\n"
        printf "mesh {\n"
        x = rand() * 2 - 1.5; z = rand() * 2 - 1; h = 0.8 + rand()
        for (i = 0; i < 6; i++) {
            printf "  triangle { <%.4f, %.4f, %.4f>, <%.4f, %.4f, %.4f>, <%.4f, %.4f, %.4f> }\n", \
                x + i * 0.3, h, z, x + i * 0.3 + 0.3, h + (i % 2) * 0.2, z, x + i * 0.3, h + 0.1, z + 0.5
            printf "  triangle { <%.4f, %.4f, %.4f>, <%.4f, %.4f, %.4f>, <%.4f, %.4f, %.4f> }\n", \
                x + i * 0.3 + 0.3, h + (i % 2) * 0.2, z, x + i * 0.3 + 0.3, h + 0.1 + rand() * 0.3, z + 0.5, x + i * 0.3, h + 0.1, z + 0.5
        }
        printf "  pigment { rgb <0.9, 0.5, 0.3> } }\n"
        hx = rand() * 2 - 1; hy = 1 + rand() * 1.5
        printf "polygon { 10, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>, <-0.4, -0.3>, <0.5, -0.3>, <0.5, 0.4>, <-0.4, 0.4>, <-0.4, -0.3>\n"
        printf "  pigment { rgb 0.6 } rotate <%.2f, %.2f, 0> translate <%.4f, %.4f, %.4f> }\n", 60 + rand() * 60, rand() * 90, hx, hy, rand()
        printf "box { <-0.3, 0, -0.3>, <0.3, %.4f, 0.3> rotate %.2f*y translate <%.4f, 0, %.4f> pigment { rgb 0.5 } }\n", 0.3 + rand(), rand() * 90, rand() * 3 - 1.5, rand() * 2 - 1.5
        printf "polygon { 5, <-0.5, 0>, <0.5, 0>, <0.5, 0.7>, <-0.5, 0.7>, <-0.5, 0> pigment { rgbf <0.4, 0.8, 0.6, 0.7> } rotate %.2f*y translate <%.4f, 0, %.4f> }\n", rand() * 180, rand() * 2 - 1, rand() * 2 - 2
        printf "triangle { <%.4f, %.4f, %.4f>, <%.4f, %.4f, %.4f>, <%.4f, %.4f, %.4f> pigment { rgb 0.4 } }\n", lx - 1, ly, lz - 1, lx + 1, ly, lz - 1, lx, ly, lz + 1.5
    }' >"$work/r$seed.pov"
    run "r$seed.pov" +W48 +H36 --verify-shadows --stats-json "r$seed.json" -o "r$seed.exr"
    check "random scene $seed: renders" exited 0
    check "random scene $seed: hst agrees with the shadow ray on every sample" \
        same_count "$(json_number "$work/r$seed.json" disagreements)" 0
    lit=$(json_number "$work/r$seed.json" area_beam_lit)
    umbra=$(json_number "$work/r$seed.json" area_beam_umbra)
    proved=$((proved + ${lit:-0} + ${umbra:-0}))
done
check "random scenes: the beams proved $proved points uniform (more than 0)" above "$proved" 0

run "$scenes/soft.pov" +W64 +H48 --stats -o s.exr
check "--stats: the area lights' samples" grep -q "area lights .* shading points sampled them: .* samples decided" "$work/err"
check "--stats: each area light's plan says it has no volumes, the beam or the shadow ray deciding" \
    grep -q "light 2   an area light: no volumes; hst's beam, or the shadow ray, decides its samples" "$work/err"
check "--stats: the beams, and the points they proved uniform" \
    grep -q "area beams  .* points (100.0% of them): .* proved lit, .* in umbra" "$work/err"

# hst's beams prove most points lit or in umbra without a ray: at least
# half the points measured on 2026-12-02 (160x120), so that a beam that
# stops proving fails here (the images are the shadow ray's either way,
# section 3).
while read -r scene lit umbra; do
    run "$scenes/$scene.pov" +W160 +H120 --stats-json "beam-$scene.json" -o "beam-$scene.exr"
    got_lit=$(json_number "$work/beam-$scene.json" area_beam_lit)
    got_umbra=$(json_number "$work/beam-$scene.json" area_beam_umbra)
    check "$scene.pov: hst's beams proved $got_lit points lit >= $((lit / 2)) (measured $lit)" at_least "$got_lit" "$((lit / 2))"
    check "$scene.pov: ... and $got_umbra in umbra >= $((umbra / 2)) (measured $umbra)" at_least "$got_umbra" "$((umbra / 2))"
done <<'BEAMS'
soft 46089 925
spot 23443 69
BEAMS
run "$scenes/soft.pov" +W64 +H48 +Q4 --stats -o s4.exr
check "+Q4: an area light is a point light at its centre, no samples" sh -c "! grep -q 'area lights' '$work/err'"

tap_end
