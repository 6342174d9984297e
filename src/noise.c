/* POV-Ray 3.7's noise (texture.cpp there), written from its definition.
 *
 * Two generators share one interface:
 * - the lattice noise of generators 1 and 2: each lattice point hashes (two
 *   4096-entry permutation look-ups) to one of 256 rows of a table of
 *   random numbers, which give it a value and a gradient; the eight
 *   corners around a point are blended with the cubic s-curve. The
 *   permutation comes from POV-Ray's linear congruential generator; the
 *   random numbers are POV-Ray's fixed table (data only: they were typed
 *   into POV-Ray, no generator makes them).
 * - Perlin's gradient noise of generator 3: 2048 random unit gradients and
 *   a permutation, both from the same generator seeded with 1.
 *
 * Tables are computed on first use rather than stored: the code that makes
 * them is short and shows where every number comes from, and they take
 * microseconds. pthread_once makes that first use safe from any thread;
 * afterwards the tables are only read. */
#include "noise.h"

#include <pthread.h>

#define POV_EPSILON 1.0e-10 /* POV-Ray's EPSILON */

/* The lattice noise's random numbers, in POV-Ray's order. Row k of the
 * table it indexes holds value k and half of it (see build_tables). */
static const double random_values[267] = {
    -1, 0.604974, -0.937102, 0.414115, 0.576226, -0.0161593, 0.432334, 0.103685,
    0.590539, 0.0286412, 0.46981, -0.84622, -0.0734112, -0.304097, -0.40206, -0.210132,
    -0.919127, 0.652033, -0.83151, -0.183948, -0.671107, 0.852476, 0.043595, -0.404532,
    0.75494, -0.335653, 0.618433, 0.605707, 0.708583, -0.477195, 0.899474, 0.490623,
    0.221729, -0.400381, -0.853727, -0.932586, 0.659113, 0.961303, 0.325948, -0.750851,
    0.842466, 0.734401, -0.649866, 0.394491, -0.466056, -0.434073, 0.109026, 0.0847028,
    -0.738857, 0.241505, 0.16228, -0.71426, -0.883665, -0.150408, -0.90396, -0.686549,
    -0.785214, 0.488548, 0.0246433, 0.142473, -0.602136, 0.375845, -0.00779736, 0.498955,
    -0.268147, 0.856382, -0.386007, -0.596094, -0.867735, -0.570977, -0.914366, 0.28896,
    0.672206, -0.233783, 0.94815, 0.895262, 0.343252, -0.173388, -0.767971, -0.314748,
    0.824308, -0.342092, 0.721431, -0.24004, -0.63653, 0.553277, 0.376272, 0.158984,
    -0.452659, 0.396323, -0.420676, -0.454154, 0.122179, 0.295857, 0.0664225, -0.202075,
    -0.724788, 0.453513, 0.224567, -0.908812, 0.176349, -0.320516, -0.697139, 0.742702,
    -0.900786, 0.471489, -0.133532, 0.119127, -0.889769, -0.23183, -0.669673, -0.046891,
    -0.803433, -0.966735, 0.475578, -0.652644, 0.0112459, -0.730007, 0.128283, 0.145647,
    -0.619318, 0.272023, 0.392966, 0.646418, -0.0207675, -0.315908, 0.480797, 0.535668,
    -0.250172, -0.83093, -0.653773, -0.443809, 0.119982, -0.897642, 0.89453, 0.165789,
    0.633875, -0.886839, 0.930877, -0.537194, 0.587732, 0.722011, -0.209461, -0.0424659,
    -0.814267, -0.919432, 0.280262, -0.66302, -0.558099, -0.537469, -0.598779, 0.929656,
    -0.170794, -0.537163, 0.312581, 0.959442, 0.722652, 0.499931, 0.175616, -0.534874,
    -0.685115, 0.444999, 0.17171, 0.108202, -0.768704, -0.463828, 0.254231, 0.546014,
    0.869474, 0.875212, -0.944427, 0.130724, -0.110185, 0.312184, -0.33138, -0.629206,
    0.0606546, 0.722866, -0.0979477, 0.821561, 0.0931258, -0.972808, 0.0318151, -0.867033,
    -0.387228, 0.280995, -0.218189, -0.539178, -0.427359, -0.602075, 0.311971, 0.277974,
    0.773159, 0.592493, -0.0331884, -0.630854, -0.269947, 0.339132, 0.581079, 0.209461,
    -0.317433, -0.284993, 0.181323, 0.341634, 0.804959, -0.229572, -0.758907, -0.336721,
    0.605463, -0.991272, -0.0188754, -0.300191, 0.368307, -0.176135, -0.3832, -0.749569,
    0.62356, -0.573938, 0.278309, -0.971313, 0.839994, -0.830686, 0.439078, 0.66128,
    0.694514, 0.0565042, 0.54342, -0.438804, -0.0228428, -0.687068, 0.857267, 0.301991,
    -0.494255, -0.941039, 0.775509, 0.410575, -0.362081, -0.671534, -0.348379, 0.932433,
    0.886442, 0.868681, -0.225666, -0.062211, -0.0976425, -0.641444, -0.848112, 0.724697,
    0.473503, 0.998749, 0.174701, 0.559625, -0.029099, -0.337392, -0.958129, -0.659785,
    0.236042, -0.246937, 0.659449, -0.027512, 0.821897, -0.226215, 0.0181735, 0.500481,
    -0.420127, -0.427878, 0.566186,
};

enum {
    HASH_SIZE = 4096,        /* lattice coordinates are taken modulo this */
    GRADIENTS = 2048,        /* generator 3's gradients (a power of 2) */
};

static struct {
    unsigned short hash[2 * HASH_SIZE]; /* a permutation of 0..4095, twice */
    double rtable[2 * 267];            /* value k at 2k, half of it at 2k+1 */
    int perm[2 * (GRADIENTS + 1)];     /* generator 3: permutation, twice */
    Vec3 gradients[2 * (GRADIENTS + 1)];
} tables;

static pthread_once_t tables_once = PTHREAD_ONCE_INIT;

/* POV-Ray's pseudo-random generator: a 32-bit linear congruential sequence
 * (an int overflowing as two's complement), bits 16..30 as the result. */
static unsigned lcg_next(unsigned *state)
{
    *state = *state * 1812433253u + 12345u;
    return (*state >> 16) & 0x7FFFu;
}

static void build_tables(void)
{
    unsigned state = 0;
    for (int i = 0; i < HASH_SIZE; i++)
        tables.hash[i] = (unsigned short)i;
    for (int i = HASH_SIZE - 1; i >= 0; i--) {
        int j = (int)(lcg_next(&state) % HASH_SIZE);
        unsigned short t = tables.hash[i];
        tables.hash[i] = tables.hash[j];
        tables.hash[j] = t;
    }
    for (int i = 0; i < HASH_SIZE; i++)
        tables.hash[HASH_SIZE + i] = tables.hash[i];
    for (int i = 0; i < 267; i++) {
        tables.rtable[2 * i] = random_values[i];
        tables.rtable[2 * i + 1] = random_values[i] * 0.5;
    }

    /* Generator 3: gradients uniform on the unit sphere (rejection from the
     * cube), then a permutation, from one sequence seeded with 1. */
    state = 1;
    for (int i = 0; i < GRADIENTS; i++) {
        double v[3], s;
        do {
            for (int k = 0; k < 3; k++)
                v[k] = (double)((int)(lcg_next(&state) % (GRADIENTS << 1)) - GRADIENTS) / (double)GRADIENTS;
            s = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        } while (s > 1.0 || s < 1.0e-5);
        s = 1.0 / sqrt(s);
        tables.gradients[i] = v3(v[0] * s, v[1] * s, v[2] * s);
    }
    for (int i = 0; i < GRADIENTS; i++)
        tables.perm[i] = i;
    /* As POV-Ray: the walk starts one past the end (entry GRADIENTS, still
     * 0) and takes every other entry. */
    for (int i = GRADIENTS; i > 0; i -= 2) {
        int k = tables.perm[i];
        int j = (int)(lcg_next(&state) % GRADIENTS);
        tables.perm[i] = tables.perm[j];
        tables.perm[j] = k;
    }
    for (int i = 0; i < GRADIENTS + 2; i++) { /* in order: later copies read earlier ones */
        tables.perm[GRADIENTS + i] = tables.perm[i];
        tables.gradients[GRADIENTS + i] = tables.gradients[i];
    }
}

static void ensure_tables(void)
{
    pthread_once(&tables_once, build_tables);
}

/* ---- generators 1 and 2 ---------------------------------------------------- */

/* The lattice cell of one coordinate: its index modulo 4096 (offset as
 * POV-Ray offsets it, by 10000) and the position in the cell. */
typedef struct {
    int index;
    double frac;
} LatticeCoord;

static LatticeCoord lattice_coord(double x)
{
    LatticeCoord c;
    /* POV-Ray truncates toward zero after lowering negative values by
     * 1 - 1e-10 (so -0.5 is in cell -1, and -1 in cell -1 at frac 0).
     * Beyond int's range that is undefined there; here such coordinates
     * are held at the range's ends. */
    double lowered = x >= 0.0 ? x : x - (1.0 - POV_EPSILON);
    if (!(lowered > -2147483000.0))
        lowered = -2147483000.0;
    if (lowered > 2147483000.0)
        lowered = 2147483000.0;
    int whole = (int)lowered;
    c.index = (int)((unsigned)(whole + 10000) & 0xFFFu);
    c.frac = x - whole;
    return c;
}

static double s_curve(double a) { return a * a * (3.0 - 2.0 * a); }

static int hash2(int a, int b) { return tables.hash[tables.hash[a] ^ b]; }

/* The row of the random table for a lattice point (hash of x and y, z). */
static const double *table_row(int xy_hash, int z)
{
    return &tables.rtable[(tables.hash[xy_hash ^ z] & 0xFF) * 2];
}

/* One corner's contribution: its value plus its gradient dotted with the
 * offset from it, weighted. */
static double corner(const double *m, double weight, double x, double y, double z)
{
    return weight * (m[1] + m[2] * x + m[4] * y + m[6] * z);
}

static double lattice_noise(Vec3 p)
{
    LatticeCoord cx = lattice_coord(p.x), cy = lattice_coord(p.y), cz = lattice_coord(p.z);
    int ix = cx.index, iy = cy.index, iz = cz.index;
    double x0 = cx.frac, y0 = cy.frac, z0 = cz.frac;
    double x1 = x0 - 1, y1 = y0 - 1, z1 = z0 - 1;
    double sx = s_curve(x0), sy = s_curve(y0), sz = s_curve(z0);
    double tx = 1 - sx, ty = 1 - sy, tz = 1 - sz;
    double txty = tx * ty, sxty = sx * ty, txsy = tx * sy, sxsy = sx * sy;
    int h00 = hash2(ix, iy), h10 = hash2(ix + 1, iy), h01 = hash2(ix, iy + 1), h11 = hash2(ix + 1, iy + 1);
    /* the same eight terms in the same order as POV-Ray: sums round alike */
    double sum = corner(table_row(h00, iz), txty * tz, x0, y0, z0);
    sum += corner(table_row(h10, iz), sxty * tz, x1, y0, z0);
    sum += corner(table_row(h01, iz), txsy * tz, x0, y1, z0);
    sum += corner(table_row(h11, iz), sxsy * tz, x1, y1, z0);
    sum += corner(table_row(h00, iz + 1), txty * sz, x0, y0, z1);
    sum += corner(table_row(h10, iz + 1), sxty * sz, x1, y0, z1);
    sum += corner(table_row(h01, iz + 1), txsy * sz, x0, y1, z1);
    sum += corner(table_row(h11, iz + 1), sxsy * sz, x1, y1, z1);
    return sum;
}

/* The vector version: three values per corner, from consecutive rows. */
static void vector_corner(Vec3 *acc, const double *m, double weight, double x, double y, double z)
{
    acc->x += corner(m, weight, x, y, z);
    acc->y += corner(m + 8, weight, x, y, z);
    acc->z += corner(m + 16, weight, x, y, z);
}

Vec3 noise_vector(Vec3 p)
{
    ensure_tables();
    LatticeCoord cx = lattice_coord(p.x), cy = lattice_coord(p.y), cz = lattice_coord(p.z);
    int ix = cx.index, iy = cy.index, iz = cz.index;
    double x0 = cx.frac, y0 = cy.frac, z0 = cz.frac;
    double x1 = x0 - 1, y1 = y0 - 1, z1 = z0 - 1;
    double sx = s_curve(x0), sy = s_curve(y0), sz = s_curve(z0);
    double tx = 1 - sx, ty = 1 - sy, tz = 1 - sz;
    double txty = tx * ty, sxty = sx * ty, txsy = tx * sy, sxsy = sx * sy;
    int h00 = hash2(ix, iy), h10 = hash2(ix + 1, iy), h01 = hash2(ix, iy + 1), h11 = hash2(ix + 1, iy + 1);
    const double *m = table_row(h00, iz);
    double w = txty * tz;
    Vec3 r = v3(corner(m, w, x0, y0, z0), corner(m + 8, w, x0, y0, z0), corner(m + 16, w, x0, y0, z0));
    /* POV-Ray's order of corners here differs from the scalar noise's */
    vector_corner(&r, table_row(h10, iz), sxty * tz, x1, y0, z0);
    vector_corner(&r, table_row(h11, iz), sxsy * tz, x1, y1, z0);
    vector_corner(&r, table_row(h01, iz), txsy * tz, x0, y1, z0);
    vector_corner(&r, table_row(h01, iz + 1), txsy * sz, x0, y1, z1);
    vector_corner(&r, table_row(h11, iz + 1), sxsy * sz, x1, y1, z1);
    vector_corner(&r, table_row(h10, iz + 1), sxty * sz, x1, y0, z1);
    vector_corner(&r, table_row(h00, iz + 1), txty * sz, x0, y0, z1);
    return r;
}

/* ---- generator 3 ------------------------------------------------------------ */

typedef struct {
    int b0, b1;
    double r0, r1;
} GradientCoord;

static GradientCoord gradient_coord(double x)
{
    GradientCoord c;
    double t = x + 10000000.023157213; /* POV-Ray's offset: keeps t positive */
    double f = floor(t);
    if (!(f > -2147483000.0))
        f = -2147483000.0;
    if (f > 2147483000.0)
        f = 2147483000.0;
    int it = (int)f;
    c.b0 = it & (GRADIENTS - 1);
    c.b1 = (c.b0 + 1) & (GRADIENTS - 1);
    c.r0 = t - it;
    c.r1 = c.r0 - 1.0;
    return c;
}

static double lerp(double t, double a, double b) { return a + t * (b - a); }

static double at_gradient(int i, double x, double y, double z)
{
    Vec3 g = tables.gradients[i];
    return x * g.x + y * g.y + z * g.z;
}

static double gradient_noise(Vec3 p)
{
    GradientCoord cx = gradient_coord(p.x), cy = gradient_coord(p.y), cz = gradient_coord(p.z);
    int i = tables.perm[cx.b0], j = tables.perm[cx.b1];
    int b00 = tables.perm[i + cy.b0], b10 = tables.perm[j + cy.b0];
    int b01 = tables.perm[i + cy.b1], b11 = tables.perm[j + cy.b1];
    double sx = s_curve(cx.r0), sy = s_curve(cy.r0), sz = s_curve(cz.r0);
    double a = lerp(sx, at_gradient(b00 + cz.b0, cx.r0, cy.r0, cz.r0), at_gradient(b10 + cz.b0, cx.r1, cy.r0, cz.r0));
    double b = lerp(sx, at_gradient(b01 + cz.b0, cx.r0, cy.r1, cz.r0), at_gradient(b11 + cz.b0, cx.r1, cy.r1, cz.r0));
    double c = lerp(sy, a, b);
    a = lerp(sx, at_gradient(b00 + cz.b1, cx.r0, cy.r0, cz.r1), at_gradient(b10 + cz.b1, cx.r1, cy.r0, cz.r1));
    b = lerp(sx, at_gradient(b01 + cz.b1, cx.r0, cy.r1, cz.r1), at_gradient(b11 + cz.b1, cx.r1, cy.r1, cz.r1));
    double d = lerp(sy, a, b);
    return lerp(sz, c, d);
}

/* ---- the interface ------------------------------------------------------------ */

static double clamp01(double v) { return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v; }

double noise_value(Vec3 p, int generator)
{
    ensure_tables();
    if (generator == NOISE_PERLIN) /* POV-Ray's factors correct the table's bias */
        return clamp01(0.5 * (1.59 * gradient_noise(p) + 0.985));
    double sum = lattice_noise(p);
    if (generator == NOISE_RANGE_CORRECTED) {
        /* the raw range is about [-1.05242, 0.988997]: stretched to [0, 1] */
        sum += 1.05242;
        sum *= 0.48985582;
    } else {
        sum = sum + 0.5;
    }
    return clamp01(sum);
}

/* One octave's share: generators 2 and 3 stretch the noise's middle. */
static double octave_noise(Vec3 p, int generator)
{
    return generator > 1 ? 2.0 * noise_value(p, generator) - 0.5 : noise_value(p, generator);
}

double noise_turbulence(Vec3 p, int octaves, double omega, double lambda, int generator)
{
    double value = octave_noise(p, generator);
    if (generator > 1)
        value = fmin(fmax(value, 0.0), 1.0); /* only the first octave is clamped */
    double l = lambda, o = omega;
    for (int i = 2; i <= octaves; i++) {
        value += o * octave_noise(v3(p.x * l, p.y * l, p.z * l), generator);
        if (i < octaves) {
            l *= lambda;
            o *= omega;
        }
    }
    return value;
}

Vec3 noise_vector_turbulence(Vec3 p, int octaves, double omega, double lambda)
{
    Vec3 r = noise_vector(p);
    double l = lambda, o = omega;
    for (int i = 2; i <= octaves; i++) {
        Vec3 v = noise_vector(v3(p.x * l, p.y * l, p.z * l));
        r.x += o * v.x;
        r.y += o * v.y;
        r.z += o * v.z;
        if (i < octaves) {
            l *= lambda;
            o *= omega;
        }
    }
    return r;
}
