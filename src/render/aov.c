/* Analysis channels: the groups and the planes. */
#include "aov.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const group_names[AOV_NGROUPS] = { "Z", "N", "P", "shadow", "hst", "depth", "cost" };

int aov_parse(const char *list, unsigned *groups, char *err, int errlen)
{
    *groups = 0;
    const char *s = list;
    for (;;) {
        size_t n = strcspn(s, ",");
        int g = -1;
        if (n == 3 && strncmp(s, "all", 3) == 0) {
            *groups |= AOV_ALL;
            g = AOV_NGROUPS;
        }
        for (int k = 0; k < AOV_NGROUPS && g < 0; k++)
            if (strlen(group_names[k]) == n && strncmp(s, group_names[k], n) == 0)
                g = k;
        if (g < 0) {
            snprintf(err, (size_t)errlen, "--aov: unknown channel group '%.*s' (valid: Z, N, P, shadow, hst, depth, "
                     "cost, all; comma separated)", (int)(n < 64 ? n : 64), s);
            return -1;
        }
        if (g < AOV_NGROUPS)
            *groups |= 1u << g;
        if (s[n] == '\0')
            return 0;
        s += n + 1;
    }
}

/* ---- the planes ----------------------------------------------------------- */

static int add_channel(AovImage *a, const char *name, ImageChannelType type)
{
    int c = a->nchannels++;
    snprintf(a->names[c], sizeof a->names[c], "%s", name);
    a->channels[c].name = a->names[c];
    a->channels[c].type = type;
    a->channels[c].data = (const uint32_t *)a->planes + (size_t)c * (size_t)a->width * (size_t)a->height;
    return c;
}

static int add_per_light(AovImage *a, const char *layer, ImageChannelType type)
{
    char name[32];
    int first = a->nchannels;
    for (int i = 0; i < a->nlights; i++) {
        snprintf(name, sizeof name, "%s.L%d", layer, i + 1);
        add_channel(a, name, type);
    }
    return a->nlights > 0 ? first : -1;
}

int aov_image_alloc(AovImage *a, unsigned groups, int width, int height, int nlights, int exr_float)
{
    memset(a, 0, sizeof *a);
    a->groups = groups;
    a->width = width;
    a->height = height;
    a->nlights = nlights;
    a->z = a->n = a->p = a->shadow = a->loss = a->hst = a->depth = a->cost = -1;
    int most = 1 + 3 + 3 + (nlights + 3) + nlights + nlights + 2;
    a->channels = calloc((size_t)most, sizeof *a->channels);
    a->names = calloc((size_t)most, sizeof *a->names);
    a->planes = malloc((size_t)most * (size_t)width * (size_t)height * sizeof(uint32_t));
    if (!a->channels || !a->names || !a->planes) {
        aov_image_free(a);
        return -1;
    }
    ImageChannelType colour = exr_float ? IMAGE_CHANNEL_FLOAT : IMAGE_CHANNEL_HALF;
    if (groups & (1u << AOV_Z))
        a->z = add_channel(a, "Z", IMAGE_CHANNEL_FLOAT);
    if (groups & (1u << AOV_N)) {
        a->n = add_channel(a, "N.X", IMAGE_CHANNEL_FLOAT);
        add_channel(a, "N.Y", IMAGE_CHANNEL_FLOAT);
        add_channel(a, "N.Z", IMAGE_CHANNEL_FLOAT);
    }
    if (groups & (1u << AOV_P)) {
        a->p = add_channel(a, "P.X", IMAGE_CHANNEL_FLOAT);
        add_channel(a, "P.Y", IMAGE_CHANNEL_FLOAT);
        add_channel(a, "P.Z", IMAGE_CHANNEL_FLOAT);
    }
    if (groups & (1u << AOV_SHADOW)) {
        a->shadow = add_per_light(a, "shadow", colour);
        a->loss = add_channel(a, "shadow.loss.R", colour);
        add_channel(a, "shadow.loss.G", colour);
        add_channel(a, "shadow.loss.B", colour);
    }
    if (groups & (1u << AOV_HST))
        a->hst = add_per_light(a, "hst", IMAGE_CHANNEL_UINT);
    if (groups & (1u << AOV_DEPTH))
        a->depth = add_per_light(a, "depth", IMAGE_CHANNEL_FLOAT);
    if (groups & (1u << AOV_COST)) {
        a->cost = add_channel(a, "cost.shadow", IMAGE_CHANNEL_UINT);
        add_channel(a, "cost.rays", IMAGE_CHANNEL_UINT);
    }
    return 0;
}

void aov_image_free(AovImage *a)
{
    free(a->channels);
    free(a->names);
    free(a->planes);
    a->channels = NULL;
    a->names = NULL;
    a->planes = NULL;
    a->nchannels = 0;
}

static void put_float(AovImage *a, int c, size_t i, double v)
{
    ((float *)a->planes)[(size_t)c * (size_t)a->width * (size_t)a->height + i] = (float)v;
}

static void put_uint(AovImage *a, int c, size_t i, uint64_t v)
{
    ((uint32_t *)a->planes)[(size_t)c * (size_t)a->width * (size_t)a->height + i] =
        v > UINT32_MAX ? UINT32_MAX : (uint32_t)v;
}

void aov_image_store(AovImage *a, const AovPixel *px, uint64_t shadow_tests, uint64_t rays, int x, int y)
{
    size_t i = (size_t)y * (size_t)a->width + (size_t)x;
    if (a->z >= 0)
        put_float(a, a->z, i, px->z);
    if (a->n >= 0) {
        put_float(a, a->n, i, px->n.x);
        put_float(a, a->n + 1, i, px->n.y);
        put_float(a, a->n + 2, i, px->n.z);
    }
    if (a->p >= 0) {
        put_float(a, a->p, i, px->p.x);
        put_float(a, a->p + 1, i, px->p.y);
        put_float(a, a->p + 2, i, px->p.z);
    }
    for (int l = 0; l < a->nlights && l < px->nlights; l++) {
        if (a->shadow >= 0)
            put_float(a, a->shadow + l, i, px->light[l].visibility);
        if (a->hst >= 0)
            put_uint(a, a->hst + l, i, px->light[l].code);
        if (a->depth >= 0)
            put_float(a, a->depth + l, i, px->light[l].depth);
    }
    if (a->loss >= 0)
        for (int k = 0; k < 3; k++)
            put_float(a, a->loss + k, i, px->loss[k]);
    if (a->cost >= 0) {
        put_uint(a, a->cost, i, shadow_tests - px->shadow_tests);
        put_uint(a, a->cost + 1, i, rays - px->rays);
    }
}
