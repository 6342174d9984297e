/* ripples and waves (POV-Ray 3.7's ripples_pattern and waves_pattern), and
 * the wave sources they and their normals sum (Initialize_Waves). */
#include <math.h>
#include <pthread.h>
#include <stdint.h>

#include "noise.h"
#include "patterns.h"

/* Source i is the vector noise at (i, 0, 0), normalised; the frequencies
 * come from a linear congruential sequence in 32-bit arithmetic (POV-Ray's
 * int, wrapping). Neither depends on how many there are, so one table of
 * the most a scene may ask for is made, once, on first use
 * (pthread_once), and only read after: any thread may use it at any time. */
static Vec3 sources[MAX_NUMBER_OF_WAVES];
static double frequencies[MAX_NUMBER_OF_WAVES];
static pthread_once_t waves_once = PTHREAD_ONCE_INIT;

static void make_waves(void)
{
    int32_t next = -560851967;
    for (int i = 0; i < MAX_NUMBER_OF_WAVES; i++) {
        sources[i] = v3_normalize(noise_vector(v3((double)i, 0.0, 0.0)));
        next = (int32_t)(uint32_t)((int64_t)next * 1812433253LL + 12345LL);
        frequencies[i] = (double)((int)(next >> 16) & 0x7FFF) * 0.000030518509476 + 0.01;
    }
}

Vec3 wave_source(int i)
{
    pthread_once(&waves_once, make_waves);
    return sources[i];
}

double wave_frequency(int i)
{
    pthread_once(&waves_once, make_waves);
    return frequencies[i];
}

/* POV-Ray's cycloidal(): a sine of period 1, through the fraction. */
static double cycloidal(double v)
{
    if (v >= 0.0)
        return sin((v - floor(v)) * 50000.0 / 50000.0 * (2.0 * M_PI));
    return 0.0 - sin((0.0 - (v + floor(0.0 - v))) * 50000.0 / 50000.0 * (2.0 * M_PI));
}

/* The distance of p from source i (1 on the source itself). */
static double source_distance(Vec3 p, int i)
{
    Vec3 d = v3_sub(p, wave_source(i));
    double length = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return length == 0.0 ? 1.0 : length;
}

/* Rings around each source at the pattern's frequency and phase, their
 * sines averaged into [0, 1]. */
double ripples_value(const Pigment *pig, Vec3 p, int nwaves)
{
    double scalar = 0.0;
    for (int i = 0; i < nwaves; i++)
        scalar += cycloidal(source_distance(p, i) * pig->frequency + pig->phase);
    return 0.5 * (1.0 + scalar / (double)nwaves);
}

/* The same, each source at its own frequency and weighed by its
 * wavelength. */
double waves_value(const Pigment *pig, Vec3 p, int nwaves)
{
    double scalar = 0.0;
    for (int i = 0; i < nwaves; i++) {
        double index = source_distance(p, i) * pig->frequency * wave_frequency(i) + pig->phase;
        scalar += cycloidal(index) / wave_frequency(i);
    }
    return 0.2 * (2.5 + scalar / (double)nwaves);
}
