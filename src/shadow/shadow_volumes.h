/* Shadow volumes per light (Crow, generalised as Bergeron did): every edge of
 * every shadow-casting polygon is extruded away from the light into a
 * semi-infinite shadow polygon. Vertices are welded by exact position; the
 * shadow polygons of one welded edge are merged into one with an integer
 * weight, so edges inside a mesh whose two faces continue each other as seen
 * from the light cancel (weight 0, dropped) and only silhouettes remain. This
 * needs no consistent winding, and handles open meshes, single cards, holes
 * and edges shared by three or more faces alike.
 *
 * The depth count of a point X is the number of polygons that the segment
 * X->light crosses (the polygon X lies on excluded), kept in two channels:
 * opaque polygons, and transparent ones (filter/transmit), whose light must
 * still be filtered by the conventional path. Crossing a shadow polygon from
 * its negative to its positive side adds its weight.
 *
 * Shadow polygons are registered, per light, in the grid cells they overlap
 * (clipped to the grid box, which holds the camera). Infinite planes have no
 * silhouette; every method tests them directly. */
#ifndef HST_SHADOW_VOLUMES_H
#define HST_SHADOW_VOLUMES_H

#include <stdint.h>

#include "cell_lists.h"
#include "grid.h"
#include "world.h"

typedef struct {
    Vec3 normal;          /* unit normal of the plane through the edge and the light */
    double d;             /* plane: dot(normal, x) == d */
    /* The two borders through the edge's ends run along the light's rays;
     * neighbouring silhouette edges share them. A crossing's side of the
     * border through end v is the sign of orient(p1, p2, v, v + toward[v]),
     * computed from v and toward[v] alone, so two shadow polygons sharing v
     * get the same number and a crossing there is counted exactly once
     * (border_orientation below). */
    Vec3 end[2];          /* the edge's ends a, b */
    Vec3 toward[2];       /* unit, from each end toward the light (point: toward its location; parallel: its direction) */
    Vec3 edge_normal;     /* in-plane unit normal of the edge, pointing away from the light */
    double edge_d;        /* dot(edge_normal, x) - edge_d >= 0 beyond the edge */
    /* the small fields together, at the end: 168 bytes, no padding between */
    int16_t weight_opaque, weight_transparent; /* count change, negative -> positive side */
    int8_t inside_sign[2]; /* orient sign, for a crossing toward +normal, of points inside the wedge */
} ShadowPolygon;

/* A polygon's relation to one light. */
typedef struct {
    int8_t channel;       /* 0 casts no shadow (no_shadow, or edge-on to the light), 1 opaque, 2 transparent */
    int8_t light_side;    /* +1: the light is on the side of polygon.normal, -1 the other */
    /* An edge of the polygon cancelled against a face not in its plane:
     * for points in this polygon's plane, crossing that edge changes the
     * neighbour's count but not this polygon's, which the merged (zero)
     * weight cannot say. Counts along segments in its plane across its
     * border are undecidable. */
    int8_t bent;
} OccluderSide;

typedef struct {
    /* 0: no volumes for this light, every test fires the shadow ray (a
     * shadowless light, or a parallel light whose plane cuts the grid box:
     * polygons beyond that plane cast nothing, which extruded shadow
     * polygons cannot say). */
    int usable;
    int plane_cuts_scene; /* why a parallel light has none */
    int not_wanted;       /* the build was asked to leave it out (volume_plan.h) */
    int dropped;          /* built, then dropped (shadow_volumes_drop_light) */
    int first, count;     /* shadow polygons of this light: polygons[first .. first+count) */
    CellLists cells;      /* per grid cell: global shadow polygon indices */
    size_t nitems;        /* registrations (cells.nitems) */
    OccluderSide *occluder; /* per world polygon */
    /* The eye's depth count, computed once. */
    int eye_known;
    int eye_opaque, eye_transparent;
    int silhouette_edges;   /* edges with nonzero weight */
    int cancelled_edges;    /* welded edges whose contributions cancelled */
} LightVolumes;

/* The planes of the shadow polygons alone, packed: most tests end there. */
typedef struct {
    Vec3 normal;
    double d;
} ShadowPlane;

/* The same in single precision, for --plane-precision float. */
typedef struct {
    float nx, ny, nz, d;
} ShadowPlaneF;

/* How the packed planes are tested (--plane-precision): the rejection
 * "both ends clearly on one side" is most of the work. */
typedef enum {
    PLANES_DOUBLE,      /* in double, with the margin */
    PLANES_FLOAT,       /* in float, with the margin widened by float's rounding: the same decisions */
    PLANES_FLOAT_NAIVE  /* in float with the double margin: what that costs in wrong decisions */
} PlanePrecision;

typedef struct ShadowVolumes {
    int nlights;
    LightVolumes *light;
    int npolygons;
    ShadowPolygon *polygons;
    ShadowPlane *planes;  /* planes[i] is polygons[i]'s plane */
    PlanePrecision precision;
    ShadowPlaneF *planes_f; /* with float precisions */
    float float_margin;     /* their rejection margin */
    int nwelded_vertices;
    double tolerance;     /* distances below this are undecidable: fall back to the ray */
    Vec3 box_min, box_max; /* the grid box: points outside have no valid count */
} ShadowVolumes;

/* Builds the volumes of every light that casts shadows (shadowless lights
 * get none) and that `want` asks for (NULL: all; else want[i] != 0 for
 * light i), the lights on up to `threads` threads (the volumes are the
 * same for any number). `eye`: where every camera ray starts, or NULL when
 * they start at different points (orthographic camera): no eye count
 * then. Returns 0, or -1 when out of memory. */
int shadow_volumes_build(ShadowVolumes *sv, const World *w, const Grid *g, const Vec3 *eye, int threads,
                         const int8_t *want);
/* The same volumes the plain way: the side of every edge use found from
 * the plane through the edge and the light, where the build above finds a
 * triangle's from the light's side of its plane (the reference that tests
 * compare it with, volume for volume). */
int shadow_volumes_build_plain(ShadowVolumes *sv, const World *w, const Grid *g, const Vec3 *eye, int threads,
                               const int8_t *want);
void shadow_volumes_free(ShadowVolumes *sv);

/* Frees light li's registrations and turns its volumes off: from then on
 * every method fires shadow rays toward it. Its shadow polygons stay in
 * the shared array (other lights' indices point past them). */
void shadow_volumes_drop_light(ShadowVolumes *sv, int li);
int shadow_volumes_usable_lights(const ShadowVolumes *sv);

/* What shadow_volumes_build would cost on one thread, estimated before
 * building: the same code (welding, edges' uses, silhouettes, wedges
 * registered in the grid) timed on a run of `sample` consecutive polygons
 * and scaled by the polygons' points, whole over sample; filling a light's
 * cells timed at the grid's full size. Where g has no polygons registered
 * yet, their registration (grid_register, which volumes need) is shared
 * cost too: timed on the sample, scaled by the polygons, with one fill. */
typedef struct {
    int sample_polygons;
    double scale;                /* points in the scene over points in the sample */
    double shared_seconds;       /* welding and edges' uses, register_seconds, once for all lights */
    double register_seconds;     /* the polygons' registration in the grid (0: registered already) */
    double *light_seconds;       /* per light (0: not estimated), filling included */
    double *light_registrations; /* per light, estimated */
    double fill_seconds;         /* filling one light's cells (in light_seconds) */
} VolumesEstimate;

int shadow_volumes_estimate(const World *w, const Grid *g, const Vec3 *eye, const int8_t *want, int sample,
                            VolumesEstimate *est);
void shadow_volumes_estimate_free(VolumesEstimate *est);

/* Chooses how the planes are tested (PLANES_DOUBLE after a build). Returns
 * 0, or -1 when out of memory. */
int shadow_volumes_set_precision(ShadowVolumes *sv, PlanePrecision p);

/* Outcome of one segment/shadow polygon test. */
typedef enum { CROSS_NONE = 0, CROSS_YES = 1, CROSS_UNSURE = 2 } CrossResult;

/* The orientation of p1, p2 against the line through v along r:
 * det(p1 - v, p2 - v, r). Always computed this way, from the same v and r,
 * so shadow polygons sharing a border get bit-identical values. */
static inline double border_orientation(Vec3 p1, Vec3 p2, Vec3 v, Vec3 r)
{
    return v3_dot(v3_cross(v3_sub(p1, v), v3_sub(p2, v)), r);
}

/* The part of p1->p2 within tol of sp's plane (an end point lies there):
 * CROSS_NONE when it is clearly outside one border of the wedge (which is
 * convex), else CROSS_UNSURE. The crossing itself can be anywhere in that
 * part: a segment almost parallel to the plane stays within tol of it for
 * its whole length. */
static inline CrossResult shadow_polygon_near_plane(const ShadowPolygon *sp, Vec3 p1, Vec3 p2, double s1, double s2,
                                                    double tol)
{
    double t_lo = 0.0, t_hi = 1.0;
    if (s1 != s2) {
        double ta = (tol - s1) / (s2 - s1), tb = (-tol - s1) / (s2 - s1);
        t_lo = fmax(t_lo, fmin(ta, tb));
        t_hi = fmin(t_hi, fmax(ta, tb));
    }
    Vec3 d = v3_sub(p2, p1), q[2] = { v3_add(p1, v3_scale(d, t_lo)), v3_add(p1, v3_scale(d, t_hi)) };
    for (int i = 0; i < 3; i++) {
        int outside = 0;
        for (int k = 0; k < 2; k++) {
            double e = i < 2 ? sp->inside_sign[i] * v3_dot(sp->normal, v3_cross(sp->toward[i], v3_sub(q[k], sp->end[i])))
                             : v3_dot(sp->edge_normal, q[k]) - sp->edge_d;
            outside += e < -tol;
        }
        if (outside == 2)
            return CROSS_NONE;
    }
    return CROSS_UNSURE;
}

/* Segment p1->p2 against shadow polygon sp, given the signed distances s1,
 * s2 of p1 and p2 from its plane (see shadow_polygon_cross below).
 *
 * Three borders bound a wedge: the two light rays through the edge's ends
 * and the edge itself. Where the segment meets the plane, its side of a
 * light ray is the sign of border_orientation (a crossing toward -normal
 * flips it); a value of exactly 0 counts as positive in every wedge, so a
 * crossing through the ray shared by two silhouette edges belongs to
 * exactly one of them, however it rounds. The edge is shared with the
 * occluder itself, which the tracer tests separately: there a margin
 * decides, and too close to call is CROSS_UNSURE. */
static inline CrossResult shadow_polygon_cross_sides(const ShadowPolygon *sp, Vec3 p1, Vec3 p2, double s1, double s2,
                                                     double tol, int *sign)
{
    if ((s1 > tol && s2 > tol) || (s1 < -tol && s2 < -tol))
        return CROSS_NONE;
    if (fabs(s1) <= tol || fabs(s2) <= tol)
        return shadow_polygon_near_plane(sp, p1, p2, s1, s2, tol);
    int toward_positive = s1 < 0.0 ? 1 : -1;
    for (int i = 0; i < 2; i++) {
        int side = border_orientation(p1, p2, sp->end[i], sp->toward[i]) >= 0.0 ? 1 : -1;
        if (side * toward_positive != sp->inside_sign[i])
            return CROSS_NONE;
    }
    Vec3 x = v3_add(p1, v3_scale(v3_sub(p2, p1), s1 / (s1 - s2)));
    double e = v3_dot(sp->edge_normal, x) - sp->edge_d;
    if (e < -tol)
        return CROSS_NONE;
    if (e <= tol)
        return CROSS_UNSURE;
    *sign = toward_positive;
    return CROSS_YES;
}

/* Does the segment p1->p2 cross shadow polygon sp? On CROSS_YES, *sign is
 * +1 when it goes from the negative to the positive side. CROSS_UNSURE when
 * an end point or the crossing lies within `tol` of the shadow polygon's
 * plane or border: rounding could decide either way there, so the caller
 * must fall back to the exact shadow ray. */
static inline CrossResult shadow_polygon_cross(const ShadowPolygon *sp, Vec3 p1, Vec3 p2, double tol, int *sign)
{
    return shadow_polygon_cross_sides(sp, p1, p2, v3_dot(sp->normal, p1) - sp->d, v3_dot(sp->normal, p2) - sp->d,
                                      tol, sign);
}

/* Adds the signed crossings of the segment p1 -> p2 with the shadow
 * polygons bucket[0..n) to the two counts. Returns 0 when one of them is
 * too close to call (the counts are then meaningless). */
int shadow_bucket_crossings(const ShadowVolumes *sv, const uint32_t *bucket, int n, Vec3 p1, Vec3 p2, int *opaque,
                            int *transparent);

#endif
