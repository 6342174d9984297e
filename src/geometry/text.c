/* POV-Ray 3.7's TrueType glyph (source/backend/shape/truetype.cpp:
 * Inside_Glyph, solve_quad, GetZeroOneHits, GlyphIntersect, Inside,
 * Compute_BBox), with its tolerances and in its order of operations, so
 * that a ray meets a letter where POV-Ray's does. Written anew from reading
 * it. */
#include "text.h"

#include <math.h>

#include "scene.h"

#define POV_EPSILON 1.0e-10    /* POV-Ray's EPSILON */
#define TTF_TOLERANCE 1.0e-6   /* truetype.cpp's TTF_Tolerance: nearer crossings are dropped */
#define COEFF_LIMIT 1.0e-20    /* truetype.cpp's COEFF_LIMIT: a quadratic this flat is linear */

/* One outline segment as the walks over a contour meet it: from (x0, y0)
 * to (x2, y2), through control point (x1, y1) for a curve, to (x1, y1) for
 * a line. */
typedef struct {
    int curve;
    double x0, y0, x1, y1, x2, y2;
} Segment;

/* The segment ending at (line) or controlled by (curve) point j of a
 * contour of points v[0..m] (v[m] a copy of v[0]), given where the walk
 * stands (x0, y0); the walk's next standing point in *nx, *ny. As
 * Inside_Glyph and GlyphIntersect walk: a curve's far end is the next point,
 * or the midpoint to it where it is off the curve too, or the contour's
 * first point after its last. */
static Segment segment(const double *xv, const double *yv, const unsigned char *on, int j, int m, double x0,
                       double y0)
{
    Segment s;
    s.x0 = x0;
    s.y0 = y0;
    s.x1 = xv[j];
    s.y1 = yv[j];
    s.curve = !on[j];
    if (!s.curve) {
        s.x2 = s.x1;
        s.y2 = s.y1;
        return s;
    }
    if (j == m) {
        s.x2 = xv[0];
        s.y2 = yv[0];
    } else {
        s.x2 = xv[j + 1];
        s.y2 = yv[j + 1];
        if (!on[j + 1]) {
            s.x2 = 0.5 * (s.x1 + s.x2);
            s.y2 = 0.5 * (s.y1 + s.y2);
        }
    }
    return s;
}

int glyph_max_hits(const struct SceneGlyph *g)
{
    int n = 2;
    for (int c = 0; c < g->ncontours; c++)
        for (int i = g->start[c] + 1; i < g->start[c + 1]; i++)
            n += g->on_curve[i] ? 1 : 2;
    return n;
}

/* solve_quad: the roots in [mindist, maxdist] of x[0] s^2 + x[1] s + x[2],
 * none where the discriminant is below EPSILON. */
static int solve_quad(const double *x, double *y, double mindist, double maxdist)
{
    const double a = x[0], b = -x[1], c = x[2];
    if (fabs(a) < COEFF_LIMIT) {
        if (fabs(b) < COEFF_LIMIT)
            return 0;
        double q = c / b;
        if (q >= mindist && q <= maxdist) {
            y[0] = q;
            return 1;
        }
        return 0;
    }
    double d = b * b - 4.0 * a * c;
    if (d < POV_EPSILON)
        return 0;
    d = sqrt(d);
    const double t = 2.0 * a;
    double q = (b + d) / t;
    if (q >= mindist && q <= maxdist) {
        y[0] = q;
        q = (b - d) / t;
        if (q >= mindist && q <= maxdist) {
            y[1] = q;
            return 2;
        }
        return 1;
    }
    q = (b - d) / t;
    if (q >= mindist && q <= maxdist) {
        y[0] = q;
        return 1;
    }
    return 0;
}

/* Inside_Glyph: the crossings of the ray from (x, y) toward +x with the
 * outline, odd inside. */
static int inside_glyph(double x, double y, const SceneGlyph *g)
{
    int crossings = 0;
    for (int c = 0; c < g->ncontours; c++) {
        const double *xv = g->x + g->start[c], *yv = g->y + g->start[c];
        const unsigned char *fv = g->on_curve + g->start[c];
        const int m = g->start[c + 1] - g->start[c] - 1;
        double x0 = xv[0], y0 = yv[0];
        for (int j = 1; j <= m; j++) {
            Segment s = segment(xv, yv, fv, j, m, x0, y0);
            if (!s.curve) {
                const double x1 = s.x1, y1 = s.y1;
                x0 = s.x0;
                y0 = s.y0;
                if (y0 != y1) {
                    int qi = y0 < y, qj = y1 < y;
                    if (qi != qj) {
                        int ri = x0 > x, rj = x1 > x;
                        if (ri && rj) {
                            crossings++;
                        } else if (ri || rj) {
                            double mm = (y1 - y0) / (x1 - x0);
                            double b = (y1 - y) - mm * (x1 - x);
                            if (b / mm < POV_EPSILON)
                                crossings++;
                        }
                    }
                }
                x0 = x1;
                y0 = y1;
                continue;
            }
            const double x1 = s.x1, y1 = s.y1, x2 = s.x2, y2 = s.y2;
            /* only where y is within the curve's points' range */
            if (!((y0 < y && y1 < y && y2 < y) || (y0 > y && y1 > y && y2 > y))) {
                double yt[3] = { y0 - 2.0 * y1 + y2, 2.0 * (y1 - y0), y0 - y }, roots[2];
                int k = solve_quad(yt, roots, 0.0, 1.0);
                for (int ri = 0; ri < k;) {
                    /* a root at an end where y is not actually in range is
                     * dropped */
                    if (roots[ri] <= POV_EPSILON) {
                        if ((y <= y0 && y < y1) || (y >= y0 && y > y1)) {
                            k--;
                            if (k > ri)
                                roots[ri] = roots[ri + 1];
                            continue;
                        }
                    } else if (roots[ri] >= 1.0 - POV_EPSILON) {
                        if ((y < y2 && y < y1) || (y > y2 && y > y1)) {
                            k--;
                            if (k > ri)
                                roots[ri] = roots[ri + 1];
                            continue;
                        }
                    }
                    ri++;
                }
                const double xt0 = x0 - 2.0 * x1 + x2, xt1 = 2.0 * (x1 - x0), xt2 = x0;
                for (int r = 0; r < k; r++) {
                    double t = roots[r];
                    double xc = (xt0 * t + xt1) * t + xt2;
                    if (xc > x)
                        crossings++;
                }
            }
            x0 = x2;
            y0 = y2;
        }
    }
    return (crossings & 1) != 0;
}

typedef struct {
    ShapeHit *hits;
    int n, cap;
    double tmax;
    int inverse;
} Found;

static void keep(Found *f, double t, int part, Vec3 d, Vec3 n)
{
    if (!(t < f->tmax) || f->n >= f->cap)
        return;
    ShapeHit *h = &f->hits[f->n++];
    h->t = t;
    h->part = part;
    /* the normal POV-Ray gives is the outline's outward one where the
     * contours run as TrueType orders them */
    h->entering = (v3_dot(d, n) < 0.0) != (f->inverse != 0);
}

int glyph_intersect_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    const Vec3 P = inverse_transform_point(&s->to_world, org);
    const Vec3 D = inverse_transform_direction(&s->to_world, dir);
    const SceneGlyph *g = s->u.glyph.glyph;
    const double depth = s->u.glyph.depth;
    Found f = { hits, 0, s->max_hits, tmax, s->inverse };

    /* GetZeroOneHits: the faces, where the point is inside the outline */
    if (!(fabs(D.z) < POV_EPSILON)) {
        double t = -P.z / D.z;
        double t0 = inside_glyph(P.x + t * D.x, P.y + t * D.y, g) ? t : -1.0;
        t += depth / D.z;
        double t1 = inside_glyph(P.x + t * D.x, P.y + t * D.y, g) ? t : -1.0;
        if (t0 > 0.0 && t0 > TTF_TOLERANCE)
            keep(&f, t0, GLYPH_FRONT, D, v3(0.0, 0.0, -1.0));
        if (t1 > 0.0 && t1 > TTF_TOLERANCE)
            keep(&f, t1, GLYPH_BACK, D, v3(0.0, 0.0, 1.0));
    }

    /* GlyphIntersect's walls: the ray's projection on the outline's plane
     * is a x + b y + c = 0 */
    int dirflag;
    if (fabs(D.x) < POV_EPSILON) {
        if (fabs(D.y) < POV_EPSILON)
            goto sorted; /* along the walls */
        dirflag = 0;
    } else {
        dirflag = 1;
    }
    const double a = D.y, b = -D.x, c = P.y * D.x - P.x * D.y;
    for (int ci = 0; ci < g->ncontours; ci++) {
        const int base = g->start[ci];
        const double *xv = g->x + base, *yv = g->y + base;
        const unsigned char *fv = g->on_curve + base;
        const int m = g->start[ci + 1] - base - 1;
        double x0 = xv[0], y0 = yv[0];
        for (int j = 1; j <= m; j++) {
            Segment sg = segment(xv, yv, fv, j, m, x0, y0);
            if (!sg.curve) {
                const double d0 = sg.x1 - x0, d1 = sg.y1 - y0;
                const double den = d1 * D.x - d0 * D.y;
                if (!(fabs(den) < POV_EPSILON)) {
                    double t = (D.x * (P.y - y0) - D.y * (P.x - x0)) / den;
                    if (!(t < 0.0 || t > 1.0)) {
                        if (dirflag)
                            t = ((x0 + t * d0) - P.x) / D.x;
                        else
                            t = ((y0 + t * d1) - P.y) / D.y;
                        double z = P.z + t * D.z;
                        if (z >= 0 && z <= depth && t > TTF_TOLERANCE)
                            keep(&f, t, GLYPH_WALL + base + j, D, v3(d1, -d0, 0.0));
                    }
                }
                x0 = sg.x1;
                y0 = sg.y1;
                continue;
            }
            const double xt2 = x0 - 2.0 * sg.x1 + sg.x2, xt1 = 2.0 * (sg.x1 - x0), xt0 = x0;
            const double yt2 = y0 - 2.0 * sg.y1 + sg.y2, yt1 = 2.0 * (sg.y1 - y0), yt0 = y0;
            const double C[3] = { a * xt2 + b * yt2, a * xt1 + b * yt1, a * xt0 + b * yt0 + c };
            double S[2];
            int k = solve_quad(C, S, 0.0, 1.0);
            for (int l = 0; l < k; l++) {
                double t;
                if (dirflag)
                    t = ((S[l] * S[l] * xt2 + S[l] * xt1 + xt0) - P.x) / D.x;
                else
                    t = ((S[l] * S[l] * yt2 + S[l] * yt1 + yt0) - P.y) / D.y;
                double z = P.z + t * D.z;
                if (z >= 0 && z <= depth && t > TTF_TOLERANCE)
                    keep(&f, t, GLYPH_WALL + base + j, D,
                         v3(2.0 * yt2 * S[l] + yt1, -2.0 * xt2 * S[l] - xt1, 0.0));
            }
            x0 = sg.x2;
            y0 = sg.y2;
        }
    }
sorted:
    /* nearest first; at one distance in the order found */
    shape_hits_sort(hits, f.n);
    return f.n;
}

int glyph_inside(const Shape *s, Vec3 p)
{
    const Vec3 q = inverse_transform_point(&s->to_world, p);
    int in = q.z >= 0.0 && q.z <= s->u.glyph.depth && inside_glyph(q.x, q.y, s->u.glyph.glyph);
    return in != (s->inverse != 0);
}

/* The curve's parameter at q, a point on it: the root of x(s) = q.x or
 * y(s) = q.y nearest the curve, polished by Newton's steps on the distance
 * (GlyphIntersect knew it from the ray; the crossing keeps only its part). */
static double curve_parameter(const Segment *sg, double qx, double qy)
{
    const double xt2 = sg->x0 - 2.0 * sg->x1 + sg->x2, xt1 = 2.0 * (sg->x1 - sg->x0), xt0 = sg->x0;
    const double yt2 = sg->y0 - 2.0 * sg->y1 + sg->y2, yt1 = 2.0 * (sg->y1 - sg->y0), yt0 = sg->y0;
    double best = 0.5, best_d = HUGE_VAL;
    const double eq[2][3] = { { xt2, xt1, xt0 - qx }, { yt2, yt1, yt0 - qy } };
    for (int e = 0; e < 2; e++) {
        double r[2];
        int k = solve_quad(eq[e], r, -0.5, 1.5);
        for (int i = 0; i < k; i++) {
            double dx = (xt2 * r[i] + xt1) * r[i] + xt0 - qx, dy = (yt2 * r[i] + yt1) * r[i] + yt0 - qy;
            double d = dx * dx + dy * dy;
            if (d < best_d) {
                best_d = d;
                best = r[i];
            }
        }
    }
    for (int it = 0; it < 3; it++) {
        double dx = (xt2 * best + xt1) * best + xt0 - qx, dy = (yt2 * best + yt1) * best + yt0 - qy;
        double tx = 2.0 * xt2 * best + xt1, ty = 2.0 * yt2 * best + yt1;
        double f = dx * tx + dy * ty;
        double df = tx * tx + ty * ty + dx * 2.0 * xt2 + dy * 2.0 * yt2;
        if (!(fabs(df) > 0.0))
            break;
        best -= f / df;
    }
    return best;
}

Vec3 glyph_normal(const Shape *s, Vec3 p, int part)
{
    Vec3 n = v3(0.0, 0.0, part == GLYPH_FRONT ? -1.0 : 1.0);
    const SceneGlyph *g = s->u.glyph.glyph;
    const int index = part - GLYPH_WALL;
    for (int ci = 0; part >= GLYPH_WALL && ci < g->ncontours; ci++) {
        const int base = g->start[ci];
        if (index <= base || index >= g->start[ci + 1])
            continue;
        /* the contour walked to the segment, as GlyphIntersect walks it */
        const double *xv = g->x + base, *yv = g->y + base;
        const unsigned char *fv = g->on_curve + base;
        const int m = g->start[ci + 1] - base - 1;
        double x0 = xv[0], y0 = yv[0];
        for (int j = 1; j <= m; j++) {
            Segment sg = segment(xv, yv, fv, j, m, x0, y0);
            if (base + j == index) {
                if (!sg.curve) {
                    n = v3(sg.y1 - sg.y0, -(sg.x1 - sg.x0), 0.0);
                } else {
                    Vec3 q = inverse_transform_point(&s->to_world, p);
                    double S = curve_parameter(&sg, q.x, q.y);
                    const double xt2 = sg.x0 - 2.0 * sg.x1 + sg.x2, xt1 = 2.0 * (sg.x1 - sg.x0);
                    const double yt2 = sg.y0 - 2.0 * sg.y1 + sg.y2, yt1 = 2.0 * (sg.y1 - sg.y0);
                    n = v3(2.0 * yt2 * S + yt1, -2.0 * xt2 * S - xt1, 0.0);
                }
                break;
            }
            x0 = sg.curve ? sg.x2 : sg.x1;
            y0 = sg.curve ? sg.y2 : sg.y1;
        }
        break;
    }
    return v3_normalize(transform_normal(&s->to_world, n));
}

void glyph_local_bounds(const Shape *s, Vec3 *lo, Vec3 *hi)
{
    const SceneGlyph *g = s->u.glyph.glyph;
    const double funit = 1.0 / (double)g->units_per_em;
    const double z0 = -TTF_TOLERANCE, z1 = s->u.glyph.depth + TTF_TOLERANCE;
    *lo = v3(g->xmin * funit, g->ymin * funit, fmin(z0, z1));
    *hi = v3(g->xmax * funit, g->ymax * funit, fmax(z0, z1));
}
