/* bicubic_patch as POV-Ray 3.7 intersects it (bezier.cpp): the patch, its
 * control points already in world space (POV-Ray moves them with every
 * transform and subdivides afresh), is split at the middle of u and v
 * (de Casteljau, as bezier_split_left_right and bezier_split_up_down) until
 * a piece is flat enough -- its control points within `flatness` of the
 * plane of three of its corners -- or u_steps and v_steps levels are spent
 * (only u split once v_steps are spent, and the reverse). A piece is two
 * triangles, corners P[0][0] P[0][3] P[3][3] and P[0][0] P[3][3] P[3][0],
 * shaded by the patch's own normals at those corners interpolated by the
 * hit's barycentric weights (intersect_subpatch): a smooth triangle.
 * Type 0 (subdivided per ray) and type 1 (subdivided once) make the same
 * triangles; POV-Ray skips the thin ones (area below BEZIER_EPSILON of
 * their sides' product), and so does this. uv_mapping takes the piece's
 * (u, v) through uv_vectors as POV-Ray's Compute_Texture_UV does, at the
 * corners: exact where the four uv_vectors form a parallelogram (the
 * default square among them). A patch has no inside. */
#include "planar_shapes.h"

#include <math.h>

/* POV-Ray's BEZIER_EPSILON and EPSILON (bezier.cpp, frame.h). */
#define BEZIER_EPSILON 1.0e-10
#define POV_EPSILON 1.0e-10

typedef Vec3 Patch[4][4];

typedef struct {
    Patch whole;                /* the patch in world space */
    double st[4][2];            /* uv_vectors */
    int u_steps, v_steps;
    double flatness;
    PieceSink *sink;
} Subdivision;

static Vec3 half(Vec3 a, Vec3 b) { return v3(0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.z + b.z)); }

/* One cubic's four points c[0..3] split at its middle into l and r. */
static void split_cubic(const Vec3 c[4], Vec3 l[4], Vec3 r[4])
{
    Vec3 mid = half(c[1], c[2]);
    l[0] = c[0];
    l[1] = half(c[0], c[1]);
    l[2] = half(l[1], mid);
    r[2] = half(c[2], c[3]);
    r[1] = half(mid, r[2]);
    l[3] = half(l[2], r[1]);
    r[0] = l[3];
    r[3] = c[3];
}

/* Halves in u (the first index): p[0..3][i]. */
static void split_u(const Patch p, Patch low, Patch high)
{
    for (int i = 0; i < 4; i++) {
        Vec3 c[4] = { p[0][i], p[1][i], p[2][i], p[3][i] }, l[4], r[4];
        split_cubic(c, l, r);
        for (int j = 0; j < 4; j++) {
            low[j][i] = l[j];
            high[j][i] = r[j];
        }
    }
}

/* Halves in v (the second index): p[i][0..3]. */
static void split_v(const Patch p, Patch low, Patch high)
{
    for (int i = 0; i < 4; i++) {
        Vec3 l[4], r[4];
        split_cubic(p[i], l, r);
        for (int j = 0; j < 4; j++) {
            low[i][j] = l[j];
            high[i][j] = r[j];
        }
    }
}

static int near_point(Vec3 a, Vec3 b) { return fabs(v3_length(v3_sub(a, b))) < POV_EPSILON; }

/* POV-Ray's determine_subpatch_flatness: how far the control points lie
 * from the plane of three distinct corners; -1 when there are no such. */
static double flatness_of(const Patch p)
{
    Vec3 c[3] = { p[0][0], p[0][3], p[3][0] };
    if (near_point(c[0], c[1])) {
        c[1] = p[3][3];
        if (near_point(c[0], c[1]))
            return -1.0;
        c[2] = p[3][0];
        if (near_point(c[0], c[1]) || near_point(c[1], c[2]))
            return -1.0;
    } else if (near_point(c[1], c[2])) {
        return -1.0;
    }
    /* subpatch_normal(c0, c1, c2): (c0 - c1) x (c2 - c1) */
    Vec3 e1 = v3_sub(c[0], c[1]), e2 = v3_sub(c[2], c[1]);
    Vec3 n = v3_cross(e1, e2);
    double len2 = v3_dot(n, n);
    if (len2 <= BEZIER_EPSILON * v3_dot(e1, e1) * v3_dot(e2, e2))
        return -1.0;
    n = v3_scale(n, 1.0 / sqrt(len2));
    double d = -v3_dot(n, c[0]);
    double worst = 0.0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            worst = fmax(worst, fabs(v3_dot(p[i][j], n) + d));
    return worst;
}

/* The patch's unit normal at (u, v) (POV-Ray's bezier_value): the cross
 * product of its tangents, or <1, 0, 0> where it vanishes. */
static Vec3 patch_normal(const Patch cp, double u0, double v0)
{
    static const double C[4] = { 1.0, 3.0, 3.0, 1.0 };
    double u[4], uu[4], v[4], vv[4], du[4], duu[4], dv[4], dvv[4];
    u[0] = uu[0] = v[0] = vv[0] = 1.0;
    du[0] = duu[0] = dv[0] = dvv[0] = 0.0;
    for (int i = 1; i < 4; i++) {
        u[i] = u[i - 1] * u0;
        uu[i] = uu[i - 1] * (1.0 - u0);
        v[i] = v[i - 1] * v0;
        vv[i] = vv[i - 1] * (1.0 - v0);
        du[i] = i * u[i - 1];
        duu[i] = -i * uu[i - 1];
        dv[i] = i * v[i - 1];
        dvv[i] = -i * vv[i - 1];
    }
    Vec3 tu = v3(0, 0, 0), tv = v3(0, 0, 0);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double c = C[i] * C[j], ut = u[i] * uu[3 - i], vt = v[j] * vv[3 - j];
            tu = v3_add(tu, v3_scale(cp[i][j], c * vt * (du[i] * uu[3 - i] + u[i] * duu[3 - i])));
            tv = v3_add(tv, v3_scale(cp[i][j], c * ut * (dv[j] * vv[3 - j] + v[j] * dvv[3 - j])));
        }
    Vec3 n = v3_cross(tu, tv);
    double t = v3_dot(n, n);
    if (t > BEZIER_EPSILON * v3_dot(tu, tu) * v3_dot(tv, tv))
        return v3_scale(n, 1.0 / sqrt(t));
    return v3(1, 0, 0);
}

/* The texture's uv at the patch's (u, v) (Compute_Texture_UV of (v, u)). */
static Vec3 texture_uv(const double st[4][2], double u, double v)
{
    double a0 = st[0][0] + v * (st[1][0] - st[0][0]), a1 = st[0][1] + v * (st[1][1] - st[0][1]);
    double b0 = st[3][0] + v * (st[2][0] - st[3][0]), b1 = st[3][1] + v * (st[2][1] - st[3][1]);
    return v3(a0 + u * (b0 - a0), a1 + u * (b1 - a1), 0.0);
}

/* Triangle a b c of the patch at (u, v) corners uu, vv, unless POV-Ray's
 * intersect_subpatch finds it degenerate. */
static int add_triangle(Subdivision *s, Vec3 a, Vec3 b, Vec3 c, const double uu[3], const double vv[3])
{
    Vec3 b0 = v3_sub(b, a), b1 = v3_sub(c, a);
    Vec3 n = v3_cross(b0, b1);
    if (v3_dot(n, n) <= BEZIER_EPSILON * v3_dot(b1, b1) * v3_dot(b0, b0))
        return 0;
    const Vec3 pts[3] = { a, b, c };
    Vec3 normals[3], uv[3];
    for (int i = 0; i < 3; i++) {
        normals[i] = patch_normal(s->whole, uu[i], vv[i]);
        uv[i] = texture_uv(s->st, uu[i], vv[i]);
    }
    return s->sink->triangle(s->sink, pts, normals, uv);
}

/* A piece done: its two triangles (bezier_subpatch_intersect). */
static int add_piece(Subdivision *s, const Patch p, double u0, double u1, double v0, double v1)
{
    const double uu1[3] = { u0, u0, u1 }, vv1[3] = { v0, v1, v1 };
    const double uu2[3] = { u0, u1, u1 }, vv2[3] = { v0, v1, v0 };
    if (add_triangle(s, p[0][0], p[0][3], p[3][3], uu1, vv1))
        return -1;
    return add_triangle(s, p[0][0], p[3][3], p[3][0], uu2, vv2);
}

static int subdivide(Subdivision *s, const Patch p, double u0, double u1, double v0, double v1, int depth)
{
    double flat = flatness_of(p);
    if (flat >= 0.0 && flat < s->flatness)
        return add_piece(s, p, u0, u1, v0, v1);
    const int split_in_u = depth < s->u_steps, split_in_v = depth < s->v_steps;
    const double um = (u0 + u1) / 2.0, vm = (v0 + v1) / 2.0;
    Patch a, b, c, d;
    if (!split_in_u && !split_in_v)
        return add_piece(s, p, u0, u1, v0, v1);
    if (!split_in_u) {
        split_v(p, a, b);
        return subdivide(s, a, u0, u1, v0, vm, depth + 1) || subdivide(s, b, u0, u1, vm, v1, depth + 1) ? -1 : 0;
    }
    if (!split_in_v) {
        split_u(p, a, b);
        return subdivide(s, a, u0, um, v0, v1, depth + 1) || subdivide(s, b, um, u1, v0, v1, depth + 1) ? -1 : 0;
    }
    Patch low_u, high_u;
    split_u(p, low_u, high_u);
    split_v(low_u, a, b);
    split_v(high_u, c, d);
    return subdivide(s, a, u0, um, v0, vm, depth + 1) || subdivide(s, b, u0, um, vm, v1, depth + 1) ||
                   subdivide(s, c, um, u1, v0, vm, depth + 1) || subdivide(s, d, um, u1, vm, v1, depth + 1)
               ? -1
               : 0;
}

int bicubic_patch_pieces(const SceneObject *o, const Transform *to_world, PieceSink *sink)
{
    Subdivision s;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            s.whole[i][j] = transform_point(to_world, o->u.bicubic_patch.control[i][j]);
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 2; k++)
            s.st[i][k] = o->u.bicubic_patch.st[i][k];
    s.u_steps = o->u.bicubic_patch.u_steps;
    s.v_steps = o->u.bicubic_patch.v_steps;
    s.flatness = o->u.bicubic_patch.flatness;
    s.sink = sink;
    return subdivide(&s, (const Vec3(*)[4])s.whole, 0.0, 1.0, 0.0, 1.0, 0);
}

void bicubic_patch_count(const SceneObject *o, double *pieces, double *points)
{
    /* at most every level split in both: 2^u_steps x 2^v_steps pieces */
    double u = o->u.bicubic_patch.u_steps > 0 ? o->u.bicubic_patch.u_steps : 0;
    double v = o->u.bicubic_patch.v_steps > 0 ? o->u.bicubic_patch.v_steps : 0;
    double triangles = 2.0 * pow(2.0, u + v);
    *pieces = triangles;
    *points = triangles * 9.0; /* corners, normals, uv */
}
