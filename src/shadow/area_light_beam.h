/* hst's test for area lights: the beam from a shading point to the whole
 * light, and what it proves.
 *
 * Every sample a point can ask about (jitter and rounding included) lies in
 * one parallelogram around the light's centre, spanned by its axes (turned
 * to face the point with orient); the shadow rays of all of them lie in the
 * pyramid from the point to that parallelogram: the beam. So
 *   - a polygon wholly outside one of the pyramid's five planes (by a
 *     margin) meets no sample's ray: the polygons left, gathered once from
 *     the hierarchy, are the only ones any sample's ray needs testing
 *     against (the beam's candidates);
 *   - a candidate whose plane lies strictly between the point and the
 *     light, where the beam crosses that plane in a quadrilateral (the
 *     corners' rays) that no border of the polygon crosses: every sample's
 *     ray crosses it in its interior (opaque: the point is in the light's
 *     umbra), or none does (the beam passes through a hole, or beside it:
 *     it is no candidate after all);
 *   - no candidate left, and no infinite plane between the point and the
 *     light: every sample is lit.
 * The proofs are conservative: where one does not hold, the samples are
 * decided one by one by the shadow ray, against the candidates only; the
 * answer is the shadow ray's either way. Starting point: the paper's
 * buckets (a shadow ray tests the polygons of the cells it crosses), made
 * one bucket for the whole light; the penumbra wedges and soft shadow
 * volumes of Assarsson and Akenine-Moeller (2003) and Laine et al. (2005)
 * classify points as lit, umbra and penumbra the same way, by the light's
 * extent against the occluders. */
#ifndef HST_AREA_LIGHT_BEAM_H
#define HST_AREA_LIGHT_BEAM_H

#include "bvh.h"
#include "world.h"

typedef struct {
    Vec3 apex;           /* the shading point */
    Vec3 corner[4];      /* the parallelogram, in order around it */
    Vec3 dir[4];         /* the corners' rays' directions (not unit) */
    int parallel;        /* a parallel light's: its rays run along the lines from point_at */
    Vec3 normal[5];      /* the pyramid's planes: x is inside when dot(normal[k], x - apex) <= limit[k] */
    double limit[5];
    double margin;       /* the distance kept from every plane and border */
} AreaBeam;

/* The beam from p to light l, whose samples span axis1, axis2 (as
 * area_light_axes gives them). tol: a distance below which geometry is
 * taken as touching (the grid's tolerance). Returns 0, or -1 where there
 * is no beam to build (p, or a parallel light's point_at, in the light's
 * plane; a light too thin): then every sample is to be decided on its own.
 * A parallel light's beam bounds its rays but not where each ends, so it
 * proves points lit, never in umbra. */
int area_beam_init(AreaBeam *b, const Light *l, Vec3 p, Vec3 axis1, Vec3 axis2, double tol);


/* The polygons the samples' rays may meet: every one the exact test could
 * find along any of them, and perhaps some more; `exclude` (the point's
 * own polygon, or -1) and no_shadow ones left out. Writes at most cap of
 * them to out and returns how many, or -1 when there are more than cap.
 * *nodes counts the hierarchy's boxes tested. */
int area_beam_gather(const AreaBeam *b, const World *w, const Bvh *bvh, int exclude, uint32_t *out, int cap,
                     uint64_t *nodes);

/* No infinite plane (no_shadow ones and `exclude`, the point's own, or
 * -1, left out) can come between the point and any sample, and the world
 * has no shapes (which only each sample's own ray tests). */
int area_beam_planes_clear(const AreaBeam *b, const World *w, int exclude);

/* How polygon pi (a candidate) meets the beam where it crosses the
 * polygon's plane, strictly between the point and the light: wholly in
 * its interior (every sample's ray crosses it there), wholly beside it
 * (in a hole, or outside: no sample's ray meets it), or neither (or not
 * known: the plane not strictly between them). */
enum { BEAM_PARTIAL, BEAM_COVERED, BEAM_MISSES };
int area_beam_classify(const AreaBeam *b, const World *w, uint32_t pi);

#endif
