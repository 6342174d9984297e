/* Pigment patterns, written from POV-Ray 3.7's definitions (checker_pattern,
 * hexagon_pattern, gradient_pattern, the noise patterns, spiral1/2_pattern,
 * Warp_EPoint's turbulence, Evaluate_TPat's dispatch to every pattern
 * (the others' values are patterns.h's) and its frequency/phase/wave,
 * Search_Blend_Map with pigment_map's and average's pigments
 * (Compute_Pigment), the uv coordinates of UVCoord, image_map's lookup and
 * interpolation, the textures of a texture_map as ComputeOneTextureColour
 * picks and weighs them): the same small offsets
 * and the same order of operations, so that pattern borders fall where
 * POV-Ray puts them. */
#include "pigment.h"

#include <math.h>

#include "convert.h"
#include "deadline.h"
#include "intersect.h"
#include "noise.h"
#include "normal.h"
#include "patterns.h"


static double checker_value(Vec3 p)
{
    /* The EPSILON nudges points on a cell face (a plane through whole
     * units, the usual case for a checkered floor) into the upper cell. */
    int v = int_as_povray(floor(p.x + POV_EPSILON) + floor(p.y + POV_EPSILON) + floor(p.z + POV_EPSILON));
    return (v & 1) ? 1.0 : 0.0;
}

/* Hexagons in the x-z plane, three colours, as POV-Ray tiles them: a 6 x 6
 * grid of blocks half a unit wide and sqrt(3)/2 deep, some split along a
 * diagonal. */
static double hexagon_value(Vec3 p)
{
    const double xfactor = 0.5, zfactor = 0.866025404; /* POV-Ray's constants */
    double x = fabs(p.x);
    double z = p.z < 0.0 ? 5.196152424 - fabs(p.z) : p.z; /* no mirroring across x */
    double xs = x / xfactor, zs = z / zfactor;
    xs -= floor(xs / 6.0) * 6.0;
    zs -= floor(zs / 6.0) * 6.0;
    /* Far from the origin (|x| beyond ~1e15) the reduction above leaves
     * [0, 6); POV-Ray's switch then matches no block and answers 0. */
    int xm = int_as_povray(pattern_floor(xs)) % 6, zm = int_as_povray(pattern_floor(zs)) % 6;
    if (xm < 0 || zm < 0)
        return 0.0;
    static const int straight_05[6] = { 0, 1, 1, 2, 2, 0 }; /* columns 0 and 5 by zm */
    static const int straight_23[6] = { 2, 2, 0, 0, 1, 1 }; /* columns 2 and 3 */
    static const int below[6] = { 0, 2, 1, 0, 2, 1 };       /* split columns, under the diagonal */
    static const int above[6] = { 2, 1, 0, 2, 1, 0 };
    switch (xm) {
    case 0: case 5: return straight_05[zm];
    case 2: case 3: return straight_23[zm];
    default: {
        double xl = xs - xm, zl = zs - zm;
        if ((xm + zm) % 2 == 1)
            xl = 1.0 - xl; /* these blocks slope the other way */
        if (xl == 0.0)
            xl = 0.0001; /* POV-Ray's guard against dividing by zero */
        return zl / xl < 1.0 ? below[zm] : above[zm];
    }
    }
}

static double gradient_value(const Pigment *pig, Vec3 p)
{
    double v = v3_dot(p, pig->gradient);
    return v > 1.0 ? fmod(v, 1.0) : v;
}

/* POV-Ray's cycloidal(): a sine of period 1, through the fraction. */
static double cycloidal(double v)
{
    if (v >= 0.0)
        return sin((v - floor(v)) * 50000.0 / 50000.0 * (2.0 * M_PI));
    return 0.0 - sin((0.0 - (v + floor(0.0 - v))) * 50000.0 / 50000.0 * (2.0 * M_PI));
}

/* POV-Ray's Triangle_Wave(): 0 at whole numbers, 1 halfway. */
static double triangle_wave(double v)
{
    double offset = v >= 0.0 ? v - floor(v) : v + 1.0 + floor(fabs(v));
    return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

/* POV-Ray's Search_For_Turb: the turbulence a pattern uses itself (marble,
 * wood, agate, the spirals) is the last warp, if written as `turbulence`. */
static const PatternTurbulence *own_turbulence(const Pigment *pig)
{
    if (pig->nturbulence > 0 && pig->turbulence[pig->nturbulence - 1].classic)
        return &pig->turbulence[pig->nturbulence - 1];
    return NULL;
}

static double turbulence_at(const PatternTurbulence *t, Vec3 p, int generator)
{
    return noise_turbulence(p, t->octaves, t->omega, t->lambda, generator);
}

/* The warps in order (Warp_EPoint): each turbulence displaces the point by
 * its vector noise times its amount; marble and wood use a `turbulence`
 * written in the pigment in their own way instead. */
static Vec3 warp_point(const Pigment *pig, Vec3 p)
{
    for (int i = 0; i < pig->nturbulence; i++) {
        const PatternTurbulence *t = &pig->turbulence[i];
        if (t->classic && (pig->kind == PIGMENT_MARBLE || pig->kind == PIGMENT_WOOD))
            continue;
        Vec3 d = noise_vector_turbulence(p, t->octaves, t->omega, t->lambda);
        p.x += d.x * t->amount.x;
        p.y += d.y * t->amount.y;
        p.z += d.z * t->amount.z;
    }
    return p;
}

static double granite_value(Vec3 p, int generator)
{
    double noise = 0.0, freq = 1.0;
    Vec3 q = v3(p.x * 4.0, p.y * 4.0, p.z * 4.0);
    for (int i = 0; i < 6; freq *= 2.0, i++) {
        double n = noise_value(v3(q.x * freq, q.y * freq, q.z * freq), generator), t;
        if (generator == NOISE_ORIGINAL) {
            t = fabs(0.5 - n);
        } else {
            t = fabs(1.0 - 2.0 * n);
            if (t > 0.5)
                t = 0.5;
        }
        noise += t / freq;
    }
    return noise;
}

static double wrinkles_value(Vec3 p, int generator)
{
    double lambda = 2.0, omega = 0.5, value;
    if (generator > 1)
        value = fmin(fmax(noise_value(p, generator) * 2.0 - 0.5, 0.0), 1.0);
    else
        value = noise_value(p, generator);
    for (int i = 1; i < 10; i++) {
        Vec3 q = v3(p.x * lambda, p.y * lambda, p.z * lambda);
        if (generator > 1)
            value += omega * fmin(fmax(noise_value(q, generator) * 2.0 - 0.5, 0.0), 1.0);
        else
            value += omega * noise_value(q, generator);
        lambda *= 2.0;
        omega *= 0.5;
    }
    return value / 2.0;
}

static double agate_value(const Pigment *pig, Vec3 p, int generator)
{
    static const PatternTurbulence plain = { 1, { 0, 0, 0 }, 6, 0.5, 2.0 };
    const PatternTurbulence *t = own_turbulence(pig);
    double turb = pig->agate_turb * turbulence_at(t ? t : &plain, p, generator);
    double noise = 0.5 * (cycloidal(1.3 * turb + 1.1 * p.z) + 1.0);
    if (noise < 0.0)
        return 0.0;
    return pow(fmin(1.0, noise), 0.77);
}

static double marble_value(const Pigment *pig, Vec3 p, int generator)
{
    const PatternTurbulence *t = own_turbulence(pig);
    return p.x + (t ? t->amount.x * turbulence_at(t, p, generator) : 0.0);
}

static double wood_value(const Pigment *pig, Vec3 p)
{
    const PatternTurbulence *t = own_turbulence(pig);
    double x = 0.0, y = 0.0;
    if (t) {
        Vec3 d = noise_vector_turbulence(p, t->octaves, t->omega, t->lambda);
        x = cycloidal((p.x + d.x) * t->amount.x);
        y = cycloidal((p.y + d.y) * t->amount.y);
    }
    x += p.x;
    y += p.y;
    return sqrt(x * x + y * y + 0.0 * 0.0);
}

/* Both spirals: arms around the z axis, rising with z and the distance. */
static double spiral_value(const Pigment *pig, Vec3 p, int generator)
{
    const PatternTurbulence *t = own_turbulence(pig);
    double turb = t ? t->amount.x * turbulence_at(t, p, generator) : 0.0;
    double rad = sqrt(p.x * p.x + p.y * p.y), phi;
    if (rad == 0.0)
        phi = 0.0;
    else if (p.x < 0.0)
        phi = 3.0 * (M_PI / 2.0) - asin(p.y / rad);
    else
        phi = (M_PI / 2.0) + asin(p.y / rad);
    double v = p.z + rad + (double)pig->arms * phi / (2.0 * M_PI) + turb;
    if (pig->kind == PIGMENT_SPIRAL1)
        return v;
    return triangle_wave(rad) + triangle_wave(v);
}

static double wave(const Pigment *pig, double v)
{
    switch (pig->wave) {
    case WAVE_RAMP: return v;
    case WAVE_SINE: return (1.0 + cycloidal(v)) * 0.5;
    case WAVE_TRIANGLE: return triangle_wave(v);
    case WAVE_SCALLOP: return fabs(cycloidal(v * 0.5));
    case WAVE_CUBIC: return v * v * (-2.0 * v + 3.0);
    case WAVE_POLY: return pow(v, pig->wave_exponent);
    }
    return v;
}

double pattern_value(const Pigment *pig, Vec3 p)
{
    return pattern_value_warped(pig, warp_point(pig, p), NOISE_RANGE_CORRECTED, DEFAULT_NUMBER_OF_WAVES);
}

Vec3 pattern_warp(const Pigment *pig, Vec3 p)
{
    return warp_point(pig, p);
}

static Colour image_map_at(const Pigment *pig, Vec3 p);

/* POV-Ray's Colour::greyscale, in its single-precision colour. */
static double colour_grey(Colour c)
{
    return (double)(float)(0.297 * (double)(float)c.r + 0.589 * (double)(float)c.g + 0.114 * (double)(float)c.b);
}

static Colour pigment_colour(const Pigment *pig, Vec3 p, int generator, int nwaves);

/* A map's colour at `value` (Search_Blend_Map): the entries around it
 * blended linearly, as colour_map_at does; an entry with a pigment of its
 * own gives that pigment's colour at the pattern's warped point
 * (Compute_Pigment's pigment_map). */
static Colour blend_map_at(const Pigment *pig, double value, Vec3 warped, int generator, int nwaves)
{
    const ColourMapEntry *map = pig->map;
    const int n = pig->nmap;
    int cur = 0, prev;
    if (value >= map[n - 1].value) {
        cur = n - 1;
    } else {
        while (value > map[cur].value)
            cur++;
    }
    prev = cur == 0 || value == map[cur].value || value >= map[n - 1].value ? cur : cur - 1;
    Colour c = map[cur].pigment ? pigment_colour(map[cur].pigment, warped, generator, nwaves) : map[cur].colour;
    if (prev == cur)
        return c;
    Colour t = map[prev].pigment ? pigment_colour(map[prev].pigment, warped, generator, nwaves) : map[prev].colour;
    double f = (value - map[prev].value) / (map[cur].value - map[prev].value);
    Colour r = {
        t.r + f * (c.r - t.r), t.g + f * (c.g - t.g), t.b + f * (c.b - t.b),
        t.filter + f * (c.filter - t.filter), t.transmit + f * (c.transmit - t.transmit),
    };
    return r;
}

/* average: the entries' colours at the warped point weighed by their
 * values, summed and divided in single precision as Do_Average_Pigments
 * does in POV-Ray's float colours. */
static Colour average_colour(const Pigment *pig, Vec3 warped, int generator, int nwaves)
{
    float sum[5] = { 0, 0, 0, 0, 0 }, total = 0.0f;
    for (int i = 0; i < pig->nmap; i++) {
        const ColourMapEntry *e = &pig->map[i];
        Colour c = e->pigment ? pigment_colour(e->pigment, warped, generator, nwaves) : e->colour;
        const float w = (float)e->value;
        sum[0] += (float)c.r * w;
        sum[1] += (float)c.g * w;
        sum[2] += (float)c.b * w;
        sum[3] += (float)c.filter * w;
        sum[4] += (float)c.transmit * w;
        total += w;
    }
    Colour r = { sum[0] / total, sum[1] / total, sum[2] / total, sum[3] / total, sum[4] / total };
    return r;
}

/* The colour of a pigment at point p of the space it is written in (its
 * own transforms and warps from there, as Compute_Pigment takes it), with
 * the noise generator and wave sources of its scene where it names none. */
static Colour pigment_colour(const Pigment *pig, Vec3 p, int generator, int nwaves)
{
    /* nested maps and averages may ask for 2^40 colours at one point:
     * past --max-render-seconds each ends at once (its colour is of no
     * use, the render is discarded) */
    if (deadline_step())
        return pig->colour;
    Vec3 q = inverse_transform_point(&pig->transform, p);
    switch (pig->kind) {
    case PIGMENT_SOLID: return pig->colour;
    case PIGMENT_IMAGE_MAP: return image_map_at(pig, q);
    default: break;
    }
    Vec3 warped = warp_point(pig, q);
    if (pig->kind == PIGMENT_AVERAGE)
        return average_colour(pig, warped, generator, nwaves);
    double v = pattern_value_warped(pig, warped, generator, nwaves);
    if (!pig->map_pigments)
        return colour_map_at(pig->map, pig->nmap, v);
    return blend_map_at(pig, v, warped, generator, nwaves);
}

/* pigment_pattern: the grey of another pigment's colour at the point. */
static double pigment_pattern_value(const Pigment *inner, Vec3 p, int generator, int nwaves)
{
    return inner ? colour_grey(pigment_colour(inner, p, generator, nwaves)) : 0.0;
}

double pattern_value_warped(const Pigment *pig, Vec3 p, int default_generator, int default_waves)
{
    int generator = pig->noise_generator ? pig->noise_generator : default_generator;
    int nwaves = pig->nwaves ? pig->nwaves : default_waves;
    double v;
    switch (pig->kind) {
    case PIGMENT_CHECKER: v = checker_value(p); break;
    case PIGMENT_HEXAGON: v = hexagon_value(p); break;
    case PIGMENT_GRADIENT: v = gradient_value(pig, p); break;
    case PIGMENT_BOZO: v = noise_value(p, generator); break;
    case PIGMENT_GRANITE: v = granite_value(p, generator); break;
    case PIGMENT_WRINKLES: v = wrinkles_value(p, generator); break;
    case PIGMENT_AGATE: v = agate_value(pig, p, generator); break;
    case PIGMENT_MARBLE: v = marble_value(pig, p, generator); break;
    case PIGMENT_WOOD: v = wood_value(pig, p); break;
    case PIGMENT_SPIRAL1: case PIGMENT_SPIRAL2: v = spiral_value(pig, p, generator); break;
    case PIGMENT_DENTS: v = noise_value(p, generator); v = v * v * v; break;
    case PIGMENT_BRICK: v = brick_value(pig, p); break;
    case PIGMENT_LEOPARD: v = leopard_value(p); break;
    case PIGMENT_ONION: v = onion_value(p); break;
    case PIGMENT_RADIAL: v = radial_value(p); break;
    case PIGMENT_QUILTED: v = quilted_value(pig, p); break;
    case PIGMENT_RIPPLES: v = ripples_value(pig, p, nwaves); break;
    case PIGMENT_WAVES: v = waves_value(pig, p, nwaves); break;
    case PIGMENT_PLANAR: v = planar_value(p); break;
    case PIGMENT_SPHERICAL: v = spherical_value(p); break;
    case PIGMENT_CYLINDRICAL: v = cylindrical_value(p); break;
    case PIGMENT_BOXED: v = boxed_value(p); break;
    case PIGMENT_SQUARE: v = square_value(p); break;
    case PIGMENT_TRIANGULAR: v = triangular_value(p); break;
    case PIGMENT_CUBIC: v = cubic_value(p); break;
    case PIGMENT_CELLS: v = cells_value(p); break;
    case PIGMENT_CRACKLE: v = crackle_value(pig, p, generator); break;
    case PIGMENT_FRACTAL: v = fractal_value(pig, p); break;
    case PIGMENT_PIGMENT_PATTERN:
        v = pigment_pattern_value(pig->inner, p, pig->scene_generator ? pig->scene_generator : default_generator,
                                  nwaves);
        break;
    default: return 0.0;
    }
    if (pig->frequency != 0.0)
        v = fmod(v * pig->frequency + pig->phase, 1.00001); /* POV-Ray's constant */
    if (v < 0.0)
        v -= floor(v);
    return wave(pig, v);
}

/* ---- image_map (POV-Ray's imageutil.cpp) -------------------------------- */

/* POV-Ray's wrap(): into [0, limit), also for negative values. */
static double pov_wrap(double v, double limit)
{
    double t = fmod(v, limit);
    if (t < 0.0)
        t += limit;
    if (t >= limit)
        t = 0.0;
    return t;
}

/* A pixel's colour (no_interpolation), at a place already on the picture
 * (or, with once, clamped to its edge), as float colour and filter and
 * transmit, POV-Ray's COLC, and its palette entry (-1: the picture is not
 * colour-mapped). A colour-mapped picture shows its entry's colour, filter
 * and transmit; another adds `filter all` and `transmit all` to its own
 * (transmit 1 - alpha). */
static int image_pixel(const Pigment *pig, double xc, double yc, float out[5])
{
    const SceneImage *im = pig->image;
    int ix, iy;
    if (pig->image_once) {
        ix = xc < 0.0 ? 0 : xc >= (double)im->width ? im->width - 1 : (int)xc;
        iy = yc < 0.0 ? 0 : yc >= (double)im->height ? im->height - 1 : (int)yc;
    } else {
        ix = (int)pov_wrap(xc, (double)im->width);
        iy = (int)pov_wrap(yc, (double)im->height);
    }
    const size_t at = (size_t)iy * (size_t)im->width + (size_t)ix;
    if (im->npalette > 0) {
        const int entry = im->index[at];
        for (int k = 0; k < 5; k++)
            out[k] = im->palette[entry][k];
        return entry;
    }
    const float *px = im->rgba + at * 4;
    out[0] = px[0];
    out[1] = px[1];
    out[2] = px[2];
    out[3] = 0.0f + (float)pig->image_filter_all;
    out[4] = (1.0f - px[3]) + (float)pig->image_transmit_all; /* transmit all adds to the alpha channel's */
    return -1;
}

/* The angle of (x, z) from the x axis about y, in [0, 2 pi), as POV-Ray's
 * image mappers take it; -1 where (x, z) is 0. */
static double angle_about_y(double x, double z)
{
    double len = sqrt(x * x + z * z);
    if (len == 0.0)
        return -1.0;
    if (z == 0.0)
        return x > 0 ? 0.0 : M_PI;
    double theta = acos(x / len);
    return z < 0.0 ? 2.0 * M_PI - theta : theta;
}

/* POV-Ray's mappers (imageutil.cpp): the picture's coordinates of p, 0
 * where p is off it. Planar with POV-Ray's gradient <1, -1, 0>: x across,
 * y up. */
static int image_map_coordinates(const Pigment *pig, Vec3 p, double w, double h, double *u, double *v)
{
    double x = p.x, y = p.y, z = p.z;
    switch (pig->image_map_type) {
    case 1: { /* spherical: longitude about y, latitude from the x-z plane */
        double len = sqrt(x * x + y * y + z * z);
        if (len == 0.0)
            return 0;
        x /= len;
        y /= len;
        z /= len;
        double phi = 0.5 + asin(y) / M_PI;
        double theta = angle_about_y(x, z);
        theta = theta < 0.0 ? 0.0 : theta / (2.0 * M_PI); /* at a pole any u will do */
        *u = theta * w;
        *v = phi * h;
        return 1;
    }
    case 2: { /* cylindrical about y, one picture's height from y 0 to 1 */
        if (pig->image_once && (y < 0.0 || y > 1.0))
            return 0;
        *v = fmod(y * h, h);
        double len = sqrt(x * x + y * y + z * z);
        if (len == 0.0)
            return 0;
        double theta = angle_about_y(x / len, z / len);
        if (theta < 0.0)
            return 0;
        *u = theta / (2.0 * M_PI) * w;
        return 1;
    }
    case 5: { /* torus of major radius 1 about y */
        double theta = angle_about_y(x, z);
        if (theta < 0.0)
            return 0;
        theta = 0.0 - theta;
        double r = sqrt(x * x + z * z) - 1.0, len = sqrt(r * r + y * y);
        double phi = acos(-r / len);
        if (y > 0.0)
            phi = 2.0 * M_PI - phi;
        *u = -(theta / (2.0 * M_PI)) * w;
        *v = phi / (2.0 * M_PI) * h;
        return 1;
    }
    default:
        if (pig->image_once && (x < 0.0 || x > 1.0 || y < 0.0 || y > 1.0))
            return 0;
        *u = fmod(x * w, w);
        *v = fmod(y * h, h);
        return 1;
    }
}

int image_map_position(const Pigment *pig, Vec3 p, double *x, double *y)
{
    const SceneImage *im = pig->image;
    const double w = (double)im->width, h = (double)im->height;
    double xc = 0.0, yc = 0.0;
    if (!image_map_coordinates(pig, p, w, h, &xc, &yc))
        return 0;
    /* map_pos */
    xc += POV_EPSILON;
    yc += POV_EPSILON;
    if (pig->image_once && (xc >= w || yc >= h || xc < 0.0 || yc < 0.0))
        return 0;
    *x = pov_wrap(xc, w);
    *y = pov_wrap(-yc, h); /* the picture's rows run down */
    return 1;
}

static Colour image_map_at(const Pigment *pig, Vec3 p)
{
    double xc, yc;
    if (!image_map_position(pig, p, &xc, &yc))
        return (Colour){ 1, 1, 1, 0, 1 }; /* off the picture: clear */
    return image_colour_at(pig, xc, yc);
}

Colour image_colour_index_at(const Pigment *pig, double xc, double yc, int *index, int as_stored)
{
    float c[5];
    if (pig->image_interpolate == 0) {
        *index = image_pixel(pig, xc, yc, c);
    } else {
        /* Interp: the four pixels around, weighed in double, their palette
         * entries too (as POV-Ray weighs them, -1 for a picture that has
         * none, then truncates) */
        xc += 0.5;
        yc += 0.5;
        int ix = (int)xc, iy = (int)yc;
        float corner[4][5];
        int entry[4];
        entry[0] = image_pixel(pig, (double)ix, (double)iy, corner[0]);
        entry[1] = image_pixel(pig, (double)ix - 1, (double)iy, corner[1]);
        entry[2] = image_pixel(pig, (double)ix, (double)iy - 1, corner[2]);
        entry[3] = image_pixel(pig, (double)ix - 1, (double)iy - 1, corner[3]);
        double f[4], a = xc - (int)xc, b = yc - (int)yc;
        if (pig->image_interpolate == 2) { /* bilinear */
            f[0] = a * b;
            f[1] = (1 - a) * b;
            f[2] = a * (1 - b);
            f[3] = (1 - a) * (1 - b);
        } else { /* normalised distance */
            double wt[4] = { 1.0 / ((1 - a) * (1 - a) + (1 - b) * (1 - b)), 1.0 / (a * a + (1 - b) * (1 - b)),
                             1.0 / ((1 - a) * (1 - a) + b * b), 1.0 / (a * a + b * b) };
            double sum = 0.0;
            for (int i = 0; i < 4; i++)
                sum += wt[i];
            for (int i = 0; i < 4; i++)
                f[i] = wt[i] / sum;
        }
        double weighed_index = 0.0;
        for (int k = 0; k < 5; k++) {
            double v = 0.0;
            for (int i = 0; i < 4; i++)
                v += (double)corner[i][k] * f[i];
            c[k] = (float)v;
        }
        for (int i = 0; i < 4; i++)
            weighed_index += entry[i] * f[i];
        *index = (int)weighed_index;
    }
    if (pig->image->premultiplied && !as_stored) {
        /* interpolated as stored; the colour un-premultiplied after, by the
         * alpha its transmit leaves (image_colour_at) */
        float alpha = 1.0f - c[4];
        if (alpha > 1e-10f) {
            c[0] /= alpha;
            c[1] /= alpha;
            c[2] /= alpha;
        }
    }
    return (Colour){ c[0], c[1], c[2], c[3], c[4] };
}

Colour image_colour_at(const Pigment *pig, double xc, double yc)
{
    int index;
    return image_colour_index_at(pig, xc, yc, &index, 0);
}

int material_map_number(const Pigment *pig, Vec3 p, int count)
{
    double xc, yc;
    int number = 0; /* off the picture: the first texture */
    if (image_map_position(pig, p, &xc, &yc)) {
        int index;
        Colour c = image_colour_index_at(pig, xc, yc, &index, 1);
        number = index == -1 ? (int)(c.r * 255.0) : index;
    }
    if (number > count)
        number %= count;
    /* POV-Ray walks its list that far, stopping at the last texture (and
     * never moving for a negative number) */
    return number < 0 ? 0 : number > count - 1 ? count - 1 : number;
}

Colour pigment_at(const Pigment *pig, Vec3 p)
{
    if (pig->kind == PIGMENT_IMAGE_MAP)
        return image_map_at(pig, p);
    if (pig->kind == PIGMENT_SOLID)
        return pig->colour;
    if (!pig->map_pigments && pig->kind != PIGMENT_AVERAGE)
        return colour_map_at(pig->map, pig->nmap, pattern_value(pig, p));
    Vec3 warped = warp_point(pig, p);
    const int generator = pig->scene_generator ? pig->scene_generator : NOISE_RANGE_CORRECTED;
    const int nwaves = pig->nwaves ? pig->nwaves : DEFAULT_NUMBER_OF_WAVES;
    if (pig->kind == PIGMENT_AVERAGE)
        return average_colour(pig, warped, generator, nwaves);
    double v = pattern_value_warped(pig, warped, generator, nwaves);
    return blend_map_at(pig, v, warped, generator, nwaves);
}

/* Barycentric weights of q (in the polygon's plane) with respect to the
 * polygon's first three points, from areas in its projection: they extend
 * affinely beyond the triangle, which suits the four-point box faces. */
static void first_three_weights(const World *w, const Polygon *p, Vec3 q, double b[3])
{
    const Vec3 *v = &w->points[p->first_point];
    int iu = p->axis_u, iv = p->axis_v;
    double u0 = v3_comp(v[0], iu), w0 = v3_comp(v[0], iv), u1 = v3_comp(v[1], iu), w1 = v3_comp(v[1], iv);
    double u2 = v3_comp(v[2], iu), w2 = v3_comp(v[2], iv), qu = v3_comp(q, iu), qv = v3_comp(q, iv);
    double area = (u1 - u0) * (w2 - w0) - (w1 - w0) * (u2 - u0);
    if (area == 0.0) {
        b[0] = 1.0;
        b[1] = b[2] = 0.0;
        return;
    }
    b[0] = ((u2 - u1) * (qv - w1) - (w2 - w1) * (qu - u1)) / area;
    b[1] = ((u0 - u2) * (qv - w2) - (w0 - w2) * (qu - u2)) / area;
    b[2] = 1.0 - b[0] - b[1];
}

Vec3 surface_uv(const World *w, int polygon, Vec3 world_point)
{
    if (polygon < -1)
        return shape_uv(&w->shapes[surface_shape(polygon)], world_point);
    if (polygon >= 0 && w->polygons[polygon].uv >= 0) {
        const Polygon *p = &w->polygons[polygon];
        const Vec3 *uv = &w->uvs[p->uv];
        double b[3];
        first_three_weights(w, p, world_point, b);
        return v3(b[0] * uv[0].x + b[1] * uv[1].x + b[2] * uv[2].x, b[0] * uv[0].y + b[1] * uv[1].y + b[2] * uv[2].y,
                  0.0);
    }
    return v3(world_point.x, world_point.y, 0.0); /* POV-Ray's default UVCoord */
}

Colour material_colour_at(const World *w, const Material *m, int polygon, Vec3 world_point)
{
    if (m->pattern.kind == PIGMENT_SOLID)
        return m->pigment;
    Vec3 at = m->pattern.uv_mapping ? surface_uv(w, polygon, world_point) : world_point;
    return pigment_at(&m->pattern, inverse_transform_point(&m->pattern_to_world, at));
}

/* ---- texture_map (POV-Ray's ComputeOneTextureColour) ----------------------- */

/* What the textures' normals need: the surface normal facing the ray, and
 * whether to perturb it (NULL: normals are not asked for, as by shadow
 * rays). */
typedef struct {
    Vec3 normal;
    int perturb;
    NormalSetting setting;
} NormalAsk;

static int map_textures(const World *w, int map, const Pigment *pattern, Vec3 p, int polygon, Vec3 world_point,
                        double weight, const Transform *chain, const NormalAsk *ask, SurfaceTexture *out, int n);

/* Entry e of a texture_map, seen at p (the point in the map's space, after
 * the map's turbulence; chain: that space to world): its plain textures
 * appended to out[n ...]. */
static int entry_textures(const World *w, const MapEntry *e, Vec3 p, int polygon, Vec3 world_point, double weight,
                          const Transform *chain, const NormalAsk *ask, SurfaceTexture *out, int n)
{
    if (n >= MAX_SURFACE_TEXTURES)
        return n; /* the parser keeps maps shallow enough never to come here */
    const Pigment *pig = &e->pattern;
    Vec3 q = p;
    if (pig->kind != PIGMENT_SOLID || e->map >= 0) {
        /* A uv-mapped pigment reads the surface's uv, whatever the maps
         * around it did to the point (POV-Ray's UV_MAP_PATTERN). */
        Vec3 at = pig->uv_mapping ? surface_uv(w, polygon, world_point) : p;
        q = inverse_transform_point(&pig->transform, at);
    }
    if (e->map >= 0) {
        Transform inner = pig->transform; /* the inner map's space to world */
        if (ask && !pig->uv_mapping)
            transform_compose(&inner, chain);
        return map_textures(w, e->map, pig, q, polygon, world_point, weight, &inner, ask, out, n);
    }
    out[n].weight = weight;
    out[n].colour = pigment_at(pig, q);
    out[n].finish = &e->finish;
    if (ask) {
        out[n].normal = ask->normal;
        if (ask->perturb && e->normal) {
            Vec3 uv = e->normal->kind == NORMAL_UV ? surface_uv(w, polygon, world_point) : v3(0, 0, 0);
            out[n].normal = normal_perturb_in(&ask->setting, e->normal, chain, p, uv, ask->normal);
        }
    }
    return n + 1;
}

/* A texture_map of pattern `pattern` at p (in its pattern space, before
 * its turbulence): the entries around the pattern's value there (POV-Ray's
 * Search_Blend_Map), weighed as ComputeOneTextureColour blends them; a
 * material_map's one entry. Its entries see the point as its turbulence
 * leaves it (POV-Ray's tpoint). */
static int map_textures(const World *w, int map, const Pigment *pattern, Vec3 p, int polygon, Vec3 world_point,
                        double weight, const Transform *chain, const NormalAsk *ask, SurfaceTexture *out, int n)
{
    const TextureMap *tm = &w->maps[map];
    const MapEntry *e = &w->map_entries[tm->first];
    Vec3 tp = warp_point(pattern, p);
    if (tm->material_map) /* one entry, by the picture there (ComputeOneTextureColour's BITMAP_PATTERN) */
        return entry_textures(w, &e[material_map_number(pattern, tp, tm->count)], tp, polygon, world_point, weight,
                              chain, ask, out, n);
    double v = pattern_value_warped(pattern, tp, NOISE_RANGE_CORRECTED, DEFAULT_NUMBER_OF_WAVES);
    int last = tm->count - 1, cur = 0, prev = 0;
    if (v >= e[last].value) {
        cur = prev = last;
    } else {
        while (v > e[cur].value)
            prev = cur++;
    }
    if (v == e[cur].value)
        prev = cur;
    if (prev == cur)
        return entry_textures(w, &e[cur], tp, polygon, world_point, weight, chain, ask, out, n);
    double f = (v - e[prev].value) / (e[cur].value - e[prev].value);
    n = entry_textures(w, &e[cur], tp, polygon, world_point, weight * f, chain, ask, out, n);
    return entry_textures(w, &e[prev], tp, polygon, world_point, weight * (1.0 - f), chain, ask, out, n);
}

SurfaceTexture material_plain_texture_at(const World *w, const Material *m, int polygon, Vec3 world_point,
                                         Vec3 normal, int perturb)
{
    SurfaceTexture t = { 1.0, material_colour_at(w, m, polygon, world_point), &m->finish, normal };
    if (perturb && m->normal) {
        const NormalSetting setting = normal_setting_of(w);
        Vec3 uv = m->normal->kind == NORMAL_UV ? surface_uv(w, polygon, world_point) : v3(0, 0, 0);
        t.normal = normal_perturb(&setting, m->normal, &m->normal_to_world, world_point, uv, normal);
    }
    return t;
}

/* A face with a texture per vertex (POV-Ray's Mesh::Determine_Textures):
 * its three plain textures, weighed by the point's barycentric weights
 * (normalised by their sum, as POV-Ray does); one whose weight is below
 * adc_bailout is left out and the others keep theirs (ComputeTextureColour
 * and ComputeShadowColour skip it), so near a vertex the weights sum to a
 * little less than 1. Each is shaded whole and the shaded colours blended,
 * as a texture_map's are. */
static int vertex_textures_at(const World *w, int polygon, Vec3 world_point, const NormalAsk *ask,
                              SurfaceTexture out[MAX_SURFACE_TEXTURES])
{
    const Polygon *p = &w->polygons[polygon];
    double b[3];
    if (!polygon_barycentric(w, p, world_point, b))
        b[0] = 1.0, b[1] = b[2] = 0.0;
    double sum = b[0] + b[1] + b[2];
    int n = 0;
    for (int i = 0; i < 3; i++) {
        double weight = b[i] / sum;
        if (weight < w->adc_bailout)
            continue;
        const Material *m = &w->materials[w->vertex_materials[p->vertex_materials + i]];
        out[n] = material_plain_texture_at(w, m, polygon, world_point, ask ? ask->normal : v3(0, 0, 0),
                                           ask && ask->perturb);
        out[n++].weight = weight;
    }
    if (n == 0) { /* adc_bailout above a third: POV-Ray shades with no texture, black */
        out[0] = material_plain_texture_at(w, &w->materials[p->material], polygon, world_point,
                                           ask ? ask->normal : v3(0, 0, 0), 0);
        out[n++].weight = 0.0;
    }
    return n;
}

static int textures_at(const World *w, const Material *m, int polygon, Vec3 world_point, const NormalAsk *ask,
                       SurfaceTexture out[MAX_SURFACE_TEXTURES])
{
    if (polygon >= 0 && w->polygons[polygon].vertex_materials >= 0)
        return vertex_textures_at(w, polygon, world_point, ask, out);
    if (m->map < 0) {
        out[0] = material_plain_texture_at(w, m, polygon, world_point, ask ? ask->normal : v3(0, 0, 0),
                                           ask && ask->perturb);
        return 1;
    }
    Vec3 at = m->pattern.uv_mapping ? surface_uv(w, polygon, world_point) : world_point;
    Vec3 p = inverse_transform_point(&m->pattern_to_world, at);
    return map_textures(w, m->map, &m->pattern, p, polygon, world_point, 1.0, &m->pattern_to_world, ask, out, 0);
}

int material_textures_at(const World *w, const Material *m, int polygon, Vec3 world_point,
                         SurfaceTexture out[MAX_SURFACE_TEXTURES])
{
    return textures_at(w, m, polygon, world_point, NULL, out);
}

int material_textures_normals_at(const World *w, const Material *m, int polygon, Vec3 world_point, Vec3 normal,
                                 int perturb, SurfaceTexture out[MAX_SURFACE_TEXTURES])
{
    NormalAsk ask = { normal, perturb, normal_setting_of(w) };
    return textures_at(w, m, polygon, world_point, &ask, out);
}

int material_layers_at(const World *w, const Material *m, int polygon, Vec3 world_point, Vec3 normal, int perturb,
                       SurfaceTexture out[MAX_TEXTURE_LAYERS])
{
    int n = 0;
    for (;;) {
        out[n++] = material_plain_texture_at(w, m, polygon, world_point, normal, perturb);
        if (m->below < 0 || n == MAX_TEXTURE_LAYERS) /* the parser keeps stacks within the limit */
            return n;
        m = &w->materials[m->below];
    }
}

/* A layered texture's filter (ComputeShadowTexture): what each layer lets
 * through, multiplied. */
static RGB layers_filter_at(const World *w, const Material *m, int polygon, Vec3 world_point, int *blocks)
{
    RGB through = { 1, 1, 1 };
    *blocks = 0;
    for (; m; m = m->below >= 0 ? &w->materials[m->below] : NULL) {
        Colour c = material_colour_at(w, m, polygon, world_point);
        *blocks |= c.filter == 0.0 && c.transmit == 0.0;
        through.r *= c.r * c.filter + c.transmit;
        through.g *= c.g * c.filter + c.transmit;
        through.b *= c.b * c.filter + c.transmit;
    }
    return through;
}

RGB material_filter_at(const World *w, const Material *m, int polygon, Vec3 world_point, int *blocks)
{
    if (m->below >= 0 && (polygon < 0 || w->polygons[polygon].vertex_materials < 0))
        return layers_filter_at(w, m, polygon, world_point, blocks);
    if (m->map < 0 && (polygon < 0 || w->polygons[polygon].vertex_materials < 0)) {
        /* a plain texture (textures_at's first case): its one colour, with
         * none of the textures' records made (the shadow ray's filtering
         * through glass, at every surface it crosses) */
        Colour c = material_colour_at(w, m, polygon, world_point);
        *blocks = c.filter == 0.0 && c.transmit == 0.0;
        RGB through = { c.r * c.filter + c.transmit, c.g * c.filter + c.transmit, c.b * c.filter + c.transmit };
        return through;
    }
    SurfaceTexture t[MAX_SURFACE_TEXTURES];
    int n = material_textures_at(w, m, polygon, world_point, t);
    const Colour *c = &t[0].colour;
    RGB through = { c->r * c->filter + c->transmit, c->g * c->filter + c->transmit, c->b * c->filter + c->transmit };
    *blocks = c->filter == 0.0 && c->transmit == 0.0;
    if (n == 1 && t[0].weight == 1.0)
        return through;
    /* POV-Ray's ComputeShadowTexture for each texture, blended by weight */
    through.r *= t[0].weight;
    through.g *= t[0].weight;
    through.b *= t[0].weight;
    for (int i = 1; i < n; i++) {
        c = &t[i].colour;
        through.r += t[i].weight * (c->r * c->filter + c->transmit);
        through.g += t[i].weight * (c->g * c->filter + c->transmit);
        through.b += t[i].weight * (c->b * c->filter + c->transmit);
        *blocks &= c->filter == 0.0 && c->transmit == 0.0;
    }
    return through;
}

/* The sky's pigment i at the unit direction's point p. */
static Colour sky_pigment_at(const World *w, int i, Vec3 p)
{
    const Pigment *pig = &w->sky->pigments[i];
    return pigment_at(pig, inverse_transform_point(&pig->transform, p));
}

/* Scenes before #version 3.7: POV-Ray 3.6's layering, kept by 3.7 for
 * them. Opacity is weighed by the filter and transmit gathered so far,
 * and the background shows through by the layers' combined filter and
 * transmit. */
static RGB legacy_sky_colour(const World *w, Vec3 p)
{
    RGB col = { 0, 0, 0 };
    double fr = 1, fg = 1, fb = 1, ff = 1, ft = 1; /* the product of the layers' colours */
    double trans = 1.0;
    for (int i = w->sky->npigments - 1; i >= 0; i--) {
        Colour c = sky_pigment_at(w, i, p);
        double att = trans * (1.0 - c.filter - c.transmit);
        col.r += c.r * att;
        col.g += c.g * att;
        col.b += c.b * att;
        fr *= c.r;
        fg *= c.g;
        fb *= c.b;
        ff *= c.filter;
        ft *= c.transmit;
        trans = fabs(ff) + fabs(ft);
    }
    col.r += w->background.r * (fr * ff + ft);
    col.g += w->background.g * (fg * ff + ft);
    col.b += w->background.b * (fb * ff + ft);
    return col;
}

/* POV-Ray 3.7's sky: the sky sphere's layers, the last written on top, each
 * letting through its colour times filter plus transmit; fil is what the
 * layers together let through. */
static RGB sky_layers(const World *w, Vec3 dir, RGB *fil)
{
    RGB col = { 0, 0, 0 };
    const SkySphere *sky = w->sky;
    *fil = (RGB){ 1, 1, 1 };
    if (!sky)
        return col;
    /* POV-Ray transforms the direction as a point (MInvTransPoint) */
    Vec3 p = inverse_transform_point(&sky->transform, dir);
    for (int i = sky->npigments - 1; i >= 0; i--) {
        Colour c = sky_pigment_at(w, i, p);
        double opacity = 1.0 - c.filter - c.transmit;
        col.r += c.r * opacity * fil->r;
        col.g += c.g * opacity * fil->g;
        col.b += c.b * opacity * fil->b;
        fil->r *= c.r * c.filter + c.transmit;
        fil->g *= c.g * c.filter + c.transmit;
        fil->b *= c.b * c.filter + c.transmit;
    }
    return col;
}

RGB sky_colour(const World *w, Vec3 dir)
{
    return sky_colour_over(w, dir, w->background);
}

RGB sky_colour_over(const World *w, Vec3 dir, RGB below)
{
    if (w->sky && w->legacy_sky)
        return legacy_sky_colour(w, inverse_transform_point(&w->sky->transform, dir));
    RGB fil, col = sky_layers(w, dir, &fil);
    /* the background below, as one more opaque layer */
    col.r += below.r * fil.r;
    col.g += below.g * fil.g;
    col.b += below.b * fil.b;
    return col;
}

RGB sky_colour_alpha(const World *w, Vec3 dir, double *transmit)
{
    RGB col = { 0, 0, 0 };
    if (w->legacy_sky) { /* POV-Ray 3.6's rule: the background is not there */
        *transmit = 1.0;
        return col;
    }
    RGB fil;
    col = sky_layers(w, dir, &fil);
    /* the background as one more layer, with its own filter and transmit */
    const RGB bg = w->background_colour;
    const double f = w->background_filter, t = w->background_transmit, opacity = 1.0 - f - t;
    col.r += bg.r * opacity * fil.r;
    col.g += bg.g * opacity * fil.g;
    col.b += bg.b * opacity * fil.b;
    fil.r *= bg.r * f + t;
    fil.g *= bg.g * f + t;
    fil.b *= bg.b * f + t;
    /* POV-Ray: min(1, |greyscale|), its weights summed in single precision */
    double grey = fabs((double)(float)(0.297 * fil.r + 0.589 * fil.g + 0.114 * fil.b));
    *transmit = grey < 1.0 ? grey : 1.0;
    return col;
}
