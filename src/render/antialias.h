/* POV-Ray 3.7's anti-aliasing, block by block as its render tasks do it
 * (backend/render/tracetask.cpp of 3.7.0.10, read for this):
 *
 * Method 1 (+AM1, the default): every pixel is traced at its centre; the
 * block also traces the row above it and the column left of it, which it
 * compares with but never supersamples. Row by row, a pixel whose colour
 * differs from its left or upper neighbour's by the threshold or more is
 * supersampled, and so is that neighbour when it has not been yet: a
 * depth x depth grid of samples across the pixel, averaged with the
 * centre's (depth^2 + 1 in all). Later comparisons see the averaged
 * colours.
 *
 * Method 2 (+AM2): the corners of every pixel are traced; a pixel whose
 * four corners differ pairwise by the threshold or more is cut in four,
 * the new corners and centre traced (each once, shared with its
 * neighbours in the pixel), down depth - 1 times; a pixel is the mean of
 * its four quarters, a quarter left whole the mean of its corners.
 *
 * Colours are compared gamma encoded (x^(1/Antialias_Gamma), 2.5 by
 * default, after decoding the scene's working gamma) as the sum of the absolute differences of red, green, blue and
 * transmit, in single precision as POV-Ray keeps colours. Blocks are 32
 * pixels square (Render_Block_Size, +BS) from the render area's corner, no
 * larger than the area's longer side (backend/scene/view.cpp); what a block decides does
 * not depend on any other, so the image is the same for any thread count.
 * Jitter (on by default) moves each supersample by POV-Ray's own
 * deterministic offsets, the amount spread over the samples' spacing;
 * the centres (method 1) and the corners (method 2) stay put. */
#ifndef HST_ANTIALIAS_H
#define HST_ANTIALIAS_H

#define ANTIALIAS_BLOCK 32

typedef struct {
    int method;       /* 0 off, 1 non-recursive, 2 recursive */
    double threshold; /* 0..1 */
    int depth;        /* 1..9 */
    double gamma;     /* Antialias_Gamma; <= 0: compare the colours as they are */
    double work_gamma; /* the scene's working gamma (assumed_gamma): decoded before; 0 or 1: none */
    double jitter;    /* Jitter_Amount, 0..1 (0: no jitter) */
    int block;        /* the blocks' side in pixels (Render_Block_Size); 0: ANTIALIAS_BLOCK */
} Antialias;

/* A colour as POV-Ray's render keeps it: red, green, blue, transmit. */
typedef struct {
    float c[4];
} AaColour;

/* Traces a camera ray through pixel coordinates (x, y): integer values are
 * pixel centres' as the plain render makes them. */
typedef void (*AaTrace)(void *user, double x, double y, AaColour *out);

/* The pixels [left, right] x [top, bottom] (inclusive) of one block into
 * out (row by row, (right - left + 1) wide). Returns 0, or -1 when out of
 * memory. */
int antialias_block(const Antialias *aa, int left, int top, int right, int bottom, AaTrace trace, void *user,
                    AaColour *out);

#endif
