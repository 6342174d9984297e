#!/bin/sh
# Writes a POV-Ray 3.7 scene for measurements of scale: one mesh2 of about
# TRIANGLES triangles, made of bumpy closed "rocks" on a square grid a little
# above a floor polygon, lit by LIGHTS point lights (1 to 8, default 3) on a
# circle at moderate distance, so that every rock throws shadows on the floor
# and on its neighbours. The exact triangle count is written in a comment
# line "// triangles: N". The scene is the same for the same arguments.
#
# usage: make-mesh.sh TRIANGLES [LIGHTS] > scene.pov
#   e.g. scenes/make-mesh.sh 1000000 4 > big.pov && hstrace big.pov --stats
# POSIX sh and awk only; 10^6 triangles take a few seconds.
# Exit status: 0 done, 2 bad usage.
set -eu
usage() {
    echo "usage: $0 TRIANGLES [LIGHTS] > scene.pov" >&2
    echo "  TRIANGLES  about how many triangles (1 to 100000000)" >&2
    echo "  LIGHTS     point lights, 1 to 8 (default 3)" >&2
    exit 2
}
[ $# -ge 1 ] && [ $# -le 2 ] || usage
tris=$1
lights=${2:-3}
case $tris in '' | *[!0-9]*) usage ;; esac
case $lights in '' | *[!0-9]*) usage ;; esac
# Compare as strings' lengths first, so that huge numbers cannot overflow.
[ ${#tris} -le 9 ] && [ "$tris" -ge 1 ] && [ "$tris" -le 100000000 ] || usage
[ ${#lights} -le 1 ] && [ "$lights" -ge 1 ] && [ "$lights" -le 8 ] || usage

awk -v N="$tris" -v L="$lights" '
function round(v) { return int(v + 0.5) }
BEGIN {
    pi = atan2(0, -1)
    # G x G rocks of NL bands of latitude and NM of longitude; a rock is
    # 2*NM*(NL-1) triangles (fans at the poles, two per facet elsewhere).
    G = round(sqrt(N / 400)); if (G < 1) G = 1
    R = G * G
    B = N / R
    # NM near sqrt(B), chosen so that the total comes closest to N
    # (within 2% from 600 triangles up, 4% from 60 up)
    s = sqrt(B); best = -1
    lo = int(s / 1.6); if (lo < 3) lo = 3
    hi = int(s * 1.6) + 1; if (hi < lo) hi = lo
    for (m = lo; m <= hi; m++) {
        nl = round(B / (2 * m)) + 1; if (nl < 2) nl = 2
        d = R * 2 * m * (nl - 1) - N; if (d < 0) d = -d
        if (best < 0 || d < best) { best = d; NM = m; NL = nl }
    }
    per = 2 * NM * (NL - 1)
    nt = R * per
    nvr = NM * (NL - 1) + 2             # vertices of one rock
    nv = R * nvr
    size = 12                           # the rocks cover size x size
    sp = size / G
    r0 = 0.33 * sp                      # mean radius of a rock

    printf "// make-mesh.sh %d %d -- generated for hstrace scale measurements:\n", N, L
    printf "// %d bumpy rock%s (%d x %d) of %d triangles each, above a floor polygon,\n", \
        R, (R > 1 ? "s" : ""), G, G, per
    printf "// lit by %d point light%s.\n", L, (L > 1 ? "s" : "")
    printf "// triangles: %d\n", nt
    print  "#version 3.7;"
    print  "global_settings { assumed_gamma 1 }"
    print  "camera { location <0, 10.5, -15.5> look_at <0, 0.2, 0.6> angle 52 right x*4/3 }"
    print  "background { color rgb <0.06, 0.07, 0.10> }"
    for (l = 0; l < L; l++) {
        a = 2 * pi * l / L + 0.6
        printf "light_source { <%.4f, %.4f, %.4f> color rgb <%.4f, %.4f, %.4f> }\n", \
            11 * cos(a), 7 + 2 * (l % 3), 11 * sin(a), \
            (0.95 - 0.05 * (l % 3)) / L * 1.3, 0.9 / L * 1.3, (0.80 + 0.07 * (l % 3)) / L * 1.3
    }
    h = size / 2 + 3
    printf "polygon { 5, <%g, 0, %g>, <%g, 0, %g>, <%g, 0, %g>, <%g, 0, %g>, <%g, 0, %g>\n", \
        -h, -h, h, -h, h, h, -h, h, -h, -h
    print  "  pigment { color rgb <0.70, 0.68, 0.63> } }"

    print  "mesh2 {"
    printf "  vertex_vectors { %d", nv
    for (k = 0; k < R; k++) {
        cx = -size / 2 + sp * (k % G + 0.5)
        cz = -size / 2 + sp * (int(k / G) + 0.5)
        p1 = 1.7 * k; p2 = 2.9 * k; p3 = 0.7 * k
        cy = 1.4 * r0 + 0.05 * sp        # the lowest bump stays above the floor
        # poles first, then the rings from the top down
        printf ",\n    <%.6g, %.6g, %.6g>, <%.6g, %.6g, %.6g>", cx, cy + 0.85 * r0, cz, cx, cy - 0.85 * r0, cz
        for (j = 1; j < NL; j++) {
            th = pi * j / NL
            for (i = 0; i < NM; i++) {
                ph = 2 * pi * i / NM
                rr = r0 * (1 + 0.22 * sin(3 * th + p1) * cos(2 * ph + p2) + 0.12 * sin(5 * ph + p3) * sin(th))
                printf ",\n    <%.6g, %.6g, %.6g>", cx + rr * sin(th) * cos(ph), cy + 0.85 * rr * cos(th), cz + rr * sin(th) * sin(ph)
            }
        }
    }
    print "\n  }"
    printf "  face_indices { %d", nt
    for (k = 0; k < R; k++) {
        o = k * nvr
        top = o; bot = o + 1
        for (i = 0; i < NM; i++) {
            i1 = (i + 1) % NM
            printf ",\n    <%d, %d, %d>", top, o + 2 + i, o + 2 + i1
            for (j = 1; j < NL - 1; j++) {
                a = o + 2 + (j - 1) * NM; b = a + NM
                printf ", <%d, %d, %d>, <%d, %d, %d>", a + i, b + i, b + i1, a + i, b + i1, a + i1
            }
            a = o + 2 + (NL - 2) * NM
            printf ", <%d, %d, %d>", bot, a + i1, a + i
        }
    }
    print "\n  }"
    print "  pigment { color rgb <0.62, 0.45, 0.30> }"
    print "  finish { phong 0.3 phong_size 30 }"
    print "}"
}'
