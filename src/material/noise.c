/* POV-Ray 3.7's noise (texture.cpp there), written from its definition.
 *
 * Two generators share one interface:
 * - the lattice noise of generators 1 and 2: each lattice point hashes (two
 *   4096-entry permutation look-ups) to one of 256 rows of a table of
 *   random numbers, which give it a value and a gradient; the eight
 *   corners around a point are blended with the cubic s-curve. The
 *   permutation comes from POV-Ray's linear congruential generator; the
 *   random numbers from the CRC-16 generator that once made POV-Ray's
 *   fixed table (see random_value).
 * - Perlin's gradient noise of generator 3: 2048 random unit gradients and
 *   a permutation, both from the same generator seeded with 1.
 *
 * Tables are computed on first use rather than stored: the code that makes
 * them is short and shows where every number comes from, and they take
 * microseconds. pthread_once makes that first use safe from any thread;
 * afterwards the tables are only read. */
#include "noise.h"

#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "convert.h"

#define POV_EPSILON 1.0e-10 /* POV-Ray's EPSILON */

enum { RANDOM_VALUES = 267 };

/* CRC-16 (the reflected polynomial 0xA001, starting from 0) of bytes. */
static unsigned crc16(const unsigned char *bytes, int n)
{
    unsigned crc = 0;
    for (int i = 0; i < n; i++) {
        crc ^= bytes[i];
        for (int bit = 0; bit < 8; bit++)
            crc = (crc & 1u) ? (crc >> 1) ^ 0xA001u : crc >> 1;
    }
    return crc;
}

/* The lattice noise's random number k, as POV-Ray has it. POV-Ray keeps
 * these 267 numbers as a typed-in table; they are what its old generator
 * (POV-Ray 3.0's InitRTable) made on a big-endian machine: the CRC-16 of the
 * point (k, k, k) * 0.12345 as three big-endian doubles, scaled to [-1, 1],
 * then printed to 6 significant digits (%g). The same steps here give the
 * same doubles, bit for bit. */
static double random_value(int k)
{
    double v = (double)k * 0.12345;
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    unsigned char point[24];
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < 8; i++)
            point[8 * c + i] = (unsigned char)(bits >> (56 - 8 * i));
    double r = (double)crc16(point, 24) * (2.0 / 65535.0) - 1.0;
    char printed[32];
    snprintf(printed, sizeof printed, "%g", r);
    return strtod(printed, NULL);
}

enum {
    HASH_SIZE = 4096,        /* lattice coordinates are taken modulo this */
    GRADIENTS = 2048,        /* generator 3's gradients (a power of 2) */
};

static struct {
    unsigned short hash[2 * HASH_SIZE]; /* a permutation of 0..4095, twice */
    double rtable[2 * RANDOM_VALUES];  /* value k at 2k, half of it at 2k+1 */
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
    for (int i = 0; i < RANDOM_VALUES; i++) {
        tables.rtable[2 * i] = random_value(i);
        tables.rtable[2 * i + 1] = tables.rtable[2 * i] * 0.5;
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

unsigned noise_hash(unsigned i)
{
    ensure_tables();
    return tables.hash[i & 0xfffu];
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
    int whole = int_clamped(lowered, -2147483000, 2147483000);
    c.index = (int)(((unsigned)whole + 10000u) & 0xFFFu); /* unsigned: no overflow near the ends */
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

/* The lattice cell around a point: the offsets from its corners, the
 * s-curve weights and the hashes of its four (x, y) columns, shared by the
 * scalar and the vector noise. */
typedef struct {
    int iz;
    double x0, y0, z0, x1, y1, z1;
    double sz, tz, txty, sxty, txsy, sxsy;
    int h00, h10, h01, h11;
} LatticeCell;

static LatticeCell lattice_cell(Vec3 p)
{
    LatticeCoord cx = lattice_coord(p.x), cy = lattice_coord(p.y), cz = lattice_coord(p.z);
    LatticeCell c;
    int ix = cx.index, iy = cy.index;
    c.iz = cz.index;
    c.x0 = cx.frac, c.y0 = cy.frac, c.z0 = cz.frac;
    c.x1 = c.x0 - 1, c.y1 = c.y0 - 1, c.z1 = c.z0 - 1;
    double sx = s_curve(c.x0), sy = s_curve(c.y0);
    c.sz = s_curve(c.z0);
    double tx = 1 - sx, ty = 1 - sy;
    c.tz = 1 - c.sz;
    c.txty = tx * ty, c.sxty = sx * ty, c.txsy = tx * sy, c.sxsy = sx * sy;
    c.h00 = hash2(ix, iy), c.h10 = hash2(ix + 1, iy), c.h01 = hash2(ix, iy + 1), c.h11 = hash2(ix + 1, iy + 1);
    return c;
}

static double lattice_noise(Vec3 p)
{
    const LatticeCell c = lattice_cell(p);
    const int iz = c.iz, h00 = c.h00, h10 = c.h10, h01 = c.h01, h11 = c.h11;
    const double x0 = c.x0, y0 = c.y0, z0 = c.z0, x1 = c.x1, y1 = c.y1, z1 = c.z1;
    const double sz = c.sz, tz = c.tz, txty = c.txty, sxty = c.sxty, txsy = c.txsy, sxsy = c.sxsy;
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
    const LatticeCell c = lattice_cell(p);
    const int iz = c.iz, h00 = c.h00, h10 = c.h10, h01 = c.h01, h11 = c.h11;
    const double x0 = c.x0, y0 = c.y0, z0 = c.z0, x1 = c.x1, y1 = c.y1, z1 = c.z1;
    const double sz = c.sz, tz = c.tz, txty = c.txty, sxty = c.sxty, txsy = c.txsy, sxsy = c.sxsy;
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
    int it = int_clamped(floor(t), -2147483000, 2147483000);
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
