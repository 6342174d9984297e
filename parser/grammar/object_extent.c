/* The bounding box POV-Ray keeps on an object (ObjectBase::BBox), which
 * min_extent and max_extent report: a corner and lengths in single
 * precision (BBOX_VAL), made from a minimum and maximum by
 * Make_BBox_from_min_max and carried through each transform by
 * Recompute_BBox (bbox.cpp): the box around its eight corners moved, held
 * within BOUND_HUGE. Written anew from reading them. */
#include "grammar.h"

#include <math.h>

#define BOUND_HUGE 2.0e10     /* POV-Ray's BOUND_HUGE */
#define CRITICAL_LENGTH 1.0e6 /* POV-Ray's CRITICAL_LENGTH: a longer box is the box of everything */

void gram_extent_from_min_max(SceneObject *o, const double min[3], const double max[3])
{
    for (int i = 0; i < 3; i++) {
        o->extent_lower[i] = (float)min[i];
        o->extent_lengths[i] = (float)(max[i] - min[i]);
    }
    o->has_extent = 1;
}

void gram_extent_min_max(const SceneObject *o, double min[3], double max[3])
{
    for (int i = 0; i < 3; i++) {
        min[i] = o->extent_lower[i];
        max[i] = min[i] + o->extent_lengths[i];
    }
}

void gram_extent_transform(SceneObject *o, const Transform *t)
{
    if (!o->has_extent)
        return;
    double mins[3] = { BOUND_HUGE, BOUND_HUGE, BOUND_HUGE }, maxs[3] = { -BOUND_HUGE, -BOUND_HUGE, -BOUND_HUGE };
    for (int k = 1; k <= 8; k++) {
        Vec3 c = v3(o->extent_lower[0], o->extent_lower[1], o->extent_lower[2]);
        c.x += (k & 1) ? (double)o->extent_lengths[0] : 0.0;
        c.y += (k & 2) ? (double)o->extent_lengths[1] : 0.0;
        c.z += (k & 4) ? (double)o->extent_lengths[2] : 0.0;
        c = transform_point(t, c);
        const double v[3] = { c.x, c.y, c.z };
        for (int i = 0; i < 3; i++) {
            if (v[i] < mins[i])
                mins[i] = v[i];
            if (v[i] > maxs[i])
                maxs[i] = v[i];
        }
    }
    for (int i = 0; i < 3; i++) {
        if (mins[i] < -BOUND_HUGE / 2)
            mins[i] = -BOUND_HUGE / 2;
        if (maxs[i] > BOUND_HUGE / 2)
            maxs[i] = BOUND_HUGE / 2;
    }
    gram_extent_from_min_max(o, mins, maxs);
}

void gram_csg_extent(SceneObject *o)
{
    const int intersection = o->kind == OBJ_INTERSECTION || o->kind == OBJ_DIFFERENCE;
    if (o->u.csg.nlights > 0) /* light sources are children too in POV-Ray: not followed */
        return;
    /* CSG::Compute_BBox: an intersection's box is the overlap of its parts'
     * that are not inverted (a difference's later parts are), a union's or
     * merge's the box around them all */
    double nmin[3], nmax[3];
    for (int k = 0; k < 3; k++) {
        nmin[k] = intersection ? -BOUND_HUGE : BOUND_HUGE;
        nmax[k] = intersection ? BOUND_HUGE : -BOUND_HUGE;
    }
    for (int i = 0; i < o->u.csg.nchildren; i++) {
        const SceneObject *c = o->u.csg.children[i];
        const int inverted = (o->kind == OBJ_DIFFERENCE && i > 0) != (c->inverse != 0);
        if (intersection && inverted)
            continue;
        if (!c->has_extent)
            return; /* a part whose box hstrace does not keep */
        double lo[3], hi[3];
        gram_extent_min_max(c, lo, hi);
        for (int k = 0; k < 3; k++) {
            nmin[k] = intersection ? fmax(nmin[k], lo[k]) : fmin(nmin[k], lo[k]);
            nmax[k] = intersection ? fmin(nmax[k], hi[k]) : fmax(nmax[k], hi[k]);
        }
    }
    if (nmin[0] > nmax[0] || nmin[1] > nmax[1] || nmin[2] > nmax[2])
        return; /* degenerate: POV-Ray keeps the huge box it starts with */
    const double volume = (nmax[0] - nmin[0]) * (nmax[1] - nmin[1]) * (nmax[2] - nmin[2]);
    const float start = (float)BOUND_HUGE; /* the huge box's lengths, its volume in single precision */
    if (!(volume < (double)(start * start * start)))
        return;
    gram_extent_from_min_max(o, nmin, nmax);
    for (int k = 0; k < 3; k++)
        if (o->extent_lengths[k] > CRITICAL_LENGTH) {
            const double huge_min[3] = { -BOUND_HUGE / 2, -BOUND_HUGE / 2, -BOUND_HUGE / 2 };
            const double huge_max[3] = { BOUND_HUGE / 2, BOUND_HUGE / 2, BOUND_HUGE / 2 };
            gram_extent_from_min_max(o, huge_min, huge_max);
            break;
        }
}

/* ---- the primitives' boxes (each kind's Compute_BBox) ---------------------- */

#define SMALL_TOLERANCE 1.0e-3 /* POV-Ray's SMALL_TOLERANCE */

/* POV-Ray's Make_BBox: a corner and lengths, each rounded to single
 * precision. */
static void make_bbox(SceneObject *o, Vec3 lower, Vec3 lengths)
{
    const double lo[3] = { lower.x, lower.y, lower.z }, len[3] = { lengths.x, lengths.y, lengths.z };
    for (int i = 0; i < 3; i++) {
        o->extent_lower[i] = (float)lo[i];
        o->extent_lengths[i] = (float)len[i];
    }
    o->has_extent = 1;
}

/* Make_BBox of [lo, hi], then Recompute_BBox through t. */
static void box_through(SceneObject *o, Vec3 lo, Vec3 hi, const Transform *t)
{
    make_bbox(o, lo, v3_sub(hi, lo));
    gram_extent_transform(o, t);
}

/* The box around points pts carried by t, grown by `grow` each way
 * (Make_BBox_from_min_max). */
static void points_box(SceneObject *o, const Vec3 *pts, int n, const Transform *t, double grow)
{
    double mins[3] = { BOUND_HUGE, BOUND_HUGE, BOUND_HUGE }, maxs[3] = { -BOUND_HUGE, -BOUND_HUGE, -BOUND_HUGE };
    for (int k = 0; k < n; k++) {
        Vec3 w = transform_point(t, pts[k]);
        const double v[3] = { w.x, w.y, w.z };
        for (int i = 0; i < 3; i++) {
            mins[i] = v[i] < mins[i] ? v[i] : mins[i];
            maxs[i] = v[i] > maxs[i] ? v[i] : maxs[i];
        }
    }
    for (int i = 0; i < 3; i++) {
        mins[i] -= grow;
        maxs[i] += grow;
    }
    gram_extent_from_min_max(o, mins, maxs);
}

/* Whether t only scales along the axes and moves: what POV-Ray's Box takes
 * into its corners (a rotation or a matrix gives it a transform of its
 * own, through which Recompute_BBox turns its box). */
static int axis_aligned(const Transform *t)
{
    return t->m[0][1] == 0.0 && t->m[0][2] == 0.0 && t->m[1][0] == 0.0 && t->m[1][2] == 0.0 && t->m[2][0] == 0.0 &&
           t->m[2][1] == 0.0;
}

void gram_sphere_extent_step(Parser *p, SceneObject *o, int kw, const Transform *step)
{
    /* Sphere::Translate, Rotate and a uniform Scale move the centre and
     * the radius while it has no transform of its own; anything else
     * (a scale that is not uniform, a matrix, a transform) begins one,
     * which every later step extends (Sphere::Transform) */
    const double sx = step->m[0][0], sy = step->m[1][1], sz = step->m[2][2];
    if (!o->u.sphere.pov_trans) {
        if (kw == KW_translate || kw == KW_rotate) {
            o->u.sphere.pov_center = transform_point(step, o->u.sphere.pov_center);
            return;
        }
        if (kw == KW_scale && sx == sy && sx == sz) {
            o->u.sphere.pov_center = v3_scale(o->u.sphere.pov_center, sx);
            o->u.sphere.pov_radius *= fabs(sx);
            return;
        }
    }
    /* a new transform each time: copies of a declared sphere share the old */
    Transform *t = tok_scene_alloc(p, sizeof *t);
    if (o->u.sphere.pov_trans)
        *t = *o->u.sphere.pov_trans;
    else
        transform_identity(t);
    transform_compose(t, step);
    o->u.sphere.pov_trans = t;
}

void gram_primitive_extent(SceneObject *o)
{
    const Transform *t = &o->transform;
    switch (o->kind) {
    case OBJ_SPHERE: { /* Sphere::Compute_BBox */
        double r = o->u.sphere.pov_radius;
        make_bbox(o, v3_sub(o->u.sphere.pov_center, v3(r, r, r)), v3(2.0 * r, 2.0 * r, 2.0 * r));
        if (o->u.sphere.pov_trans)
            gram_extent_transform(o, o->u.sphere.pov_trans);
        return;
    }
    case OBJ_BOX: { /* Box::Compute_BBox, its corners put in order as Parse_Box puts them */
        Vec3 lo = v3_min(o->u.box.corner1, o->u.box.corner2), hi = v3_max(o->u.box.corner1, o->u.box.corner2);
        if (axis_aligned(t)) {
            Vec3 a = transform_point(t, lo), b = transform_point(t, hi);
            make_bbox(o, v3_min(a, b), v3_sub(v3_max(a, b), v3_min(a, b)));
        } else {
            box_through(o, lo, hi, t);
        }
        return;
    }
    case OBJ_CONE: { /* Cone::Compute_BBox: its canonical box through its frame, then its transforms */
        Transform frame;
        double dist;
        /* a cylinder's (and a cone's of ends within EPSILON) frame runs
         * from its second point to its first, as POV-Ray's
         * Compute_Cylinder_Data makes it: measured, its box turns with it
         * (the engine's frame runs the other way, which its intersections
         * do not tell apart) */
        if (fabs(o->u.cone.apex_radius - o->u.cone.base_radius) < 1e-10)
            (void)transform_cone_frame(&frame, o->u.cone.apex, o->u.cone.apex_radius, o->u.cone.base,
                                       o->u.cone.base_radius, &dist);
        else
            (void)transform_cone_frame(&frame, o->u.cone.base, o->u.cone.base_radius, o->u.cone.apex,
                                       o->u.cone.apex_radius, &dist);
        transform_compose(&frame, t);
        box_through(o, v3(-1.0, -1.0, dist), v3(1.0, 1.0, 1.0), &frame);
        return;
    }
    case OBJ_TORUS: { /* Torus::Compute_BBox */
        double r = o->u.torus.minor, r2 = o->u.torus.major + r;
        box_through(o, v3(-r2, -r, -r2), v3(r2, r, r2), t);
        return;
    }
    case OBJ_DISC: { /* Disc::Compute_BBox: the unit disc's frame, as Compute_Disc makes it */
        Transform frame;
        transform_coordinate_frame(&frame, o->u.disc.center, o->u.disc.normal, 1.0, 1.0);
        transform_compose(&frame, t);
        double r = o->u.disc.radius;
        box_through(o, v3(-r, -r, -SMALL_TOLERANCE), v3(r, r, SMALL_TOLERANCE), &frame);
        return;
    }
    case OBJ_TRIANGLE: /* Triangle::Compute_BBox: its points, moved by every transform, and EPSILON */
        points_box(o, o->u.triangle.v, 3, t, 1e-10);
        return;
    case OBJ_MESH: { /* Mesh::Compute_BBox: its triangles' points' box, then its transform */
        if (o->u.mesh.nfaces == 0)
            return;
        if (!o->u.mesh.has_box) {
            Vec3 lo = v3(BOUND_HUGE, BOUND_HUGE, BOUND_HUGE), hi = v3(-BOUND_HUGE, -BOUND_HUGE, -BOUND_HUGE);
            for (int f = 0; f < o->u.mesh.nfaces; f++)
                for (int k = 0; k < 3; k++) {
                    Vec3 v = o->u.mesh.vertices[o->u.mesh.faces[f].v[k]];
                    lo = v3_min(lo, v);
                    hi = v3_max(hi, v);
                }
            o->u.mesh.box_lo = lo;
            o->u.mesh.box_hi = hi;
            o->u.mesh.has_box = 1;
        }
        const Vec3 lo = o->u.mesh.box_lo, hi = o->u.mesh.box_hi;
        gram_extent_from_min_max(o, (const double[3]){ lo.x, lo.y, lo.z }, (const double[3]){ hi.x, hi.y, hi.z });
        gram_extent_transform(o, t);
        return;
    }
    case OBJ_POLYGON: /* Polygon::Compute_BBox: its points, a flat side widened */
        points_box(o, o->u.polygon.points, o->u.polygon.npoints, t, 0.0);
        for (int i = 0; i < 3; i++)
            if (fabsf(o->extent_lengths[i]) < SMALL_TOLERANCE) {
                o->extent_lower[i] = (float)((double)o->extent_lower[i] - SMALL_TOLERANCE);
                o->extent_lengths[i] = (float)((double)o->extent_lengths[i] + 2.0 * SMALL_TOLERANCE);
            }
        return;
    case OBJ_SUPERELLIPSOID: /* Superellipsoid::Compute_BBox: a little more than the unit cube */
        box_through(o, v3(-1.0001, -1.0001, -1.0001), v3(1.0001, 1.0001, 1.0001), t);
        return;
    case OBJ_PLANE: /* Plane::Compute_BBox: everything */
        make_bbox(o, v3(-BOUND_HUGE / 2, -BOUND_HUGE / 2, -BOUND_HUGE / 2), v3(BOUND_HUGE, BOUND_HUGE, BOUND_HUGE));
        return;
    default:
        return;
    }
}
