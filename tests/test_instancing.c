/* Randomized instancing (instance.h): small scenes of lattice meshes, each
 * declared once and placed two to four times (lattice translations,
 * quarter turns, mirrors, and general turns with uneven scales), beside a
 * world triangle and a plane, some meshes see-through. For every scene the
 * world is built twice: with instances (WorldLimits.instance_meshes) and
 * flattened.
 *
 * On the instanced world, at camera hits aimed at the meshes' vertices,
 * edges and random points and at one bounce from each, every method that
 * takes instances (cache, light buffer with and without split cells, hst)
 * must decide every light exactly as the shadow ray does (the colour that
 * gets through, bit for bit: --verify-shadows' rule), ties included.
 *
 * Against the flattened world, which users compare with: camera rays aimed
 * at random points hit the same surfaces at the same distance up to
 * rounding (an image the same within rounding); a ray that hits in one
 * world and misses in the other can only graze a border, so such rays are
 * counted and must be rare. (Rays aimed at vertices and edges are left
 * out of that count: there the two worlds' rounding may well differ.)
 *
 * usage: test_instancing [--seed N] [--scenes N]  (defaults: a fixed seed, 1500 scenes) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixtures.h"
#include "grid.h"
#include "light_buffer.h"
#include "shadow.h"
#include "shadow_registry.h"
#include "tap.h"
#include "tracer.h"
#include "world.h"

#define PROBES 40
#define MAX_LIGHTS 3

static Vec3 lattice_point(TestRng *r, double half)
{
    int n = (int)(2 * half);
    return v3((double)((int)(rng_uniform(r) * (2 * n + 1)) - n) * 0.5,
              (double)((int)(rng_uniform(r) * (2 * n + 1)) - n) * 0.5,
              (double)((int)(rng_uniform(r) * (2 * n + 1)) - n) * 0.5);
}

/* A mesh of `nf` faces on lattice points: fans and strips sharing edges. */
static SceneObject *lattice_mesh(Scene *s, TestRng *r)
{
    int nv = 6 + (int)(rng_uniform(r) * 6), nf = 8 + (int)(rng_uniform(r) * 8);
    SceneObject *o = arena_alloc(s->arena, sizeof *o);
    memset(o, 0, sizeof *o);
    o->kind = OBJ_MESH;
    transform_identity(&o->transform);
    o->u.mesh.nvertices = nv;
    o->u.mesh.vertices = arena_alloc(s->arena, sizeof(Vec3) * (size_t)nv);
    for (int i = 0; i < nv; i++)
        o->u.mesh.vertices[i] = lattice_point(r, 1);
    o->u.mesh.nfaces = nf;
    o->u.mesh.faces = arena_alloc(s->arena, sizeof(MeshFace) * (size_t)nf);
    for (int f = 0; f < nf; f++) {
        MeshFace *face = &o->u.mesh.faces[f];
        /* every other face shares an edge with the one before */
        int a = f > 0 && f % 2 ? o->u.mesh.faces[f - 1].v[1] : (int)(rng_uniform(r) * nv);
        int b = f > 0 && f % 2 ? o->u.mesh.faces[f - 1].v[2] : (int)(rng_uniform(r) * nv);
        face->v[0] = a;
        face->v[1] = b;
        face->v[2] = (int)(rng_uniform(r) * nv);
        for (int k = 0; k < 3; k++) {
            face->n[k] = -1;
            face->uv[k] = -1;
        }
        face->texture = -1;
        face->texture2 = face->texture3 = -1;
    }
    return o;
}

/* A placement of mesh m: a shallow copy sharing its faces (as the parser
 * copies `object { M ... }`), moved by one of the transforms exporters write. */
static void place(Scene *s, TestRng *r, const SceneObject *m, const SceneTexture *tex)
{
    SceneObject *o = arena_alloc(s->arena, sizeof *o);
    *o = *m;
    transform_identity(&o->transform);
    double kind = rng_uniform(r);
    if (kind < 0.3) {
        double q[12] = { 0, 0, 1, 0, 1, 0, -1, 0, 0, 0, 0, 0 }; /* a quarter turn about y */
        transform_matrix(&o->transform, q);
    } else if (kind < 0.45) {
        transform_scale(&o->transform, v3(-1, 1, 1)); /* a mirror */
    } else if (kind < 0.7) {
        transform_scale(&o->transform, v3(1.0, 0.75, 1.3));
        transform_rotate(&o->transform, v3(rng_range(r, -60, 60), rng_range(r, -60, 60), rng_range(r, -60, 60)));
    }
    transform_translate(&o->transform, lattice_point(r, 1.5));
    o->texture = tex;
    transform_identity(&o->texture_bind);
    s->objects[s->nobjects++] = o;
}

static SceneTexture *texture(Scene *s, TestRng *r, int see_through)
{
    SceneTexture *t = arena_alloc(s->arena, sizeof *t);
    *t = s->default_texture;
    t->pigment.colour.r = rng_range(r, 0.2, 1);
    t->pigment.colour.g = rng_range(r, 0.2, 1);
    t->pigment.colour.b = rng_range(r, 0.2, 1);
    if (see_through)
        t->pigment.colour.filter = 0.5;
    return t;
}

static void random_scene(Scene *s, TestRng *r)
{
    int nmeshes = 1 + (int)(rng_uniform(r) * 2);
    for (int k = 0; k < nmeshes; k++) {
        SceneObject *m = lattice_mesh(s, r);
        int copies = 2 + (int)(rng_uniform(r) * 3);
        for (int c = 0; c < copies; c++)
            place(s, r, m, texture(s, r, rng_uniform(r) < 0.25));
    }
    fixture_triangle(s, lattice_point(r, 2), lattice_point(r, 2), lattice_point(r, 2));
    SceneObject *pl = fixture_object(s, OBJ_PLANE);
    pl->u.plane.normal = v3(0, 1, 0);
    pl->u.plane.distance = -3;
}

typedef struct {
    long scenes, instanced, decisions, not_ray[8], hits_both, far_apart, hit_one;
} Totals;

/* hst is prepared as hstrace prepares it, for an image of width x height
 * (its light buffers pay on a large one, not on a tiny one). */
static const struct {
    const char *method;
    int split;
    int width, height;
    const char *label;
} methods[] = {
    { "cache", 0, 0, 0, "cache" },
    { "light-buffer", 0, 0, 0, "light buffer" },
    { "light-buffer", 1, 0, 0, "light buffer (cells split at once)" },
    { "hst", 0, 640, 480, "hst (640x480: its light buffers)" },
    { "hst", 0, 4, 3, "hst (4x3: the cache's rule)" },
};
#define NMETHODS (int)(sizeof methods / sizeof methods[0])

/* The light through to hit for light li, by ctx's method. */
static RGB decide(ShadowContext *ctx, const World *w, const Hit *hit, const Segment *seg, int li)
{
    const Light *l = &w->lights[li];
    Vec3 d = v3_sub(l->location, hit->point);
    double distance = v3_length(d);
    Vec3 to_light = v3_scale(d, 1.0 / distance);
    if (l->kind == LIGHT_PARALLEL) {
        distance *= v3_dot(l->direction, to_light);
        to_light = l->direction;
    }
    ShadowQuery q = { hit->point, hit, seg, li, to_light, distance, v3(0, 0, 0), l };
    RGB through;
    ctx->method->test(ctx, &q, &through);
    return through;
}

typedef struct {
    ShadowContext ctx;
    ShadowPrepared prepared;
} Decider;

static void decider_init(Decider *d, const World *w, Grid *g, const Bvh *bvh, const char *name, int split, int width,
                         int height)
{
    ShadowSetup setup = { w, g, bvh, &w->camera.location, width > 0 ? width : 320, height > 0 ? height : 240, 1, 1,
                          0, { NTH_AUTO, 0.0 }, 0, NULL, 1 };
    char err[256];
    if (shadow_method_prepare(shadow_method_find(name), &setup, &d->prepared, err, (int)sizeof err)) {
        fprintf(stderr, "%s\n", err);
        exit(99);
    }
    if (split && d->prepared.light_buffers)
        d->prepared.light_buffers->split_at = 0; /* every cell split, down to the last level */
    if (shadow_context_init(&d->ctx, NULL, w, g, &d->prepared, 0, 0))
        exit(99);
    tracer_use_bvh(d->ctx.tracer, bvh);
}

static void decider_free(Decider *d)
{
    shadow_context_free(&d->ctx);
    shadow_prepared_free(&d->prepared);
}

static int same(RGB a, RGB b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

/* A world of s and its grid and hierarchy; 0 when it has no polygon. */
static int build(const Scene *s, int instancing, World *w, Grid *g, Bvh *b)
{
    WorldError err;
    WorldLimits lim = { 0, 0.0, 0.0, instancing };
    if (world_build_limited(w, s, 1, &lim, &err))
        exit(99);
    if (w->npolygons == 0 && w->ninstances == 0) {
        world_free(w);
        return 0;
    }
    Vec3 extra[64];
    int nextra = grid_extra_points(w, extra, 64);
    grid_build_box(g, w, NULL, extra, nextra);
    if (bvh_build(b, w, 1))
        exit(99);
    return 1;
}

static void one_scene(TestRng *rng, Totals *tot)
{
    Scene *s = fixture_scene(64);
    random_scene(s, rng);
    SceneLight lights[MAX_LIGHTS];
    memset(lights, 0, sizeof lights);
    int nl = 1 + (int)(rng_uniform(rng) * MAX_LIGHTS);
    for (int li = 0; li < nl; li++) {
        lights[li].colour.r = lights[li].colour.g = lights[li].colour.b = 1;
        lights[li].kind = rng_uniform(rng) < 0.2 ? LIGHT_PARALLEL : LIGHT_POINT;
        lights[li].location = lattice_point(rng, rng_uniform(rng) < 0.5 ? 2 : 4);
        if (v3_length(lights[li].location) == 0.0)
            lights[li].location = v3(1, 3, 2);
    }
    s->lights = lights;
    s->nlights = nl;
    s->camera.location = lattice_point(rng, 4);
    World wi, wf;
    Grid gi, gf;
    Bvh bi, bf;
    if (!build(s, 1, &wi, &gi, &bi)) {
        fixture_scene_free(s);
        return;
    }
    if (!build(s, 0, &wf, &gf, &bf))
        exit(99); /* the same scene flattened has polygons too */
    tot->scenes++;
    tot->instanced += wi.ninstances > 0;
    Vec3 targets[PROBES], bounce[PROBES];
    int on_border[PROBES]; /* aimed at a vertex or an edge */
    for (int k = 0; k < PROBES; k++) {
        /* a vertex, an edge's middle or a random point of the flattened
         * polygons (the same places in both worlds) */
        const Polygon *p = &wf.polygons[(int)(rng_uniform(rng) * wf.npolygons)];
        int i = p->first_point + (int)(rng_uniform(rng) * 3);
        int j = p->first_point + (i - p->first_point + 1) % 3;
        double kind = rng_uniform(rng);
        on_border[k] = kind < 0.7;
        targets[k] = kind < 0.35  ? wf.points[i]
                     : kind < 0.7 ? v3_scale(v3_add(wf.points[i], wf.points[j]), 0.5)
                                  : v3(rng_range(rng, -2, 2), rng_range(rng, -2, 2), rng_range(rng, -2, 2));
        Vec3 d = v3(rng_range(rng, -1, 1), rng_range(rng, -1, 1), rng_range(rng, -1, 1));
        bounce[k] = v3_length(d) > 0.0 ? v3_normalize(d) : v3(0, 1, 0);
    }
    Decider ray, by[NMETHODS];
    decider_init(&ray, &wi, &gi, &bi, "conventional", 0, 0, 0);
    for (int m = 0; m < NMETHODS; m++)
        decider_init(&by[m], &wi, &gi, &bi, methods[m].method, methods[m].split, methods[m].width, methods[m].height);
    Tracer flat;
    if (tracer_init(&flat, &wf, &gf))
        exit(99);
    tracer_use_bvh(&flat, &bf);
    const Vec3 eye = wi.camera.location;
    double size = 1.0 + fmax(v3_max_abs(wf.bounds_min), v3_max_abs(wf.bounds_max));
    for (int k = 0; k < PROBES; k++) {
        Vec3 dir = v3_sub(targets[k], eye);
        if (!(v3_length(dir) > 0.0))
            continue;
        dir = v3_normalize(dir);
        Hit none = { HIT_NONE, -1, 0.0, eye, -1, 0 }, h1, hf;
        int got = trace_nearest(ray.ctx.tracer, eye, dir, HUGE_VAL, &none, &h1);
        int got_flat = trace_nearest(&flat, eye, dir, HUGE_VAL, &none, &hf);
        /* A ray aimed at a vertex or an edge meets it in one world and may
         * pass it by rounding in the other (the instance's ray is carried
         * into its space): both are right. The others must agree. */
        if (!on_border[k] && got && got_flat) {
            tot->hits_both++;
            tot->far_apart += fabs(h1.t - hf.t) > 1e-9 * size;
        } else if (!on_border[k] && got != got_flat) {
            tot->hit_one++;
        }
        if (!got)
            continue;
        Hit at[2] = { h1, h1 };
        int nat = 1;
        if (trace_nearest(ray.ctx.tracer, h1.point, bounce[k], HUGE_VAL, &h1, &at[1]))
            nat = 2;
        for (int a = 0; a < nat; a++) {
            Segment seg = { a == 0 ? eye : h1.point, a == 0 ? dir : bounce[k], a == 0 ? &none : &h1, NULL, NULL, NULL, 0 };
            for (int li = 0; li < nl; li++) {
                RGB want = decide(&ray.ctx, &wi, &at[a], &seg, li);
                tot->decisions++;
                for (int m = 0; m < NMETHODS; m++)
                    tot->not_ray[m] += !same(decide(&by[m].ctx, &wi, &at[a], &seg, li), want);
            }
        }
    }
    tracer_free(&flat);
    decider_free(&ray);
    for (int m = 0; m < NMETHODS; m++)
        decider_free(&by[m]);
    bvh_free(&bi);
    bvh_free(&bf);
    grid_free(&gi);
    grid_free(&gf);
    world_free(&wi);
    world_free(&wf);
    fixture_scene_free(s);
}

int main(int argc, char **argv)
{
    unsigned long long seed = 0x2545F4914F6CDD1Dull;
    long scenes = 1500;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--seed") == 0 && i + 1 < argc)
            seed = strtoull(argv[++i], NULL, 0);
        else if (strcmp(argv[i], "--scenes") == 0 && i + 1 < argc)
            scenes = strtol(argv[++i], NULL, 10);
    }
    TestRng rng = { seed };
    Totals tot;
    memset(&tot, 0, sizeof tot);
    while (tot.scenes < scenes)
        one_scene(&rng, &tot);
    printf("# %ld scenes (%ld with instances), %ld decisions; camera rays at random points hitting in both worlds "
           "%ld, in one only %ld\n",
           tot.scenes, tot.instanced, tot.decisions, tot.hits_both, tot.hit_one);
    tap_ok(tot.instanced * 10 >= tot.scenes * 9, "nine scenes in ten or more have instances (%ld of %ld)",
              tot.instanced, tot.scenes);
    tap_ok(tot.decisions > 100 * tot.scenes, "at least 100 decisions a scene (%ld)", tot.decisions);
    for (int m = 0; m < NMETHODS; m++)
        tap_ok(tot.not_ray[m] == 0, "%s on instances: every decision the shadow ray's (%ld of %ld differ)",
                  methods[m].label, tot.not_ray[m], tot.decisions);
    tap_ok(tot.far_apart == 0,
              "camera rays: the instanced world's hits at the flattened world's distance, within 1e-9 of the "
              "scene's size (%ld of %ld apart)",
              tot.far_apart, tot.hits_both);
    tap_ok(tot.hit_one * 1000 <= tot.hits_both,
              "camera rays that hit in one world only (grazing a border): at most one in 1000 (%ld of %ld)",
              tot.hit_one, tot.hits_both);
    return tap_done();
}
