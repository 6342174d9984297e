/* Image buffers: the linear RGBA floats a render makes, and the extra
 * planes (analysis channels) it may make beside them. The files they are
 * written to and read from are image.h's. */
#ifndef HST_IMAGE_BUFFER_H
#define HST_IMAGE_BUFFER_H

/* Largest accepted width or height, and pixel count, of a buffer (and so of
 * any image read or written). */
#define IMAGE_MAX_DIM 65536
#define IMAGE_MAX_PIXELS (1L << 28)

typedef struct {
    int width, height;
    float *rgba; /* width*height*4, row 0 at the top, linear light; colour
                  * premultiplied by alpha, as in POV-Ray and EXR files */
} Image;

/* Extra channels beside R G B A (the analysis channels of aov.h), written
 * to EXR files (image.h), each a plane of width*height samples, row 0 at the
 * top: floats for HALF and FLOAT channels (converted to half by the
 * library), uint32_t for UINT ones. */
typedef enum { IMAGE_CHANNEL_HALF, IMAGE_CHANNEL_FLOAT, IMAGE_CHANNEL_UINT } ImageChannelType;

typedef struct {
    const char *name;
    ImageChannelType type;
    const void *data;
} ImageChannel;

/* Returns 0, or -1 when the size is out of range or memory is short. */
int image_alloc(Image *img, int width, int height);
void image_free(Image *img);

#endif
