/* Image buffers (image_buffer.h). */
#include "image_buffer.h"
#include "big_memory.h"

#include <stdlib.h>

int image_alloc(Image *img, int width, int height)
{
    img->width = 0;
    img->height = 0;
    img->rgba = NULL;
    if (width <= 0 || height <= 0 || width > IMAGE_MAX_DIM || height > IMAGE_MAX_DIM ||
        (long)width * (long)height > IMAGE_MAX_PIXELS)
        return -1;
    /* 20 MB at 1280x960, written pixel by pixel by the render's threads:
     * on huge pages, some ten page faults instead of 4,800. */
    img->rgba = big_calloc((size_t)width * (size_t)height * 4, sizeof(float));
    if (img->rgba == NULL)
        return -1;
    img->width = width;
    img->height = height;
    return 0;
}

void image_free(Image *img)
{
    if (img == NULL)
        return;
    free(img->rgba);
    img->rgba = NULL;
    img->width = 0;
    img->height = 0;
}
