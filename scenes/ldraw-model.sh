#!/bin/sh
# Writes a brick model in the style of LDraw exports (LeoCAD, L3P, LDView) to
# standard output: each part declared once as a union of meshes (flat
# `triangle`s, and `smooth_triangle`s for round parts, as LDView writes
# them), a few faces or meshes textured inside the part, and the parts
# placed by `object { PART matrix <...> texture/material {...} }`, many
# times each. Written for hstrace's instancing (issue 42): the figures of
# bench/instancing.sh and the scene of tests/instancing.sh.
#
# Usage: sh scenes/ldraw-model.sh PLACEMENTS [SEGMENTS]
#   PLACEMENTS  parts placed (8 x 8 a layer, layer on layer, on a
#               baseplate placed once)
#   SEGMENTS    segments around a stud (default 32: parts of about 400 to
#               2,100 triangles; 8 for a small test scene)
# The model is the same for the same arguments (no randomness).
set -eu
placements=${1:?usage: ldraw-model.sh PLACEMENTS [SEGMENTS]}
segments=${2:-32}
exec awk -v N="$placements" -v S="$segments" '
function tri(a, b, c) { printf "  triangle { %s, %s, %s }\n", a, b, c; ntri++ }
function texttri(a, b, c, t) { printf "  triangle { %s, %s, %s texture { %s } }\n", a, b, c, t; ntri++ }
function smooth(a, na, b, nb, c, nc) { printf "  smooth_triangle { %s, %s, %s, %s, %s, %s }\n", a, na, b, nb, c, nc; ntri++ }
function v(x, y, z) { return sprintf("<%.4f,%.4f,%.4f>", x, y, z) }
# a box open at the bottom (LDraw bricks are hollow underneath)
function box(x0, y0, z0, x1, y1, z1) {
    tri(v(x0,y1,z0), v(x1,y1,z0), v(x1,y1,z1)); tri(v(x0,y1,z0), v(x1,y1,z1), v(x0,y1,z1))
    tri(v(x0,y0,z0), v(x1,y0,z0), v(x1,y1,z0)); tri(v(x0,y0,z0), v(x1,y1,z0), v(x0,y1,z0))
    tri(v(x0,y0,z1), v(x1,y0,z1), v(x1,y1,z1)); tri(v(x0,y0,z1), v(x1,y1,z1), v(x0,y1,z1))
    tri(v(x0,y0,z0), v(x0,y0,z1), v(x0,y1,z1)); tri(v(x0,y0,z0), v(x0,y1,z1), v(x0,y1,z0))
    tri(v(x1,y0,z0), v(x1,y0,z1), v(x1,y1,z1)); tri(v(x1,y0,z0), v(x1,y1,z1), v(x1,y1,z0))
}
# a stud: radius 6, height 4, on top of y = y0, centred at (cx, cz)
function stud(cx, cz, y0,   i, a0, a1, p0, p1, q0, q1, c) {
    c = v(cx, y0 + 4, cz)
    for (i = 0; i < S; i++) {
        a0 = 2 * 3.14159265358979 * i / S; a1 = 2 * 3.14159265358979 * (i + 1) / S
        p0 = v(cx + 6 * cos(a0), y0, cz + 6 * sin(a0)); p1 = v(cx + 6 * cos(a1), y0, cz + 6 * sin(a1))
        q0 = v(cx + 6 * cos(a0), y0 + 4, cz + 6 * sin(a0)); q1 = v(cx + 6 * cos(a1), y0 + 4, cz + 6 * sin(a1))
        tri(p0, p1, q1); tri(p0, q1, q0); tri(c, q0, q1)
    }
}
function studs(nx, nz, y0,   i, j) {
    for (i = 0; i < nx; i++) for (j = 0; j < nz; j++) stud(10 + 20 * i, 10 + 20 * j, y0)
}
# a dome of smooth triangles: radius r over (cx, cz) from y0, rings x S segments
function dome(cx, cy, cz, r,   i, j, rings, t0, t1, a0, a1, p, n) {
    rings = S / 2
    for (i = 0; i < rings; i++) {
        t0 = 1.5707963 * i / rings; t1 = 1.5707963 * (i + 1) / rings
        for (j = 0; j < S; j++) {
            a0 = 6.2831853 * j / S; a1 = 6.2831853 * (j + 1) / S
            n[0] = v(cos(t0) * cos(a0), sin(t0), cos(t0) * sin(a0)); n[1] = v(cos(t0) * cos(a1), sin(t0), cos(t0) * sin(a1))
            n[2] = v(cos(t1) * cos(a1), sin(t1), cos(t1) * sin(a1)); n[3] = v(cos(t1) * cos(a0), sin(t1), cos(t1) * sin(a0))
            p[0] = v(cx + r * cos(t0) * cos(a0), cy + r * sin(t0), cz + r * cos(t0) * sin(a0))
            p[1] = v(cx + r * cos(t0) * cos(a1), cy + r * sin(t0), cz + r * cos(t0) * sin(a1))
            p[2] = v(cx + r * cos(t1) * cos(a1), cy + r * sin(t1), cz + r * cos(t1) * sin(a1))
            p[3] = v(cx + r * cos(t1) * cos(a0), cy + r * sin(t1), cz + r * cos(t1) * sin(a0))
            smooth(p[0], n[0], p[1], n[1], p[2], n[2])
            if (i < rings - 1) smooth(p[0], n[0], p[2], n[2], p[3], n[3])
        }
    }
}
BEGIN {
    print "// LDraw model as LeoCAD / L3P / LDView export it: parts declared once,"
    print "// placed by matrix. Written by scenes/ldraw-model.sh " N " " S "."
    print "#version 3.7;"
    print "global_settings { assumed_gamma 1.0 }"
    print "background { color rgb <0.5, 0.55, 0.65> }"
    print "camera { location <-300, 520, -560> look_at <330, 40, 170> angle 50 right x*4/3 }"
    print "light_source { <-400, 900, -600> color rgb <0.8, 0.8, 0.8> }"
    print "light_source { <700, 500, -300> color rgb <0.4, 0.4, 0.45> }"
    print "#declare lc_4 = texture { pigment { rgb <0.70, 0.08, 0.05> } finish { ambient 0.15 diffuse 0.7 phong 0.3 phong_size 30 } }"
    print "#declare lc_1 = texture { pigment { rgb <0.05, 0.20, 0.60> } finish { ambient 0.15 diffuse 0.7 phong 0.3 phong_size 30 } }"
    print "#declare lc_14 = texture { pigment { rgb <0.85, 0.70, 0.10> } finish { ambient 0.15 diffuse 0.7 phong 0.3 phong_size 30 } }"
    print "#declare lc_15 = texture { pigment { rgb <0.90, 0.90, 0.88> } finish { ambient 0.15 diffuse 0.7 } }"
    print "#declare lc_0 = texture { pigment { rgb <0.03, 0.03, 0.03> } finish { ambient 0.15 diffuse 0.7 phong 0.5 } }"
    print "#declare lc_2 = texture { pigment { rgb <0.10, 0.45, 0.15> } finish { ambient 0.15 diffuse 0.7 } }"
    print "#declare lc_47 = texture { pigment { rgbf <0.85, 0.85, 0.90, 0.7> } finish { ambient 0.1 diffuse 0.5 } }"
    # 3001 brick 2 x 4: body and studs, two meshes
    print "#declare lc_3001 = union {"
    print " mesh {"; box(0, 0, 0, 80, 24, 40); print " }"
    print " mesh {"; studs(4, 2, 24); print " }"
    print "}"
    # 3003 brick 2 x 2: one mesh, one face printed black (a texture inside the mesh)
    print "#declare lc_3003 = union {"
    print " mesh {"; box(0, 0, 0, 40, 24, 40); studs(2, 2, 24)
    texttri(v(0, 4, -0.01), v(40, 4, -0.01), v(40, 20, -0.01), "lc_0")
    print " }"
    print "}"
    # 3710 plate 1 x 4
    print "#declare lc_3710 = union {"
    print " mesh {"; box(0, 0, 0, 80, 8, 20); studs(4, 1, 8); print " }"
    print "}"
    # 553 dome 2 x 2: a plate body and a smooth dome textured inside the part
    print "#declare lc_553 = union {"
    print " mesh {"; box(0, 0, 0, 40, 8, 40); print " }"
    print " mesh {"; dome(20, 8, 20, 19); print "  texture { lc_15 }"; print " }"
    print "}"
    # the baseplate, placed once (flattened: a part used once shares nothing)
    print "#declare lc_3811 = union {"
    print " mesh {"; box(0, -4, 0, 680, 0, 360); print " }"
    print " mesh {"; for (i = 0; i < 34; i++) for (j = 0; j < 18; j++) if ((i + j) % 3 == 0) stud(10 + 20 * i, 10 + 20 * j, 0); print " }"
    print "}"
    print "plane { y, -4.5 texture { pigment { rgb <0.6, 0.6, 0.55> } finish { ambient 0.1 diffuse 0.6 } } }"
    print "object { lc_3811 matrix <1,0,0, 0,1,0, 0,0,1, -6,0,-8> texture { lc_2 } }"
    split("lc_4 lc_1 lc_14 lc_15 lc_47 lc_4 lc_1 lc_14", colour, " ")
    split("lc_3001 lc_3003 lc_3710 lc_553 lc_3001 lc_3003", part, " ")
    split("80 40 80 40 80 40", width, " ")
    split("40 40 20 40 40 40", depth, " ")
    # a wall of parts, layer on layer: 8 x 8 spots of 84 x 44 a layer, each
    # part turned about the centre of its spot (a quarter turn only for the
    # square ones), 0.25 between layers so that no two parts touch
    for (k = 0; k < N; k++) {
        layer = int(k / 64); spot = k % 64
        cx = 84 * (spot % 8) + 42; cz = 44 * int(spot / 8) + 22
        q = 1 + (k * 7 + layer) % 6
        turn = (k * 5 + layer) % 4
        if (width[q] != depth[q]) turn = 2 * (turn % 2)
        c = turn == 0 ? 1 : turn == 2 ? -1 : 0
        s = turn == 1 ? 1 : turn == 3 ? -1 : 0
        # on the top layer one part in four turned by some angle and
        # stretched (loose parts, or a scaled copy): the
        # rounding of a general matrix, and normals by its inverse transpose
        sy = 1; sz = 1
        if (layer == int((N - 1) / 64) && k % 4 == 1) {
            a = (15 + (k * 37) % 60) * 3.14159265358979 / 180
            c = cos(a); s = sin(a); sy = 1.25; sz = 0.85
        }
        # x = c x + s sz z, z = -s x + c sz z about the origin; then the part centre to the spot centre
        w = width[q] / 2; d = depth[q] / 2
        tx = cx - (c * w + s * sz * d); tz = cz - (-s * w + c * sz * d)
        y = 24.25 * layer + 0.25
        col = colour[1 + (k * 3 + layer) % 8]
        m = sprintf("%.10g,0,%.10g, 0,%g,0, %.10g,0,%.10g", c, -s, sy, s * sz, c * sz)
        if (k % 2)
            printf "object {\n %s\n matrix <%s, %.4f,%.4f,%.4f>\n texture { %s }\n}\n", part[q], m, tx, y, tz, col
        else
            printf "object { %s matrix <%s,%.4f,%.4f,%.4f> material { texture { %s } } }\n", part[q], m, tx, y, tz, col
    }
}'
