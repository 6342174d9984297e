/* Randomized agreement: every shadow method against a brute-force reference
 * computed in long double, on 5000 small random scenes (by default) built on a
 * lattice (so that shared vertices and edges, coplanar and touching polygons,
 * lights in the planes of polygons and rays through vertices and along edges
 * are common, not rare).
 *
 * For each scene: camera rays aimed at polygon vertices, at points on edges
 * and at random points, and from each hit one secondary segment (a random
 * direction, or aimed at a vertex); at every hit and for every light, each
 * method decides lit or blocked exactly as the renderer asks it (the
 * segment's start state, the previous "pixel" for pixel coherence), and the
 * reference decides by testing every polygon in long double.
 *
 * Every other scene has transparent objects (filter, transmit, both; a
 * second generator paints them, so the geometry is the same as without),
 * and a decision is the colour of the light that gets through: the
 * reference's is written here from POV-Ray's rule, the product of
 * rgb * filter + transmit of every polygon the reference finds in the way
 * (black if one is opaque). In some of them the closed tetrahedron is one
 * see-through object with a fading interior, and the reference fades the
 * light by the way the shadow ray runs inside it, as POV-Ray does
 * (fade_along).
 *
 * The reference separates clear cases from ties: a decision is a tie when
 * some polygon is met within 1e-12 of the scene's size of its border, of the
 * segment's ends, or edge-on (unless a clear opaque blocker decides), and
 * when two transparent polygons met lie within POV-Ray's SHADOW_TOLERANCE
 * (1e-3) of each other along the shadow ray: POV-Ray filters those once,
 * hstrace once per polygon (a known difference, a TAP TODO). On
 * clear cases every method, the shadow ray included, must agree with the
 * reference (colours within 1e-12); on ties every method must agree with
 * the shadow ray (the tie rule the others fall back to). Every method's
 * colour must also equal the shadow ray's exactly, as --verify-shadows asks.
 * Ties are counted and printed.
 *
 * usage: test_agreement [--seed N] [--scenes N] [--verbose N] [--tolerance R]
 *        defaults: a fixed seed, 5000 scenes, the engine's margin; --verbose N
 *        describes the first N disagreements on stderr. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixtures.h"
#include "grid.h"
#include "light_buffer.h"
#include "shadow.h"
#include "shadow_coherence.h"
#include "shadow_reference.h"
#include "shadow_registry.h"
#include "shadow_volumes.h"
#include "tap.h"
#include "tracer.h"
#include "world.h"

typedef long double ld;

/* ---- random lattice scenes ------------------------------------------------ */

static Vec3 lattice_point(TestRng *r, double half)
{
    /* Multiples of 0.5 in [-half, half]: exact in binary. */
    int n = (int)(2 * half);
    return v3(0.5 * ((int)(rng_uniform(r) * (2 * n + 1)) - n), 0.5 * ((int)(rng_uniform(r) * (2 * n + 1)) - n),
              0.5 * ((int)(rng_uniform(r) * (2 * n + 1)) - n));
}

/* Some objects transparent: filter only, transmit only, or both. */
static void paint(Scene *s, TestRng *r)
{
    static const double colours[4][3] = { { 1, 0.5, 0.25 }, { 0.2, 0.9, 0.6 }, { 0.75, 0.75, 0.75 }, { 0.3, 0.1, 1 } };
    static const double ft[4][2] = { { 0.6, 0 }, { 0, 0.3 }, { 0.4, 0.2 }, { 0.9, 0.05 } };
    for (int i = 0; i < s->nobjects; i++) {
        if (rng_uniform(r) < 0.5)
            continue;
        const double *c = colours[(int)(rng_uniform(r) * 4)], *f = ft[(int)(rng_uniform(r) * 4)];
        fixture_pigment(s, s->objects[i], c[0], c[1], c[2], f[0], f[1]);
    }
}

/* Returns the index of the closed tetrahedron's first triangle among the
 * scene's objects, or -1 when it has none. */
static int random_scene(Scene *s, TestRng *r)
{
    int tetrahedron = -1;
    int ntri = 2 + (int)(rng_uniform(r) * 4);
    for (int k = 0; k < ntri; k++)
        fixture_triangle(s, lattice_point(r, 2), lattice_point(r, 2), lattice_point(r, 2));
    if (rng_uniform(r) < 0.6) { /* two triangles sharing an edge (a quad, maybe bent) */
        Vec3 a = lattice_point(r, 2), b = lattice_point(r, 2), c = lattice_point(r, 2), d = lattice_point(r, 2);
        fixture_triangle(s, a, b, c);
        if (rng_uniform(r) < 0.5)
            fixture_triangle(s, a, c, d);
        else
            fixture_triangle(s, c, a, d); /* the other winding */
    }
    if (rng_uniform(r) < 0.5) { /* an axis-aligned rectangle on a lattice plane */
        int axis = (int)(rng_uniform(r) * 3);
        Vec3 lo = lattice_point(r, 2), hi = lattice_point(r, 2);
        double at = v3_comp(lo, axis);
        Vec3 q[5];
        for (int k = 0; k < 4; k++) {
            double u = (k == 1 || k == 2) ? v3_comp(hi, (axis + 1) % 3) : v3_comp(lo, (axis + 1) % 3);
            double v = (k >= 2) ? v3_comp(hi, (axis + 2) % 3) : v3_comp(lo, (axis + 2) % 3);
            double c[3];
            c[axis] = at;
            c[(axis + 1) % 3] = u;
            c[(axis + 2) % 3] = v;
            q[k] = v3(c[0], c[1], c[2]);
        }
        q[4] = q[0];
        int starts[2] = { 0, 5 };
        if (v3_comp(lo, (axis + 1) % 3) != v3_comp(hi, (axis + 1) % 3) &&
            v3_comp(lo, (axis + 2) % 3) != v3_comp(hi, (axis + 2) % 3))
            fixture_polygon(s, q, 5, starts, 1);
    }
    if (rng_uniform(r) < 0.4) { /* a fan of three triangles around one vertex */
        Vec3 c = lattice_point(r, 2), a = lattice_point(r, 2), b = lattice_point(r, 2), d = lattice_point(r, 2);
        fixture_triangle(s, c, a, b);
        fixture_triangle(s, c, b, d);
        fixture_triangle(s, c, d, a);
    }
    if (rng_uniform(r) < 0.3) { /* a closed tetrahedron */
        Vec3 a = lattice_point(r, 2), b = lattice_point(r, 2), c = lattice_point(r, 2), d = lattice_point(r, 2);
        tetrahedron = s->nobjects;
        fixture_triangle(s, a, b, c);
        fixture_triangle(s, a, d, b);
        fixture_triangle(s, b, d, c);
        fixture_triangle(s, c, d, a);
    }
    return tetrahedron;
}

/* The tetrahedron's four triangles made one see-through object with a
 * fading interior (their one interior, as a mesh's), as exporters write
 * transparent parts: a shadow ray through it is dimmed and tinted by the
 * way it runs inside. Linear or exponential fade (power 1001), tinted or
 * not. */
static void paint_fading(Scene *s, int first, TestRng *r)
{
    static const double powers[3] = { 1, 2, 1001 };
    Interior *in = arena_alloc(s->arena, sizeof *in);
    *in = scene_default_interior();
    in->fade_distance = 0.5 + rng_uniform(r);
    in->fade_power = powers[(int)(rng_uniform(r) * 3)];
    if (rng_uniform(r) < 0.5) {
        in->fade_colour.r = 0.8;
        in->fade_colour.g = 0.3;
        in->fade_colour.b = 0.1;
    }
    double filter = rng_uniform(r) < 0.5 ? 0.9 : 0.0;
    for (int k = first; k < first + 4; k++) {
        fixture_pigment(s, s->objects[k], 0.9, 0.7, 0.5, filter, 0.9 - filter);
        s->objects[k]->interior = in;
    }
}

/* ---- one scene, every method ---------------------------------------------- */

typedef struct {
    const char *method;
    double nth;
    int coherence;
    int hierarchy;      /* polygon queries through the BVH (as hstrace renders), else the grid's walk */
    const char *label;
} Variant;

/* The first is the reference the others are held to: the shadow ray by the
 * grid's walk, the path the hierarchy replaced. */
static const Variant variants[] = {
    { "conventional", 0, 0, 0, "conventional (grid walk)" },
    { "conventional", 0, 0, 1, "conventional" },
    { "cache", 0, 0, 1, "cache" },
    { "volume", 0, 0, 1, "volume" },
    { "hst", 1e9, 1, 1, "hst (N_th 1e9, pixel coherence)" },
    { "hst", 1e9, 0, 1, "hst (N_th 1e9)" },
    { "hst", 4, 1, 1, "hst (N_th 4, pixel coherence)" },
    { "hst", 4, 1, 0, "hst (N_th 4, pixel coherence, grid walk)" },
    { "light-buffer", 0, 0, 1, "light buffer" },
    /* every cell split at its first test, down to the last level */
    { "light-buffer", 1, 0, 1, "light buffer (cells split at once)" },
};
#define NVARIANTS (int)(sizeof variants / sizeof variants[0])

typedef struct {
    int has_target;
    Vec3 eye_target;    /* the camera ray's aim */
    Vec3 bounce_dir;    /* the secondary segment's direction */
} Probe;

#define PROBES 40
#define MAX_LIGHTS 3

typedef struct {
    /* Per probe: hits and decisions per light (primary, secondary); -1: none. */
    signed char decision[NVARIANTS][PROBES][2][MAX_LIGHTS];
    signed char scheme[NVARIANTS][PROBES][2][MAX_LIGHTS];
    RGB colour[NVARIANTS][PROBES][2][MAX_LIGHTS]; /* the light that gets through */
} Decisions;

static int decide_one(ShadowContext *ctx, const World *w, const Hit *hit, const Segment *seg, int li, RGB *through)
{
    const Light *l = &w->lights[li];
    Vec3 d = v3_sub(l->location, hit->point);
    double distance = v3_length(d);
    Vec3 to_light = v3_scale(d, 1.0 / distance);
    if (l->kind == LIGHT_PARALLEL) {
        distance *= v3_dot(l->direction, to_light);
        to_light = l->direction;
    }
    ShadowQuery q = { hit->point, hit, seg, li, to_light, distance, v3(0, 0, 0), &w->lights[li] };
    ctx->method->test(ctx, &q, through);
    return through->r == 0.0 && through->g == 0.0 && through->b == 0.0;
}

/* The light buffer's block masks, SSE against plain, and its float plane
 * test against the double bound it stands for (light_buffer.h), on every
 * cell built, at the points the variant decided. */
static long mask_blocks, mask_differ, float_passes, float_not_double;
static long shapes_classified, shapes_differ, shapes_sure, shapes_not_bound;

/* The shape's verdict for direction (u, v) against the bound it stands
 * for (light_buffer.h), in long double on the stored lines: 1 when it holds. */
static int shape_verdict_holds(const LbShape *sh, int where, double u, double v)
{
    long double pad = LB_SHAPE_FLOAT_PAD;
    int outside = 0, inside = 1;
    for (int k = 0; k < sh->n; k++) {
        long double d = (long double)sh->a[k] * u + (long double)sh->b[k] * v + (long double)sh->c[k];
        outside |= d < -((long double)sh->out - pad);
        inside &= d >= (long double)sh->in - pad;
    }
    return where == LB_OUTSIDE ? outside : where == LB_INSIDE ? inside : 1;
}

/* A shape's verdicts at directions within the float's rounding of where
 * they change: at `out` outside and `in` inside each edge, a few ulps to
 * either side, along the edge. (Probes elsewhere seldom come that close.) */
static void check_shape_borders(const LbShape *sh)
{
    for (int k = 0; k < sh->n; k++) {
        double a = sh->a[k], b = sh->b[k], c = sh->c[k];
        const double at[4] = { -sh->out, sh->in, -sh->out * (1 + 1e-7), sh->in * (1 - 1e-7) };
        for (int j = 0; j < 4; j++)
            for (int t = -3; t <= 3; t++) {
                double off = at[j] - c, u = a * off - b * 0.1 * t, v = b * off + a * 0.1 * t;
                if (!(fabs(u) <= 1.0 && fabs(v) <= 1.0))
                    continue;
                for (int e = -4; e <= 4; e++) {
                    float fu = nextafterf((float)u, e < 0 ? -INFINITY : INFINITY);
                    fu = e == 0 ? (float)u : fu;
                    int where = lb_shape_classify(sh, fu, (float)v);
                    shapes_sure += where != LB_UNSURE;
                    shapes_not_bound += !shape_verdict_holds(sh, where, fu, (float)v);
                }
            }
    }
}

static void check_cell_masks(const LbCell *c, const LbPoint *pt, const LbSpot *spot)
{
    if (!c)
        return;
    LbPlane pl;
    const LbScan scan = lb_scan(INFINITY, (float)spot->u, (float)spot->v, pt);
    for (uint32_t b = 0; b * LB_BLOCK < c->n; b++) {
        mask_blocks++;
        mask_differ += lb_block_mask(c, b, &scan) != lb_block_mask_plain(c, b, &scan);
        for (uint32_t i = b * LB_BLOCK; i < (b + 1) * LB_BLOCK && i < c->n; i++) {
            const LbShape *sh = &c->shapes[c->shape_at[i]];
            int where = lb_shape_classify(sh, (float)spot->u, (float)spot->v);
            shapes_classified++;
            shapes_differ += where != lb_shape_classify_plain(sh, (float)spot->u, (float)spot->v);
            shapes_sure += where != LB_UNSURE;
            shapes_not_bound += !shape_verdict_holds(sh, where, spot->u, spot->v);
            if (!lb_float_passed(c, i, &scan))
                continue;
            float_passes++;
            pl = lb_plane_at(c, i);
            float_not_double += !lb_candidate_passed(&pl, pt);
        }
    }
    for (int k = 0; c->child && k < LB_SUB * LB_SUB; k++)
        check_cell_masks(atomic_load(&c->child[k]), pt, spot);
}

static void check_masks(const LightBuffers *lbs, const World *w, Hit hits[PROBES][2])
{
    for (int k = 0; k < PROBES; k++)
        for (int s = 0; s < 2; s++) {
            if (hits[k][s].kind == HIT_NONE)
                continue;
            for (int li = 0; li < w->nlights; li++) {
                LightBuffer *lb = lbs->light[li];
                LbSpot spot;
                Vec3 d = v3_sub(hits[k][s].point, w->lights[li].location);
                if (!lb || !light_buffer_spot(d, &spot))
                    continue;
                LbPoint pt = lb_point(hits[k][s].point, v3_length(d));
                for (int c = 0; c < LB_TOP * LB_TOP; c++)
                    check_cell_masks(atomic_load(&lb->top[spot.face][c]), &pt, &spot);
            }
        }
    /* every shape kept (by its top cell), at its borders */
    for (int li = 0; li < w->nlights; li++)
        for (int f = 0; lbs->light[li] && f < 6; f++)
            for (int c = 0; c < LB_TOP * LB_TOP; c++) {
                const LbCell *top = atomic_load(&lbs->light[li]->top[f][c]);
                for (uint32_t k = 0; top && k < top->nshapes; k++)
                    check_shape_borders(&top->shapes[k]);
            }
}

static void run_variant(const World *w, const Grid *g, const Bvh *bvh, const ShadowVolumes *sv, const Variant *v,
                        const Probe *probes,
                        Decisions *dec, int vi, Hit hits[PROBES][2])
{
    const ShadowMethod *m = shadow_method_find(v->method);
    ShadowContext ctx;
    PixelCoherence pc;
    memset(&pc, 0, sizeof pc);
    /* The pixel coherence is driven here by hand (its neighbours' rows are
     * this test's own), so the context makes none. */
    ShadowPrepared prepared = { .decider = m, .volumes = m->uses_volumes ? (ShadowVolumes *)sv : NULL, .nth = v->nth };
    LightBuffers lbs;
    int light_buffer = strcmp(v->method, "light-buffer") == 0;
    if (light_buffer) {
        /* nth 1: every cell split, down to the last level */
        if (light_buffers_init(&lbs, w, bvh, grid_tolerance(g), (size_t)64 << 20)) {
            fprintf(stderr, "out of memory\n");
            exit(99);
        }
        if (v->nth > 0)
            lbs.split_at = 0; /* every cell split */
        prepared.light_buffers = &lbs;
    }
    if (shadow_context_init(&ctx, NULL, w, g, &prepared, 0, 0) || (v->coherence && pixel_coherence_init(&pc, w, g))) {
        fprintf(stderr, "out of memory\n");
        exit(99);
    }
    if (v->hierarchy)
        tracer_use_bvh(ctx.tracer, bvh);
    if (v->coherence)
        ctx.coherence = &pc;
    int nl = w->nlights;
    LightState row0[MAX_LIGHTS], row1[MAX_LIGHTS];
    for (int k = 0; k < PROBES; k++) {
        memset(dec->decision[vi][k], -1, sizeof dec->decision[vi][k]);
        hits[k][0].kind = hits[k][1].kind = HIT_NONE;
        if (!probes[k].has_target)
            continue;
        if (v->coherence)
            pixel_coherence_begin(&pc, k == 0, 1);
        Hit none = { HIT_NONE, -1, 0, w->camera.location, -1, 0 };
        Vec3 dir = v3_normalize(v3_sub(probes[k].eye_target, w->camera.location));
        Hit h1;
        int got = trace_nearest(ctx.tracer, w->camera.location, dir, HUGE_VAL, &none, &h1);
        if (got) {
            hits[k][0] = h1;
            if (v->coherence) {
                pc.hit = h1;
                pc.have_hit = 1;
            }
            Segment seg = { w->camera.location, dir, &none, NULL, m->uses_volumes ? row0 : NULL, NULL, 0 };
            for (int li = 0; li < nl; li++)
            {
                dec->decision[vi][k][0][li] =
                    (signed char)decide_one(&ctx, w, &h1, &seg, li, &dec->colour[vi][k][0][li]);
                dec->scheme[vi][k][0][li] = (signed char)ctx.last_scheme;
            }
            Hit h2;
            Vec3 d2 = probes[k].bounce_dir;
            if (trace_nearest(ctx.tracer, h1.point, d2, HUGE_VAL, &h1, &h2)) {
                hits[k][1] = h2;
                Segment seg2 = { h1.point, d2, &h1, m->uses_volumes ? row0 : NULL, m->uses_volumes ? row1 : NULL, NULL, 0 };
                for (int li = 0; li < nl; li++)
                {
                    dec->decision[vi][k][1][li] =
                        (signed char)decide_one(&ctx, w, &h2, &seg2, li, &dec->colour[vi][k][1][li]);
                    dec->scheme[vi][k][1][li] = (signed char)ctx.last_scheme;
                }
            }
        }
        if (v->coherence)
            pixel_coherence_end(&pc, got ? &h1 : NULL, row0, k == 0);
    }
    if (v->coherence)
        pixel_coherence_free(&pc);
    ctx.coherence = NULL; /* this test's own */
    shadow_context_free(&ctx);
    if (light_buffer) {
        check_masks(&lbs, w, hits);
        light_buffers_free(&lbs);
    }
}

static int verbose; /* --verbose: describe the first disagreements */
static double tolerance = GRID_TOLERANCE; /* --tolerance: the engine's margin (bench/hard.sh) */

static void describe(const World *w, const char *what, const Hit *h, int seg, int li, int probe)
{
    const Light *l = &w->lights[li];
    fprintf(stderr, "%s: probe %d %s hit %s %d at (%.17g, %.17g, %.17g); light %d %s (%g, %g, %g); eye (%g, %g, %g)\n",
            what, probe, seg ? "secondary" : "primary", h->kind == HIT_POLYGON ? "polygon" : "plane", h->index,
            h->point.x, h->point.y, h->point.z, li, l->kind == LIGHT_PARALLEL ? "parallel" : "point", l->location.x,
            l->location.y, l->location.z, w->camera.location.x, w->camera.location.y, w->camera.location.z);
    for (int i = 0; i < w->npolygons; i++) {
        const Polygon *p = &w->polygons[i];
        fprintf(stderr, "  polygon %d:", i);
        int n = p->first_outline < 0 ? 3 : p->npoints;
        for (int k = 0; k < n; k++) {
            Vec3 a = w->points[p->first_point + k];
            fprintf(stderr, " <%.17g, %.17g, %.17g>", a.x, a.y, a.z);
        }
        fprintf(stderr, "\n");
    }
}

/* What --verbose prints about a disagreement: the scene, the reference's
 * answer per polygon, the own polygon's sides, the eye's count. */
static void explain(const World *w, const ShadowVolumes *sv, const char *what, const Hit hits[2], int seg, int li,
                    int probe, ld eps)
{
    const Hit *h = &hits[seg];
    const Light *l = &w->lights[li];
    describe(w, what, h, seg, li, probe);
    fprintf(stderr, "  reference per polygon (Lit, Blocked, Tie):");
    for (int i = 0; i < w->npolygons; i++)
        fprintf(stderr, " %d:%c", i, "LBT"[shadow_reference_polygon(w, i, h->point, l, trace_min_distance(h->point), eps)]);
    fprintf(stderr, "\n");
    if (h->kind == HIT_POLYGON) {
        const Polygon *pp = &w->polygons[h->index];
        const OccluderSide *o = &sv->light[li].occluder[h->index];
        Vec3 from = seg ? hits[0].point : w->camera.location;
        fprintf(stderr, "  own polygon: light side %+.3g (occluder light_side %d, channel %d), segment start side %+.3g\n",
                l->kind == LIGHT_PARALLEL ? v3_dot(pp->normal, l->direction) : v3_dot(pp->normal, l->location) - pp->d,
                o->light_side, o->channel, v3_dot(pp->normal, from) - pp->d);
    }
    if (seg)
        fprintf(stderr, "  the segment starts on polygon %d at (%.17g, %.17g, %.17g)\n", hits[0].index, hits[0].point.x,
                hits[0].point.y, hits[0].point.z);
    Hit eye = { HIT_NONE, -1, 0, w->camera.location, -1, 0 };
    fprintf(stderr, "  eye count %s %d, reference at the eye %d\n", sv->light[li].eye_known ? "known" : "unknown",
            sv->light[li].eye_opaque, shadow_reference_count(w, &eye, l, eps));
}

typedef struct {
    long decisions, ties, clear_wrong[NVARIANTS], tie_vs_ray[NVARIANTS], not_ray[NVARIANTS], other_path[NVARIANTS];
    long scenes, skipped;
    long tie_blocked, tie_lit;
    long painted, filtered; /* scenes with transparent objects; decisions where coloured light gets through */
    long by_scheme[NVARIANTS][SCHEME_COUNT]; /* decisions per variant and sub-scheme */
    long close, close_povray; /* transparent surfaces close along the shadow ray; and there POV-Ray's colour */
} Totals;

/* POV-Ray's SHADOW_TOLERANCE (render/trace.cpp): after each transparent
 * surface its shadow ray starts again from the hit, ignoring hits closer
 * than this, so surfaces within it of each other along the ray filter once. */
#define POV_SHADOW_TOLERANCE 1e-3

typedef struct {
    ld t;
    RGB factor;
    const Material *m;
} Filter;

static int filter_cmp(const void *a, const void *b)
{
    const Filter *x = a, *y = b;
    return x->t < y->t ? -1 : x->t > y->t;
}

/* POV-Ray 3.7's fade of a shadow ray (render/trace.cpp): the ray starts
 * outside every interior here (the test's segments carry none), passes the
 * surfaces f[0 .. n) in order, entering a surface's interior where it is
 * outside it and leaving it where inside (ComputeShadowMedia); at a surface
 * of an interior it is inside, the light is multiplied by the interior's
 * fade over the distance from the previous surface (ComputeShadowTexture):
 * fade_colour + (1 - fade_colour) / (1 + (d / fade_distance)^fade_power),
 * or exp(-(1 - fade_colour) d / fade_distance) for a power of 1000 or more.
 * Written out here, not taken from the engine. */
static long faded; /* decisions the reference faded */

/* Multiplies *c by the fades of the surfaces f[0 .. n), in order; 1 when
 * some interior faded it. */
static int fade_along(const Filter *f, int n, RGB *c)
{
    const void *inside[64];
    int ninside = 0, any = 0;
    ld from = 0;
    for (int i = 0; i < n; i++) {
        const Material *m = f[i].m;
        ld d = f[i].t - from;
        from = f[i].t;
        if (!(m->fade_power > 0 && fabs(m->fade_distance) > 1e-10))
            continue;
        int was = -1;
        for (int k = 0; k < ninside; k++)
            if (inside[k] == m->interior_key)
                was = k;
        if (was < 0) {
            inside[ninside++] = m->interior_key;
            continue;
        }
        inside[was] = inside[--ninside];
        double x = (double)(d / m->fade_distance);
        double k[3], fc[3] = { m->fade_colour.r, m->fade_colour.g, m->fade_colour.b };
        for (int ch = 0; ch < 3; ch++)
            k[ch] = m->fade_power >= 1000 ? exp(-(1 - fc[ch]) * x) : fc[ch] + (1 - fc[ch]) / (1 + pow(x, m->fade_power));
        c->r *= k[0];
        c->g *= k[1];
        c->b *= k[2];
        any = 1;
    }
    return any;
}

/* The reference's colour: POV-Ray's rule (each surface the shadow ray
 * meets multiplies the light by rgb * filter + transmit; an opaque one stops
 * it) over the polygons the long-double reference finds in the way. REF_TIE
 * when one is too close to call and no clear opaque blocker decides. The
 * random scenes have no infinite planes.
 *
 * *close is set when two of the transparent polygons met lie within
 * POV_SHADOW_TOLERANCE of each other along the ray (coplanar overlapping
 * ones, or crossed near where they meet): there POV-Ray filters once per
 * such group (taking whichever it meets first), which the colours in
 * alt[0 .. *nalt) list; *c multiplies every polygon, as hstrace does. */
static RefAnswer reference_colour(const World *w, const Hit *at, const Light *l, ld eps, RGB *c, int *close,
                                  RGB *alt, int *nalt)
{
    c->r = c->g = c->b = 1;
    *close = 0;
    *nalt = 0;
    int tie = 0, nf = 0;
    Filter f[64];
    ld tmin = trace_min_distance(at->point);
    Vec3 dir = l->kind == LIGHT_PARALLEL ? l->direction : v3_normalize(v3_sub(l->location, at->point));
    for (int i = 0; i < w->npolygons; i++) {
        const Polygon *poly = &w->polygons[i];
        const Material *m = &w->materials[poly->material];
        if ((at->kind == HIT_POLYGON && at->index == i) || m->no_shadow)
            continue;
        RefAnswer a = shadow_reference_polygon(w, i, at->point, l, tmin, eps);
        if (a == REF_TIE)
            tie = 1;
        if (a != REF_BLOCKED)
            continue;
        const Colour *p = &m->pigment;
        if (p->filter == 0 && p->transmit == 0) {
            c->r = c->g = c->b = 0;
            return REF_BLOCKED;
        }
        RGB k = { p->r * p->filter + p->transmit, p->g * p->filter + p->transmit, p->b * p->filter + p->transmit };
        c->r *= k.r;
        c->g *= k.g;
        c->b *= k.b;
        if (nf < 64) {
            ld nd = (ld)poly->normal.x * dir.x + (ld)poly->normal.y * dir.y + (ld)poly->normal.z * dir.z;
            ld np = (ld)poly->normal.x * at->point.x + (ld)poly->normal.y * at->point.y +
                    (ld)poly->normal.z * at->point.z;
            f[nf].t = ((ld)poly->d - np) / nd;
            f[nf].m = m;
            f[nf++].factor = k;
        }
    }
    if (tie)
        return REF_TIE;
    /* Groups of surfaces within the tolerance of the first of the group. */
    qsort(f, (size_t)nf, sizeof *f, filter_cmp);
    int start[64], ng = 0;
    for (int i = 0; i < nf; i++)
        if (ng == 0 || f[i].t > f[start[ng - 1]].t + POV_SHADOW_TOLERANCE)
            start[ng++] = i;
    start[ng] = nf;
    int combos = 1;
    for (int g = 0; g < ng; g++) {
        *close |= start[g + 1] - start[g] > 1;
        combos *= start[g + 1] - start[g];
    }
    for (int k = 0; *close && k < combos && k < 64; k++) {
        RGB a = { 1, 1, 1 };
        Filter picked[64];
        for (int g = 0, rest = k; g < ng; g++) {
            int size = start[g + 1] - start[g];
            picked[g] = f[start[g] + rest % size];
            rest /= size;
            a.r *= picked[g].factor.r;
            a.g *= picked[g].factor.g;
            a.b *= picked[g].factor.b;
        }
        fade_along(picked, ng, &a); /* the surface picked of each group is the one the ray passes */
        alt[(*nalt)++] = a;
    }
    if (!*close)
        faded += fade_along(f, nf, c);
    return c->r == 1 && c->g == 1 && c->b == 1 ? REF_LIT : REF_BLOCKED;
}

static int same_colour(RGB a, RGB b, double tol)
{
    return fabs(a.r - b.r) <= tol && fabs(a.g - b.g) <= tol && fabs(a.b - b.b) <= tol;
}

/* The reference's verdict and colour at a point, for a method whose shadow
 * ray gave by_ray: where transparent surfaces lie within POV-Ray's
 * SHADOW_TOLERANCE of each other along the ray, POV-Ray's colour is
 * ambiguous by hstrace's rule, and the case is no clear one (a tie, held to
 * the shadow ray); *close_povray: the shadow ray gave one of POV-Ray's. */
static RefAnswer judge(const World *w, const Hit *at, const Light *l, ld eps, RGB by_ray, RGB *want, int *close,
                       int *close_povray)
{
    RGB alt[64];
    int nalt;
    RefAnswer ref = reference_colour(w, at, l, eps, want, close, alt, &nalt);
    *close_povray = 0;
    if (*close && ref != REF_TIE) {
        for (int a = 0; a < nalt; a++)
            if (same_colour(by_ray, alt[a], 1e-12)) {
                *close_povray = 1;
                break;
            }
        return REF_TIE;
    }
    *close = 0;
    return ref;
}

static void one_scene(TestRng *rng, Totals *tot)
{
    Scene *s = fixture_scene(64);
    int tetrahedron = random_scene(s, rng);
    /* Every other scene transparent in part, painted by a generator of its
     * own: the scenes' geometry is the one without transparency. */
    if ((tot->scenes + tot->skipped) % 2) {
        TestRng colours = { rng->s ^ 0xD1B54A32D192ED03ull };
        paint(s, &colours);
        tot->painted++;
        if (tetrahedron >= 0 && rng_uniform(&colours) < 0.7)
            paint_fading(s, tetrahedron, &colours);
    }
    SceneLight lights[MAX_LIGHTS];
    memset(lights, 0, sizeof lights);
    int nl = 1 + (int)(rng_uniform(rng) * MAX_LIGHTS);
    for (int li = 0; li < nl; li++) {
        lights[li].colour.r = lights[li].colour.g = lights[li].colour.b = 1;
        if (rng_uniform(rng) < 0.25) {
            lights[li].kind = LIGHT_PARALLEL;
            lights[li].location = lattice_point(rng, 4);
            lights[li].point_at = v3(0, 0, 0);
            if (v3_length(lights[li].location) == 0.0)
                lights[li].location = v3(1, 3, 2);
        } else {
            lights[li].kind = LIGHT_POINT;
            lights[li].location = lattice_point(rng, rng_uniform(rng) < 0.5 ? 2 : 4); /* among or around */
        }
    }
    s->lights = lights;
    s->nlights = nl;
    s->camera.location = lattice_point(rng, 4);
    World w;
    WorldError err;
    int built = world_build(&w, s, &err) == 0;
    if (!built || w.npolygons == 0) {
        if (built)
            world_free(&w);
        tot->skipped++;
        fixture_scene_free(s);
        return;
    }
    Vec3 extra[64]; /* as the renderer builds its grid */
    int nextra = grid_extra_points(&w, extra, 64);
    Grid g;
    ShadowVolumes sv;
    int grid_failed = grid_build(&g, &w, NULL, extra, nextra);
    if (!grid_failed)
        grid_set_tolerance(&g, tolerance);
    Bvh bvh;
    if (grid_failed || shadow_volumes_build(&sv, &w, &g, &w.camera.location, 2, NULL) || bvh_build(&bvh, &w, 1)) {
        fprintf(stderr, "out of memory\n");
        exit(99);
    }
    /* Probes: vertices, points on edges, random points; bounces random or at a vertex. */
    Probe probes[PROBES];
    for (int k = 0; k < PROBES; k++) {
        const Polygon *p = &w.polygons[(int)(rng_uniform(rng) * w.npolygons)];
        int i = p->first_point + (int)(rng_uniform(rng) * 3);
        int j = p->first_point + (i - p->first_point + 1) % 3;
        double kind = rng_uniform(rng);
        Vec3 target;
        if (kind < 0.35)
            target = w.points[i];
        else if (kind < 0.7)
            target = v3_add(w.points[i], v3_scale(v3_sub(w.points[j], w.points[i]), rng_uniform(rng) < 0.5 ? 0.5 : 0.25));
        else
            target = v3(rng_range(rng, -2, 2), rng_range(rng, -2, 2), rng_range(rng, -2, 2));
        probes[k].eye_target = target;
        probes[k].has_target = v3_length(v3_sub(target, w.camera.location)) > 0.0;
        Vec3 d = v3(rng_range(rng, -1, 1), rng_range(rng, -1, 1), rng_range(rng, -1, 1));
        if (rng_uniform(rng) < 0.4)
            d = v3_sub(w.points[(int)(rng_uniform(rng) * w.npoints)], target);
        probes[k].bounce_dir = v3_length(d) > 0.0 ? v3_normalize(d) : v3(0, 1, 0);
    }
    static Decisions dec;
    Hit hits[NVARIANTS][PROBES][2];
    for (int vi = 0; vi < NVARIANTS; vi++)
        run_variant(&w, &g, &bvh, &sv, &variants[vi], probes, &dec, vi, hits[vi]);
    ld eps = shadow_reference_eps(&g);
    for (int k = 0; k < PROBES; k++)
        for (int seg = 0; seg < 2; seg++)
            for (int li = 0; li < nl; li++) {
                const Hit *at0 = &hits[0][k][seg];
                int ray0 = dec.decision[0][k][seg][li];
                RGB want0 = { 1, 1, 1 };
                RefAnswer ref0 = REF_TIE;
                if (ray0 >= 0) {
                    tot->decisions++;
                    RGB by_ray0 = dec.colour[0][k][seg][li];
                    int close, close_povray;
                    ref0 = judge(&w, at0, &w.lights[li], eps, by_ray0, &want0, &close, &close_povray);
                    tot->close += close;
                    tot->close_povray += close_povray;
                    tot->filtered += !ray0 && !(by_ray0.r == 1 && by_ray0.g == 1 && by_ray0.b == 1);
                    if (ref0 == REF_TIE) {
                        tot->ties++;
                        if (ray0)
                            tot->tie_blocked++;
                        else
                            tot->tie_lit++;
                    }
                }
                for (int vi = 0; vi < NVARIANTS; vi++) {
                    /* Each variant against the reference at its own point:
                     * the hierarchy may find another polygon than the grid's
                     * walk where several meet within rounding (at a shared
                     * vertex, or one the grid did not list in a cell it
                     * touches), and the path goes on from there. On ties,
                     * against the shadow ray of the same polygon queries. */
                    int got = dec.decision[vi][k][seg][li];
                    if (got < 0)
                        continue;
                    int base = variants[vi].hierarchy ? 1 : 0;
                    int ray = dec.decision[base][k][seg][li];
                    RGB by_ray = dec.colour[base][k][seg][li];
                    const Hit *at = &hits[vi][k][seg];
                    int same_point = ray0 >= 0 && at->kind == at0->kind && at->index == at0->index &&
                                     at->t == at0->t && at->point.x == at0->point.x && at->point.y == at0->point.y &&
                                     at->point.z == at0->point.z;
                    if (!same_point && seg == 0)
                        tot->other_path[vi]++;
                    RGB want = want0;
                    RefAnswer ref = ref0;
                    if (!same_point) {
                        int close, close_povray;
                        ref = judge(&w, at, &w.lights[li], eps, by_ray, &want, &close, &close_povray);
                    }
                    RGB colour = dec.colour[vi][k][seg][li];
                    int sch = dec.scheme[vi][k][seg][li];
                    if (sch >= 0 && sch < SCHEME_COUNT)
                        tot->by_scheme[vi][sch]++;
                    int bad = ref == REF_TIE ? !same_colour(colour, by_ray, 0) : !same_colour(colour, want, 1e-12);
                    tot->not_ray[vi] += !same_colour(colour, by_ray, 0);
                    if (ref == REF_TIE)
                        tot->tie_vs_ray[vi] += bad;
                    else
                        tot->clear_wrong[vi] += bad;
                    if (bad && verbose > 0) {
                        verbose--;
                        char what[320];
                        snprintf(what, sizeof what,
                                 "scene %ld: %s says %s (%g, %g, %g) (%s), reference %s (%g, %g, %g), shadow ray %s "
                                 "(%g, %g, %g)",
                                 tot->scenes, variants[vi].label, got ? "blocked" : "lit", colour.r, colour.g, colour.b,
                                 shadow_scheme_names[dec.scheme[vi][k][seg][li]],
                                 ref == REF_TIE ? "tie" : ref == REF_BLOCKED ? "blocked" : "lit", want.r, want.g,
                                 want.b,
                                 ray ? "blocked" : "lit", by_ray.r, by_ray.g, by_ray.b);
                        explain(&w, &sv, what, hits[0][k], seg, li, k, eps);
                    }
                }
            }
    tot->scenes++;
    shadow_volumes_free(&sv);
    bvh_free(&bvh);
    grid_free(&g);
    world_free(&w);
    fixture_scene_free(s);
}

int main(int argc, char **argv)
{
    unsigned long long seed = 0x9E3779B97F4A7C15ull;
    long scenes = 5000;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--seed") == 0 && i + 1 < argc)
            seed = strtoull(argv[++i], NULL, 0);
        else if (strcmp(argv[i], "--tolerance") == 0 && i + 1 < argc)
            tolerance = strtod(argv[++i], NULL);
        else if (strcmp(argv[i], "--verbose") == 0 && i + 1 < argc)
            verbose = atoi(argv[++i]);
        else if (strcmp(argv[i], "--scenes") == 0 && i + 1 < argc)
            scenes = strtol(argv[++i], NULL, 0);
        else {
            fprintf(stderr, "usage: %s [--seed N] [--scenes N] [--verbose N] [--tolerance R]\n", argv[0]);
            return 2;
        }
    }
    TestRng rng = { seed ? seed : 1 };
    Totals tot;
    memset(&tot, 0, sizeof tot);
    for (long i = 0; i < scenes; i++)
        one_scene(&rng, &tot);
    tap_diag("seed %#llx: %ld scenes (%ld without polygons skipped, %ld with transparent objects), %ld decisions, "
             "%ld ties (%ld blocked, %ld lit by the shadow ray; %ld of them with transparent surfaces close along the "
             "shadow ray), %ld with filtered light",
             seed, tot.scenes, tot.skipped, tot.painted, tot.decisions, tot.ties, tot.tie_blocked, tot.tie_lit,
             tot.close, tot.filtered);
    tap_ok(tot.decisions > 50 * scenes, "enough decisions checked (%ld)", tot.decisions);
    tap_ok(tot.filtered * 20 > tot.decisions, "enough of them through transparent objects only (%ld)", tot.filtered);
    tap_ok(faded * 200 > tot.decisions, "enough of them through a fading interior (%ld)", faded);
    tap_ok(tot.close > 0 && tot.close_povray == tot.close,
           "the shadow ray gives POV-Ray's colour where transparent surfaces lie within 1e-3 of each other along it, "
           "filtering once per group of them (%ld of %ld)",
           tot.close_povray, tot.close);
    for (int vi = 0; vi < NVARIANTS; vi++) {
        tap_ok(tot.clear_wrong[vi] == 0,
               "%s agrees with the long-double reference on every clear case, colours too (%ld wrong of %ld)",
               variants[vi].label, tot.clear_wrong[vi], tot.decisions - tot.ties);
        if (vi > 0) {
            tap_ok(tot.tie_vs_ray[vi] == 0, "%s agrees with the shadow ray on every tie (%ld differ of %ld)",
                   variants[vi].label, tot.tie_vs_ray[vi], tot.ties);
            tap_ok(tot.not_ray[vi] == 0,
                   "%s gives the shadow ray's colour exactly, everywhere (%ld differ of %ld; the shadow ray of the "
                   "same polygon queries)",
                   variants[vi].label, tot.not_ray[vi], tot.decisions);
        }
        if (strcmp(variants[vi].method, "light-buffer") == 0) {
            /* each of the light buffer's ways of deciding must be exercised */
            tap_ok(tot.by_scheme[vi][SCHEME_BUFFER_LIT] > 0 && tot.by_scheme[vi][SCHEME_BUFFER_COVER] > 0 &&
                       tot.by_scheme[vi][SCHEME_BUFFER_LIST] > 0,
                   "%s decided by each of its sub-schemes: %ld empty, %ld cover, %ld list (and %ld by the shadow ray)",
                   variants[vi].label, tot.by_scheme[vi][SCHEME_BUFFER_LIT], tot.by_scheme[vi][SCHEME_BUFFER_COVER],
                   tot.by_scheme[vi][SCHEME_BUFFER_LIST],
                   tot.by_scheme[vi][SCHEME_CONVENTIONAL] + tot.by_scheme[vi][SCHEME_CACHE_HIT]);
        }
        if (tot.other_path[vi])
            tap_diag("%s: %ld decisions at a primary hit other than the grid walk's (polygons meeting within "
                     "rounding), held to the reference at their own point",
                     variants[vi].label, tot.other_path[vi]);
    }
    tap_ok(mask_blocks > 0 && mask_differ == 0, "light buffer: SSE block masks equal the plain ones (%ld differ of %ld)",
           mask_differ, mask_blocks);
    tap_ok(float_passes > 0 && float_not_double == 0,
           "light buffer: every plane the float test passes over, the double bound does too (%ld not, of %ld)",
           float_not_double, float_passes);
    tap_ok(shapes_classified > 0 && shapes_differ == 0,
           "light buffer: SSE shape classes equal the plain ones (%ld differ of %ld)", shapes_differ, shapes_classified);
    tap_ok(shapes_sure > 0 && shapes_not_bound == 0,
           "light buffer: every shape's outside or inside holds in exact arithmetic with its margins (%ld not, of %ld)",
           shapes_not_bound, shapes_sure);
    return tap_done();
}
