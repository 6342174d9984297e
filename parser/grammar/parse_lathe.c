/* lathe { [linear_spline|quadratic_spline|cubic_spline|bezier_spline] N,
 * <r, h>... modifiers }, as POV-Ray 3.7's Parse_Lathe reads it, its
 * segments' polynomials made as Compute_Lathe makes them (the engine's
 * src/geometry/lathe.c turns them about the y axis). */
#include "grammar.h"

#define MAX_LATHE_POINTS 50000000

SceneObject *gram_lathe(Parser *p, const Token *kw)
{
    tok_begin_block(p, "lathe");
    SceneObject *o = gram_new_object(p, OBJ_LATHE, kw);
    SplineKind spline = SPLINE_LINEAR;
    Token *t = tok_next(p);
    if (!gram_spline_kind(t->type == TK_WORD ? t->kw : -1, &spline))
        tok_unget(p);
    Token at = *tok_peek(p);
    double count = expr_float(p);
    if (!(count >= -1e9 && count <= MAX_LATHE_POINTS))
        tok_fail(p, at.pos, "lathe: %g is not a usable number of points", count);
    int n = (int)count; /* POV-Ray truncates it */
    static const char *const too_few[] = {
        "Lathe with linear splines must have at least two points.",
        "Lathe with quadratic splines must have at least three points.",
        "Prism with cubic splines must have at least four points.", /* sic: POV-Ray's message */
        "Lathe with Bezier splines must have four points per segment.",
    };
    if ((spline == SPLINE_LINEAR && n < 2) || (spline == SPLINE_QUADRATIC && n < 3) || (spline == SPLINE_CUBIC && n < 4) ||
        (spline == SPLINE_BEZIER && (n & 3) != 0) || (spline == SPLINE_BEZIER && n == 0))
        tok_fail(p, at.pos, "%s", too_few[spline]);
    double (*pt)[2] = tok_scene_alloc(p, sizeof *pt * (size_t)n);
    for (int i = 0; i < n; i++) {
        expr_comma(p);
        Token pat = *tok_peek(p);
        gram_uv_vector(p, pt[i]);
        if (i > 0 && i < n - 1 && pt[i][0] < 0.0)
            tok_fail(p, pat.pos, "Incorrect point in lathe.");
    }
    int nseg = spline == SPLINE_LINEAR ? n - 1 : spline == SPLINE_QUADRATIC ? n - 2 : spline == SPLINE_CUBIC ? n - 3 : n / 4;
    SplineSegment *seg = tok_scene_alloc(p, sizeof *seg * (size_t)nseg);
    for (int s = 0, i = 0; s < nseg; s++, i += spline == SPLINE_BEZIER ? 4 : 1) {
        for (int a = 0; a < 2; a++) { /* a = 0: the radius, 1: the height */
            double p0 = pt[i][a], p1 = pt[i + 1][a];
            double p2 = spline == SPLINE_LINEAR ? 0.0 : pt[i + 2][a];
            double p3 = spline == SPLINE_LINEAR || spline == SPLINE_QUADRATIC ? 0.0 : pt[i + 3][a];
            SplineSegment *e = &seg[s];
            switch (spline) {
            case SPLINE_LINEAR:
                e->a[a] = 0.0;
                e->b[a] = 0.0;
                e->c[a] = -1.0 * p0 + 1.0 * p1;
                e->d[a] = 1.0 * p0;
                break;
            case SPLINE_QUADRATIC:
                e->a[a] = 0.0;
                e->b[a] = 0.5 * p0 - 1.0 * p1 + 0.5 * p2;
                e->c[a] = -0.5 * p0 + 0.5 * p2;
                e->d[a] = 1.0 * p1;
                break;
            case SPLINE_CUBIC:
                e->a[a] = -0.5 * p0 + 1.5 * p1 - 1.5 * p2 + 0.5 * p3;
                e->b[a] = p0 - 2.5 * p1 + 2.0 * p2 - 0.5 * p3;
                e->c[a] = -0.5 * p0 + 0.5 * p2;
                e->d[a] = p1;
                break;
            case SPLINE_BEZIER:
                e->a[a] = p3 - 3.0 * p2 + 3.0 * p1 - p0;
                e->b[a] = 3.0 * p2 - 6.0 * p1 + 3.0 * p0;
                e->c[a] = 3.0 * p1 - 3.0 * p0;
                e->d[a] = p0;
                break;
            }
        }
    }
    o->u.lathe.spline = spline;
    o->u.lathe.nsegments = nseg;
    o->u.lathe.segments = seg;
    gram_object_mods(p, o, "lathe");
    return o;
}

int gram_spline_kind(int kw, SplineKind *kind)
{
    switch (kw) {
    case KW_linear_spline: *kind = SPLINE_LINEAR; return 1;
    case KW_quadratic_spline: *kind = SPLINE_QUADRATIC; return 1;
    case KW_cubic_spline: *kind = SPLINE_CUBIC; return 1;
    case KW_bezier_spline: *kind = SPLINE_BEZIER; return 1;
    default: return 0;
    }
}

