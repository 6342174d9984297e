/* --shadows embree (shadow_embree.h): the world's polygons in one Embree 3
 * scene, rtcOccluded1 per shadow ray, and an occlusion filter that applies
 * the shadow ray's rules to every hit Embree reports.
 *
 * What goes in the scene:
 * - triangles as Embree triangles, their float corners rounded from the
 *   world's double points once (one shared vertex buffer, so two triangles
 *   sharing a corner share its float too: with RTC_SCENE_FLAG_ROBUST a ray
 *   through a shared edge does not leak between them);
 * - convex polygons of one outline (box faces, cards, most POV-Ray
 *   polygons) as a fan of triangles over the same vertices: the fan covers
 *   exactly the polygon, and a ray through an inner diagonal hits one or
 *   both of its triangles, the same polygon (each polygon is taken once);
 * - every other polygon (holes, concave or self-overlapping outlines) as
 *   user geometry whose test is hstrace's own watertight double test
 *   (intersect_polygon_in). Triangulating them needs ear clipping with
 *   bridges to the holes, whose new edges would be float edges the
 *   even-odd rule does not have; they are few (--stats counts them), so an
 *   exact test costs little and keeps their decisions the shadow ray's;
 * - no_shadow polygons not at all (the shadow ray skips them; leaving them
 *   out is the same rule at no cost per ray);
 * - a world with instances (instance.h): each prototype's triangles in a
 *   scene of their own, in its space, and each instance as an Embree
 *   instance of it (its transform rounded to float); the filter names the
 *   hit by the instance's polygon id and takes its distance on the polygon's
 *   plane in the instance's space, on the ray instance_ray carries there,
 *   as the shadow ray's walk does, and leaves out what the instance's
 *   materials make no_shadow.
 *
 * The filter (and the user geometry's test) rejects a hit on the shading
 * point's own polygon, on a polygon edge-on to the light, or at a distance
 * outside (trace_min_distance, the light) on the polygon's plane computed
 * in double as the shadow ray computes it (so a neighbour the float origin
 * lands just behind is not taken for a blocker); accepts an opaque polygon
 * (Embree stops: blocked); records a see-through one once and rejects it,
 * so that the ray goes on to find them all. They are folded afterwards by
 * shadow_fold_filtered, in distance order, once per 1e-3 group, exactly as
 * the shadow ray folds them. */
#include "shadow_embree.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "config.h"
#include "instance.h"
#include "intersect.h"
#include "light.h"

#ifdef HAVE_EMBREE
#include <embree3/rtcore.h>

/* Measured at 640x480, 1 thread, 5 interleaved runs each (glasses, and
 * make-mesh 10^5 with 3 lights): LOW, MEDIUM and HIGH gave the same time
 * per shadow decision within the noise (medians 164-165 and 183-192 ns),
 * and their builds cost at most 0.04 s there (0.3-0.8 s at 10^6
 * triangles, on a loaded machine). HIGH, Embree's best trees, stays. */
#define EMBREE_QUALITY RTC_BUILD_QUALITY_HIGH
#define EMBREE_QUALITY_NAME "high"

struct EmbreeScene {
    RTCDevice device;
    RTCScene scene;
    const World *world;
    uint32_t *triangle_polygon; /* Embree triangle -> world polygon */
    uint32_t *user_polygon;     /* user primitive -> world polygon */
    RTCScene *proto;            /* per prototype: its triangles' scene, in its space */
    int nproto;
    int *instance_of;           /* the top scene's geometry ID -> World.instances (-1: none) */
    unsigned ninstance_of;
    EmbreeSceneInfo info;
    char error[256];            /* the device's first error */
};

int shadow_embree_built(void) { return 1; }

const char *shadow_embree_version(void) { return RTC_VERSION_STRING; }

static void on_error(void *user, enum RTCError code, const char *message)
{
    EmbreeScene *es = user;
    if (!es->error[0])
        snprintf(es->error, sizeof es->error, "Embree error %d: %s", (int)code, message ? message : "");
}

/* ---- which polygons become fans ----------------------------------------- */

static inline double comp(Vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }

/* The outline of p without repeated consecutive points (and without the
 * closing repeat), as indices into w->points; returns their count. */
static int outline_points(const World *w, const Polygon *p, int *idx, int cap)
{
    int n;
    const Vec3 *pts = polygon_outline(w, p, 0, &n);
    int first = (int)(pts - w->points), m = 0;
    for (int i = 0; i < n && m < cap; i++) {
        Vec3 a = pts[i];
        if (m > 0) {
            Vec3 b = w->points[idx[m - 1]];
            if (a.x == b.x && a.y == b.y && a.z == b.z)
                continue;
        }
        idx[m++] = first + i;
    }
    while (m > 1) {
        Vec3 a = w->points[idx[m - 1]], b = w->points[idx[0]];
        if (a.x != b.x || a.y != b.y || a.z != b.z)
            break;
        m--;
    }
    return m;
}

/* Convex, projected onto p's two kept axes: every turn the same way (or
 * straight), and the turns add up to one revolution (a pentagram turns the
 * same way at every corner, twice round). */
static int outline_convex(const World *w, const Polygon *p, const int *idx, int n)
{
    if (n < 3)
        return 0;
    int sign = 0;
    double turned = 0.0;
    for (int i = 0; i < n; i++) {
        Vec3 a = w->points[idx[i]], b = w->points[idx[(i + 1) % n]], c = w->points[idx[(i + 2) % n]];
        double ux = comp(b, p->axis_u) - comp(a, p->axis_u), uy = comp(b, p->axis_v) - comp(a, p->axis_v);
        double vx = comp(c, p->axis_u) - comp(b, p->axis_u), vy = comp(c, p->axis_v) - comp(b, p->axis_v);
        double cross = ux * vy - uy * vx;
        int s = (cross > 0.0) - (cross < 0.0);
        if (s != 0) {
            if (sign != 0 && s != sign)
                return 0;
            sign = s;
        } else if (ux * vx + uy * vy < 0.0) {
            return 0; /* the outline doubles back on itself */
        }
        turned += atan2(cross, ux * vx + uy * vy);
    }
    return sign != 0 && fabs(fabs(turned) - 2.0 * 3.14159265358979323846) < 1e-6;
}

/* ---- the rules, for each hit Embree reports ------------------------------ */

/* One shadow ray's state, handed to the callbacks: Embree passes the
 * context back to them, and it is this struct's first member. */
typedef struct {
    struct RTCIntersectContext rtc;
    ShadowContext *ctx;
    const ShadowQuery *q;
    const EmbreeScene *es;
    RayFrame frame;       /* the double ray, for distances and the exact test */
    int framed_instance;  /* the instance `local` is the ray of, or -1 */
    RayFrame local;       /* the ray in that instance's space (instance_ray) */
    double tmin;
    int exclude;          /* the shading point's own polygon, or -1 */
    uint32_t mark;        /* stamp of this ray: see-through polygons taken once */
    int blocker;          /* the opaque polygon accepted, or -1 */
} EmbreeRay;

/* 1: pi blocks (opaque, within the segment); 0: the ray goes on. t: the
 * hit's double distance on pi's plane. */
static int meet(EmbreeRay *er, uint32_t pi, int instance, double t)
{
    if ((int)pi == er->exclude || !(t > er->tmin && t < er->q->distance))
        return 0;
    ShadowContext *ctx = er->ctx;
    const World *w = er->es->world;
    Polygon scratch;
    const Polygon *p = world_polygon_plane(w, (int)pi, instance, &scratch);
    if (light_side_of(p, er->q->source, grid_tolerance(ctx->tracer->grid)) == 0)
        return 0;
    const Material *m = &w->materials[world_polygon_material_hinted(w, (int)pi, instance)];
    if (m->no_shadow)
        return 0; /* an instance's: its material's (world polygons so made are not in the scene) */
    if (m->opaque) {
        er->blocker = (int)pi;
        return 1;
    }
    if ((int)pi >= w->npolygons) {
        /* an instance's polygon, taken once: the stamps are the world's */
        for (int i = 0; i < ctx->nfiltered; i++)
            if (ctx->filtered[i].polygon == pi)
                return 0;
        ctx->filtered[ctx->nfiltered].t = t;
        ctx->filtered[ctx->nfiltered].polygon = pi;
        ctx->nfiltered++;
    } else if (bucket_admit(ctx->tracer, er->mark, pi)) {
        ctx->filtered[ctx->nfiltered].t = t;
        ctx->filtered[ctx->nfiltered].polygon = pi;
        ctx->nfiltered++;
    }
    return 0;
}

/* The occlusion filter of the triangles: valid[i] = 0 rejects hit i. */
static void triangle_filter(const struct RTCFilterFunctionNArguments *args)
{
    EmbreeRay *er = (EmbreeRay *)args->context;
    const uint32_t *polygon_of = args->geometryUserPtr;
    const unsigned *prim = (const unsigned *)args->hit + 5 * args->N; /* RTCHitN's primID column */
    for (unsigned i = 0; i < args->N; i++) {
        if (args->valid[i] == 0)
            continue;
        uint32_t pi = polygon_of[prim[i]];
        double t = intersect_plane_distance(&er->es->world->polygons[pi], &er->frame);
        if (!meet(er, pi, -1, t))
            args->valid[i] = 0;
    }
}

/* The occlusion filter of a prototype's triangles, hit through an
 * instance (its geometry ID in the hit's instance column). */
static void instance_filter(const struct RTCFilterFunctionNArguments *args)
{
    EmbreeRay *er = (EmbreeRay *)args->context;
    const EmbreeScene *es = er->es;
    const World *w = es->world;
    const unsigned *prim = (const unsigned *)args->hit + 5 * args->N; /* RTCHitN's primID column */
    const unsigned *inst = (const unsigned *)args->hit + 7 * args->N; /* ... instID, level 0 */
    for (unsigned i = 0; i < args->N; i++) {
        if (args->valid[i] == 0)
            continue;
        int k = inst[i] < es->ninstance_of ? es->instance_of[inst[i]] : -1;
        if (k < 0) {
            args->valid[i] = 0;
            continue;
        }
        const Instance *in = &w->instances[k];
        if (er->framed_instance != k) {
            Vec3 lorg, ldir;
            instance_ray(in, er->frame.org, er->frame.dir, &lorg, &ldir);
            er->local = ray_frame(lorg, ldir);
            er->framed_instance = k;
        }
        const Prototype *pr = &w->prototypes[in->prototype];
        uint32_t pi = (uint32_t)(in->first_id + (int)prim[i]);
        double t = intersect_plane_distance(&w->polygons[pr->first_polygon + (int)prim[i]], &er->local);
        if (!meet(er, pi, k, t))
            args->valid[i] = 0;
    }
}

static void user_bounds(const struct RTCBoundsFunctionArguments *args)
{
    const EmbreeScene *es = args->geometryUserPtr;
    const Polygon *p = &es->world->polygons[es->user_polygon[args->primID]];
    struct RTCBounds *b = args->bounds_o;
    b->lower_x = nextafterf((float)p->bbox_min.x, -INFINITY);
    b->lower_y = nextafterf((float)p->bbox_min.y, -INFINITY);
    b->lower_z = nextafterf((float)p->bbox_min.z, -INFINITY);
    b->upper_x = nextafterf((float)p->bbox_max.x, INFINITY);
    b->upper_y = nextafterf((float)p->bbox_max.y, INFINITY);
    b->upper_z = nextafterf((float)p->bbox_max.z, INFINITY);
}

/* The user polygons' occlusion test: the exact double test, then the
 * rules; a block is reported by setting tfar to -inf. */
static void user_occluded(const struct RTCOccludedFunctionNArguments *args)
{
    EmbreeRay *er = (EmbreeRay *)args->context;
    const EmbreeScene *es = er->es;
    uint32_t pi = es->user_polygon[args->primID];
    er->ctx->stats.shadow_polygon_tests++;
    double t = intersect_polygon_in(es->world, &es->world->polygons[pi], &er->frame, er->q->distance);
    if (!meet(er, pi, -1, t))
        return;
    float *tfar = (float *)args->ray + 8 * args->N; /* RTCRayN's tfar column */
    for (unsigned i = 0; i < args->N; i++)
        if (args->valid[i])
            tfar[i] = -INFINITY;
}

/* Never called (the method asks occlusion only), but user geometry must
 * answer both kinds of query: no hit. */
static void user_intersect(const struct RTCIntersectFunctionNArguments *args) { (void)args; }

/* ---- building ------------------------------------------------------------ */

static int fail(EmbreeScene *es, char *err, int errlen, const char *what)
{
    snprintf(err, (size_t)errlen, "Embree: %s%s%s", what, es && es->error[0] ? ": " : "", es ? es->error : "");
    shadow_embree_free(es);
    return 0;
}

/* Each prototype's triangles (a mesh's, every one a triangle) in a scene
 * of their own, and each instance of it in the top scene. 1, or 0 when
 * out of memory. */
static int add_instances(EmbreeScene *es)
{
    const World *w = es->world;
    es->proto = calloc((size_t)w->nprototypes, sizeof *es->proto);
    if (!es->proto)
        return 0;
    es->nproto = w->nprototypes;
    for (int k = 0; k < w->nprototypes; k++) {
        const Prototype *pr = &w->prototypes[k];
        RTCScene sc = rtcNewScene(es->device);
        es->proto[k] = sc;
        if (!sc)
            return 0;
        rtcSetSceneFlags(sc, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(sc, EMBREE_QUALITY);
        RTCGeometry g = rtcNewGeometry(es->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        size_t n = (size_t)(pr->npolygons > 0 ? pr->npolygons : 1);
        float *v = g ? rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 4 * sizeof(float), 3 * n)
                     : NULL;
        unsigned *tri = g ? rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n)
                          : NULL;
        if (!v || !tri) {
            if (g)
                rtcReleaseGeometry(g);
            return 0;
        }
        for (int q = 0; q < pr->npolygons; q++) {
            const Polygon *p = &w->polygons[pr->first_polygon + q];
            for (int j = 0; j < 3; j++) { /* meshes make triangles only */
                Vec3 x = w->points[p->first_point + j];
                v[4 * (3 * q + j)] = (float)x.x;
                v[4 * (3 * q + j) + 1] = (float)x.y;
                v[4 * (3 * q + j) + 2] = (float)x.z;
                v[4 * (3 * q + j) + 3] = 0.0f;
                tri[3 * q + j] = (unsigned)(3 * q + j);
            }
        }
        rtcSetGeometryOccludedFilterFunction(g, instance_filter);
        rtcCommitGeometry(g);
        rtcAttachGeometry(sc, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(sc);
    }
    for (int i = 0; i < w->ninstances; i++) {
        const Instance *in = &w->instances[i];
        RTCGeometry g = rtcNewGeometry(es->device, RTC_GEOMETRY_TYPE_INSTANCE);
        if (!g)
            return 0;
        rtcSetGeometryInstancedScene(g, es->proto[in->prototype]);
        /* object to world, row vectors (p M): Embree's column-major 3x4 is
         * the same numbers, column j being M's row j */
        float xfm[12];
        for (int r = 0; r < 4; r++)
            for (int c = 0; c < 3; c++)
                xfm[3 * r + c] = (float)in->to_world.m[r][c];
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
        rtcCommitGeometry(g);
        unsigned id = rtcAttachGeometry(es->scene, g);
        rtcReleaseGeometry(g);
        if (id >= es->ninstance_of) {
            unsigned cap = id + 1 > 2 * es->ninstance_of ? id + 1 : 2 * es->ninstance_of;
            int *map = realloc(es->instance_of, sizeof *map * cap);
            if (!map)
                return 0;
            for (unsigned j = es->ninstance_of; j < cap; j++)
                map[j] = -1;
            es->instance_of = map;
            es->ninstance_of = cap;
        }
        es->instance_of[id] = i;
    }
    return 1;
}

EmbreeScene *shadow_embree_build(const World *w, int threads, char *err, int errlen)
{
    double t0 = clock_wall();
    EmbreeScene *es = calloc(1, sizeof *es);
    if (!es) {
        fail(NULL, err, errlen, "out of memory");
        return NULL;
    }
    es->world = w;
    es->info.quality = EMBREE_QUALITY_NAME;
    char config[64] = "verbose=0";
    if (threads > 0)
        snprintf(config, sizeof config, "verbose=0,threads=%d", threads);
    es->device = rtcNewDevice(config);
    if (!es->device) {
        fail(es, err, errlen, "cannot create a device");
        return NULL;
    }
    rtcSetDeviceErrorFunction(es->device, on_error, es);

    /* Which polygons go how; the triangles a fan makes. */
    int ntri = 0, nuser = 0, most = 3;
    for (int i = 0; i < w->npolygons; i++)
        if (w->polygons[i].first_outline >= 0 && w->polygons[i].npoints > most)
            most = w->polygons[i].npoints;
    int *idx = malloc(sizeof(int) * (size_t)most);
    signed char *how = malloc((size_t)(w->npolygons > 0 ? w->npolygons : 1)); /* 0 out, 1 triangles, 2 user */
    int *fan = malloc(sizeof(int) * (size_t)(w->npolygons > 0 ? w->npolygons : 1));
    if (!idx || !how || !fan) {
        free(idx);
        free(how);
        free(fan);
        fail(es, err, errlen, "out of memory");
        return NULL;
    }
    for (int i = 0; i < w->npolygons; i++) {
        const Polygon *p = &w->polygons[i];
        fan[i] = 0;
        if (w->materials[p->material].no_shadow) {
            how[i] = 0;
            es->info.left_out++;
        } else if (p->first_outline < 0) {
            how[i] = 1;
            ntri++;
            es->info.triangles++;
        } else if (p->noutlines == 1 && (fan[i] = outline_points(w, p, idx, most)) >= 3 &&
                   outline_convex(w, p, idx, fan[i])) {
            how[i] = 1;
            ntri += fan[i] - 2;
            es->info.fanned_polygons++;
            es->info.fan_triangles += fan[i] - 2;
        } else {
            how[i] = 2;
            nuser++;
            es->info.user_polygons++;
        }
    }

    es->scene = rtcNewScene(es->device);
    rtcSetSceneFlags(es->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(es->scene, EMBREE_QUALITY);
    int ok = es->scene != NULL;
    if (ok && ntri > 0) {
        RTCGeometry g = rtcNewGeometry(es->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        float *v = g ? rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 4 * sizeof(float),
                                               (size_t)(w->npoints > 0 ? w->npoints : 1))
                     : NULL;
        unsigned *tri = g ? rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                    3 * sizeof(unsigned), (size_t)ntri)
                          : NULL;
        es->triangle_polygon = malloc(sizeof(uint32_t) * (size_t)ntri);
        ok = v && tri && es->triangle_polygon;
        if (ok) {
            for (int i = 0; i < w->npoints; i++) {
                v[4 * i] = (float)w->points[i].x;
                v[4 * i + 1] = (float)w->points[i].y;
                v[4 * i + 2] = (float)w->points[i].z;
                v[4 * i + 3] = 0.0f;
            }
            int k = 0;
            for (int i = 0; i < w->npolygons; i++) {
                const Polygon *p = &w->polygons[i];
                if (how[i] != 1)
                    continue;
                if (p->first_outline < 0) {
                    for (int j = 0; j < 3; j++)
                        tri[3 * k + j] = (unsigned)(p->first_point + j);
                    es->triangle_polygon[k++] = (uint32_t)i;
                    continue;
                }
                int n = outline_points(w, p, idx, most);
                for (int j = 1; j + 1 < n; j++) {
                    tri[3 * k] = (unsigned)idx[0];
                    tri[3 * k + 1] = (unsigned)idx[j];
                    tri[3 * k + 2] = (unsigned)idx[j + 1];
                    es->triangle_polygon[k++] = (uint32_t)i;
                }
            }
            rtcSetGeometryUserData(g, es->triangle_polygon);
            rtcSetGeometryOccludedFilterFunction(g, triangle_filter);
            rtcCommitGeometry(g);
            rtcAttachGeometry(es->scene, g);
        }
        if (g)
            rtcReleaseGeometry(g);
    }
    if (ok && nuser > 0) {
        RTCGeometry g = rtcNewGeometry(es->device, RTC_GEOMETRY_TYPE_USER);
        es->user_polygon = malloc(sizeof(uint32_t) * (size_t)nuser);
        ok = g && es->user_polygon;
        if (ok) {
            int k = 0;
            for (int i = 0; i < w->npolygons; i++)
                if (how[i] == 2)
                    es->user_polygon[k++] = (uint32_t)i;
            rtcSetGeometryUserPrimitiveCount(g, (unsigned)nuser);
            rtcSetGeometryUserData(g, es);
            rtcSetGeometryBoundsFunction(g, user_bounds, es);
            rtcSetGeometryIntersectFunction(g, user_intersect);
            rtcSetGeometryOccludedFunction(g, user_occluded);
            rtcCommitGeometry(g);
            rtcAttachGeometry(es->scene, g);
        }
        if (g)
            rtcReleaseGeometry(g);
    }
    free(idx);
    free(how);
    free(fan);
    if (ok && w->ninstances > 0)
        ok = add_instances(es);
    if (ok)
        rtcCommitScene(es->scene);
    if (!ok || es->error[0] || rtcGetDeviceError(es->device) != RTC_ERROR_NONE) {
        fail(es, err, errlen, ok ? "cannot build the scene" : "out of memory");
        return NULL;
    }
    es->info.seconds = clock_wall() - t0;
    return es;
}

void shadow_embree_free(EmbreeScene *es)
{
    if (!es)
        return;
    if (es->scene)
        rtcReleaseScene(es->scene);
    if (es->device)
        rtcReleaseDevice(es->device);
    for (int k = 0; k < es->nproto; k++)
        if (es->proto[k])
            rtcReleaseScene(es->proto[k]);
    free(es->proto);
    free(es->instance_of);
    free(es->triangle_polygon);
    free(es->user_polygon);
    free(es);
}

/* ---- the test ------------------------------------------------------------ */

void shadow_embree_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    light->r = light->g = light->b = 1.0;
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    ctx->stats.shadow_schemes[SCHEME_CONVENTIONAL]++;
    ctx->last_blocker = -1;
    if (shadow_planes_test(ctx, q, light)) {
        ctx->stats.shadow_blocked++;
        return;
    }
    ctx->stats.shadow_rays++;
    EmbreeRay er;
    rtcInitIntersectContext(&er.rtc);
    er.ctx = ctx;
    er.q = q;
    er.es = ctx->embree;
    er.frame = ray_frame(q->point, q->to_light);
    er.framed_instance = -1;
    er.tmin = trace_min_distance(q->point);
    er.exclude = q->surface->kind == HIT_POLYGON ? q->surface->index : -1;
    er.mark = trace_new_segment(ctx->tracer);
    er.blocker = -1;
    ctx->nfiltered = 0;
    /* From the float point to a little beyond the light: the filter holds
     * every hit to the double segment. */
    struct RTCRay ray;
    ray.org_x = (float)q->point.x;
    ray.org_y = (float)q->point.y;
    ray.org_z = (float)q->point.z;
    ray.tnear = 0.0f;
    ray.dir_x = (float)q->to_light.x;
    ray.dir_y = (float)q->to_light.y;
    ray.dir_z = (float)q->to_light.z;
    ray.time = 0.0f;
    ray.tfar = (float)(q->distance * (1.0 + 1e-5));
    ray.mask = ~0u;
    ray.id = 0;
    ray.flags = 0;
    rtcOccluded1(ctx->embree->scene, &er.rtc, &ray);
    if (ray.tfar == -INFINITY) {
        light->r = light->g = light->b = 0.0;
        ctx->last_blocker = er.blocker;
        ctx->stats.shadow_blocked++;
        return;
    }
    if (shadow_fold_filtered(ctx, q, light))
        ctx->stats.shadow_blocked++;
}

void *shadow_embree_rtc_scene(const EmbreeScene *es) { return es ? es->scene : NULL; }

#else /* !HAVE_EMBREE */

void *shadow_embree_rtc_scene(const EmbreeScene *es)
{
    (void)es;
    return NULL;
}

struct EmbreeScene {
    EmbreeSceneInfo info;
};

int shadow_embree_built(void) { return 0; }

const char *shadow_embree_version(void) { return NULL; }

EmbreeScene *shadow_embree_build(const World *w, int threads, char *err, int errlen)
{
    (void)w;
    (void)threads;
    snprintf(err, (size_t)errlen, "this hstrace was built without Embree (install the Debian package "
                                  "libembree-dev, then configure and make again)");
    return NULL;
}

void shadow_embree_free(EmbreeScene *es) { (void)es; }

/* Never reached: --shadows embree is refused when not built in. */
void shadow_embree_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    shadow_conventional_test(ctx, q, light);
}

#endif

const EmbreeSceneInfo *shadow_embree_info(const EmbreeScene *es) { return es ? &es->info : NULL; }

int shadow_embree_prepare(const ShadowMethod *self, const ShadowSetup *s, ShadowPrepared *out, char *err, int errlen)
{
    (void)self;
    if (!s->shadows_on)
        return 0;
    out->embree = shadow_embree_build(s->world, s->threads, err, errlen);
    return out->embree ? 0 : -1;
}
