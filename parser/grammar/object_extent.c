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
