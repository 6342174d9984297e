/* A linear-spline prism as POV-Ray 3.7 intersects it (prism.cpp): its 2-D
 * outlines (x, z) swept between height1 and height2 along y. Linear sweep:
 * a side is the rectangle over each outline edge, and the caps at both
 * heights are the outlines themselves, a point inside when inside an odd
 * number of them (in_curve). Conic sweep: the outlines at height 1 scaled
 * by the height, through the apex at the origin, so a side over an edge is
 * a trapezoid in the plane through the apex and that edge (two triangles
 * meeting at the apex when the heights lie either side of 0), and a cap at
 * height h is the outlines scaled by h (none where h is 0: POV-Ray skips a
 * cap within EPSILON of the apex). `open` leaves the caps out. A prism's
 * inside test matters only to CSG, which hstrace does not model. */
#include "planar_shapes.h"

#include <math.h>
#include <stdlib.h>

/* POV-Ray's EPSILON: a conic cap this close to the apex is not tested. */
#define POV_EPSILON 1.0e-10

/* Outline point i at height h, in world space. */
static Vec3 at_height(const SceneObject *o, const Transform *to_world, int i, double h)
{
    Vec3 p = o->u.prism.points[i]; /* (x, z) in .x, .y */
    double scale = o->u.prism.sweep == PRISM_CONIC_SWEEP ? h : 1.0;
    return transform_point(to_world, v3(p.x * scale, h, p.y * scale));
}

static int add_side(const SceneObject *o, const Transform *to_world, PieceSink *sink, int i)
{
    const double h1 = o->u.prism.height1, h2 = o->u.prism.height2;
    const int starts[2] = { 0, 4 };
    if (o->u.prism.sweep == PRISM_CONIC_SWEEP && h1 < 0.0 && h2 > 0.0) {
        const Vec3 apex = transform_point(to_world, v3(0, 0, 0));
        const Vec3 below[3] = { apex, at_height(o, to_world, i, h1), at_height(o, to_world, i + 1, h1) };
        const Vec3 above[3] = { apex, at_height(o, to_world, i, h2), at_height(o, to_world, i + 1, h2) };
        return sink->triangle(sink, below, NULL, NULL) || sink->triangle(sink, above, NULL, NULL) ? -1 : 0;
    }
    const Vec3 quad[4] = { at_height(o, to_world, i, h1), at_height(o, to_world, i + 1, h1),
                           at_height(o, to_world, i + 1, h2), at_height(o, to_world, i, h2) };
    if (o->u.prism.sweep == PRISM_CONIC_SWEEP && (h1 == 0.0 || h2 == 0.0)) {
        /* one end is the apex: a triangle */
        const Vec3 tri[3] = { h1 == 0.0 ? quad[0] : quad[3], quad[h1 == 0.0 ? 2 : 0], quad[h1 == 0.0 ? 3 : 1] };
        return sink->triangle(sink, tri, NULL, NULL);
    }
    return sink->polygon(sink, quad, 4, starts, 1);
}

static int add_cap(const SceneObject *o, const Transform *to_world, PieceSink *sink, double h)
{
    if (o->u.prism.sweep == PRISM_CONIC_SWEEP && fabs(h) <= POV_EPSILON)
        return 0;
    const int n = o->u.prism.npoints;
    Vec3 *pts = malloc(sizeof *pts * (size_t)n);
    if (!pts)
        return -1;
    for (int i = 0; i < n; i++)
        pts[i] = at_height(o, to_world, i, h);
    int rc = sink->polygon(sink, pts, n, o->u.prism.outline_start, o->u.prism.noutlines);
    free(pts);
    return rc;
}

int prism_pieces(const SceneObject *o, const Transform *to_world, PieceSink *sink)
{
    for (int k = 0; k < o->u.prism.noutlines; k++) {
        /* each outline ends on its first point: its edges are i, i + 1 */
        for (int i = o->u.prism.outline_start[k]; i + 1 < o->u.prism.outline_start[k + 1]; i++)
            if (add_side(o, to_world, sink, i))
                return -1;
    }
    if (o->u.prism.open)
        return 0;
    if (add_cap(o, to_world, sink, o->u.prism.height1))
        return -1;
    return add_cap(o, to_world, sink, o->u.prism.height2);
}

void prism_count(const SceneObject *o, double *pieces, double *points)
{
    /* a side or two a point, two caps of every point */
    *pieces = 2.0 * o->u.prism.npoints + 2.0;
    *points = 6.0 * o->u.prism.npoints + 2.0 * o->u.prism.npoints;
}
