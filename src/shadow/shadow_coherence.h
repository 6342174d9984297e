/* Pixel shadow coherence (hst): neighbouring pixels usually see nearby
 * points, so the depth count of a camera ray's hit P2 can be carried from
 * the previous pixel's hit N instead of from the eye:
 *
 *   depth(P2) = depth(N) + signed crossings along the segment N -> P2.
 *
 * Unlike a camera ray, N -> P2 may pass through polygons (it runs behind
 * whatever lies between the two hits), so besides the shadow polygons of
 * the cells it pierces, every polygon it crosses is counted: crossing a
 * polygon from its light side to its far side enters that polygon's shadow
 * (+1), the other way leaves it (-1). The polygons N and P2 lie on are
 * excluded from their own points' counts, as everywhere else.
 *
 * Every crossing is decided with a margin; where a polygon is too close to
 * call (an end point on or near its plane and inside it, a crossing near its
 * border) the pixel falls back to the count from the eye, which is exact on
 * its own. The walk N -> P2 does not depend on the light, so it is made at
 * most once per pixel and shared by all lights. */
#ifndef HST_SHADOW_COHERENCE_H
#define HST_SHADOW_COHERENCE_H

#include "shadow.h"

/* A previous pixel's camera-ray hit and its light states. */
typedef struct {
    int valid;
    Hit hit;
    LightState *state;      /* one per light */
} PixelNeighbour;

/* How a polygon met the segment N -> P2 (light-independent). */
typedef enum {
    MEET_CROSS,       /* crossed inside; side: N's side of its plane */
    MEET_START_CAP,   /* N's own polygon; side: P2's side of its plane */
    MEET_END_CAP,     /* P2's own polygon; side: N's side of its plane */
    MEET_IN_PLANE     /* runs in its plane across its border: undecidable if it is bent */
} MeetKind;

typedef struct {
    int polygon;
    int8_t kind;      /* MeetKind */
    int8_t side;      /* +1 the polygon normal's side, -1 the other */
} PolygonMeet;

typedef struct PixelCoherence {
    /* Kept by the render loop: the pixel to the left in the tile's row,
     * and the first pixel of the row above (for the row's first pixel). */
    PixelNeighbour left, row_first;
    const PixelNeighbour *neighbour; /* for the current pixel, or NULL */
    Hit hit;                         /* the current pixel's camera-ray hit */
    int have_hit;
    int nlights;
    /* The walk N -> P2 of the current pixel: 0 not made yet, 1 usable,
     * -1 not usable (a polygon too close to call, an end outside the box). */
    int walked;
    uint32_t *cells;
    int ncells, cells_cap;
    PolygonMeet *meets;
    int nmeets, meets_cap;
} PixelCoherence;

/* Returns 0, or -1 when out of memory. */
int pixel_coherence_init(PixelCoherence *pc, const World *w, const Grid *g);
void pixel_coherence_free(PixelCoherence *pc);

/* Before a pixel is traced: which neighbour it may count from. */
void pixel_coherence_begin(PixelCoherence *pc, int first_in_row, int first_row);
/* After: keep the pixel's camera-ray hit and its states (row 0 of the
 * context's states) as the next pixel's neighbour. hit NULL: no hit. */
void pixel_coherence_end(PixelCoherence *pc, const Hit *hit, const LightState *states, int first_in_row);

/* Counts the crossings from the neighbour to q's point for q's light,
 * starting from the neighbour's depth, into *out. Returns 1 when counted,
 * 0 when not applicable (no neighbour, its depth unknown, the count would
 * cost more than from the eye or exceed nth), -1 when undecidable. */
int pixel_coherence_count(ShadowContext *ctx, const ShadowQuery *q, double nth, uint32_t eye_registrations,
                          LightState *out);

#endif
