/* POV-Ray 3.7's patterns against POV-Ray itself: for each
 * pattern below, POV-Ray evaluates `function { pattern { ... } }` at a set
 * of points and writes the values (17 significant digits) to a file; hstrace
 * parses the same pattern and evaluates it at the same points. They must
 * agree to rounding: that is what puts colour_map borders on the same
 * pixels. Needs POV-Ray (POVRAY in the environment, as `make check` sets
 * it); skipped without it. Nothing here is computed by hstrace's own code
 * in advance. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "parser.h"
#include "pigment.h"
#include "tap.h"

/* Patterns as written in a pigment (without the colour map). */
static const char *const patterns[] = {
    "bozo",
    "bozo noise_generator 1",
    "bozo noise_generator 3",
    "spotted scale 0.3",
    "bumps translate <-3.2, 0, 7>",
    "bozo turbulence 0.6",
    "bozo warp { turbulence 0.6 }",
    "bozo warp { turbulence <0.3, 0.9, 0.1> octaves 3 omega 0.7 lambda 2.5 } scale 0.4",
    "bozo scale 2 turbulence 0.5 octaves 4 rotate <10, 20, 30>",
    "bozo warp { turbulence 0.6 } noise_generator 1",
    "granite",
    "granite noise_generator 1",
    "wrinkles",
    "wrinkles noise_generator 1",
    "agate",
    "agate agate_turb 0.4 noise_generator 3",
    "marble",
    "marble turbulence 0.8",
    "marble turbulence 0.8 noise_generator 1 frequency 3",
    "wood",
    "wood turbulence 0.05 scale 0.2",
    "spiral1 5",
    "spiral1 3 turbulence 0.3",
    "spiral2 8 scale 0.8",
    "spiral2 8 warp { turbulence 0.2 }",
    "bozo frequency 2 phase 0.3 sine_wave",
    "bozo scallop_wave",
    "bozo frequency -1.5 triangle_wave",
    "checker turbulence 0.4",
    "gradient x warp { turbulence 1 }",
    "brick",
    "brick brick_size <1, 0.4, 0.7> mortar 0.07",
    "brick scale 0.3 rotate <0, 30, 0> turbulence 0.2",
    "leopard",
    "leopard scale 0.2 frequency 2 sine_wave",
    "onion",
    "onion scale 0.7 phase 0.3",
    "radial",
    "radial frequency 8 rotate <90, 0, 0>",
    "quilted",
    "quilted control0 0.3 control1 -0.6 scale 0.6",
    "dents",
    "dents noise_generator 1",
    "ripples",
    "ripples frequency 3 phase 0.2 scale 0.5",
    "waves",
    "waves frequency 0.5 phase 0.7",
    "planar",
    "spherical scale 5",
    "cylindrical scale 4",
    "boxed scale 6 cubic_wave",
    "cells",
    "cells scale 0.3",
    "crackle",
    "crackle scale 0.4",
    "crackle metric 1 offset 0.1",
    "crackle metric 3 form <1, 0, 0> offset 0.2",
    "crackle form <0.5, 0.3, 0.2>",
    "crackle solid",
    "mandel 50 scale 3",
    "mandel 30 exponent 3 scale 3",
    "mandel 30 exponent 4 scale 3",
    "mandel 20 exponent 6 scale 3",
    "mandel 40 scale 3 interior 1, 0.5 exterior 2, 0.3",
    "mandel 40 scale 3 interior 6, 2 exterior 5, 3",
    "mandel 40 scale 3 interior 4, 2 exterior 0, 0.7",
    "julia <0.3, 0.44>, 30 scale 3",
    "julia <-0.7, 0.27>, 30 exponent 3 scale 3 interior 3, 1 exterior 6, 0.2",
    "julia <0.3, -0.1>, 20 exponent 7 scale 3",
    "magnet 1 mandel 30 scale 2",
    "magnet 1 julia <0.6, 0.3>, 30 scale 2 interior 1, 1",
    "magnet 2 mandel 30 scale 2 exterior 4, 0.01",
    "magnet 2 julia <1.4, 0.1>, 30 scale 2",
    "pigment_pattern { checker rgb 0.2 rgb <1, 0.5, 0.1> scale 0.7 }",
    "pigment_pattern { leopard scale 0.3 color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0.4, 1>] } }",
};
#define NPATTERNS ((int)(sizeof patterns / sizeof patterns[0]))

/* Points: spread over both signs and several lattice cells, with some on
 * whole numbers (noise's lattice) and near zero. */
#define NPOINTS 24
static Vec3 point(int i)
{
    static const Vec3 fixed[6] = { { 0, 0, 0 }, { 1, 2, 3 }, { -1, -2, -3 }, { 0.5, -0.5, 0 },
                                   { 1e-11, -1e-11, 0.25 }, { 123.456, -78.9, 1000.5 } };
    if (i < 6)
        return fixed[i];
    /* a fixed scatter: no randomness, the same on every run */
    double a = i * 0.7548776662, b = i * 0.5698402910, c = i * 0.3247179572;
    return v3((a - floor(a)) * 14.0 - 7.0, (b - floor(b)) * 9.0 - 4.5, (c - floor(c)) * 11.0 - 3.3);
}

static const char *povray_path(void)
{
    const char *p = getenv("POVRAY");
    return p && *p ? p : NULL;
}

/* Writes the scene that makes POV-Ray write every pattern's values. */
static int write_pov_scene(const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fprintf(f, "#version 3.7;\n#fopen Out \"values.txt\" write\n");
    for (int k = 0; k < NPATTERNS; k++) {
        fprintf(f, "#declare F%d = function { pattern { %s } }\n", k, patterns[k]);
        for (int i = 0; i < NPOINTS; i++) {
            Vec3 q = point(i);
            fprintf(f, "#write (Out, str(F%d(%.17g, %.17g, %.17g), 0, 17), \"\\n\")\n", k, q.x, q.y, q.z);
        }
    }
    fprintf(f, "#fclose Out\ncamera { location -z look_at 0 }\n");
    return fclose(f);
}

/* hstrace's value of pattern k at point q, through the parser. */
static int hstrace_value(int k, Vec3 q, double *out)
{
    char text[512];
    snprintf(text, sizeof text, "#version 3.7;\nplane { y, 0 pigment { %s color_map { [0 rgb 0] [1 rgb 1] } } }\n",
             patterns[k]);
    ParseOptions opts = { .image_width = 320, .image_height = 240 };
    ParseError err;
    Scene *s = parse_scene_string("t.pov", text, &opts, &err);
    if (!s) {
        tap_diag("hstrace cannot parse '%s': %s:%d:%d: %s", patterns[k], err.file, err.line, err.column, err.message);
        return -1;
    }
    Pigment pig = s->objects[0]->texture->pigment;
    if (pig.noise_generator == 0)
        pig.noise_generator = scene_noise_generator(s);
    *out = pattern_value(&pig, inverse_transform_point(&pig.transform, q));
    scene_free(s);
    return 0;
}

int main(void)
{
    const char *povray = povray_path();
    if (!povray) {
        printf("1..0 # SKIP povray is not installed: the reference values come from POV-Ray\n");
        return 0;
    }
    const char *tmp = getenv("TMPDIR");
    char dirbuf[600];
    snprintf(dirbuf, sizeof dirbuf, "%s/hstpatterns.XXXXXX", tmp && *tmp ? tmp : "/tmp");
    char *work = mkdtemp(dirbuf);
    if (!work) {
        printf("Bail out! cannot make a temporary folder (%s)\n", dirbuf);
        return 1;
    }
    char scene[700], values[700], cmd[2400];
    snprintf(scene, sizeof scene, "%s/values.pov", work);
    snprintf(values, sizeof values, "%s/values.txt", work);
    if (write_pov_scene(scene) != 0) {
        printf("Bail out! cannot write %s\n", scene);
        return 1;
    }
    /* POV-Ray writes its #fopen files relative to its working folder. */
    snprintf(cmd, sizeof cmd, "cd '%s' && '%s' +Ivalues.pov -D -GA +W8 +H8 -F >/dev/null 2>&1", work, povray);
    int rc = system(cmd);
    FILE *f = fopen(values, "r");
    if (rc != 0 || !f) {
        printf("Bail out! povray did not write the pattern values (status %d)\n", rc);
        return 1;
    }
    for (int k = 0; k < NPATTERNS; k++) {
        int agree = 0, worst_i = -1;
        double worst = 0.0, worst_pov = 0.0, worst_hst = 0.0;
        for (int i = 0; i < NPOINTS; i++) {
            double ref, ours;
            if (fscanf(f, "%lf", &ref) != 1) {
                printf("Bail out! short values file from povray\n");
                return 1;
            }
            if (hstrace_value(k, point(i), &ours) != 0)
                continue;
            /* 17 digits round-trip a double: what is left is libm's last bit */
            double diff = fabs(ours - ref);
            if (diff <= 1e-13 * fmax(1.0, fabs(ref)))
                agree++;
            if (diff >= worst && (worst_i < 0 || diff > worst)) {
                worst = diff;
                worst_i = i;
                worst_pov = ref;
                worst_hst = ours;
            }
        }
        tap_ok(agree == NPOINTS, "pattern { %s }: %d of %d points agree with POV-Ray (largest difference %.3g)",
               patterns[k], agree, NPOINTS, worst);
        if (agree != NPOINTS) {
            Vec3 q = point(worst_i);
            tap_diag("at <%.17g, %.17g, %.17g>: POV-Ray %.17g, hstrace %.17g", q.x, q.y, q.z, worst_pov, worst_hst);
        }
    }
    fclose(f);
    unlink(scene);
    unlink(values);
    rmdir(work);
    return tap_done();
}
