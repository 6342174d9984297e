/* Image files: the buffers of image_buffer.h written to and read from
 * OpenEXR (through its C API), PNG, PPM, Targa, BMP, JPEG and Radiance HDR
 * files: the types POV-Ray 3.7 writes. */
#ifndef HST_IMAGE_H
#define HST_IMAGE_H

#include "colour.h"
#include "image_buffer.h"
#include "scene.h"

typedef enum {
    IMAGE_FORMAT_UNKNOWN, IMAGE_FORMAT_EXR, IMAGE_FORMAT_PNG, IMAGE_FORMAT_PPM,
    IMAGE_FORMAT_TGA, IMAGE_FORMAT_BMP, IMAGE_FORMAT_JPEG, IMAGE_FORMAT_HDR
} ImageFormat;

/* EXR compression; the zero default is ZIP (16 scanlines a block), what
 * POV-Ray 3.7 writes. */
typedef enum {
    IMAGE_EXR_ZIP = 0, IMAGE_EXR_NONE, IMAGE_EXR_RLE, IMAGE_EXR_ZIPS, IMAGE_EXR_PIZ
} ImageExrCompression;

/* Extra EXR header attributes, of the standard types string, int, double. */
typedef enum { IMAGE_ATTR_STRING, IMAGE_ATTR_INT, IMAGE_ATTR_DOUBLE } ImageAttributeType;

typedef struct {
    const char *name;
    ImageAttributeType type;
    const char *s;
    int i;
    double d;
} ImageAttribute;

typedef struct {
    int exr_float;      /* 1: 32-bit float channels; 0: half (default) */
    int png_16bit;      /* 1: 16-bit PNG; 0: 8-bit (default) */
    int write_alpha;    /* include alpha in PNG, Targa and BMP (EXR always has
                         * RGBA; PPM, JPEG and HDR have none) */
    int tga_rle;        /* Targa: 1 run-length encoded (+FC), 0 plain (+FT) */
    int jpeg_quality;   /* JPEG: 2..100; 0 or 1 mean POV-Ray's default 85 */
    const char *software; /* named in the Targa, JPEG and HDR headers; NULL: "hstrace" */
    /* Display encoding for the integer types (all but EXR and HDR), as POV-Ray 3.7 does: 0 means sRGB, any
     * other value a power-law gamma (file_gamma). */
    double display_gamma;
    /* OpenColorIO's display/view transform for PNG and PPM, replacing the
     * curve above (display_gamma is then unused; no gAMA or sRGB chunk is
     * written, since the view's curve is the config's to say); NULL:
     * POV-Ray's encoding. */
    const ColourDisplay *display;
    ImageExrCompression exr_compression; /* 0: ZIP */
    /* The EXR's chromaticities attribute (CIE xy of red, green, blue and
     * white), written when have_chromaticities. */
    int have_chromaticities;
    float chromaticities[8];
    /* EXR only (PNG and PPM ignore them): channels besides R G B A, and
     * header attributes besides the required ones. */
    const ImageChannel *channels;
    int nchannels;
    const ImageAttribute *attributes;
    int nattributes;
    /* Threads an encoder may use (EXR compresses its chunks side by side;
     * the file is the same for any number); 0 or 1: the calling thread. */
    int threads;
} ImageWriteOptions;

/* Turns colours encoded with a working gamma (scene_working_gamma: 1
 * linear, 0 the sRGB curve, else a power) into linear light, in place; alpha
 * stays, premultiplied colour is decoded unpremultiplied. POV-Ray writes
 * its files from linear light in the same way. */
void image_decode_working_gamma(Image *img, double gamma);

ImageFormat image_format_from_path(const char *path);

/* Write to a temporary file beside `path` and rename it into place, so an
 * interrupted or failed write never leaves a truncated image. Returns 0 on
 * success, or -1 with a message in err. */
int image_write(const char *path, const Image *img, const ImageWriteOptions *opt, char *err, int errlen);

/* Read an EXR, PNG, PPM, Targa, BMP, JPEG or HDR file into linear RGBA (the
 * integer types are decoded from sRGB, or the gamma given, back to linear;
 * EXR and HDR are linear already; IMAGE_GAMMA_AS_POVRAY: as POV-Ray 3.7
 * reads a file that no `gamma` overrides: PNG by its sRGB or gAMA chunk,
 * else sRGB; JPEG, Targa and BMP as sRGB; PPM not decoded). Returns 0, or
 * -1 with a message. */
#define IMAGE_GAMMA_AS_POVRAY IMAGE_GAMMA_FILE_DEFAULT
int image_read(const char *path, Image *img, double display_gamma, char *err, int errlen);

/* What image_read_ex can say besides the pixels. */
typedef struct {
    /* In: leave the colours of the formats with straight alpha (PNG,
     * Targa, BMP) as the file has them, not premultiplied. */
    int keep_straight;
    /* In, with IMAGE_GAMMA_AS_POVRAY: the curve of a PNG, JPEG, Targa, BMP
     * or PPM that names none (POV-Ray's ReadOptions.defaultGamma: 0 sRGB,
     * else a power law), when untagged_given; otherwise the type's own. */
    int untagged_given;
    double untagged_gamma;
    /* Out: the file's format. */
    ImageFormat format;
    /* In: the memory the picture may take, checked against the size its
     * header declares before anything is decoded: width x height x
     * bytes_per_pixel (the 16 of linear RGBA floats, plus whatever the
     * caller keeps besides them) more than max_bytes is refused with the
     * budget's message. max_bytes 0: no limit but the readers' own. */
    size_t max_bytes;
    size_t bytes_per_pixel;
    /* Out: the colours returned are premultiplied by alpha (with
     * keep_straight: only an EXR's, as stored; otherwise always). */
    int premultiplied;
    /* Out: a colour-mapped picture (a PNG or BMP of a palette, as POV-Ray
     * 3.7 keeps them indexed): its entries' colours, decoded as the pixels
     * are, and straight alpha; each pixel's entry (width*height, row 0 at
     * the top, malloc'd). ncolours 0, index NULL: not colour-mapped. */
    int ncolours;
    float palette[256][4];
    unsigned char *index;
    /* Out: what a height field reads of the samples (POV-Ray 3.7's
     * image_height_at): a grey picture (PNG grey, PGM, Targa grey) and
     * the largest sample value its file can hold (255, 65535, a PGM's or
     * PPM's maxval); other readers leave grey 0 and sample_max 255. */
    int grey;
    unsigned sample_max;
} ImageReadExtras;

/* The size a picture declares in its header, before anything is decoded
 * (`hstrace compare` holds its images to each other and to the memory
 * budget with it). Returns 0 with width and height; 1 when the header
 * cannot tell (image_read then says what is wrong with the file); -1 with a
 * message "cannot read 'PATH': reason" when the file cannot be opened or
 * is no regular file. */
int image_read_size(const char *path, int *width, int *height, char *err, int errlen);

/* image_read with the extras above (NULL: image_read itself). */
int image_read_ex(const char *path, Image *img, double display_gamma, ImageReadExtras *ex, char *err, int errlen);
/* The parser's ParseOptions.load_image (scene.h's LoadedPicture): a
 * picture of image_map, bump_map or material_map with its colours as the
 * file stores them, and POV-Ray 3.7's reading of them (premultiplied for
 * EXR, straight for the others, unless `premultiplied` says otherwise),
 * refused from its header when it needs more than max_bytes (0: no
 * limit), counting the parser's copy of it too; `user` is unused. */
int image_read_for_scene(void *user, const char *path, double decoding_gamma, double untagged_gamma, int premultiplied,
                         size_t max_bytes, LoadedPicture *out, char *err, int errlen);

/* Reads the named channels of a scanline EXR (part 0) as float planes of
 * width*height samples (malloc'd, row 0 at the top; half and uint are
 * converted). Returns 0; 1 when the file is readable but lacks one of them
 * (err names it; nothing allocated); -1 with a message on any other error. */
int image_read_exr_channels(const char *path, const char *const *names, int n, float **planes, int *width,
                            int *height, char *err, int errlen);

/* ---- an EXR read back whole ---------------------------------------------
 * Every channel of a scanline EXR (part 0) as stored, and the header
 * attributes of the types hstrace writes: what it takes to write the same
 * file again (image_write with ImageWriteOptions' channels, attributes and
 * chromaticities), as `hstrace stitch` does with partial renders. */
typedef struct {
    char *name;
    ImageChannelType type; /* as stored: HALF, FLOAT or UINT */
    /* width*height 4-byte samples, row 0 at the top: floats for HALF and
     * FLOAT (a half becomes a float and back exactly), uint32_t for UINT;
     * NULL when no rows were read. */
    void *data;
} ImageExrChannel;

typedef struct {
    char *name;
    ImageAttributeType type;
    char *s; /* STRING; NULL otherwise */
    int i;
    double d;
} ImageExrAttribute;

typedef struct {
    int width, height;
    ImageExrCompression compression; /* lossy kinds, which hstrace never writes, read as ZIP */
    int have_chromaticities;
    float chromaticities[8];
    ImageExrChannel *channels; /* in the file's order: sorted by name */
    int nchannels;
    /* The string, int and double attributes, in the file's order (the
     * required ones are of other types; chromaticities is above, any other
     * type is skipped). */
    ImageExrAttribute *attributes;
    int nattributes;
} ImageExrFile;

/* Reads the header of a scanline EXR and, when y0 < y1, the samples of
 * every channel in the chunks holding rows [y0, y1) (clipped to the image;
 * the other rows are 0): y0 == y1 reads the header alone. Returns 0, or -1
 * with a message "cannot read 'PATH': reason" (f is then empty). Free with
 * image_exr_file_free either way. */
int image_read_exr_file(const char *path, ImageExrFile *f, int y0, int y1, char *err, int errlen);
/* The attribute called name, or NULL. */
const ImageExrAttribute *image_exr_file_attribute(const ImageExrFile *f, const char *name);
void image_exr_file_free(ImageExrFile *f);

#endif
