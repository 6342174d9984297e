/* prism { [linear_spline|quadratic_spline|cubic_spline|bezier_spline]
 * [linear_sweep|conic_sweep] H1, H2, N, <x, z>... [open] modifiers }, as
 * POV-Ray 3.7's Parse_Prism reads it: its outline rule (an open linear
 * outline closed, an open curved one left out with a warning), then each
 * segment's cubic in the spline parameter and its rectangle as
 * Compute_Prism makes them (src/geometry/prism.c sweeps them along y). */
#include <math.h>

#include "grammar.h"

#define PRISM_EPSILON 1e-10 /* POV-Ray's EPSILON, for closing outlines */
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

static int same_point(const double a[2], const double b[2])
{
    return fabs(a[0] - b[0]) < PRISM_EPSILON && fabs(a[1] - b[1]) < PRISM_EPSILON;
}

/* Parse_Prism's test of whether every outline ends where it began: for
 * linear, quadratic and cubic splines the outline's first point (the
 * second written for the curved ones, the first being a control point)
 * met again; for Bezier splines each run of joined segments ending on the
 * point it started from. *start: a linear spline's last outline's first
 * point, which closes it. */
static int outlines_closed(SplineKind spline, double (*pt)[2], int n, const double **start)
{
    if (spline == SPLINE_BEZIER) {
        int loop = 0;
        for (int i = 4; i < n; i += 4)
            if (!same_point(pt[i], pt[i - 1])) { /* a new run: the last must have closed */
                if (!same_point(pt[i - 1], pt[loop]))
                    return 0;
                loop = i;
            }
        return same_point(pt[n - 1], pt[loop]);
    }
    int i = spline == SPLINE_LINEAR ? 1 : 2;
    int closed = 0;
    *start = pt[i - 1];
    for (; i < n; i++) {
        closed = 0;
        if (same_point(*start, pt[i])) {
            i += spline == SPLINE_LINEAR ? 1 : spline == SPLINE_QUADRATIC ? 2 : 3;
            if (i < n)
                *start = pt[i];
            closed = 1;
        }
    }
    return closed;
}

static double cubic_at(const double c[4], double w)
{
    return w * (w * (w * c[0] + c[1]) + c[2]) + c[3];
}

/* The extremes over t in [0, 1] of one coordinate's cubic c (c[0] t^3 ...)
 * where its derivative vanishes, widening *lo, *hi (Compute_Prism's
 * quadratic and cubic splines; POV-Ray's solver on the derivative gives
 * these roots). */
static void widen_by_extremes(const double c[4], double *lo, double *hi)
{
    const double a = 3.0 * c[0], b = 2.0 * c[1], k = c[2];
    double r[2];
    int n = 0;
    if (a == 0.0) {
        if (b != 0.0)
            r[n++] = -k / b;
    } else {
        double disc = b * b - 4.0 * a * k;
        if (disc >= 0.0) {
            double q = -0.5 * (b + copysign(sqrt(disc), b));
            r[n++] = q / a;
            if (q != 0.0)
                r[n++] = k / q;
        }
    }
    while (n--)
        if (r[n] >= 0.0 && r[n] <= 1.0) {
            double v = cubic_at(c, r[n]);
            *lo = fmin(*lo, v);
            *hi = fmax(*hi, v);
        }
}

/* Compute_Prism: the segments of the n points pt into seg (room for n),
 * returning how many; -1 where POV-Ray throws "Too few points in prism"
 * (a quadratic or cubic outline not closed runs past the last point; a
 * linear one is closed and a Bezier one's count checked before). */
static int make_segments(SplineKind spline, double (*pt)[2], int n, PrismSegment *seg)
{
    const double *first = spline == SPLINE_LINEAR ? pt[0] : pt[1];
    int count = 0;
    for (int i = 0; i < n - 1; i++) {
        const int need = spline == SPLINE_LINEAR ? 1 : spline == SPLINE_QUADRATIC ? 2 : 3;
        if (i + need >= n)
            return -1;
        PrismSegment *e = &seg[count++];
        for (int a = 0; a < 2; a++) {
            const double p0 = pt[i][a], p1 = pt[i + 1][a];
            const double p2 = need >= 2 ? pt[i + 2][a] : 0.0, p3 = need >= 3 ? pt[i + 3][a] : 0.0;
            double c[4]; /* t^3, t^2, t, 1 */
            double lo, hi;
            switch (spline) {
            case SPLINE_LINEAR:
                c[0] = 0.0, c[1] = 0.0, c[2] = -1.0 * p0 + 1.0 * p1, c[3] = 1.0 * p0;
                lo = fmin(p0, p1), hi = fmax(p0, p1);
                break;
            case SPLINE_QUADRATIC:
                c[0] = 0.0, c[1] = 0.5 * p0 - 1.0 * p1 + 0.5 * p2, c[2] = -0.5 * p0 + 0.5 * p2, c[3] = 1.0 * p1;
                lo = fmin(p1, p2), hi = fmax(p1, p2);
                break;
            case SPLINE_CUBIC:
                c[0] = -0.5 * p0 + 1.5 * p1 - 1.5 * p2 + 0.5 * p3;
                c[1] = p0 - 2.5 * p1 + 2.0 * p2 - 0.5 * p3;
                c[2] = -0.5 * p0 + 0.5 * p2;
                c[3] = p1;
                lo = fmin(p1, p2), hi = fmax(p1, p2);
                break;
            case SPLINE_BEZIER: /* POV-Ray's parameter runs from the last point (t = 0) to the first */
            default:
                c[0] = p0 - 3.0 * p1 + 3.0 * p2 - p3;
                c[1] = 3.0 * p1 - 6.0 * p2 + 3.0 * p3;
                c[2] = 3.0 * p2 - 3.0 * p3;
                c[3] = p3;
                lo = fmin(fmin(p0, p1), fmin(p2, p3)), hi = fmax(fmax(p0, p1), fmax(p2, p3));
                break;
            }
            if (spline == SPLINE_QUADRATIC || spline == SPLINE_CUBIC)
                widen_by_extremes(c, &lo, &hi);
            e->a[a] = c[0], e->b[a] = c[1], e->c[a] = c[2], e->d[a] = c[3];
            if (a == 0)
                e->u1 = lo, e->u2 = hi;
            else
                e->v1 = lo, e->v2 = hi;
        }
        /* the next segment: past an outline's closing point onto the next */
        if (spline == SPLINE_BEZIER)
            i += 3;
        else if (same_point(pt[spline == SPLINE_LINEAR ? i + 1 : i + 2], first)) {
            i += need;
            const int next = spline == SPLINE_LINEAR ? i + 1 : i + 2;
            if (next < n)
                first = pt[next];
        }
    }
    return count;
}

/* The rectangles swept (Compute_Prism's end): a conic sweep's scaled by
 * both heights. */
static void sweep_rectangles(SceneObject *o, PrismSegment *seg, int nseg)
{
    const double h1 = o->u.prism.height1, h2 = o->u.prism.height2;
    const int conic = o->u.prism.sweep == PRISM_CONIC_SWEEP;
    double u1 = HUGE_VAL, u2 = -HUGE_VAL, v1 = HUGE_VAL, v2 = -HUGE_VAL;
    for (int i = 0; i < nseg; i++) {
        PrismSegment *e = &seg[i];
        u1 = fmin(u1, e->u1), u2 = fmax(u2, e->u2), v1 = fmin(v1, e->v1), v2 = fmax(v2, e->v2);
        e->x1 = conic ? fmin(fmin(e->u1 * h1, e->u1 * h2), fmin(e->u2 * h1, e->u2 * h2)) : e->u1;
        e->x2 = conic ? fmax(fmax(e->u1 * h1, e->u1 * h2), fmax(e->u2 * h1, e->u2 * h2)) : e->u2;
        e->y1 = conic ? fmin(fmin(e->v1 * h1, e->v1 * h2), fmin(e->v2 * h1, e->v2 * h2)) : e->v1;
        e->y2 = conic ? fmax(fmax(e->v1 * h1, e->v1 * h2), fmax(e->v2 * h1, e->v2 * h2)) : e->v2;
    }
    o->u.prism.u1 = u1, o->u.prism.u2 = u2, o->u.prism.v1 = v1, o->u.prism.v2 = v2;
    o->u.prism.x1 = conic ? fmin(fmin(u1 * h1, u1 * h2), fmin(u2 * h1, u2 * h2)) : u1;
    o->u.prism.x2 = conic ? fmax(fmax(u1 * h1, u1 * h2), fmax(u2 * h1, u2 * h2)) : u2;
    o->u.prism.y1 = conic ? fmin(fmin(v1 * h1, v1 * h2), fmin(v2 * h1, v2 * h2)) : v1;
    o->u.prism.y2 = conic ? fmax(fmax(v1 * h1, v1 * h2), fmax(v2 * h1, v2 * h2)) : v2;
}

SceneObject *gram_prism(Parser *p, const Token *kw)
{
    tok_begin_block(p, "prism");
    SceneObject *o = gram_new_object(p, OBJ_PRISM, kw);
    o->u.prism.sweep = PRISM_LINEAR_SWEEP;
    SplineKind spline = SPLINE_LINEAR;
    for (;;) { /* in any order, the last of each kind counting */
        Token *t = tok_next(p);
        int k = t->type == TK_WORD ? t->kw : -1;
        if (gram_spline_kind(k, &spline))
            continue;
        if (k == KW_linear_sweep)
            o->u.prism.sweep = PRISM_LINEAR_SWEEP;
        else if (k == KW_conic_sweep)
            o->u.prism.sweep = PRISM_CONIC_SWEEP;
        else {
            tok_unget(p);
            break;
        }
    }
    /* the expressions refuse a NaN or infinite height */
    double h1 = expr_float(p);
    expr_comma(p);
    double h2 = expr_float(p);
    expr_comma(p);
    o->u.prism.height1 = fmin(h1, h2);
    o->u.prism.height2 = fmax(h1, h2);
    Token count_at = *tok_peek(p);
    double count = expr_float(p);
    if (!(count >= -1e9 && count <= MAX_PRISM_POINTS))
        tok_fail(p, count_at.pos, "prism: %g is not a usable number of points", count);
    int n = (int)count; /* POV-Ray truncates it */
    if ((spline == SPLINE_LINEAR && n < 3) || (spline == SPLINE_QUADRATIC && n < 5) ||
        (spline == SPLINE_CUBIC && n < 6) || (spline == SPLINE_BEZIER && (n & 3) != 0) ||
        (spline == SPLINE_BEZIER && n <= 0)) {
        static const char *const too_few[] = {
            "Prism with linear splines must have at least three points.",
            "Prism with quadratic splines must have at least five points.",
            "Prism with cubic splines must have at least six points.",
            "Prism with Bezier splines must have four points per segment.",
        };
        tok_fail(p, count_at.pos, "%s", too_few[spline]);
    }
    /* room for the point a linear outline left open is closed by */
    double (*pt)[2] = tok_scene_alloc(p, sizeof *pt * ((size_t)n + 1));
    for (int i = 0; i < n; i++) {
        expr_comma(p);
        gram_uv_vector(p, pt[i]);
    }
    if (tok_is_kw(tok_peek(p), KW_open)) {
        (void)tok_next(p);
        o->u.prism.open = 1;
    }
    const double *start = pt[0];
    if (!outlines_closed(spline, pt, n, &start)) {
        if (spline == SPLINE_LINEAR) {
            pt[n][0] = start[0];
            pt[n][1] = start[1];
            n++;
            tok_warning(p, kw->pos, "Linear prism not closed. Closing it.");
        } else {
            o->u.prism.degenerate = 1;
            tok_warning(p, kw->pos, "Prism not closed. Ignoring it.");
        }
    }
    PrismSegment *seg = tok_scene_alloc(p, sizeof *seg * (size_t)n);
    int nseg = make_segments(spline, pt, n, seg);
    if (nseg < 0) /* an open quadratic or cubic outline (POV-Ray: a fatal error) */
        tok_fail(p, count_at.pos, "Too few points in prism.");
    o->u.prism.spline = spline;
    o->u.prism.nsegments = nseg;
    o->u.prism.segments = seg;
    sweep_rectangles(o, seg, nseg);
    gram_object_mods(p, o, "prism");
    return o;
}
