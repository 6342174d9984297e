/* Affine transforms; see transform.h for the conventions (POV-Ray's). */
#include "transform.h"

#include <string.h>

static void mat_identity(double m[4][4])
{
    memset(m, 0, sizeof(double) * 16);
    m[0][0] = m[1][1] = m[2][2] = m[3][3] = 1.0;
}

/* r = a * b */
static void mat_mul(double r[4][4], const double a[4][4], const double b[4][4])
{
    double t[4][4];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            t[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j] + a[i][3] * b[3][j];
    memcpy(r, t, sizeof t);
}

void transform_identity(Transform *t)
{
    mat_identity(t->m);
    mat_identity(t->inv);
}

void transform_compose(Transform *t, const Transform *u)
{
    mat_mul(t->m, t->m, u->m);
    mat_mul(t->inv, u->inv, t->inv);
}

void transform_translate(Transform *t, Vec3 v)
{
    Transform u;
    transform_identity(&u);
    u.m[3][0] = v.x; u.m[3][1] = v.y; u.m[3][2] = v.z;
    u.inv[3][0] = -v.x; u.inv[3][1] = -v.y; u.inv[3][2] = -v.z;
    transform_compose(t, &u);
}

void transform_scale(Transform *t, Vec3 v)
{
    Transform u;
    transform_identity(&u);
    u.m[0][0] = v.x; u.m[1][1] = v.y; u.m[2][2] = v.z;
    u.inv[0][0] = 1.0 / v.x; u.inv[1][1] = 1.0 / v.y; u.inv[2][2] = 1.0 / v.z;
    transform_compose(t, &u);
}

void transform_rotate(Transform *t, Vec3 degrees)
{
    const double k = M_PI / 180.0;
    double cx = cos(degrees.x * k), sx = sin(degrees.x * k);
    double cy = cos(degrees.y * k), sy = sin(degrees.y * k);
    double cz = cos(degrees.z * k), sz = sin(degrees.z * k);
    Transform rx, ry, rz;
    transform_identity(&rx);
    rx.m[1][1] = cx; rx.m[2][2] = cx; rx.m[1][2] = sx; rx.m[2][1] = -sx;
    transform_identity(&ry);
    ry.m[0][0] = cy; ry.m[2][2] = cy; ry.m[0][2] = -sy; ry.m[2][0] = sy;
    transform_identity(&rz);
    rz.m[0][0] = cz; rz.m[1][1] = cz; rz.m[0][1] = sz; rz.m[1][0] = -sz;
    /* Rotations are orthonormal: the inverse is the transpose. */
    Transform *parts[3] = { &rx, &ry, &rz };
    for (int p = 0; p < 3; p++) {
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++)
                parts[p]->inv[i][j] = parts[p]->m[j][i];
        transform_compose(t, parts[p]);
    }
}

/* Inverse of an affine 4x4 (last column 0,0,0,1) by cofactors of the 3x3. */
static int affine_inverse(double r[4][4], const double m[4][4])
{
    double a = m[0][0], b = m[0][1], c = m[0][2];
    double d = m[1][0], e = m[1][1], f = m[1][2];
    double g = m[2][0], h = m[2][1], i = m[2][2];
    double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    if (det == 0.0 || !isfinite(det))
        return 0;
    double s = 1.0 / det;
    mat_identity(r);
    r[0][0] = (e * i - f * h) * s; r[0][1] = (c * h - b * i) * s; r[0][2] = (b * f - c * e) * s;
    r[1][0] = (f * g - d * i) * s; r[1][1] = (a * i - c * g) * s; r[1][2] = (c * d - a * f) * s;
    r[2][0] = (d * h - e * g) * s; r[2][1] = (b * g - a * h) * s; r[2][2] = (a * e - b * d) * s;
    for (int j = 0; j < 3; j++)
        r[3][j] = -(m[3][0] * r[0][j] + m[3][1] * r[1][j] + m[3][2] * r[2][j]);
    return 1;
}

int transform_matrix(Transform *t, const double v[12])
{
    Transform u;
    transform_identity(&u);
    for (int row = 0; row < 4; row++)
        for (int col = 0; col < 3; col++)
            u.m[row][col] = v[row * 3 + col];
    if (!affine_inverse(u.inv, u.m))
        return 0;
    transform_compose(t, &u);
    return 1;
}

int transform_is_identity(const Transform *t)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            if (t->m[i][j] != (i == j ? 1.0 : 0.0))
                return 0;
    return 1;
}

static Vec3 mul_point(const double m[4][4], Vec3 p)
{
    return v3(p.x * m[0][0] + p.y * m[1][0] + p.z * m[2][0] + m[3][0],
              p.x * m[0][1] + p.y * m[1][1] + p.z * m[2][1] + m[3][1],
              p.x * m[0][2] + p.y * m[1][2] + p.z * m[2][2] + m[3][2]);
}

static Vec3 mul_direction(const double m[4][4], Vec3 d)
{
    return v3(d.x * m[0][0] + d.y * m[1][0] + d.z * m[2][0],
              d.x * m[0][1] + d.y * m[1][1] + d.z * m[2][1],
              d.x * m[0][2] + d.y * m[1][2] + d.z * m[2][2]);
}

Vec3 transform_point(const Transform *t, Vec3 p) { return mul_point(t->m, p); }
Vec3 transform_direction(const Transform *t, Vec3 d) { return mul_direction(t->m, d); }
Vec3 inverse_transform_point(const Transform *t, Vec3 p) { return mul_point(t->inv, p); }
Vec3 inverse_transform_direction(const Transform *t, Vec3 d) { return mul_direction(t->inv, d); }

Vec3 inverse_transform_normal(const Transform *t, Vec3 n)
{
    /* n * M^T: row i of the forward matrix dotted with n (POV-Ray's MInvTransNormal). */
    const double (*v)[4] = t->m;
    return v3(n.x * v[0][0] + n.y * v[0][1] + n.z * v[0][2],
              n.x * v[1][0] + n.y * v[1][1] + n.z * v[1][2],
              n.x * v[2][0] + n.y * v[2][1] + n.z * v[2][2]);
}

Vec3 transform_normal(const Transform *t, Vec3 n)
{
    /* n * (M^-1)^T: row i of the inverse dotted with n. */
    const double (*v)[4] = t->inv;
    return v3(n.x * v[0][0] + n.y * v[0][1] + n.z * v[0][2],
              n.x * v[1][0] + n.y * v[1][1] + n.z * v[1][2],
              n.x * v[2][0] + n.y * v[2][1] + n.z * v[2][2]);
}

static double row_dot(const Transform *t, int i, int j)
{
    return t->m[i][0] * t->m[j][0] + t->m[i][1] * t->m[j][1] + t->m[i][2] * t->m[j][2];
}

int transform_is_similarity(const Transform *t)
{
    double l0 = row_dot(t, 0, 0), l1 = row_dot(t, 1, 1), l2 = row_dot(t, 2, 2);
    double tol = 1e-12 * (l0 + l1 + l2);
    return fabs(l0 - l1) <= tol && fabs(l0 - l2) <= tol && fabs(row_dot(t, 0, 1)) <= tol &&
           fabs(row_dot(t, 0, 2)) <= tol && fabs(row_dot(t, 1, 2)) <= tol;
}

double transform_similarity_scale(const Transform *t) { return sqrt(row_dot(t, 0, 0)); }

void transform_coordinate_frame(Transform *t, Vec3 origin, Vec3 up, double radius, double length)
{
    /* scaled by (radius, radius, length), turned about the axis
     * (-up.y, up.x, 0) by acos(up.z) so that z becomes up, then moved to
     * origin: the frame of POV-Ray's Compute_Coordinate_Transform */
    transform_identity(t);
    transform_scale(t, v3(radius, radius, length));
    Vec3 k;
    double angle;
    if (fabs(up.z) > 1.0 - POV_EPSILON) {
        k = v3(1.0, 0.0, 0.0);
        angle = up.z < 0.0 ? M_PI : 0.0;
    } else {
        k = v3_normalize(v3(-up.y, up.x, 0.0));
        angle = acos(up.z);
    }
    double c = cos(angle), sn = sin(angle), omc = 1.0 - c;
    double m[12] = {
        k.x * k.x * omc + c,        k.x * k.y * omc + k.z * sn, k.x * k.z * omc - k.y * sn,
        k.x * k.y * omc - k.z * sn, k.y * k.y * omc + c,        k.y * k.z * omc + k.x * sn,
        k.x * k.z * omc + k.y * sn, k.y * k.z * omc - k.x * sn, k.z * k.z * omc + c,
        origin.x,                   origin.y,                   origin.z,
    };
    Transform turn;
    transform_identity(&turn);
    (void)transform_matrix(&turn, m); /* a rotation: never singular */
    transform_compose(t, &turn);
}

int transform_cone_frame(Transform *frame, Vec3 base, double base_radius, Vec3 apex, double apex_radius,
                         double *dist)
{
    Vec3 axis = v3_sub(apex, base);
    double len = v3_length(axis);
    axis = v3_scale(axis, 1.0 / len);
    *dist = 0.0;
    if (fabs(apex_radius - base_radius) >= POV_EPSILON) {
        if (apex_radius < base_radius) { /* the wider end last */
            Vec3 v = base;
            base = apex;
            apex = v;
            double r = base_radius;
            base_radius = apex_radius;
            apex_radius = r;
            axis = v3_neg(axis);
        }
        double tip = base_radius * len / (apex_radius - base_radius); /* from the base to the cone's tip */
        double total = tip + len;
        if ((apex_radius - base_radius) * len / total >= POV_EPSILON) {
            *dist = tip / total;
            transform_coordinate_frame(frame, v3_sub(base, v3_scale(axis, tip)), axis, apex_radius, total);
            return 0;
        }
    }
    transform_coordinate_frame(frame, base, axis, apex_radius, len);
    return 1;
}
