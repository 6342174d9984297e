/* prism { [linear_spline] [linear_sweep|conic_sweep] H1, H2, N, <x,z>...
 * [open] modifiers }, as POV-Ray 3.7's Parse_Prism reads it. A linear
 * spline's sides and caps are planar (a conic sweep's sides lie in planes
 * through the apex), so the prism is flattened into polygons
 * (src/geometry/prism.c); the other splines are curved and refused. */
#include <math.h>
#include <string.h>

#include "convert.h"
#include "grammar.h"

static const double PRISM_EPSILON = 1e-10; /* POV-Ray's EPSILON for closing outlines */
#define MAX_PRISM_POINTS 50000000

void gram_uv_vector(Parser *p, double out[2])
{
    Token first = *tok_peek(p);
    double e[5] = { 0, 0, 0, 0, 0 };
    int terms = 2;
    /* sums and products only, as a vector's: `<a, b> <c, d>` is two of them */
    expr_rel_factor(p, e, &terms);
    if (terms > 2)
        tok_fail(p, first.pos, "UV vector expected but vector or color expression found.");
    if (!isfinite(e[0]) || !isfinite(e[1]))
        tok_fail(p, first.pos, "a UV vector of %g, %g: not finite numbers", e[0], e[1]);
    out[0] = e[0];
    out[1] = terms >= 2 ? e[1] : e[0];
}

SceneObject *gram_prism(Parser *p, const Token *kw)
{
    tok_begin_block(p, "prism");
    SceneObject *o = gram_new_object(p, OBJ_PRISM, kw);
    o->u.prism.sweep = PRISM_LINEAR_SWEEP;
    for (;;) {
        Token *t = tok_next(p);
        int k = t->type == TK_WORD ? t->kw : -1;
        if (k == KW_linear_spline)
            continue;
        if (k == KW_quadratic_spline || k == KW_cubic_spline || k == KW_bezier_spline)
            tok_unsupported(p, t); /* curved sides: not planar pieces */
        if (k == KW_linear_sweep) {
            o->u.prism.sweep = PRISM_LINEAR_SWEEP;
            continue;
        }
        if (k == KW_conic_sweep) {
            o->u.prism.sweep = PRISM_CONIC_SWEEP;
            continue;
        }
        tok_unget(p);
        break;
    }
    double h1 = expr_float(p);
    expr_comma(p);
    double h2 = expr_float(p);
    expr_comma(p);
    o->u.prism.height1 = fmin(h1, h2);
    o->u.prism.height2 = fmax(h1, h2);
    Token count_at = *tok_peek(p);
    double count = expr_float(p);
    int n;
    if (!int_from_double(count, INT_MIN, MAX_PRISM_POINTS, &n))
        tok_fail(p, count_at.pos, "prism: %g is not a usable number of points", count);
    if (n < 3)
        tok_fail(p, count_at.pos, "Prism with linear splines must have at least three points.");
    TempVec pts;
    tok_tvec_init(&pts, sizeof(Vec3));
    for (int i = 0; i < n; i++) {
        expr_comma(p);
        double uv[2];
        gram_uv_vector(p, uv);
        *(Vec3 *)tok_tvec_push(p, &pts) = v3(uv[0], uv[1], 0.0);
    }
    if (tok_is_kw(tok_peek(p), KW_open)) {
        (void)tok_next(p);
        o->u.prism.open = 1;
    }
    /* POV-Ray's outline rule, in the plane of the outline (x and z, kept
     * as x and y here) */
    TempVec starts;
    if (!gram_outlines(p, &pts, PRISM_EPSILON, 2, &starts))
        tok_warning(p, kw->pos, "Linear prism not closed. Closing it.");
    Vec3 *kept = tok_scene_alloc(p, sizeof(Vec3) * (size_t)pts.n);
    memcpy(kept, pts.data, sizeof(Vec3) * (size_t)pts.n);
    int *outline_start = tok_scene_alloc(p, sizeof(int) * (size_t)starts.n);
    memcpy(outline_start, starts.data, sizeof(int) * (size_t)starts.n);
    o->u.prism.npoints = pts.n;
    o->u.prism.points = kept;
    o->u.prism.noutlines = starts.n - 1;
    o->u.prism.outline_start = outline_start;
    gram_object_mods(p, o, "prism");
    return o;
}
