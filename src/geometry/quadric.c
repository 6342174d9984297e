/* POV-Ray 3.7's quadric (quadrics.cpp), written anew from reading it: the
 * same arithmetic in the same order where it decides what a ray meets. */
#include "quadric.h"

#include <math.h>

#define POV_EPSILON 1.0e-10           /* POV-Ray's EPSILON */
#define POV_MAX_DISTANCE 1.0e7        /* POV-Ray's MAX_DISTANCE */
#define QUADRIC_DEPTH_TOLERANCE 1.0e-6 /* quadrics.cpp's DEPTH_TOLERANCE */
#define CRITICAL_LENGTH 1.0e6         /* POV-Ray's bounds longer than this are unbounded */

/* The form as Quadric_To_Matrix lays it out: upper triangular, the
 * mixed and linear coefficients once each. */
static void to_matrix(double q[4][4], Vec3 square, Vec3 mixed, Vec3 terms, double constant)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            q[i][j] = 0.0;
    q[0][0] = square.x;
    q[1][1] = square.y;
    q[2][2] = square.z;
    q[0][1] = mixed.x;
    q[0][2] = mixed.y;
    q[1][2] = mixed.z;
    q[0][3] = terms.x;
    q[1][3] = terms.y;
    q[2][3] = terms.z;
    q[3][3] = constant;
}

/* The axis-aligned box around the quadric as written, where
 * Quadric::Compute_BBox finds one without clipping: an ellipsoid or a
 * cylinder along an axis in its normal form (no mixed terms), else
 * unbounded (returns 0). Only a box around the solid is returned (a form
 * that Compute_BBox negates first has its solid outside the surface). */
static int local_bounds(Vec3 square, Vec3 mixed, Vec3 terms, double constant, Vec3 *lo, Vec3 *hi)
{
    double A = square.x, E = square.y, H = square.z;
    double B = mixed.x / 2.0, C = mixed.y / 2.0, F = mixed.z / 2.0;
    double D = terms.x / 2.0, G = terms.y / 2.0, I = terms.z / 2.0, J = constant;
    double *all[10] = { &A, &B, &C, &D, &E, &F, &G, &H, &I, &J };
    for (int k = 0; k < 10; k++)
        if (fabs(*all[k]) < POV_EPSILON)
            *all[k] = 0.0;
    if (B != 0.0 || C != 0.0 || F != 0.0 || A < 0.0)
        return 0;
    /* the centre, where the linear terms vanish */
    double tx = A != 0.0 ? -D / A : D != 0.0 ? J / (2.0 * D) : 0.0;
    double ty = E != 0.0 ? -G / E : G != 0.0 ? J / (2.0 * G) : 0.0;
    double tz = H != 0.0 ? -I / H : I != 0.0 ? J / (2.0 * I) : 0.0;
    if (D != 0.0 || G != 0.0 || I != 0.0) {
        D += A * tx;
        G += E * ty;
        I += H * tz;
        J -= tx * (A * tx + 2.0 * D) + ty * (E * ty + 2.0 * G) + tz * (H * tz + 2.0 * I);
    } else {
        tx = ty = tz = 0.0;
    }
    /* a linear term left over (a paraboloid's) leaves it unbounded here */
    if (D != 0.0 || G != 0.0 || I != 0.0 || !(J < 0.0))
        return 0;
    double rx = HUGE_VAL, ry = HUGE_VAL, rz = HUGE_VAL;
    if (A > 0.0 && E > 0.0 && H > 0.0) {
        rx = sqrt(-J / A);
        ry = sqrt(-J / E);
        rz = sqrt(-J / H);
    } else if (A == 0.0 && E > 0.0 && H > 0.0) {
        ry = sqrt(-J / E);
        rz = sqrt(-J / H);
    } else if (A > 0.0 && E == 0.0 && H > 0.0) {
        rx = sqrt(-J / A);
        rz = sqrt(-J / H);
    } else if (A > 0.0 && E > 0.0 && H == 0.0) {
        rx = sqrt(-J / A);
        ry = sqrt(-J / E);
    } else {
        return 0;
    }
    if (2.0 * rx > CRITICAL_LENGTH || 2.0 * ry > CRITICAL_LENGTH || 2.0 * rz > CRITICAL_LENGTH)
        return 0; /* POV-Ray makes such a box unbounded, whatever its axes */
    *lo = v3(tx - rx, ty - ry, tz - rz);
    *hi = v3(tx + rx, ty + ry, tz + rz);
    return 1;
}

void quadric_place(Shape *s, Vec3 square, Vec3 mixed, Vec3 terms, double constant, const Transform *to_world,
                   int inverse)
{
    /* Quadric::Transform: Q' = inverse * Q * transpose(inverse), then
     * Matrix_To_Quadric folds the symmetric entries together */
    double q[4][4], r[4][4], w[4][4];
    to_matrix(q, square, mixed, terms, constant);
    const double (*inv)[4] = to_world->inv;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double sum = 0.0;
            for (int k = 0; k < 4; k++)
                sum += inv[i][k] * q[k][j];
            r[i][j] = sum;
        }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double sum = 0.0;
            for (int k = 0; k < 4; k++)
                sum += r[i][k] * inv[j][k];
            w[i][j] = sum;
        }
    const double sign = inverse ? -1.0 : 1.0; /* Quadric::Invert */
    s->u.quadric.square = v3(sign * w[0][0], sign * w[1][1], sign * w[2][2]);
    s->u.quadric.mixed = v3(sign * (w[0][1] + w[1][0]), sign * (w[0][2] + w[2][0]), sign * (w[1][2] + w[2][1]));
    s->u.quadric.terms = v3(sign * (w[0][3] + w[3][0]), sign * (w[1][3] + w[3][1]), sign * (w[2][3] + w[3][2]));
    s->u.quadric.constant = sign * w[3][3];
    s->transformed = 0; /* its coefficients are the world's */
    s->to_world = *to_world;

    /* the box of the quadric as written, carried to world space as
     * Recompute_BBox carries it (its eight corners) */
    Vec3 lo, hi;
    if (!local_bounds(square, mixed, terms, constant, &lo, &hi)) {
        s->bbox_min = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
        s->bbox_max = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL);
        return;
    }
    Vec3 wlo = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL), whi = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
    for (int k = 0; k < 8; k++) {
        Vec3 c = v3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
        Vec3 p = transform_point(to_world, c);
        wlo = v3_min(wlo, p);
        whi = v3_max(whi, p);
    }
    s->bbox_min = wlo;
    s->bbox_max = whi;
}

/* Quadric::Intersect: the two roots of a t^2 + 2 b t + c, or the one of
 * 2 b t + c when there is no quadratic term (its second root POV-Ray's
 * MAX_DISTANCE, never kept). A tangent ray (discriminant <= 0) misses. */
static int quadric_roots(const Shape *s, Vec3 o, Vec3 d, double *t1, double *t2)
{
    const double QA = s->u.quadric.square.x, QE = s->u.quadric.square.y, QH = s->u.quadric.square.z;
    const double QB = s->u.quadric.mixed.x, QC = s->u.quadric.mixed.y, QF = s->u.quadric.mixed.z;
    const double QD = s->u.quadric.terms.x, QG = s->u.quadric.terms.y, QI = s->u.quadric.terms.z;
    const double QJ = s->u.quadric.constant;
    double a = d.x * (QA * d.x + QB * d.y + QC * d.z) + d.y * (QE * d.y + QF * d.z) + d.z * QH * d.z;
    double b = d.x * (QA * o.x + 0.5 * (QB * o.y + QC * o.z + QD)) + d.y * (QE * o.y + 0.5 * (QB * o.x + QF * o.z + QG)) +
               d.z * (QH * o.z + 0.5 * (QC * o.x + QF * o.y + QI));
    double c = o.x * (QA * o.x + QB * o.y + QC * o.z + QD) + o.y * (QE * o.y + QF * o.z + QG) + o.z * (QH * o.z + QI) + QJ;
    if (a != 0.0) {
        double disc = b * b - a * c;
        if (!(disc > 0.0))
            return 0;
        disc = sqrt(disc);
        *t1 = (-b + disc) / a;
        *t2 = (-b - disc) / a;
    } else {
        if (b == 0.0)
            return 0;
        *t1 = -0.5 * c / b;
        *t2 = POV_MAX_DISTANCE;
    }
    return 1;
}

/* The form's gradient at p (Quadric::Normal before it is made unit). */
static Vec3 gradient(const Shape *s, Vec3 p)
{
    const double QA = s->u.quadric.square.x, QE = s->u.quadric.square.y, QH = s->u.quadric.square.z;
    const double QB = s->u.quadric.mixed.x, QC = s->u.quadric.mixed.y, QF = s->u.quadric.mixed.z;
    const double QD = s->u.quadric.terms.x, QG = s->u.quadric.terms.y, QI = s->u.quadric.terms.z;
    return v3(2.0 * QA * p.x + QB * p.y + QC * p.z + QD, QB * p.x + 2.0 * QE * p.y + QF * p.z + QG,
              QC * p.x + QF * p.y + 2.0 * QH * p.z + QI);
}

int quadric_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    double t[2];
    if (!quadric_roots(s, org, dir, &t[0], &t[1]))
        return 0;
    int n = 0;
    for (int k = 0; k < 2; k++) {
        if (!(t[k] > QUADRIC_DEPTH_TOLERANCE && t[k] < POV_MAX_DISTANCE && t[k] < tmax))
            continue;
        hits[n].t = t[k];
        hits[n].part = SHAPE_SIDE;
        /* entering where the form falls along the ray (its coefficients
         * carry the inverse) */
        hits[n].entering = v3_dot(gradient(s, v3_add(org, v3_scale(dir, t[k]))), dir) < 0.0;
        n++;
    }
    if (n == 2 && hits[1].t < hits[0].t) {
        ShapeHit x = hits[0];
        hits[0] = hits[1];
        hits[1] = x;
    }
    return n;
}

int quadric_inside(const Shape *s, Vec3 p)
{
    const double QA = s->u.quadric.square.x, QE = s->u.quadric.square.y, QH = s->u.quadric.square.z;
    const double QB = s->u.quadric.mixed.x, QC = s->u.quadric.mixed.y, QF = s->u.quadric.mixed.z;
    const double QD = s->u.quadric.terms.x, QG = s->u.quadric.terms.y, QI = s->u.quadric.terms.z;
    const double QJ = s->u.quadric.constant;
    return p.x * (QA * p.x + QB * p.y + QD) + p.y * (QE * p.y + QF * p.z + QG) + p.z * (QH * p.z + QC * p.x + QI) + QJ <=
           0.0;
}

Vec3 quadric_normal(const Shape *s, Vec3 p)
{
    Vec3 g = gradient(s, p);
    double len = v3_length(g);
    if (len == 0.0)
        return v3(1.0, 0.0, 0.0); /* undefined there: POV-Ray's arbitrary choice */
    return v3_scale(g, 1.0 / len);
}

/* ---- Automatic_Bounds ------------------------------------------------------ */

#define BOUND_HUGE 2.0e10 /* POV-Ray's BOUND_HUGE */

/* The extent along one axis of a cone, hyperboloid or paraboloid at the
 * clipping box's two ends (Compute_BBox's rx1/rx2 pairs): the larger. */
static double larger(double a, double b) { return a > b ? a : b; }

int quadric_automatic_bounds(Vec3 square, Vec3 mixed, Vec3 terms, double constant)
{
    double A = square.x, E = square.y, H = square.z;
    double B = mixed.x / 2.0, C = mixed.y / 2.0, F = mixed.z / 2.0;
    double D = terms.x / 2.0, G = terms.y / 2.0, I = terms.z / 2.0, J = constant;
    double *all[10] = { &A, &B, &C, &D, &E, &F, &G, &H, &I, &J };
    for (int k = 0; k < 10; k++)
        if (fabs(*all[k]) < POV_EPSILON)
            *all[k] = 0.0;
    if (B != 0.0 || C != 0.0 || F != 0.0)
        return 0; /* Compute_BBox returns before it decides */
    double T[3] = { 0.0, 0.0, 0.0 };
    if (D != 0.0 || G != 0.0 || I != 0.0) {
        T[0] = A != 0.0 ? -D / A : D != 0.0 ? J / (2.0 * D) : 0.0;
        T[1] = E != 0.0 ? -G / E : G != 0.0 ? J / (2.0 * G) : 0.0;
        T[2] = H != 0.0 ? -I / H : I != 0.0 ? J / (2.0 * I) : 0.0;
        D += A * T[0];
        G += E * T[1];
        I += H * T[2];
        J -= T[0] * (A * T[0] + 2.0 * D) + T[1] * (E * T[1] + 2.0 * G) + T[2] * (H * T[2] + 2.0 * I);
    }
    double lo[3] = { -BOUND_HUGE / 2, -BOUND_HUGE / 2, -BOUND_HUGE / 2 };
    double hi[3] = { BOUND_HUGE / 2, BOUND_HUGE / 2, BOUND_HUGE / 2 };
    double cmin[3], cmax[3];
    for (int a = 0; a < 3; a++) {
        cmin[a] = -BOUND_HUGE - T[a];
        cmax[a] = BOUND_HUGE - T[a];
    }
    if (A < 0.0) {
        A = -A;
        D = -D;
        E = -E;
        G = -G;
        H = -H;
        I = -I;
        J = -J;
    }
    if (A > 0.0 && E > 0.0 && H > 0.0 && J < 0.0) { /* ellipsoid */
        hi[0] = sqrt(-J / A);
        hi[1] = sqrt(-J / E);
        hi[2] = sqrt(-J / H);
        lo[0] = -hi[0];
        lo[1] = -hi[1];
        lo[2] = -hi[2];
    }
    if (A == 0.0 && E > 0.0 && H > 0.0 && J < 0.0) { /* cylinder along x */
        hi[1] = sqrt(-J / E);
        hi[2] = sqrt(-J / H);
        lo[1] = -hi[1];
        lo[2] = -hi[2];
    }
    if (A > 0.0 && E == 0.0 && H > 0.0 && J < 0.0) { /* along y */
        hi[0] = sqrt(-J / A);
        hi[2] = sqrt(-J / H);
        lo[0] = -hi[0];
        lo[2] = -hi[2];
    }
    if (A > 0.0 && E > 0.0 && H == 0.0 && J < 0.0) { /* along z */
        hi[0] = sqrt(-J / A);
        hi[1] = sqrt(-J / E);
        lo[0] = -hi[0];
        lo[1] = -hi[1];
    }
    /* cones about x, y, z: radii at the clipping box's ends */
    if (A > 0.0 && E < 0.0 && H < 0.0 && J == 0.0) {
        double a = sqrt(1.0 / A), b = sqrt(-1.0 / E), c = sqrt(-1.0 / H);
        double ry = larger(fabs(cmin[0] * b / a), fabs(cmax[0] * b / a));
        double rz = larger(fabs(cmin[0] * c / a), fabs(cmax[0] * c / a));
        lo[1] = -ry, hi[1] = ry, lo[2] = -rz, hi[2] = rz;
    }
    if (A > 0.0 && E < 0.0 && H > 0.0 && J == 0.0) {
        double a = sqrt(1.0 / A), b = sqrt(-1.0 / E), c = sqrt(1.0 / H);
        double rx = larger(fabs(cmin[1] * a / b), fabs(cmax[1] * a / b));
        double rz = larger(fabs(cmin[1] * c / b), fabs(cmax[1] * c / b));
        lo[0] = -rx, hi[0] = rx, lo[2] = -rz, hi[2] = rz;
    }
    if (A > 0.0 && E > 0.0 && H < 0.0 && J == 0.0) {
        double a = sqrt(1.0 / A), b = sqrt(1.0 / E), c = sqrt(-1.0 / H);
        double rx = larger(fabs(cmin[2] * a / c), fabs(cmax[2] * a / c));
        double ry = larger(fabs(cmin[2] * b / c), fabs(cmax[2] * b / c));
        lo[0] = -rx, hi[0] = rx, lo[1] = -ry, hi[1] = ry;
    }
    /* hyperboloids about x, y, z */
    if (A > 0.0 && E < 0.0 && H < 0.0 && J > 0.0) {
        double d1 = 1.0 + A * cmin[0] * cmin[0], d2 = 1.0 + A * cmax[0] * cmax[0];
        double ry = larger(sqrt(-d1 / E), sqrt(-d2 / E)), rz = larger(sqrt(-d1 / H), sqrt(-d2 / H));
        lo[1] = -ry, hi[1] = ry, lo[2] = -rz, hi[2] = rz;
    }
    if (A > 0.0 && E < 0.0 && H > 0.0 && J < 0.0) {
        double d1 = 1.0 - E * cmin[1] * cmin[1], d2 = 1.0 - E * cmax[1] * cmax[1];
        double rx = larger(sqrt(d1 / A), sqrt(d2 / A)), rz = larger(sqrt(d1 / H), sqrt(d2 / H));
        lo[0] = -rx, hi[0] = rx, lo[2] = -rz, hi[2] = rz;
    }
    if (A > 0.0 && E > 0.0 && H < 0.0 && J < 0.0) {
        double d1 = 1.0 - H * cmin[2] * cmin[2], d2 = 1.0 - H * cmax[2] * cmax[2];
        double rx = larger(sqrt(d1 / A), sqrt(d2 / A)), ry = larger(sqrt(d1 / E), sqrt(d2 / E));
        lo[0] = -rx, hi[0] = rx, lo[1] = -ry, hi[1] = ry;
    }
    /* paraboloids along x, y, z */
    if (A == 0.0 && D != 0.0 && E * H > 0.0 && J == 0.0) {
        double x1 = D * E < 0 ? larger(0.0, cmin[0]) : cmin[0];
        double x2 = D * E > 0 ? (cmax[0] < 0.0 ? cmax[0] : 0.0) : cmax[0];
        double ry = larger(sqrt(fabs(2.0 * D * x1 / E)), sqrt(fabs(2.0 * D * x2 / E)));
        double rz = larger(sqrt(fabs(2.0 * D * x1 / H)), sqrt(fabs(2.0 * D * x2 / H)));
        if (D * E < 0)
            lo[0] = larger(0.0, cmin[0]);
        if (D * E > 0)
            hi[0] = cmax[0] < 0.0 ? cmax[0] : 0.0;
        lo[1] = -ry, hi[1] = ry, lo[2] = -rz, hi[2] = rz;
    }
    if (E == 0.0 && G != 0.0 && A * H > 0.0 && J == 0.0) {
        double y1 = G > 0 ? cmin[1] : larger(0.0, cmin[1]);
        double y2 = G < 0 ? cmax[1] : (cmax[1] < 0.0 ? cmax[1] : 0.0);
        double rx = larger(sqrt(fabs(2.0 * G * y1 / A)), sqrt(fabs(2.0 * G * y2 / A)));
        double rz = larger(sqrt(fabs(2.0 * G * y1 / H)), sqrt(fabs(2.0 * G * y2 / H)));
        if (G < 0)
            lo[1] = larger(0.0, cmin[1]);
        if (G > 0)
            hi[1] = cmax[1] < 0.0 ? cmax[1] : 0.0;
        lo[0] = -rx, hi[0] = rx, lo[2] = -rz, hi[2] = rz;
    }
    if (H == 0.0 && I != 0.0 && A * E > 0.0 && J == 0.0) {
        double z1 = I < 0 ? larger(cmin[2], 0.0) : cmin[2];
        double z2 = I > 0 ? (cmax[2] < 0.0 ? cmax[2] : 0.0) : cmax[2];
        double rx = larger(sqrt(fabs(2.0 * I * z1 / A)), sqrt(fabs(2.0 * I * z2 / A)));
        double ry = larger(sqrt(fabs(2.0 * I * z1 / E)), sqrt(fabs(2.0 * I * z2 / E)));
        if (I < 0)
            lo[2] = larger(cmin[2], 0.0);
        if (I > 0)
            hi[2] = cmax[2] < 0.0 ? cmax[2] : 0.0;
        lo[0] = -rx, hi[0] = rx, lo[1] = -ry, hi[1] = ry;
    }
    double volume = 1.0;
    for (int a = 0; a < 3; a++) {
        double l = larger(lo[a], cmin[a]), h = hi[a] < cmax[a] ? hi[a] : cmax[a];
        volume *= h - l;
    }
    /* the object's first box: BOUND_HUGE on each side, as floats */
    const double first = (double)(float)BOUND_HUGE * (double)(float)BOUND_HUGE * (double)(float)BOUND_HUGE;
    return volume < first;
}
