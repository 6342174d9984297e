/* --shadows every-point-lit: a method for the tests, not for users (the
 * registry hides it from --help and the list of methods). It claims that
 * every light reaches every point, as `none` does, but through every door a
 * method has: its own per-thread state (made by thread_init, freed by
 * thread_free), the pixel and segment hooks, and its own decisions counted
 * in that state. The suite renders it through the real render loop and
 * holds its image to `none`'s and its disagreements, under
 * --verify-shadows, to the shadow ray's blocked decisions: adding a method
 * is this file and one row of the registry. */
#include "shadow.h"

#include <stdlib.h>

/* The thread's own record: its hooks' calls must pair up. */
typedef struct {
    long pixels_open, segments_open;
    long decisions;
} EveryLitState;

/* The state hangs from the context's slot for a method's own data. */
static EveryLitState *state_of(ShadowContext *ctx)
{
    return ctx->method_state;
}

static int every_lit_thread_init(ShadowContext *ctx, const ShadowPrepared *p, int pixel_coherence)
{
    (void)p;
    (void)pixel_coherence;
    ctx->method_state = calloc(1, sizeof(EveryLitState));
    return ctx->method_state ? 0 : -1;
}

static void every_lit_thread_free(ShadowContext *ctx)
{
    free(ctx->method_state);
    ctx->method_state = NULL;
}

static void every_lit_pixel_begin(ShadowContext *ctx, int first_in_row, int first_row)
{
    (void)first_in_row;
    (void)first_row;
    state_of(ctx)->pixels_open++;
}

static void every_lit_pixel_end(ShadowContext *ctx, int first_in_row)
{
    (void)first_in_row;
    state_of(ctx)->pixels_open--;
}

static LightState *every_lit_segment_begin(ShadowContext *ctx, const Hit *hit, int from_eye)
{
    (void)hit;
    (void)from_eye;
    state_of(ctx)->segments_open++;
    return NULL; /* no states along the ray tree */
}

static void every_lit_segment_end(ShadowContext *ctx)
{
    state_of(ctx)->segments_open--;
}

static void every_lit_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    (void)q;
    /* A hook out of step would be a bug of the render loop's doors: then
     * the answer is wrong on purpose (black), and the image shows it. */
    EveryLitState *s = state_of(ctx);
    int in_step = s->segments_open > 0 && s->pixels_open >= 0 && s->pixels_open <= 1;
    s->decisions++;
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    light->r = light->g = light->b = in_step ? 1.0 : 0.0;
}

const ShadowMethod shadow_every_lit_method = {
    .name = "every-point-lit",
    .summary = "for the tests: every light reaches every point, through every door a method has",
    .thread_init = every_lit_thread_init,
    .thread_free = every_lit_thread_free,
    .pixel_begin = every_lit_pixel_begin,
    .pixel_end = every_lit_pixel_end,
    .segment_begin = every_lit_segment_begin,
    .segment_end = every_lit_segment_end,
    .test = every_lit_test,
    .hidden = 1,
    .instances = 1,
};
