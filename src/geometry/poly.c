/* POV-Ray 3.7's poly, cubic and quartic (poly.cpp), written anew from
 * reading it: the polynomial along a ray built in Poly::intersect's order
 * of terms and products, so that its rounding, and so the roots its
 * solver finds, are POV-Ray's. */
#include "poly.h"

#include <math.h>

#include "polynomial_solver.h"

#define POLY_DEPTH_TOLERANCE 1.0e-4  /* poly.cpp's DEPTH_TOLERANCE, in its own space */
#define POLY_INSIDE_TOLERANCE 1.0e-4 /* its INSIDE_TOLERANCE */
#define POLY_ROOT_TOLERANCE 1.0e-4   /* its ROOT_TOLERANCE: Solve_Polynomial's root elimination */
#define POLY_COEFF_LIMIT 1.0e-20     /* its COEFF_LIMIT: a quadratic's vanishing coefficients */

#define MAX_ORDER POLY_SOLVER_MAX_ORDER

int poly_term_count(int order) { return (order + 1) * (order + 2) * (order + 3) / 6; }

/* Pascal's triangle up to `order` (POV-Ray's binomials table): whole
 * numbers, exact in a double. */
static void pascal(int order, double binomial[MAX_ORDER + 1][MAX_ORDER + 1])
{
    for (int n = 0; n <= order; n++) {
        binomial[n][0] = binomial[n][n] = 1.0;
        for (int k = 1; k < n; k++)
            binomial[n][k] = binomial[n - 1][k - 1] + binomial[n - 1][k];
    }
}

/* Poly::intersect_quadratic: a poly of order 2, by the quadratic formula
 * (both roots; none where the ray is parallel to it within COEFF_LIMIT). */
static int quadratic_roots(const double *a, Vec3 o, Vec3 d, double *roots)
{
    double x = o.x, y = o.y, z = o.z, xx = d.x, yy = d.y, zz = d.z;
    double x2 = x * x, y2 = y * y, z2 = z * z, xx2 = xx * xx, yy2 = yy * yy, zz2 = zz * zz;
    double ac = a[0] * xx2 + a[1] * xx * yy + a[2] * xx * zz + a[4] * yy2 + a[5] * yy * zz + a[7] * zz2;
    double bc = 2 * a[0] * x * xx + a[1] * (x * yy + xx * y) + a[2] * (x * zz + xx * z) + a[3] * xx + 2 * a[4] * y * yy +
                a[5] * (y * zz + yy * z) + a[6] * yy + 2 * a[7] * z * zz + a[8] * zz;
    double cc = a[0] * x2 + a[1] * x * y + a[2] * x * z + a[3] * x + a[4] * y2 + a[5] * y * z + a[6] * y + a[7] * z2 +
                a[8] * z + a[9];
    if (fabs(ac) < POLY_COEFF_LIMIT) {
        if (fabs(bc) < POLY_COEFF_LIMIT)
            return 0;
        roots[0] = -cc / bc;
        return 1;
    }
    double disc = bc * bc - 4.0 * ac * cc;
    if (disc < 0.0)
        return 0;
    disc = sqrt(disc);
    roots[0] = (-bc + disc) / (2.0 * ac);
    roots[1] = (-bc - disc) / (2.0 * ac);
    return 2;
}

/* Poly::intersect: each term's (o + t d)^i (o + t d)^j (o + t d)^k
 * expanded by the binomial theorem into the polynomial in t (eqn[0] the
 * coefficient of t^order), its exactly-zero leading coefficients dropped,
 * then solved unless it is linear or constant. */
static int general_roots(const Shape *s, Vec3 o, Vec3 d, double *roots)
{
    const int order = s->u.poly.order;
    const double *coeffs = s->u.poly.coeffs;
    double pv[3][MAX_ORDER + 1], dv[3][MAX_ORDER + 1], t[3][MAX_ORDER + 1], eqn[MAX_ORDER + 1];
    double binomial[MAX_ORDER + 1][MAX_ORDER + 1];
    pascal(order, binomial);
    const double p1[3] = { o.x, o.y, o.z }, d1[3] = { d.x, d.y, d.z };
    for (int a = 0; a < 3; a++) {
        pv[a][0] = dv[a][0] = 1.0;
        pv[a][1] = p1[a];
        dv[a][1] = d1[a];
    }
    for (int i = 2; i <= order; i++)
        for (int a = 0; a < 3; a++) {
            pv[a][i] = pv[a][1] * pv[a][i - 1];
            dv[a][i] = dv[a][1] * dv[a][i - 1];
        }
    for (int i = 0; i <= order; i++)
        eqn[i] = 0.0;
    int term = 0;
    for (int i = order; i >= 0; i--) {
        for (int h = 0; h <= i; h++)
            t[0][h] = binomial[i][h] * dv[0][i - h] * pv[0][h];
        for (int j = order - i; j >= 0; j--) {
            for (int h = 0; h <= j; h++)
                t[1][h] = binomial[j][h] * dv[1][j - h] * pv[1][h];
            for (int k = order - (i + j); k >= 0; k--, term++) {
                if (coeffs[term] == 0)
                    continue;
                for (int h = 0; h <= k; h++)
                    t[2][h] = binomial[k][h] * dv[2][k - h] * pv[2][h];
                const int offset = order - (i + j + k);
                for (int i1 = 0; i1 <= i; i1++)
                    for (int j1 = 0; j1 <= j; j1++)
                        for (int k1 = 0; k1 <= k; k1++) {
                            double v = coeffs[term];
                            v *= t[0][i1];
                            v *= t[1][j1];
                            v *= t[2][k1];
                            eqn[offset + i1 + j1 + k1] += v;
                        }
            }
        }
    }
    int first = 0, degree = order;
    while (first <= order && eqn[first] == 0.0) {
        first++;
        degree--;
    }
    if (degree <= 1)
        return 0;
    return poly_solve(degree, eqn + first, roots, s->u.poly.sturm, POLY_ROOT_TOLERANCE);
}

/* The powers of q's coordinates up to order (x[i] = q.x^i, each the last
 * times q.x, as Poly's normal0 and inside build them). */
static void powers(Vec3 q, int order, double *x, double *y, double *z)
{
    x[0] = y[0] = z[0] = 1.0;
    x[1] = q.x;
    y[1] = q.y;
    z[1] = q.z;
    for (int i = 2; i <= order; i++) {
        x[i] = q.x * x[i - 1];
        y[i] = q.y * y[i - 1];
        z[i] = q.z * z[i - 1];
    }
}

/* The polynomial's gradient at q in its own space (Poly's normal0: each
 * term's partial derivatives summed in the order of terms). */
static Vec3 local_gradient(const Shape *s, Vec3 q)
{
    const int order = s->u.poly.order;
    const double *a = s->u.poly.coeffs;
    double x[MAX_ORDER + 1], y[MAX_ORDER + 1], z[MAX_ORDER + 1];
    powers(q, order, x, y, z);
    Vec3 g = v3(0.0, 0.0, 0.0);
    int term = 0;
    for (int i = order; i >= 0; i--)
        for (int j = order - i; j >= 0; j--)
            for (int k = order - (i + j); k >= 0; k--, term++) {
                if (i >= 1)
                    g.x += i * a[term] * (x[i - 1] * y[j] * z[k]);
                if (j >= 1)
                    g.y += j * a[term] * (x[i] * y[j - 1] * z[k]);
                if (k >= 1)
                    g.z += k * a[term] * (x[i] * y[j] * z[k - 1]);
            }
    return g;
}

int poly_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    /* the ray in its own space, its direction made unit there (distances
     * divided back by len) */
    Vec3 o = inverse_transform_point(&s->to_world, org);
    Vec3 d = inverse_transform_direction(&s->to_world, dir);
    double len = v3_length(d);
    if (!(len > 0.0))
        return 0;
    d = v3_scale(d, 1.0 / len);
    double roots[MAX_ORDER];
    int nr = s->u.poly.order == 2 ? quadratic_roots(s->u.poly.coeffs, o, d, roots) : general_roots(s, o, d, roots);
    int n = 0;
    for (int i = 0; i < nr; i++) {
        if (!(roots[i] > POLY_DEPTH_TOLERANCE))
            continue;
        int same = 0; /* a root returned twice counts once */
        for (int j = 0; j < i; j++)
            if (roots[j] == roots[i])
                same = 1;
        double t = roots[i] / len;
        if (same || !(t < tmax))
            continue;
        Vec3 at = v3_add(o, v3_scale(d, roots[i]));
        hits[n].t = t;
        hits[n].part = SHAPE_SIDE;
        hits[n].entering = (v3_dot(local_gradient(s, at), d) < 0.0) != (s->inverse != 0);
        n++;
    }
    /* nearest first; equal distances keep the solver's order */
    shape_hits_sort(hits, n);
    return n;
}

int poly_inside(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    const int order = s->u.poly.order;
    const double *a = s->u.poly.coeffs;
    double x[MAX_ORDER + 1], y[MAX_ORDER + 1], z[MAX_ORDER + 1];
    powers(q, order, x, y, z);
    double value = 0.0;
    int term = 0;
    for (int i = order; i >= 0; i--)
        for (int j = order - i; j >= 0; j--)
            for (int k = order - (i + j); k >= 0; k--, term++)
                if (a[term] != 0.0)
                    value += a[term] * x[i] * y[j] * z[k];
    return (value < POLY_INSIDE_TOLERANCE) != (s->inverse != 0);
}

Vec3 poly_normal(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    Vec3 n = transform_normal(&s->to_world, local_gradient(s, q));
    double len2 = v3_dot(n, n);
    if (!(len2 > 0.0))
        return v3(1.0, 0.0, 0.0); /* undefined there: POV-Ray's arbitrary choice */
    return v3_scale(n, 1.0 / sqrt(len2));
}
