/* display_codes: checks the display encoding of a PNG or PPM written by
 * hstrace, for tests/colour.sh.
 *
 *   display_codes LINEAR DISPLAY --curve srgb|gamma|raw [--gamma G] [--steps N]
 *
 * Every RGB sample of DISPLAY (read as its integer codes) against the code
 * the curve gives the same sample of LINEAR (an EXR render of the same
 * scene): srgb is IEC 61966-2-1's formula in double precision, gamma a pure
 * power 1/G (default 2.2), raw no curve; all clamp to 0..1 and round.
 * (POV-Ray's own encoding is checked against POV-Ray's files, in
 * tests/encoding.sh.) Exit 0 when no sample is more
 * than N codes off (default 1), 1 when one is, 2 on bad input. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"
#include "image_codec.h"

static double srgb_formula(double x)
{
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1 / 2.4) - 0.055;
}

static int usage(void)
{
    fprintf(stderr, "usage: display_codes LINEAR DISPLAY --curve srgb|gamma|raw [--gamma G] [--steps N]\n");
    return 2;
}

int main(int argc, char **argv)
{
    double steps = 1, gamma = 2.2;
    const char *curve = NULL;
    if (argc < 3)
        return usage();
    for (int i = 3; i < argc; i++) {
        if (i + 1 >= argc)
            return usage();
        char *end;
        if (strcmp(argv[i], "--curve") == 0)
            curve = argv[++i];
        else if (strcmp(argv[i], "--steps") == 0 || strcmp(argv[i], "--gamma") == 0) {
            double v = strtod(argv[i + 1], &end);
            if (*end || end == argv[i + 1])
                return usage();
            *(strcmp(argv[i], "--steps") == 0 ? &steps : &gamma) = v;
            i++;
        } else
            return usage();
    }
    if (!curve || (strcmp(curve, "srgb") && strcmp(curve, "gamma") && strcmp(curve, "raw")) ||
        !(gamma > 0))
        return usage();
    Image lin, disp;
    char err[512];
    lin.rgba = disp.rgba = NULL;
    /* Gamma 1 reads the display codes as they are: sample = code / 255. */
    if (image_read(argv[1], &lin, 0.0, err, sizeof err) || image_read(argv[2], &disp, 1.0, err, sizeof err)) {
        fprintf(stderr, "display_codes: %s\n", err);
        image_free(&lin);
        return 2;
    }
    if (lin.width != disp.width || lin.height != disp.height) {
        fprintf(stderr, "display_codes: '%s' is %dx%d but '%s' is %dx%d\n", argv[1], lin.width, lin.height, argv[2],
                disp.width, disp.height);
        image_free(&lin);
        image_free(&disp);
        return 2;
    }
    long off = 0, n = (long)lin.width * lin.height;
    double worst = 0;
    for (long i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            float x = lin.rgba[4 * i + k];
            double e;
            if (strcmp(curve, "srgb") == 0)
                e = srgb_formula(x > 0 ? x : 0);
            else if (strcmp(curve, "gamma") == 0)
                e = pow(x > 0 ? x : 0, 1 / gamma);
            else
                e = x;
            long want = (long)image_quantize((float)e, 255);
            long got = lround(disp.rgba[4 * i + k] * 255.0);
            double d = fabs((double)(got - want));
            off += d > 0;
            if (d > worst)
                worst = d;
        }
    printf("curve %s: %ld of %ld samples differ, by at most %.0f codes (limit %.0f)\n", curve, off, 3 * n, worst,
           steps);
    image_free(&lin);
    image_free(&disp);
    return worst <= steps ? 0 : 1;
}
