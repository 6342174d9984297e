/* Shadow masks compared (src/tools/mask_compare.h): disagreements told apart at
 * shadow edges, at silhouettes and in the interior, shadows from other lights,
 * A's leaks, and the verdict map, on a hand-made 16x12 scene whose counts are
 * worked out below. */
#include <math.h>
#include <string.h>

#include "image.h"
#include "mask_compare.h"
#include "tap.h"

#define W 16
#define H 12

static float *px(Image *img, int x, int y) { return &img->rgba[((size_t)y * img->width + x) * 4]; }

static void set(Image *img, int x, int y, float v)
{
    float *p = px(img, x, y);
    p[0] = p[1] = p[2] = v;
    p[3] = 1;
}

/* The shadowless renders (+Q3), the same for A and B: grey 0.5 left of
 * x = 12, 0.9 from there on, so x = 11 and 12 are silhouette pixels (a jump
 * of 0.4 > 0.05 to a neighbour). Shadows darken by 0.3 (+Q4):
 *   A's: the rectangle x 1..7, y 1..8, and the pixel (3,11);
 *   B's: the same rectangle one pixel to the right (x 2..8, y 1..8), the
 *        pixels (13,3) and (14,10); at (5,5) B's shadow darkens by 0.1 only
 *        (shadowed in both, by another light).
 * Disagreements:
 *   column x = 1 (A only) and x = 8 (B only), y 1..8: 16 pixels, each on or
 *     next to the boundary of both rectangles: at shadow edges;
 *   (13,3), B only: no shadow edge of A within a pixel, but next to the
 *     silhouette at x = 12 in both +Q3 renders: at a silhouette;
 *   (5,5): its 3x3 neighbourhood lies inside A's rectangle with A's loss
 *     even, so no edge of A is near: interior (the first, in reading order);
 *   (14,10), B only: far from A's edges and from the silhouette: interior,
 *     or one of A's leaks when those are allowed (B's loss 0.3 >= A's 0);
 *   (3,11), A only: next to A's own mark but no edge of B within a pixel
 *     (B's rectangle ends at y = 8): interior, and never a leak of A's (A is
 *     the darker one).
 * So 16 + 1 + 3 = 20 disagreements of 192 pixels, 1 from other lights;
 * A's mask holds 7*8 + 1 = 57 pixels, B's 7*8 + 2 = 58. */
static void make_scene(Image *a3, Image *a4, Image *b3, Image *b4)
{
    Image *all[4] = {a3, a4, b3, b4};
    for (int k = 0; k < 4; k++) {
        image_alloc(all[k], W, H);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++)
                set(all[k], x, y, x < 12 ? 0.5f : 0.9f);
    }
    for (int y = 1; y <= 8; y++) {
        for (int x = 1; x <= 7; x++)
            set(a4, x, y, 0.2f);
        for (int x = 2; x <= 8; x++)
            set(b4, x, y, 0.2f);
    }
    set(a4, 3, 11, 0.2f);
    set(b4, 13, 3, 0.6f);
    set(b4, 14, 10, 0.6f);
    set(b4, 5, 5, 0.4f);
}

static void free_scene(Image *a3, Image *a4, Image *b3, Image *b4)
{
    image_free(a3);
    image_free(a4);
    image_free(b3);
    image_free(b4);
}

static int colour(Image *img, int x, int y, float r, float g, float b)
{
    const float *p = px(img, x, y);
    return fabsf(p[0] - r) < 1e-6f && fabsf(p[1] - g) < 1e-6f && fabsf(p[2] - b) < 1e-6f && p[3] == 1.0f;
}

static void test_split(void)
{
    Image a3, a4, b3, b4, map;
    MaskComparison m;
    MaskCompareOptions opt = {.loss_tolerance = 0.02, .allow_a_leaks = 0};
    make_scene(&a3, &a4, &b3, &b4);
    tap_ok(mask_compare(&a3, &a4, &b3, &b4, &opt, &m, &map) == 0 && m.width == W && m.height == H,
           "masks: 16x12 scene compared");
    tap_ok(m.a_pixels == 57 && m.b_pixels == 58, "A's mask 57 pixels, B's 58 (got %ld, %ld)", m.a_pixels, m.b_pixels);
    tap_ok(m.shadow_edge == 16, "the shifted rectangle: 16 disagreements at shadow edges (got %ld)", m.shadow_edge);
    tap_ok(m.silhouette == 1, "the pixel beside the silhouette: 1 at silhouettes (got %ld)", m.silhouette);
    tap_ok(m.interior == 3 && m.interior_x == 5 && m.interior_y == 5,
           "3 interior errors, the first at (5,5) (got %ld at %d,%d)", m.interior, m.interior_x, m.interior_y);
    tap_ok(m.other_lights == 1, "1 pixel shadowed in both from another light (got %ld)", m.other_lights);
    tap_ok(m.a_leaks == 0 && m.disagree == 20 && m.share == 20.0 / 192, "20 of 192 pixels disagree (got %ld)",
           m.disagree);
    tap_ok(m.nonfinite == 0, "no NaN or infinite pixels");

    tap_ok(colour(&map, 1, 3, 0.45f, 0, 0), "map: shadowed in A only, at an edge: dim red");
    tap_ok(colour(&map, 8, 3, 0, 0.45f, 0), "map: shadowed in B only, at an edge: dim green");
    tap_ok(colour(&map, 13, 3, 0, 0.45f, 0), "map: shadowed in B only, at a silhouette: dim green");
    tap_ok(colour(&map, 14, 10, 0, 1, 0), "map: shadowed in B only, interior: bright green");
    tap_ok(colour(&map, 3, 11, 1, 0, 0), "map: shadowed in A only, interior: bright red");
    tap_ok(colour(&map, 5, 5, 1, 0, 1), "map: shadowed in both by other lights, interior: bright magenta");
    tap_ok(colour(&map, 4, 3, 0.2f, 0.2f, 0.2f), "map: shadowed in both alike: grey");
    tap_ok(colour(&map, 11, 0, 0, 0, 0.15f) && colour(&map, 12, 7, 0, 0, 0.15f), "map: silhouette: dark blue");
    tap_ok(colour(&map, 0, 11, 0, 0, 0), "map: lit in both: black");
    image_free(&map);

    opt.allow_a_leaks = 1;
    int rc = mask_compare(&a3, &a4, &b3, &b4, &opt, &m, NULL);
    tap_ok(rc == 0 && m.a_leaks == 1 && m.interior == 2 &&
               m.interior_x == 5 && m.interior_y == 5 && m.disagree == 20,
           "A's leaks allowed: (14,10) is one, (5,5) and (3,11) stay interior (got %ld leaks, %ld interior)",
           m.a_leaks, m.interior);

    /* A looser loss tolerance: the other light's 0.2 difference at (5,5) is
     * within 0.25, and the rest is unchanged. */
    opt.allow_a_leaks = 0;
    opt.loss_tolerance = 0.25;
    mask_compare(&a3, &a4, &b3, &b4, &opt, &m, NULL);
    tap_ok(m.other_lights == 0 && m.interior == 2 && m.interior_x == 14 && m.interior_y == 10,
           "loss tolerance 0.25: (5,5) agrees, 2 interior errors left, the first at (14,10)");

    image_free(&b4);
    image_alloc(&b4, W, H - 1);
    tap_ok(mask_compare(&a3, &a4, &b3, &b4, &opt, &m, &map) == -1 && map.rgba == NULL,
           "renders of another size are refused, no map made");
    free_scene(&a3, &a4, &b3, &b4);
}

/* A is the reference: a pixel its shadows brighten is not in its mask. B is
 * under test: a pixel brightened by shadows is in its mask (a fault). */
static void test_direction(void)
{
    Image a3, a4, b3, b4;
    MaskComparison m;
    MaskCompareOptions opt = {.loss_tolerance = 0.02, .allow_a_leaks = 0};
    Image *all[4] = {&a3, &a4, &b3, &b4};
    for (int k = 0; k < 4; k++) {
        image_alloc(all[k], 5, 5);
        for (int i = 0; i < 25; i++)
            set(all[k], i % 5, i / 5, 0.5f);
    }
    set(&a4, 2, 2, 0.6f);
    set(&b4, 2, 2, 0.6f);
    set(&b4, 0, 0, 0.5015f); /* within the mask epsilon 2e-3 */
    mask_compare(&a3, &a4, &b3, &b4, &opt, &m, NULL);
    tap_ok(m.a_pixels == 0 && m.b_pixels == 1, "brighter with shadows: not in A's mask, in B's (got %ld, %ld)",
           m.a_pixels, m.b_pixels);
    free_scene(&a3, &a4, &b3, &b4);
}

int main(void)
{
    test_split();
    test_direction();
    return tap_done();
}
