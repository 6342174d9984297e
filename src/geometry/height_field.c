/* height_field as POV-Ray 3.7 intersects it (hfield.cpp): each cell (x, z)
 * of its samples is two triangles, (x,z) (x+1,z) (x,z+1) and (x+1,z+1)
 * (x,z+1) (x+1,z), the diagonal from (x+1, z) to (x, z+1); every cell up to
 * the last row and column is there. Samples sit at x and z in whole units
 * and heights in 0..65535, the whole scaled by 1/(nx-1), 1/65536,
 * 1/(nz-1) into the unit square, then placed by the object's transforms.
 *
 * POV-Ray finds hits only inside the field's bounding box, whose floor is
 * the water level (or the lowest sample, if higher) less 0.001: the surface
 * below it is not there, so each triangle is cut at that plane, which keeps
 * it a convex polygon.
 *
 * A smooth field's shading normal is POV-Ray's: per sample the normalised
 * sum of the unit normals of the four triangles around it (add_single_normal,
 * in sample units), stored as 16-bit integers (32767 times each component,
 * truncated), carried to world space one by one, normalised, and blended
 * bilinearly by the point's place in its cell (HField::Normal) -- not by the
 * triangle's barycentric weights, hence the cell's own shading data
 * (planar_shapes.h). POV-Ray's inside test (below the triangles of the cell,
 * or under the water level) matters only to CSG, which hstrace does not
 * model. */
#include "planar_shapes.h"

#include <math.h>

/* POV-Ray's HFIELD_OFFSET: the bounding box's margin, in sample units. */
#define HFIELD_OFFSET 0.001

typedef struct {
    const unsigned short *h;
    int nx, nz;
    Transform to_world;   /* samples to world: the unit-square scaling, then the object's */
    Vec3 axis_x, axis_z;  /* world point -> sample x and z: a linear part ... */
    Vec3 origin_xz;       /* ... and the world origin's sample x and z (in .x, .y) */
} Field;

static double height(const Field *f, int x, int z) { return f->h[(size_t)z * (size_t)f->nx + (size_t)x]; }

/* One of the four triangles around a sample, (x0,z0) (x1,z1) (x2,z2): its
 * unit normal, turned upward, added to *sum; 0 when a corner is outside
 * the field. */
static int add_triangle_normal(const Field *f, int x0, int z0, int x1, int z1, int x2, int z2, Vec3 *sum)
{
    if (x0 < 0 || z0 < 0 || x1 < 0 || z1 < 0 || x2 < 0 || z2 < 0 || x0 >= f->nx || x1 >= f->nx || x2 >= f->nx ||
        z0 >= f->nz || z1 >= f->nz || z2 >= f->nz)
        return 0;
    Vec3 v0 = v3(x0, height(f, x0, z0), z0), v1 = v3(x1, height(f, x1, z1), z1), v2 = v3(x2, height(f, x2, z2), z2);
    Vec3 n = v3_cross(v3_sub(v2, v0), v3_sub(v1, v0));
    n = v3_scale(n, 1.0 / v3_length(n)); /* never 0: its y is +-1 */
    if (n.y < 0.0)
        n = v3_neg(n);
    *sum = v3_add(*sum, n);
    return 1;
}

/* A sample's normal in world space, unit length. */
static Vec3 sample_normal(const Field *f, int x, int z)
{
    Vec3 sum = v3(0, 0, 0);
    (void)add_triangle_normal(f, x, z, x + 1, z, x, z + 1, &sum);
    (void)add_triangle_normal(f, x, z, x, z + 1, x - 1, z, &sum);
    (void)add_triangle_normal(f, x, z, x - 1, z, x, z - 1, &sum);
    (void)add_triangle_normal(f, x, z, x, z - 1, x + 1, z, &sum);
    /* a field of 2x2 samples at least gives every sample one triangle */
    Vec3 n = v3_scale(sum, 1.0 / v3_length(sum));
    /* kept as POV-Ray keeps it: 16-bit, truncated */
    Vec3 stored = v3((double)(short)(32767.0 * n.x), (double)(short)(32767.0 * n.y), (double)(short)(32767.0 * n.z));
    return v3_normalize(transform_normal(&f->to_world, stored));
}

/* The cell's shading data (planar_shapes.h) for cell (x, z). */
static void cell_data(const Field *f, int x, int z, Vec3 cell[CELL_NORMAL_VECTORS])
{
    cell[0] = sample_normal(f, x, z);
    cell[1] = sample_normal(f, x + 1, z);
    cell[2] = sample_normal(f, x, z + 1);
    cell[3] = sample_normal(f, x + 1, z + 1);
    cell[4] = f->axis_x;
    cell[5] = f->axis_z;
    cell[6] = v3(f->origin_xz.x - x, f->origin_xz.y - z, 0.0);
}

Vec3 cell_normal_at(const Vec3 cell[CELL_NORMAL_VECTORS], Vec3 q, Vec3 flat)
{
    double fx = v3_dot(cell[4], q) + cell[6].x, fz = v3_dot(cell[5], q) + cell[6].y;
    double ux = 1.0 - fx, uz = 1.0 - fz;
    Vec3 r = v3_add(v3_scale(v3_add(v3_scale(cell[0], ux), v3_scale(cell[1], fx)), uz),
                    v3_scale(v3_add(v3_scale(cell[2], ux), v3_scale(cell[3], fx)), fz));
    double len = v3_length(r);
    return len > 0.0 ? v3_scale(r, 1.0 / len) : flat;
}

/* The part of triangle t (sample units) at or above height `floor`: a
 * convex polygon of up to 4 points into out; returns their count (0: none). */
static int above_floor(const Vec3 t[3], double floor, Vec3 out[4])
{
    int n = 0;
    for (int i = 0; i < 3; i++) {
        Vec3 a = t[i], b = t[(i + 1) % 3];
        int a_in = a.y >= floor, b_in = b.y >= floor;
        if (a_in)
            out[n++] = a;
        if (a_in != b_in) {
            double s = (floor - a.y) / (b.y - a.y);
            out[n++] = v3(a.x + s * (b.x - a.x), floor, a.z + s * (b.z - a.z));
        }
    }
    return n;
}

static int add_piece(const Field *f, PieceSink *sink, const Vec3 t[3], double floor, const Vec3 *cell)
{
    Vec3 kept[4], world[4];
    int n = 3;
    if (t[0].y >= floor && t[1].y >= floor && t[2].y >= floor) {
        kept[0] = t[0];
        kept[1] = t[1];
        kept[2] = t[2];
    } else {
        n = above_floor(t, floor, kept);
        if (n < 3)
            return 0;
    }
    for (int i = 0; i < n; i++)
        world[i] = transform_point(&f->to_world, kept[i]);
    if (cell)
        return sink->cell_polygon(sink, world, n, cell);
    if (n == 3)
        return sink->triangle(sink, world, NULL, NULL);
    const int starts[2] = { 0, n };
    return sink->polygon(sink, world, n, starts, 1);
}

int height_field_pieces(const SceneObject *o, const Transform *to_world, PieceSink *sink)
{
    Field f;
    f.h = o->u.height_field.heights;
    f.nx = o->u.height_field.nx;
    f.nz = o->u.height_field.nz;
    if (f.nx < 2 || f.nz < 2)
        return 0;
    transform_identity(&f.to_world);
    transform_scale(&f.to_world, v3(1.0 / (f.nx - 1), 1.0 / 65536.0, 1.0 / (f.nz - 1)));
    transform_compose(&f.to_world, to_world);
    /* world -> samples is affine: its linear part from the axes, its
     * offset from the origin */
    Vec3 o0 = inverse_transform_point(&f.to_world, v3(0, 0, 0));
    Vec3 ex = inverse_transform_direction(&f.to_world, v3(1, 0, 0));
    Vec3 ey = inverse_transform_direction(&f.to_world, v3(0, 1, 0));
    Vec3 ez = inverse_transform_direction(&f.to_world, v3(0, 0, 1));
    f.axis_x = v3(ex.x, ey.x, ez.x);
    f.axis_z = v3(ex.z, ey.z, ez.z);
    f.origin_xz = v3(o0.x, o0.z, 0.0);
    double lowest = 65535.0;
    for (size_t i = 0; i < (size_t)f.nx * (size_t)f.nz; i++)
        lowest = fmin(lowest, f.h[i]);
    const double floor = fmax(lowest, o->u.height_field.water) - HFIELD_OFFSET;
    for (int z = 0; z + 1 < f.nz; z++) {
        for (int x = 0; x + 1 < f.nx; x++) {
            Vec3 cell[CELL_NORMAL_VECTORS];
            if (o->u.height_field.smooth)
                cell_data(&f, x, z, cell);
            const Vec3 lower[3] = { v3(x, height(&f, x, z), z), v3(x + 1, height(&f, x + 1, z), z),
                                    v3(x, height(&f, x, z + 1), z + 1) };
            const Vec3 upper[3] = { v3(x + 1, height(&f, x + 1, z + 1), z + 1), v3(x, height(&f, x, z + 1), z + 1),
                                    v3(x + 1, height(&f, x + 1, z), z) };
            const Vec3 *shading = o->u.height_field.smooth ? cell : NULL;
            if (add_piece(&f, sink, lower, floor, shading) || add_piece(&f, sink, upper, floor, shading))
                return -1;
        }
    }
    return 0;
}

void height_field_count(const SceneObject *o, double *pieces, double *points)
{
    double cells = (double)(o->u.height_field.nx - 1) * (double)(o->u.height_field.nz - 1);
    *pieces = 2.0 * cells;
    /* up to 4 points a piece (cut by the water level) and a smooth one's
     * shading data */
    *points = 2.0 * cells * (4.0 + (o->u.height_field.smooth ? CELL_NORMAL_VECTORS : 0.0));
}
