/* The colour module's C interface (colour.h), in TAP: the shipped config's
 * sRGB view against the sRGB formula, its Raw view, the working space's
 * chromaticities and the EXR attribute made of them, a test config with
 * another view, $OCIO, the errors of missing and broken configs and of
 * unknown names, and the display transform from several threads at once.
 * Built without OpenColorIO, it checks the stub's message instead.
 *
 * Environment: top_srcdir (default .), for data/ocio/config.ocio and
 * tests/ocio/. */
#include <math.h>
#include <openexr.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "colour.h"
#include "image.h"
#include "image_codec.h"
#include "tap.h"

static char shipped[4096], gamma22[4096], broken_yaml[4096], missing_space[4096];

static void paths(void)
{
    const char *top = getenv("top_srcdir");
    if (top == NULL || top[0] == '\0')
        top = ".";
    snprintf(shipped, sizeof shipped, "%s/data/ocio/config.ocio", top);
    snprintf(gamma22, sizeof gamma22, "%s/tests/ocio/gamma22.ocio", top);
    snprintf(broken_yaml, sizeof broken_yaml, "%s/tests/ocio/broken-yaml.ocio", top);
    snprintf(missing_space, sizeof missing_space, "%s/tests/ocio/missing-space.ocio", top);
}

static double srgb_formula(double x)
{
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1 / 2.4) - 0.055;
}

static ColourDisplay *open_or_null(const char *config, const char *display, const char *view, ColourStatus *st,
                                   char *err, int errlen)
{
    ColourRequest req = { config, display, view, NULL };
    ColourDisplay *d = NULL;
    *st = colour_display_open(&req, &d, err, errlen);
    return d;
}

static void test_requested(void)
{
    ColourRequest none = { NULL, NULL, NULL, NULL }, view = { NULL, NULL, "Raw", NULL };
    unsetenv("OCIO");
    tap_ok(!colour_requested(&none), "no option and no $OCIO: POV-Ray's encoding, not OCIO");
    tap_ok(colour_requested(&view), "--view alone asks for OCIO");
    setenv("OCIO", "", 1);
    tap_ok(!colour_requested(&none), "an empty $OCIO counts as unset");
    setenv("OCIO", gamma22, 1);
    tap_ok(colour_requested(&none), "a non-empty $OCIO asks for OCIO");
    unsetenv("OCIO");
    {
        const float *c = colour_rec709_chromaticities;
        tap_ok(c[0] == 0.64f && c[1] == 0.33f && c[2] == 0.30f && c[3] == 0.60f && c[4] == 0.15f && c[5] == 0.06f &&
                   c[6] == 0.3127f && c[7] == 0.3290f,
               "Rec.709 primaries and D65 white for the built-in working space");
    }
}

static void test_without_ocio(void)
{
    char err[512];
    ColourStatus st;
    ColourDisplay *d = open_or_null(shipped, NULL, NULL, &st, err, sizeof err);
    tap_ok(d == NULL && st == COLOUR_ERR_UNAVAILABLE, "without OpenColorIO: opening a config is refused");
    tap_ok(strstr(err, "hstrace was built without OpenColorIO (configure --without-ocio)") != NULL,
           "and the message says why (%s)", err);
}

static void test_shipped(void)
{
    char err[512], buf[4096];
    ColourStatus st;
    ColourDisplay *d = open_or_null(shipped, NULL, NULL, &st, err, sizeof err);

    tap_ok(d != NULL && st == COLOUR_OK, "shipped config opens (%s)", d ? shipped : err);
    if (d == NULL)
        return;
    tap_ok(strcmp(colour_display_name(d), "sRGB") == 0 && strcmp(colour_display_view(d), "Standard") == 0 &&
               strcmp(colour_display_working_space(d), "Linear Rec.709") == 0,
           "defaults: display sRGB, view Standard, working space Linear Rec.709 (the scene_linear role)");

    /* The sRGB view against the formula: a fine ramp over 0..1 and past it. */
    {
        enum { N = 4097 };
        static float rgb[3 * N];
        double worst = 0;
        int worst_code = 0;
        for (int i = 0; i < N; i++)
            for (int c = 0; c < 3; c++)
                rgb[3 * i + c] = (float)i / (N - 1) * (c == 2 ? 1.25f : 1.0f);
        tap_ok(colour_display_apply(d, rgb, N, err, sizeof err) == 0, "sRGB view applies (%s)", err);
        for (int i = 0; i < N; i++)
            for (int c = 0; c < 3; c++) {
                double x = (double)i / (N - 1) * (c == 2 ? 1.25 : 1.0);
                double want = srgb_formula(x);
                double dv = fabs(rgb[3 * i + c] - want);
                int dc = abs((int)image_quantize(rgb[3 * i + c], 255) - (int)image_quantize((float)want, 255));
                if (dv > worst)
                    worst = dv;
                if (dc > worst_code)
                    worst_code = dc;
            }
        tap_ok(worst < 1.0 / 255, "sRGB view follows the sRGB formula within 1/255 (largest difference %.2g)",
               worst);
        tap_ok(worst_code <= 1, "sRGB view's 8-bit codes within one step of the formula's (largest %d)", worst_code);
    }
    {
        /* Known values: 0.18 -> 118, 0.5 -> 188, 1 -> 255, the knee. */
        float v[12] = { 0.18f, 0.5f, 1.0f, 0.0031308f, 0.0f, 0.001f, 0, 0, 0, 0, 0, 0 };
        colour_display_apply(d, v, 4, err, sizeof err);
        tap_ok(image_quantize(v[0], 255) == 118 && image_quantize(v[1], 255) == 188 &&
                   image_quantize(v[2], 255) == 255 && fabs(v[3] - 0.04045) < 1e-4 && v[4] == 0.0f &&
                   fabs(v[5] - 0.01292) < 1e-5,
               "sRGB view: 0.18 -> 118, 0.5 -> 188, 1 -> 255, knee 0.0031308 -> 0.04045, linear part below it");
    }
    {
        float xy[8];
        int ok = colour_display_chromaticities(d, xy) == 0;
        double worst = 0;
        for (int i = 0; ok && i < 8; i++)
            if (fabs(xy[i] - colour_rec709_chromaticities[i]) > worst)
                worst = fabs(xy[i] - colour_rec709_chromaticities[i]);
        tap_ok(ok && worst < 1e-4,
               "working space's chromaticities through cie_xyz_d65_interchange are Rec.709 and D65 (off by %.1g)",
               worst);
    }
    colour_display_free(d);

    d = open_or_null(shipped, "sRGB", "Raw", &st, err, sizeof err);
    tap_ok(d != NULL, "Raw view opens (%s)", d ? "ok" : err);
    if (d != NULL) {
        float v[6] = { -0.25f, 0.18f, 0.5f, 1.0f, 2.5f, 0.0031308f };
        float w[6];
        memcpy(w, v, sizeof v);
        tap_ok(colour_display_apply(d, v, 2, err, sizeof err) == 0 && memcmp(v, w, sizeof v) == 0,
               "Raw view leaves values as they are");
        colour_display_free(d);
    }

    tap_ok(colour_shipped_config(buf, (int)sizeof buf) != NULL && access(buf, R_OK) == 0,
           "shipped config found through $HSTRACE_DATADIR (%s)", buf);
}

static void test_other_view(void)
{
    char err[512];
    ColourStatus st;
    ColourDisplay *d = open_or_null(gamma22, NULL, NULL, &st, err, sizeof err);

    tap_ok(d != NULL, "test config opens (%s)", d ? "ok" : err);
    if (d == NULL)
        return;
    tap_ok(strcmp(colour_display_name(d), "Gamma") == 0 && strcmp(colour_display_view(d), "Gamma 2.2") == 0,
           "its defaults are display Gamma, view Gamma 2.2");
    {
        float v[6] = { 0.18f, 0.5f, 0.02f, 1.0f, 0.0f, 0.7f };
        double worst = 0;
        const float in[6] = { 0.18f, 0.5f, 0.02f, 1.0f, 0.0f, 0.7f };
        colour_display_apply(d, v, 2, err, sizeof err);
        for (int i = 0; i < 6; i++)
            if (fabs(v[i] - pow(in[i], 1 / 2.2)) > worst)
                worst = fabs(v[i] - pow(in[i], 1 / 2.2));
        tap_ok(worst < 1e-4, "Gamma 2.2 view is x^(1/2.2) (off by %.1g); 0.02 -> %.4f where sRGB gives %.4f", worst,
               v[2], srgb_formula(0.02));
    }
    {
        float xy[8];
        tap_ok(colour_display_chromaticities(d, xy) != 0,
               "a config without cie_xyz_d65_interchange gives no chromaticities (the EXR goes untagged)");
    }
    colour_display_free(d);
}

static void test_env(void)
{
    char err[512];
    ColourStatus st;
    ColourDisplay *d;

    setenv("OCIO", gamma22, 1);
    d = open_or_null(NULL, NULL, NULL, &st, err, sizeof err);
    tap_ok(d != NULL && strcmp(colour_display_config(d), gamma22) == 0 && strcmp(colour_display_view(d), "Gamma 2.2") == 0,
           "$OCIO is the config when --ocio-config is not given");
    colour_display_free(d);
    d = open_or_null(shipped, NULL, NULL, &st, err, sizeof err);
    tap_ok(d != NULL && strcmp(colour_display_config(d), shipped) == 0, "--ocio-config wins over $OCIO");
    colour_display_free(d);
    setenv("OCIO", "/no/such/config.ocio", 1);
    d = open_or_null(NULL, NULL, NULL, &st, err, sizeof err);
    tap_ok(d == NULL && st == COLOUR_ERR_CONFIG && strstr(err, "/no/such/config.ocio") && strstr(err, "$OCIO"),
           "a missing $OCIO config is a config error naming it and $OCIO (%s)", err);
    setenv("OCIO", "", 1);
    d = open_or_null(NULL, "sRGB", NULL, &st, err, sizeof err);
    tap_ok(d != NULL && strstr(colour_display_config(d), "ocio/config.ocio") != NULL,
           "an empty $OCIO falls back to the shipped config (%s)", d ? colour_display_config(d) : err);
    colour_display_free(d);
    unsetenv("OCIO");
}

static void test_errors(void)
{
    char err[1024];
    ColourStatus st;
    ColourDisplay *d;

    d = open_or_null("/no/such/dir/config.ocio", NULL, NULL, &st, err, sizeof err);
    tap_ok(d == NULL && st == COLOUR_ERR_CONFIG && strstr(err, "/no/such/dir/config.ocio") &&
               strstr(err, "No such file"),
           "missing config: config error with the file and the reason (%s)", err);
    d = open_or_null(broken_yaml, NULL, NULL, &st, err, sizeof err);
    tap_ok(d == NULL && st == COLOUR_ERR_CONFIG && strstr(err, "broken-yaml.ocio") && strstr(err, "broken"),
           "malformed YAML: config error (%s)", err);
    d = open_or_null(missing_space, NULL, NULL, &st, err, sizeof err);
    tap_ok(d == NULL && st == COLOUR_ERR_CONFIG && strstr(err, "no such space"),
           "config naming an undefined colour space: config error (%s)", err);
    d = open_or_null(shipped, "sRGB", "Filmic", &st, err, sizeof err);
    tap_ok(d == NULL && st == COLOUR_ERR_NAME && strstr(err, "'Filmic'") && strstr(err, "'Standard', 'Raw'"),
           "unknown view: name error listing the display's views (%s)", err);
    d = open_or_null(shipped, "Projector", NULL, &st, err, sizeof err);
    tap_ok(d == NULL && st == COLOUR_ERR_NAME && strstr(err, "'Projector'") && strstr(err, "valid: 'sRGB')"),
           "unknown display: name error listing the displays (%s)", err);
    d = open_or_null(gamma22, "sRGB", "Gamma 2.2", &st, err, sizeof err);
    tap_ok(d == NULL && st == COLOUR_ERR_NAME && strstr(err, "valid: 'Standard')"),
           "a view of another display is unknown for this one (%s)", err);
    {
        ColourRequest req = { shipped, NULL, NULL, "ACEScg" };
        st = colour_display_open(&req, &d, err, sizeof err);
        tap_ok(d == NULL && st == COLOUR_ERR_NAME && strstr(err, "'ACEScg'") && strstr(err, "'Linear Rec.709'"),
               "unknown colour space: name error listing the colour spaces (%s)", err);
        req.colorspace = "aces_interchange";
        st = colour_display_open(&req, &d, err, sizeof err);
        tap_ok(d != NULL && strcmp(colour_display_working_space(d), "ACES2065-1") == 0,
               "a role names a working space too (aces_interchange is ACES2065-1)");
        if (d != NULL) {
            /* Through the D65 interchange space: AP0 as the config adapts
             * it to D65 (Bradford), so the white comes out D65. */
            float xy[8] = { 0 };
            int ok = colour_display_chromaticities(d, xy) == 0;
            tap_ok(ok && fabs(xy[0] - 0.7347) < 3e-3 && fabs(xy[1] - 0.2653) < 3e-3 && xy[3] > 1.0f &&
                       fabs(xy[6] - 0.3127) < 1e-4 && fabs(xy[7] - 0.3290) < 1e-4,
                   "ACES2065-1 working space: AP0 primaries adapted to D65 (red %.4f %.4f, green y %.4f, white %.4f "
                   "%.4f)",
                   xy[0], xy[1], xy[3], xy[6], xy[7]);
        }
        colour_display_free(d);
    }
}

/* The display transform from several threads at once gives what one gives. */
typedef struct {
    const ColourDisplay *d;
    float rgb[3 * 1000];
    int rc;
} Job;

static void *run_job(void *p)
{
    Job *j = p;
    char err[256];
    for (int k = 0; k < 20 && j->rc == 0; k++) {
        for (int i = 0; i < 3000; i++)
            j->rgb[i] = (float)i / 2999.0f;
        j->rc = colour_display_apply(j->d, j->rgb, 1000, err, sizeof err);
    }
    return NULL;
}

static void test_threads(void)
{
    char err[512];
    ColourStatus st;
    ColourDisplay *d = open_or_null(shipped, NULL, NULL, &st, err, sizeof err);
    static Job jobs[4];
    pthread_t th[4];
    int started = 0, same = 1;

    if (d == NULL)
        return;
    for (int t = 0; t < 4; t++) {
        jobs[t].d = d;
        jobs[t].rc = 0;
        if (pthread_create(&th[t], NULL, run_job, &jobs[t]) == 0)
            started++;
    }
    for (int t = 0; t < started; t++)
        pthread_join(th[t], NULL);
    for (int t = 1; t < started; t++)
        same &= jobs[t].rc == 0 && memcmp(jobs[t].rgb, jobs[0].rgb, sizeof jobs[0].rgb) == 0;
    tap_ok(started == 4 && jobs[0].rc == 0 && same, "one display transform used by 4 threads at once: same results");
    colour_display_free(d);
}

/* The image writers with a display transform: the codes, un-premultiplied
 * alpha as POV-Ray's, and the EXR chromaticities attribute. */
static void test_writers(void)
{
    char err[512], dir[] = "/tmp/hstcolourXXXXXX", png[4200], exr[4200];
    ColourStatus st;
    ColourDisplay *d = open_or_null(shipped, NULL, NULL, &st, err, sizeof err);
    ImageWriteOptions opt;
    ImageRowEncoder pov, ocio;
    const float row[4 * 4] = { 0.18f, 0.5f, 1.0f, 1.0f,  0.25f, 0.0f, 0.1f, 0.5f,
                               0.9f, 0.9f, 0.9f, 0.5f, 0.0f, 0.0f, 0.0f, 0.0f };
    int worst = 0;

    if (d == NULL || mkdtemp(dir) == NULL) {
        tap_ok(0, "writers: set-up (%s)", err);
        colour_display_free(d);
        return;
    }
    memset(&opt, 0, sizeof opt);
    image_row_encoder_init(&pov, &opt, 4, 255, 1);
    opt.display = d;
    image_row_encoder_init(&ocio, &opt, 4, 255, 1);
    image_row_encode(&pov, row, err, sizeof err);
    tap_ok(image_row_encode(&ocio, row, err, sizeof err) == 0, "row through the sRGB view encodes (%s)", err);
    for (int i = 0; i < 16; i++)
        if (abs((int)pov.samples[i] - (int)ocio.samples[i]) > worst)
            worst = abs((int)pov.samples[i] - (int)ocio.samples[i]);
    tap_ok(worst <= 1 && ocio.samples[3] == 255 && ocio.samples[7] == 128 && ocio.samples[11] == 230 &&
               ocio.samples[15] == 0,
           "RGBA through the sRGB view: within one code of POV-Ray's encoding, same alpha handling (largest %d)",
           worst);
    image_row_encoder_free(&pov);
    image_row_encoder_free(&ocio);

    {
        Image img;
        image_alloc(&img, 2, 1);
        memcpy(img.rgba, row, 8 * sizeof(float));
        snprintf(exr, sizeof exr, "%s/c.exr", dir);
        snprintf(png, sizeof png, "%s/c.png", dir);
        opt.have_chromaticities = colour_display_chromaticities(d, opt.chromaticities) == 0;
        tap_ok(image_write(exr, &img, &opt, err, sizeof err) == 0 && image_write(png, &img, &opt, err, sizeof err) == 0,
               "EXR and PNG written with the display transform (%s)", err);
        image_free(&img);
    }
    {
        exr_context_t ctx = NULL;
        exr_attr_chromaticities_t c;
        exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
        int ok = exr_start_read(&ctx, exr, &init) == EXR_ERR_SUCCESS &&
                 exr_attr_get_chromaticities(ctx, 0, "chromaticities", &c) == EXR_ERR_SUCCESS;
        tap_ok(ok && fabs(c.red_x - 0.64) < 1e-4 && fabs(c.red_y - 0.33) < 1e-4 && fabs(c.green_x - 0.30) < 1e-4 &&
                   fabs(c.blue_y - 0.06) < 1e-4 && fabs(c.white_x - 0.3127) < 1e-4 && fabs(c.white_y - 0.3290) < 1e-4,
               "EXR carries the chromaticities attribute: Rec.709 primaries, D65 white");
        if (ctx != NULL)
            exr_finish(&ctx);
    }
    unlink(exr);
    unlink(png);
    rmdir(dir);
    colour_display_free(d);
}

int main(void)
{
    paths();
    test_requested();
    if (!colour_ocio_available()) {
        test_without_ocio();
        tap_diag("built without OpenColorIO: the rest is skipped");
        return tap_done();
    }
    tap_diag("%s", colour_ocio_version());
    test_shipped();
    test_other_view();
    test_env();
    test_errors();
    test_threads();
    test_writers();
    return tap_done();
}
