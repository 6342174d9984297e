/* The analysis channels (--aov), read back with the OpenEXR library's C
 * API, not with hstrace's own reader:
 *   - a scene built for values computable by hand: a quad at z = 5 facing a
 *     camera at the origin, lit by L1 from behind the camera, with an opaque
 *     occluder behind the camera shadowing the right half and a half-
 *     transmitting one filtering the bottom half; L2 lies behind the quad
 *     (the quad faces away from it); the top rows see the background.
 *     Every channel's name, type and value is checked, for every method.
 *   - every channel is the same for 1 and 2 threads (desk, hst and cache;
 *     N_th fixed, since --nth auto calibrates it by timing each run).
 *   - on the regression scenes, shadow.L<i> agrees with the +Q3/+Q4 mask
 *     method: a pixel whose lights are all unblocked renders the same with
 *     and without shadows, and every pixel the two renders tell apart has a
 *     blocked light; shadow.loss equals +Q3 minus +Q4.
 * Runs $top_builddir/hstrace; scenes from $top_srcdir. */
#include <math.h>
#include <openexr.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "tap.h"

#define SIZE 32

static char work[256];
static const char *builddir, *srcdir;

static int run(const char *args)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "'%s/hstrace' %s 2>'%s/err'", builddir, args, work);
    int rc = system(cmd);
    if (rc != 0) {
        char path[512], line[512];
        snprintf(path, sizeof path, "%s/err", work);
        FILE *f = fopen(path, "r");
        while (f && fgets(line, sizeof line, f))
            tap_diag("%s", line);
        if (f)
            fclose(f);
    }
    return rc;
}

/* Every channel of a scanline EXR as float planes (uint converted). */
typedef struct {
    int w, h, n;
    char name[64][32];
    exr_pixel_type_t type[64];
    float *plane[64];
} Channels;

static void channels_free(Channels *c)
{
    for (int k = 0; k < c->n; k++)
        free(c->plane[k]);
    c->n = 0;
}

static int channels_read(const char *path, Channels *c)
{
    exr_context_t ctx;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    const exr_attr_chlist_t *cl;
    exr_attr_box2i_t dw;
    int lines;
    memset(c, 0, sizeof *c);
    if (exr_start_read(&ctx, path, &init) != EXR_ERR_SUCCESS)
        return -1;
    int ok = exr_get_channels(ctx, 0, &cl) == EXR_ERR_SUCCESS && exr_get_data_window(ctx, 0, &dw) == EXR_ERR_SUCCESS &&
             exr_get_scanlines_per_chunk(ctx, 0, &lines) == EXR_ERR_SUCCESS && cl->num_channels <= 64;
    if (ok) {
        c->w = dw.max.x - dw.min.x + 1;
        c->h = dw.max.y - dw.min.y + 1;
        c->n = cl->num_channels;
        for (int k = 0; k < c->n; k++) {
            snprintf(c->name[k], sizeof c->name[k], "%s", cl->entries[k].name.str);
            c->type[k] = cl->entries[k].pixel_type;
            c->plane[k] = calloc((size_t)c->w * c->h, sizeof(float));
            ok = ok && c->plane[k];
        }
    }
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    int started = 0;
    for (int y = 0; ok && y < c->h; y += lines) {
        exr_chunk_info_t ci;
        ok = exr_read_scanline_chunk_info(ctx, 0, y + dw.min.y, &ci) == EXR_ERR_SUCCESS &&
             (started ? exr_decoding_update(ctx, 0, &ci, &dec) : exr_decoding_initialize(ctx, 0, &ci, &dec)) ==
                 EXR_ERR_SUCCESS;
        started |= ok;
        for (int k = 0; ok && k < dec.channel_count; k++) {
            exr_coding_channel_info_t *ch = &dec.channels[k];
            int j = 0;
            while (strcmp(c->name[j], ch->channel_name) != 0)
                j++;
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
            ch->user_pixel_stride = 4;
            ch->user_line_stride = 4 * c->w;
            ch->decode_to_ptr = (uint8_t *)(c->plane[j] + (size_t)(ci.start_y - dw.min.y) * c->w);
        }
        ok = ok && exr_decoding_choose_default_routines(ctx, 0, &dec) == EXR_ERR_SUCCESS &&
             exr_decoding_run(ctx, 0, &dec) == EXR_ERR_SUCCESS;
    }
    if (started)
        exr_decoding_destroy(ctx, &dec);
    exr_finish(&ctx);
    if (!ok)
        channels_free(c);
    return ok ? 0 : -1;
}

static int find(const Channels *c, const char *name)
{
    for (int k = 0; k < c->n; k++)
        if (strcmp(c->name[k], name) == 0)
            return k;
    return -1;
}

static float at(const Channels *c, const char *name, int x, int y)
{
    int k = find(c, name);
    return k < 0 ? NAN : c->plane[k][(size_t)y * c->w + x];
}

/* ---- the scene computed by hand ------------------------------------------ */

static const char scene_text[] =
    "#version 3.7;\n"
    "global_settings { assumed_gamma 1 }\n" /* linear: the values below are light */
    "camera { location <0,0,0> direction <0,0,1> up <0,1,0> right <1,0,0> }\n"
    "light_source { <0,0,-10> color rgb 1 }\n"   /* L1, behind the camera */
    "light_source { <0,0,20> color rgb 1 }\n"    /* L2, behind the quad */
    "background { color rgb <0,0,0> }\n"
    /* the quad, z = 5, up to y = 1.5: rows 0..5 see the background */
    "polygon { 5, <-10,-10,5>, <10,-10,5>, <10,1.5,5>, <-10,1.5,5>, <-10,-10,5>\n"
    "  pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }\n"
    /* opaque, behind the camera: from L1 its shadow covers x > 0 on the quad */
    "polygon { 5, <0,-1,-5>, <1,-1,-5>, <1,1,-5>, <0,1,-5>, <0,-1,-5> pigment { color rgb 1 } }\n"
    /* half-transmitting: its shadow covers y < 0 on the quad */
    "polygon { 5, <-2,-2,-4>, <2,-2,-4>, <2,0,-4>, <-2,0,-4>, <-2,-2,-4>\n"
    "  pigment { color rgb 1 transmit 0.5 } }\n";

/* POV-Ray's pixel centres (camera.c's camera_ray, written out again):
 * x0 = (x + 0.5)/w - 0.5, y0 = ((h - 1) - (y - 0.5))/h - 0.5. */
static void screen(int x, int y, double *x0, double *y0)
{
    *x0 = (x + 0.5) / SIZE - 0.5;
    *y0 = ((SIZE - 1) - (y - 0.5)) / SIZE - 0.5;
}

static int near_rel(double got, double want, double rel)
{
    return fabs(got - want) <= rel * fmax(1.0, fabs(want));
}

typedef struct {
    const char *name;
    int has_states; /* depth counts where the shadow ray alone does not know them */
} Method;

static void check_known_scene(const Method *m, int exr_float)
{
    char scene[512], out[512], args[1400];
    snprintf(scene, sizeof scene, "%s/known.pov", work);
    snprintf(out, sizeof out, "%s/known-%s.exr", work, m->name);
    /* Every light's volumes built: the codes checked are those of counting. */
    snprintf(args, sizeof args, "'%s' --width %d --height %d --shadows %s --volumes always --aov all%s -o '%s'",
             scene, SIZE, SIZE,
             m->name, exr_float ? " --exr-float" : "", out);
    tap_ok(run(args) == 0, "%s: hstrace renders the known scene with --aov all", m->name);
    Channels c;
    if (channels_read(out, &c)) {
        tap_ok(0, "%s: the EXR reads back with OpenEXR", m->name);
        return;
    }

    /* Names and types. */
    static const struct {
        const char *name;
        int type; /* -1: the colour type */
    } want[] = {
        {"A", -1}, {"B", -1}, {"G", -1}, {"R", -1}, {"Z", EXR_PIXEL_FLOAT},
        {"N.X", EXR_PIXEL_FLOAT}, {"N.Y", EXR_PIXEL_FLOAT}, {"N.Z", EXR_PIXEL_FLOAT},
        {"P.X", EXR_PIXEL_FLOAT}, {"P.Y", EXR_PIXEL_FLOAT}, {"P.Z", EXR_PIXEL_FLOAT},
        {"shadow.L1", -1}, {"shadow.L2", -1}, {"shadow.loss.R", -1}, {"shadow.loss.G", -1}, {"shadow.loss.B", -1},
        {"hst.L1", EXR_PIXEL_UINT}, {"hst.L2", EXR_PIXEL_UINT},
        {"depth.L1", EXR_PIXEL_FLOAT}, {"depth.L2", EXR_PIXEL_FLOAT},
        {"cost.shadow", EXR_PIXEL_UINT}, {"cost.rays", EXR_PIXEL_UINT},
    };
    int nwant = (int)(sizeof want / sizeof want[0]), types_ok = c.n == nwant;
    for (int k = 0; k < nwant; k++) {
        int j = find(&c, want[k].name);
        int t = want[k].type < 0 ? (exr_float ? EXR_PIXEL_FLOAT : EXR_PIXEL_HALF) : want[k].type;
        if (j < 0 || (int)c.type[j] != t) {
            tap_diag("channel %s: %s", want[k].name, j < 0 ? "missing" : "wrong type");
            types_ok = 0;
        }
    }
    tap_ok(types_ok, "%s%s: exactly the %d channels expected, with their types", m->name,
           exr_float ? " --exr-float" : "", nwant);

    /* Values, pixel by pixel. */
    int bad[12] = {0};
    const char *what[12] = {"Z", "N", "P", "shadow.L1", "shadow.L2", "hst.L1", "hst.L2", "depth.L1", "shadow.loss",
                            "cost.rays", "cost.shadow", "R G B"};
    double tol = exr_float ? 1e-6 : 1e-3; /* half: 11 bits */
    for (int y = 0; y < SIZE; y++)
        for (int x = 0; x < SIZE; x++) {
            double x0, y0;
            screen(x, y, &x0, &y0);
            int hit = 5.0 * y0 < 1.5;
            int blocked = x0 > 0.0, filtered = y0 < 0.0;
            double z = 5.0 * sqrt(x0 * x0 + y0 * y0 + 1.0);
            /* L1 at (0,0,-10): diffuse 1, white: the cosine at P. */
            double px = 5 * x0, py = 5 * y0;
            double cosine = 15.0 / sqrt(px * px + py * py + 225.0);
            double vis = blocked ? 0.0 : filtered ? 0.5 : 1.0;
            if (!hit) {
                bad[0] += !isinf(at(&c, "Z", x, y)) || at(&c, "Z", x, y) < 0;
                bad[1] += at(&c, "N.X", x, y) != 0 || at(&c, "N.Y", x, y) != 0 || at(&c, "N.Z", x, y) != 0;
                bad[2] += at(&c, "P.X", x, y) != 0 || at(&c, "P.Y", x, y) != 0 || at(&c, "P.Z", x, y) != 0;
                bad[3] += at(&c, "shadow.L1", x, y) != 0;
                bad[4] += at(&c, "shadow.L2", x, y) != 0;
                bad[5] += at(&c, "hst.L1", x, y) != 0;
                bad[6] += at(&c, "hst.L2", x, y) != 0;
                bad[7] += at(&c, "depth.L1", x, y) != -1;
                bad[8] += at(&c, "shadow.loss.R", x, y) != 0;
                bad[9] += at(&c, "cost.rays", x, y) != 1;
                bad[10] += at(&c, "cost.shadow", x, y) != 0;
                continue;
            }
            bad[0] += !near_rel(at(&c, "Z", x, y), z, 1e-6);
            bad[1] += at(&c, "N.X", x, y) != 0 || at(&c, "N.Y", x, y) != 0 || at(&c, "N.Z", x, y) != -1;
            bad[2] += !near_rel(at(&c, "P.X", x, y), px, 1e-6) || !near_rel(at(&c, "P.Y", x, y), py, 1e-6) ||
                      !near_rel(at(&c, "P.Z", x, y), 5.0, 1e-6);
            bad[3] += at(&c, "shadow.L1", x, y) != vis;
            bad[4] += at(&c, "shadow.L2", x, y) != 0; /* the quad faces away from L2 */
            unsigned code1 = (unsigned)at(&c, "hst.L1", x, y), code2 = (unsigned)at(&c, "hst.L2", x, y);
            if (strcmp(m->name, "conventional") == 0)
                bad[5] += code1 != 4;
            else if (strcmp(m->name, "cache") == 0)
                bad[5] += code1 != 4 && !(code1 == 5 && blocked);
            else if (strcmp(m->name, "volume") == 0)
                bad[5] += code1 != 3 && code1 != 4;
            else if (strcmp(m->name, "light-buffer") == 0)
                bad[5] += code1 != 5 && (code1 < 11 || code1 > 13); /* the cache's hit, or a cell's */
            else /* sustain, volume, or a decision as the shadow ray's: its own, the cache's or a light buffer's */
                bad[5] += code1 < 1 || code1 == 2 || (code1 > 5 && code1 < 11) || code1 > 13;
            /* Facing away: hst decides (sustain or self-shadow), volume keeps
             * its count (volume) or defers (6), the others do not ask (6). */
            if (strcmp(m->name, "hst") == 0)
                bad[6] += code2 != 1 && code2 != 2;
            else if (strcmp(m->name, "volume") == 0)
                bad[6] += code2 != 3 && code2 != 6;
            else
                bad[6] += code2 != 6;
            /* The opaque occluder is the only one counted; the shadow ray
             * knows the count only where light got through (0). */
            float d = at(&c, "depth.L1", x, y);
            int by_ray = code1 == 4 || code1 == 5 || (code1 >= 11 && code1 <= 13);
            if (m->has_states)
                bad[7] += !(d == (blocked ? 1 : 0) || (d == -1 && by_ray));
            else
                bad[7] += d != (blocked ? -1 : 0);
            double loss = (1.0 - vis) * cosine;
            bad[8] += !near_rel(at(&c, "shadow.loss.R", x, y), loss, tol) ||
                      !near_rel(at(&c, "shadow.loss.G", x, y), loss, tol) ||
                      !near_rel(at(&c, "shadow.loss.B", x, y), loss, tol);
            /* The camera ray, and L1's shadow ray wherever one is fired. */
            unsigned rays = (unsigned)at(&c, "cost.rays", x, y);
            if (strcmp(m->name, "conventional") == 0)
                bad[9] += rays != 2;
            else
                bad[9] += rays != 1 && rays != 2;
            /* A shadow ray that met an occluder tested it (one that met
             * nothing may have tested nothing: the hierarchy culls). */
            bad[10] += code1 == 4 && (blocked || filtered) && at(&c, "cost.shadow", x, y) == 0;
            double lit = vis * cosine;
            bad[11] += !near_rel(at(&c, "R", x, y), lit, tol) || !near_rel(at(&c, "G", x, y), lit, tol) ||
                       !near_rel(at(&c, "B", x, y), lit, tol);
        }
    for (int k = 0; k < 12; k++)
        tap_ok(bad[k] == 0, "%s%s: %s as computed by hand (%d of %d pixels off)", m->name,
               exr_float ? " --exr-float" : "", what[k], bad[k], SIZE * SIZE);
    channels_free(&c);
}

/* ---- the same for any thread count ----------------------------------------- */

static void check_threads(const char *method)
{
    char args[1200], a[512], b[512];
    snprintf(a, sizeof a, "%s/t1-%s.exr", work, method);
    snprintf(b, sizeof b, "%s/t2-%s.exr", work, method);
    snprintf(args, sizeof args,
             "'%s/scenes/desk.pov' --width 96 --height 72 --shadows %s --volumes always --nth 40 --aov all "
             "--threads 1 -o '%s'",
             srcdir, method, a);
    int ok = run(args) == 0;
    snprintf(args, sizeof args,
             "'%s/scenes/desk.pov' --width 96 --height 72 --shadows %s --volumes always --nth 40 --aov all "
             "--threads 2 -o '%s'",
             srcdir, method, b);
    ok = ok && run(args) == 0;
    Channels c1, c2;
    ok = ok && channels_read(a, &c1) == 0;
    ok = ok && channels_read(b, &c2) == 0;
    int same = ok && c1.n == c2.n && c1.w == c2.w && c1.h == c2.h, differing = 0;
    for (int k = 0; same && k < c1.n; k++)
        if (memcmp(c1.plane[k], c2.plane[k], sizeof(float) * (size_t)c1.w * c1.h) != 0) {
            tap_diag("%s differs", c1.name[k]);
            differing++;
        }
    tap_ok(same && differing == 0, "desk, %s: all %d channels identical with 1 and 2 threads", method, c1.n);
    if (ok) {
        channels_free(&c1);
        channels_free(&c2);
    }
}

/* ---- shadow.L<i> against the +Q3/+Q4 mask method ----------------------------- */

#define MASK_EPSILON 2e-3 /* src/tools/mask_compare.c's threshold of a mask pixel */

static void check_masks(const char *name)
{
    char args[1200], q3[512], q4[512], aov[512];
    snprintf(q3, sizeof q3, "%s/%s.q3.exr", work, name);
    snprintf(q4, sizeof q4, "%s/%s.q4.exr", work, name);
    snprintf(aov, sizeof aov, "%s/%s.aov.exr", work, name);
    const char *outs[3] = {q3, q4, aov}, *opts[3] = {"+Q3", "+Q4", "--aov shadow,hst --exr-float"};
    int ok = 1;
    for (int k = 0; k < 3 && ok; k++) {
        snprintf(args, sizeof args, "'%s/scenes/%s.pov' --width 160 --height 120 %s -o '%s'", srcdir, name, opts[k],
                 outs[k]);
        ok = run(args) == 0;
    }
    Channels a, b, c;
    ok = ok && channels_read(q3, &a) == 0;
    ok = ok && channels_read(q4, &b) == 0;
    ok = ok && channels_read(aov, &c) == 0;
    if (!ok) {
        tap_ok(0, "%s: renders for the mask check", name);
        return;
    }
    int nlights = 0;
    char ch[32];
    for (;; nlights++) {
        snprintf(ch, sizeof ch, "shadow.L%d", nlights + 1);
        if (find(&c, ch) < 0)
            break;
    }
    long unblocked_changed = 0, mask_unexplained = 0, loss_off = 0, mask = 0, blocked_only = 0;
    for (int y = 0; y < c.h; y++)
        for (int x = 0; x < c.w; x++) {
            int any_blocked = 0;
            for (int l = 1; l <= nlights; l++) {
                snprintf(ch, sizeof ch, "hst.L%d", l);
                unsigned code = (unsigned)at(&c, ch, x, y);
                snprintf(ch, sizeof ch, "shadow.L%d", l);
                /* decided by a method: 1 to 5, or a light buffer's cell (11 to 13) */
                any_blocked |= ((code >= 1 && code <= 5) || (code >= 11 && code <= 13)) && at(&c, ch, x, y) < 1.0f;
            }
            int changed = 0, is_mask = 0;
            static const char *const rgb[3] = {"R", "G", "B"}, *const lrgb[3] = {"shadow.loss.R", "shadow.loss.G",
                                                                                    "shadow.loss.B"};
            for (int k = 0; k < 3; k++) {
                double d = (double)at(&a, rgb[k], x, y) - at(&b, rgb[k], x, y);
                changed |= d != 0.0;
                is_mask |= fabs(d) > MASK_EPSILON;
                /* q3 and q4 are half: each off by up to half a step. */
                double step = ldexp(fmax(fabs(at(&a, rgb[k], x, y)), 1e-3), -11);
                loss_off += fabs(at(&c, lrgb[k], x, y) - d) > 2 * step + 1e-6;
            }
            mask += is_mask;
            unblocked_changed += !any_blocked && changed;
            mask_unexplained += is_mask && !any_blocked;
            blocked_only += any_blocked && !is_mask;
        }
    tap_ok(unblocked_changed == 0, "%s: where shadow.L<i> blocks no light, +Q3 and +Q4 are identical (%ld pixels not)",
           name, unblocked_changed);
    tap_ok(mask > 0 && mask_unexplained == 0,
           "%s: every pixel of the +Q3/+Q4 mask (%ld) has a light shadow.L<i> says is blocked (%ld not)", name, mask,
           mask_unexplained);
    tap_ok(loss_off == 0, "%s: shadow.loss equals +Q3 minus +Q4 (%ld samples off)", name, loss_off);
    tap_diag("%s: %d lights; %ld pixels with a blocked light below the mask's threshold (dim or grazing light)", name,
             nlights, blocked_only);
    channels_free(&a);
    channels_free(&b);
    channels_free(&c);
}

int main(void)
{
    builddir = getenv("top_builddir") ? getenv("top_builddir") : ".";
    srcdir = getenv("top_srcdir") ? getenv("top_srcdir") : ".";
    snprintf(work, sizeof work, "%s/hstaov.XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    if (!mkdtemp(work)) {
        printf("Bail out! cannot make a temporary folder\n");
        return 1;
    }
    char path[512];
    snprintf(path, sizeof path, "%s/known.pov", work);
    FILE *f = fopen(path, "w");
    if (!f || fputs(scene_text, f) < 0 || fclose(f) != 0) {
        printf("Bail out! cannot write %s\n", path);
        return 1;
    }
    static const Method methods[] = {{"conventional", 0}, {"cache", 0}, {"volume", 1}, {"hst", 1}, {"light-buffer", 0}};
    for (int k = 0; k < 5; k++)
        check_known_scene(&methods[k], 0);
    check_known_scene(&methods[3], 1);

    check_threads("hst");
    check_threads("cache");
    check_threads("light-buffer");

    static const char *const scenes[] = {"desk", "glasses", "stars", "cards", "holes", "mesh2"};
    for (int k = 0; k < 6; k++)
        check_masks(scenes[k]);

    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", work);
    if (system(cmd) != 0)
        tap_diag("could not remove %s", work);
    return tap_done();
}
