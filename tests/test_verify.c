/* --verify-shadows and --verify-reference are the suite's guard of every
 * shadow method, so they are checked here against methods known to be
 * wrong. The planted methods are registered only in this program and run
 * through the render loop exactly as hstrace's own methods do (render_image
 * -> shading -> shadow_decide); each knows what it planted (it asks the
 * shadow ray and the long-double reference itself), and the verification
 * must count exactly that: every planted disagreement, under the scheme the
 * method named, summed over threads, and no other. */
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grid.h"
#include "parser.h"
#include "render.h"
#include "shadow.h"
#include "shadow_reference.h"
#include "shadow_registry.h"
#include "tap.h"
#include "world.h"

/* Opaque boxes and a plane, a transparent card (filtered light) and two
 * lights: decisions of every kind, lit, blocked and filtered. */
static const char scene_text[] =
    "#version 3.7;\n"
    "global_settings { assumed_gamma 1 }\n"
    "camera { location <0, 4, -9> look_at <0, 0.5, 0> }\n"
    "light_source { <4, 8, -3> color rgb 1 }\n"
    "light_source { <-5, 6, -2> color rgb 0.6 }\n"
    "plane { y, 0 pigment { color rgb 0.8 } }\n"
    "box { <-2, 0, -1>, <-0.5, 1.5, 0.5> pigment { color rgb <1, 0.2, 0.2> } }\n"
    "box { <0.5, 0, 0>, <1.5, 2.5, 1> pigment { color rgb <0.2, 0.2, 1> } }\n"
    "polygon { 4, <-1, 1.5, -2>, <1, 1.5, -2>, <1, 3, -2>, <-1, 3, -2>\n"
    "          pigment { color rgbf <0.2, 1, 0.2, 0.7> } }\n"
    "triangle { <2, 0.1, -2>, <3, 0.1, -2>, <2.5, 1.5, -1.5> pigment { color rgb 1 } }\n";

/* What the planted methods did, counted by themselves (any thread). */
static atomic_ulong planted_decisions;     /* every test call */
static atomic_ulong planted_disagreements; /* answers differing from the shadow ray's */
static atomic_ulong planted_ties;          /* the reference could not tell */
static atomic_ulong planted_ref_wrong;     /* the method's verdict against the reference, clear cases */
static atomic_ulong planted_ray_wrong;     /* the shadow ray's verdict against the reference, clear cases */
static unsigned flip_every = 7;

static int same(RGB a, RGB b) { return a.r == b.r && a.g == b.g && a.b == b.b; }
static int blocked_any(RGB a) { return a.r != 1.0 || a.g != 1.0 || a.b != 1.0; }

/* What the verification should count for one decision: the truth from the
 * shadow ray and the reference, asked here directly. */
static void account(ShadowContext *ctx, const ShadowQuery *q, RGB truth, RGB answer)
{
    atomic_fetch_add(&planted_decisions, 1);
    if (!same(truth, answer))
        atomic_fetch_add(&planted_disagreements, 1);
    if (ctx->verify > 1) {
        const World *w = ctx->tracer->world;
        RefAnswer ref = shadow_reference(w, q->surface, &w->lights[q->light], ctx->reference_eps);
        if (ref == REF_TIE) {
            atomic_fetch_add(&planted_ties, 1);
        } else {
            if (blocked_any(answer) != (ref == REF_BLOCKED))
                atomic_fetch_add(&planted_ref_wrong, 1);
            if (blocked_any(truth) != (ref == REF_BLOCKED))
                atomic_fetch_add(&planted_ray_wrong, 1);
        }
    }
}

static RGB truth_of(ShadowContext *ctx, const ShadowQuery *q)
{
    RGB truth;
    shadow_conventional_test(ctx, q, &truth);
    return truth;
}

/* Light arrives everywhere, unfiltered; the method says it counted volumes. */
static void always_lit_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    RGB truth = truth_of(ctx, q);
    light->r = light->g = light->b = 1.0;
    ctx->last_scheme = SCHEME_VOLUME;
    account(ctx, q, truth, *light);
}

/* The shadow ray's answer, but every Nth call of a thread the opposite:
 * fully lit where light was taken, blocked where all of it arrived. */
static _Thread_local unsigned calls;
static void flipping_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    RGB truth = truth_of(ctx, q);
    *light = truth;
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    if (++calls % flip_every == 0) {
        double v = blocked_any(truth) ? 1.0 : 0.0;
        light->r = light->g = light->b = v;
        ctx->last_scheme = SCHEME_SUSTAIN;
    }
    account(ctx, q, truth, *light);
}

/* The exact answer: nothing may be counted. */
static void honest_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    RGB truth = truth_of(ctx, q);
    *light = truth;
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    account(ctx, q, truth, *light);
}

static const ShadowMethod always_lit = { .name = "always-lit", .summary = "planted: no shadows, claims volumes",
                                         .test = always_lit_test };
static const ShadowMethod flipping = { .name = "flipping", .summary = "planted: every Nth decision inverted",
                                       .test = flipping_test };
static const ShadowMethod honest = { .name = "honest", .summary = "the shadow ray, through a planted method",
                                     .test = honest_test };

typedef struct {
    Scene *scene;
    World world;
    Grid grid;
} Fixture;

static int fixture_build(Fixture *f)
{
    ParseOptions po = { .image_width = 96, .image_height = 72 };
    ParseError err;
    Scene *s = f->scene = parse_scene_string("verify.pov", scene_text, &po, &err);
    if (!s) {
        tap_diag("%s:%d:%d: %s", err.file, err.line, err.column, err.message);
        return -1;
    }
    WorldError we;
    if (world_build(&f->world, s, &we)) {
        scene_free(s);
        return -1;
    }
    Vec3 extra[64];
    int nextra = grid_extra_points(&f->world, extra, 64);
    if (grid_build(&f->grid, &f->world, NULL, extra, nextra)) {
        world_free(&f->world);
        scene_free(s);
        return -1;
    }
    grid_set_tolerance(&f->grid, GRID_TOLERANCE);
    return 0;
}

static void reset_planted(void)
{
    atomic_store(&planted_decisions, 0);
    atomic_store(&planted_disagreements, 0);
    atomic_store(&planted_ties, 0);
    atomic_store(&planted_ref_wrong, 0);
    atomic_store(&planted_ray_wrong, 0);
}

static int render_with(const Fixture *f, const ShadowMethod *m, int verify, int threads, RenderStats *stats)
{
    RenderOptions ro;
    memset(&ro, 0, sizeof ro);
    ro.width = 96;
    ro.height = 72;
    ro.threads = threads;
    ro.quality = (Quality){ 1, 1, 1, 0, 0, 1, 1 }; /* +Q8: shadows, reflection, refraction, normals, area lights */
    ro.verify = verify;
    ShadowSetup setup = { .world = &f->world, .grid = (Grid *)&f->grid, .width = 96, .height = 72,
                          .threads = threads, .shadows_on = 1, .nth = { NTH_FIXED, 0.0 } };
    ShadowPrepared prepared;
    char err[256];
    if (shadow_method_prepare(m, &setup, &prepared, err, (int)sizeof err)) {
        shadow_prepared_free(&prepared);
        return -1;
    }
    ro.shadows = &prepared;
    Image img;
    reset_planted();
    int failed = render_image(&f->world, &f->grid, &ro, &img, stats);
    shadow_prepared_free(&prepared);
    if (failed)
        return -1;
    image_free(&img);
    return 0;
}

static void check_method(const Fixture *f, const ShadowMethod *m, int scheme, int verify, int threads)
{
    RenderStats s;
    const char *flag = verify > 1 ? "--verify-reference" : "--verify-shadows";
    if (render_with(f, m, verify, threads, &s)) {
        tap_ok(0, "%s: %s renders", m->name, flag);
        return;
    }
    const ShadowCounters *c = &s.shadow;
    unsigned long decisions = atomic_load(&planted_decisions), wrong = atomic_load(&planted_disagreements);
    tap_ok(c->shadow_verified == decisions && decisions > 0,
           "%s, %d thread(s): %s checks every decision (%llu verified, %lu made)", m->name, threads, flag,
           (unsigned long long)c->shadow_verified, decisions);
    tap_ok(c->shadow_disagreements == wrong,
           "%s, %d thread(s): %s counts exactly the planted disagreements (%llu counted, %lu planted)", m->name,
           threads, flag, (unsigned long long)c->shadow_disagreements, wrong);
    uint64_t elsewhere = 0;
    for (int i = 0; i < SCHEME_COUNT; i++)
        if (i != scheme)
            elsewhere += c->shadow_disagreements_by_scheme[i];
    tap_ok(c->shadow_disagreements_by_scheme[scheme] == wrong && elsewhere == 0,
           "%s: disagreements are put under the scheme the method named (%s: %llu, others %llu)", m->name,
           shadow_scheme_names[scheme], (unsigned long long)c->shadow_disagreements_by_scheme[scheme],
           (unsigned long long)elsewhere);
    if (verify > 1) {
        tap_ok(c->reference_ties == atomic_load(&planted_ties) && c->reference_wrong == atomic_load(&planted_ref_wrong) &&
                   c->reference_ray_wrong == atomic_load(&planted_ray_wrong),
               "%s: --verify-reference counts ties %llu (planted %lu), method wrong %llu (%lu), shadow ray wrong "
               "%llu (%lu)",
               m->name, (unsigned long long)c->reference_ties, atomic_load(&planted_ties),
               (unsigned long long)c->reference_wrong, atomic_load(&planted_ref_wrong),
               (unsigned long long)c->reference_ray_wrong, atomic_load(&planted_ray_wrong));
    } else {
        tap_ok(c->reference_ties == 0 && c->reference_wrong == 0 && c->reference_ray_wrong == 0,
               "%s: --verify-shadows alone asks nothing of the reference", m->name);
    }
}

int main(void)
{
    Fixture f;
    if (fixture_build(&f)) {
        tap_ok(0, "the test scene builds");
        return tap_done();
    }

    /* The plants must plant something, or the checks below prove nothing. */
    RenderStats s;
    render_with(&f, &always_lit, 1, 1, &s);
    unsigned long lit_wrong = atomic_load(&planted_disagreements);
    render_with(&f, &flipping, 1, 1, &s);
    unsigned long flipped = atomic_load(&planted_disagreements);
    tap_ok(lit_wrong > 100 && flipped > 100,
           "the planted methods are wrong often (always-lit: %lu wrong decisions, every %uth flipped: %lu)", lit_wrong,
           flip_every, flipped);

    for (int threads = 1; threads <= 2; threads++) {
        check_method(&f, &always_lit, SCHEME_VOLUME, 1, threads);
        check_method(&f, &flipping, SCHEME_SUSTAIN, 1, threads);
    }
    check_method(&f, &always_lit, SCHEME_VOLUME, 2, 2);
    check_method(&f, &flipping, SCHEME_SUSTAIN, 2, 1);
    check_method(&f, &honest, SCHEME_CONVENTIONAL, 2, 2);

    /* Without verification nothing is checked or counted. */
    render_with(&f, &flipping, 0, 2, &s);
    tap_ok(s.shadow.shadow_verified == 0 && s.shadow.shadow_disagreements == 0,
           "without --verify-shadows nothing is verified (%llu) or counted (%llu)",
           (unsigned long long)s.shadow.shadow_verified, (unsigned long long)s.shadow.shadow_disagreements);

    grid_free(&f.grid);
    world_free(&f.world);
    scene_free(f.scene);
    return tap_done();
}
