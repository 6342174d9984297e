/* Shadow masks compared: where two renderers disagree on which pixels are in
 * shadow, and whether each disagreement is explained by a shadow edge or a
 * silhouette (a tie broken differently, displaced by about a pixel) or lies
 * in the interior (a real error).
 *
 * A renderer's shadow mask comes from a pair of renders of the same scene,
 * without shadows (POV-Ray's +Q3) and with them (+Q4): the pixels shadowed at
 * the primary hit are exactly those that change. A is the reference: its
 * mask holds the pixels its shadows darken (+Q3 brighter than +Q4 in a
 * channel). B is under test: its mask holds every pixel its two renders
 * differ at, since a pixel made brighter by shadows is a fault of B's.
 *
 * With several lights nearly every pixel is in some shadow, so the masks
 * alone say little; the shadow loss (+Q3 minus +Q4, per channel) tells which
 * lights are blocked, since they differ in colour and strength. A pixel
 * disagrees when it is in one mask only, or when the two shadow losses differ
 * by more than the loss tolerance in a channel (shadowed in both, from other
 * lights). A disagreeing pixel is
 *   - at a shadow edge: within one pixel (8-neighbourhood) of a shadow edge
 *     in A's pair AND within one pixel of one in B's: the same edge in both,
 *     displaced by about a pixel. A shadow-edge pixel is one whose mask value
 *     differs from one of its 8 neighbours', or whose shadow loss differs from
 *     a neighbour's by more than the loss tolerance in a channel. Requiring
 *     the edge in both matters: a wrong pixel is nearly always on a boundary
 *     of the mask it is wrong in, so "a boundary of either mask" would excuse
 *     any stray shadow pixel and any missing shadow up to 3 pixels wide;
 *   - else at a silhouette: within one pixel of a silhouette in A's +Q3
 *     render AND within one pixel of one in B's: the visible surface changes
 *     there, and sub-pixel differences in geometry decide which surface (and
 *     so which shadow) a pixel shows;
 *   - else, with allow_a_leaks, one of A's leaks when B's shadow loss is at
 *     least A's in every channel and B's mask holds the pixel if A's does (A
 *     let more light through: POV-Ray's ray/triangle test leaks through the
 *     shared edges of a mesh);
 *   - else in the interior: an error. */
#ifndef HST_MASK_COMPARE_H
#define HST_MASK_COMPARE_H

#include "image.h"

typedef struct {
    /* Shadow losses agree when no channel differs by more; also the jump
     * between neighbouring losses that makes a shadow edge (hard shadows
     * jump by a light's whole contribution). */
    double loss_tolerance;
    int allow_a_leaks; /* count A's leaks apart instead of as interior errors */
} MaskCompareOptions;

typedef struct {
    int width, height;
    long a_pixels, b_pixels; /* the sizes of the two masks */
    long disagree;           /* shadow_edge + silhouette + interior + a_leaks */
    long other_lights;       /* of them, in both masks but with other shadow losses */
    long shadow_edge, silhouette, interior, a_leaks;
    int interior_x, interior_y; /* the first interior pixel in reading order; -1 when none */
    double share;            /* disagree / (width * height) */
    long nonfinite;          /* pixels holding NaN or infinity, summed over the four renders */
} MaskComparison;

/* Compares A's mask (a3, a4) with B's (b3, b4). With map != NULL, fills a
 * fresh image of the verdicts: black lit in both, dark grey shadowed in both,
 * dark blue silhouettes; disagreements in red (shadowed in A only), green (in
 * B only) or magenta (in both, from other lights), dim at an edge or
 * silhouette, bright elsewhere. Returns 0, or -1 when the four sizes differ
 * or memory runs out. */
int mask_compare(const Image *a3, const Image *a4, const Image *b3, const Image *b4, const MaskCompareOptions *opt,
                 MaskComparison *out, Image *map);

/* The +Q3/+Q4 pair that one hstrace render made with --aov shadow stands
 * for: q4 is the render, q3 the render plus its shadow.loss.R/G/B channels
 * (loss[0..2], width*height each), the light its shadows took at the
 * primary hit. For a +Q4 render the pair is the +Q3/+Q4 pair up to float
 * rounding; for a fuller one (+Q9) both hold the same reflected and
 * refracted light, so the shadow losses are still exact and only q3's
 * silhouettes include reflected edges. Returns 0, or -1 when out of memory. */
int mask_pair_from_loss(const Image *render, const float *const loss[3], Image *q3, Image *q4);

#endif
