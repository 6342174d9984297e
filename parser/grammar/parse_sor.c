/* sor { N, <r, h>... [open] modifiers }, as POV-Ray 3.7's Parse_Sor reads
 * it, its segments' cubics in the height made as Compute_Sor makes them:
 * the squared radius through two points with the slopes their neighbours
 * give (src/geometry/sor.c turns them about the y axis). */
#include <math.h>

#include "grammar.h"

#define MAX_SOR_POINTS 50000000
#define SOR_EPSILON 1e-10 /* POV-Ray's EPSILON */

/* m = m^-1 for a 4x4 matrix (Gauss-Jordan with partial pivoting, as
 * POV-Ray's MInvers); 0 when it is singular. */
static int invert4(double m[4][4])
{
    double a[4][8];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 8; j++)
            a[i][j] = j < 4 ? m[i][j] : (j - 4 == i ? 1.0 : 0.0);
    for (int c = 0; c < 4; c++) {
        int pivot = c;
        for (int r = c + 1; r < 4; r++)
            if (fabs(a[r][c]) > fabs(a[pivot][c]))
                pivot = r;
        if (a[pivot][c] == 0.0)
            return 0;
        for (int j = 0; j < 8; j++) {
            double t = a[c][j];
            a[c][j] = a[pivot][j];
            a[pivot][j] = t;
        }
        double inv = 1.0 / a[c][c];
        for (int j = 0; j < 8; j++)
            a[c][j] *= inv;
        for (int r = 0; r < 4; r++)
            if (r != c && a[r][c] != 0.0) {
                double f = a[r][c];
                for (int j = 0; j < 8; j++)
                    a[r][j] -= f * a[c][j];
            }
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            m[i][j] = a[i][j + 4];
    return 1;
}

SceneObject *gram_sor(Parser *p, const Token *kw)
{
    tok_begin_block(p, "sor");
    SceneObject *o = gram_new_object(p, OBJ_SOR, kw);
    Token at = *tok_peek(p);
    double count = expr_float(p);
    if (!(count >= -1e9 && count <= MAX_SOR_POINTS))
        tok_fail(p, at.pos, "sor: %g is not a usable number of points", count);
    int n = (int)count;
    if (n < 4)
        tok_fail(p, at.pos, "Surface of revolution must have at least four points.");
    double (*pt)[2] = tok_scene_alloc(p, sizeof *pt * (size_t)n);
    for (int i = 0; i < n; i++) {
        expr_comma(p);
        Token pat = *tok_peek(p);
        gram_uv_vector(p, pt[i]);
        if (pt[i][0] < 0.0 || (i > 1 && i < n - 1 && pt[i][1] <= pt[i - 1][1]))
            tok_fail(p, pat.pos, "Incorrect point in surface of revolution.");
    }
    Token *t = tok_peek(p);
    if (t->type == TK_WORD && t->kw == KW_open) {
        (void)tok_next(p);
        o->u.sor.open = 1;
    }
    const int nseg = n - 3;
    SorSegment *seg = tok_scene_alloc(p, sizeof *seg * (size_t)nseg);
    for (int i = 0; i < nseg; i++) {
        const double *p0 = pt[i], *p1 = pt[i + 1], *p2 = pt[i + 2], *p3 = pt[i + 3];
        if (fabs(p2[1] - p0[1]) < SOR_EPSILON || fabs(p3[1] - p1[1]) < SOR_EPSILON)
            tok_fail(p, at.pos, "Incorrect point in surface of revolution.");
        double k[4];
        k[0] = p1[0] * p1[0];
        k[1] = p2[0] * p2[0];
        k[2] = (p2[0] - p0[0]) / (p2[1] - p0[1]);
        k[3] = (p3[0] - p1[0]) / (p3[1] - p1[1]);
        k[2] *= 2.0 * p1[0];
        k[3] *= 2.0 * p2[0];
        double w = p1[1], m[4][4];
        m[0][0] = w * w * w, m[0][1] = w * w, m[0][2] = w, m[0][3] = 1.0;
        m[2][0] = 3.0 * w * w, m[2][1] = 2.0 * w, m[2][2] = 1.0, m[2][3] = 0.0;
        w = p2[1];
        m[1][0] = w * w * w, m[1][1] = w * w, m[1][2] = w, m[1][3] = 1.0;
        m[3][0] = 3.0 * w * w, m[3][1] = 2.0 * w, m[3][2] = 1.0, m[3][3] = 0.0;
        if (!invert4(m))
            tok_fail(p, at.pos, "Incorrect point in surface of revolution.");
        double c[4];
        for (int r = 0; r < 4; r++) {
            c[r] = k[0] * m[r][0] + k[1] * m[r][1] + k[2] * m[r][2] + k[3] * m[r][3];
            if (fabs(c[r]) < SOR_EPSILON)
                c[r] = 0.0;
        }
        seg[i] = (SorSegment){ c[0], c[1], c[2], c[3], p1[1], p2[1], p1[0], p2[0] };
    }
    o->u.sor.nsegments = nseg;
    o->u.sor.segments = seg;
    gram_object_mods(p, o, "sor");
    return o;
}
