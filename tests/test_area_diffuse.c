/* area_illumination's diffuse sum (src/shading/area_diffuse.h): the fast
 * loop, two samples at a time, against the plain one, which computes what
 * shade.c's general loop computes sample by sample: the same light in
 * every texture, bit for bit, over random lights (square and circular
 * grids, lights one sample wide along an axis, odd and even counts, axes
 * turned as orient turns them), points, normals facing either way and
 * grazing, one to three textures, lit on one side or both. Also that the
 * sum is not empty: a light in front of a surface adds to it. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "area_diffuse.h"
#include "area_light_samples.h"
#include "tap.h"

static uint64_t rng = 0x9e3779b97f4a7c15ull;

static double uniform(double lo, double hi) /* xorshift64* */
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return lo + (hi - lo) * (double)((rng * 0x2545f4914f6cdd1dull) >> 11) / 9007199254740992.0;
}

static Vec3 random_vec(double r) { return v3(uniform(-r, r), uniform(-r, r), uniform(-r, r)); }

static int same_bits(RGB a, RGB b) { return memcmp(&a, &b, sizeof a) == 0; }

/* One random case: returns 1 when the two loops agree bit for bit; *lit
 * tells whether any light arrived. */
static int one_case(int size1, int size2, int circular, int orient, int *lit)
{
    Light l;
    memset(&l, 0, sizeof l);
    l.kind = LIGHT_POINT;
    l.beam = BEAM_NONE;
    l.location = v3(uniform(-5, 5), uniform(2, 9), uniform(-5, 5));
    l.area.axis1 = random_vec(2);
    l.area.axis2 = random_vec(2);
    l.area.size1 = size1;
    l.area.size2 = size2;
    l.area.circular = circular;
    l.area.orient = orient;
    l.area.full_area = 1;
    double(*factors)[2] = NULL;
    if (area_light_fixed_factors(&l, &factors) || !factors) {
        free(factors);
        return 0;
    }
    AreaDiffuseSamples s = { &l, (const double(*)[2])factors, l.area.axis1, l.area.axis2, random_vec(3),
                             { uniform(0, 0.1), uniform(0, 0.1), uniform(0, 0.1) }, uniform(0, 1) < 0.2 };
    Vec3 centre_dir = v3_normalize(v3_sub(l.location, s.point));
    area_light_axes(&l, centre_dir, &s.axis1, &s.axis2);
    int n = 1 + (int)uniform(0, 3);
    AreaDiffuseTexture plain[3], fast[3];
    RGB plain_acc[3], fast_acc[3];
    for (int i = 0; i < n; i++) {
        /* mostly toward the light; some away, some nearly edge-on */
        double k = uniform(0, 1);
        Vec3 n_dir = k < 0.6 ? v3_add(centre_dir, random_vec(0.7))
                     : k < 0.8 ? random_vec(1)
                               : v3_cross(centre_dir, random_vec(1));
        plain[i] = (AreaDiffuseTexture){ v3_normalize(n_dir), { uniform(0, 1), uniform(0, 1), uniform(0, 1) },
                                         uniform(0.05, 1), uniform(0.2, 1), &plain_acc[i] };
        plain_acc[i] = (RGB){ uniform(0, 0.3), uniform(0, 0.3), uniform(0, 0.3) };
        fast[i] = plain[i];
        fast[i].acc = &fast_acc[i];
        fast_acc[i] = plain_acc[i];
    }
    RGB before = plain_acc[0];
    area_diffuse_plain(&s, plain, n);
    area_diffuse(&s, fast, n);
    free(factors);
    int same = 1;
    for (int i = 0; i < n; i++)
        same &= same_bits(plain_acc[i], fast_acc[i]);
    *lit = !same_bits(before, plain_acc[0]);
    return same;
}

int main(void)
{
    static const int sizes[][2] = { { 2, 2 }, { 3, 3 }, { 5, 5 }, { 17, 17 }, { 4, 7 }, { 1, 5 }, { 6, 1 }, { 9, 2 } };
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++)
        for (int circular = 0; circular <= 1; circular++)
            for (int orient = 0; orient <= 1; orient++) {
                int size1 = sizes[k][0], size2 = sizes[k][1];
                if ((circular || orient) && (size1 < 2 || size2 < 2))
                    continue; /* POV-Ray's circular and orient lights are at least 2 x 2 */
                int agree = 0, lit = 0, cases = 400;
                for (int c = 0; c < cases; c++) {
                    int got_light;
                    agree += one_case(size1, size2, circular, orient, &got_light);
                    lit += got_light;
                }
                tap_ok(agree == cases, "%dx%d%s%s: the fast sum equals the plain one bit for bit (%d of %d)", size1,
                       size2, circular ? " circular" : "", orient ? " orient" : "", agree, cases);
                tap_ok(lit > cases / 4, "%dx%d%s%s: light arrives in %d of %d cases", size1, size2,
                       circular ? " circular" : "", orient ? " orient" : "", lit, cases);
            }
    return tap_done();
}
