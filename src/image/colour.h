/* Colour management: the display transform of PNG and PPM output and the
 * primaries of the working space, through OpenColorIO (colour_ocio.cpp, the
 * project's only C++ file) or a stub when built without it (colour_none.c).
 * What does not depend on the library (when OCIO is asked for, where the
 * shipped config is, the Rec.709 primaries) is in colour.c.
 *
 * hstrace renders in a scene-linear space: POV-Ray's colours, taken as
 * linear Rec.709 with a D65 white. Without OCIO, PNG and PPM get POV-Ray
 * 3.7's own encoding (image_encoding.c); with it, the display/view transform
 * of an OCIO config replaces that curve. */
#ifndef HST_COLOUR_H
#define HST_COLOUR_H

#ifdef __cplusplus
extern "C" {
#endif

/* What the command line and the environment ask for. NULL fields take the
 * defaults named beside them. */
typedef struct {
    const char *config;     /* --ocio-config FILE; NULL: $OCIO, else the shipped config */
    const char *display;    /* --display; NULL: the config's default display */
    const char *view;       /* --view; NULL: the display's default view */
    const char *colorspace; /* --colorspace, the working space; NULL: the scene_linear role */
} ColourRequest;

typedef enum {
    COLOUR_OK = 0,
    COLOUR_ERR_CONFIG,      /* config missing, unreadable or broken: exit status 3 */
    COLOUR_ERR_NAME,        /* a display, view or colour space the config lacks: 1 */
    COLOUR_ERR_UNAVAILABLE, /* built without OpenColorIO: 1 */
} ColourStatus;

/* An opened config with its display processor. Immutable once opened: any
 * number of threads may call colour_display_apply on one at the same time. */
typedef struct ColourDisplay ColourDisplay;

/* 1 when built with OpenColorIO. */
int colour_ocio_available(void);
/* "OpenColorIO 2.1.2", or a sentence saying it is not built in. */
const char *colour_ocio_version(void);

/* Whether OCIO is asked for: any field of req set, or a non-empty $OCIO.
 * Otherwise PNG and PPM keep POV-Ray's encoding. */
int colour_requested(const ColourRequest *req);

/* The config file to use: req->config, else $OCIO when non-empty, else the
 * shipped config (see colour_shipped_config). *origin says which, for
 * messages ("--ocio-config", "$OCIO", "the shipped config"). Returns NULL
 * when the shipped config is wanted and cannot be found, with a message in
 * err. */
const char *colour_config_path(const ColourRequest *req, const char **origin, char *buf, int buflen, char *err,
                               int errlen);

/* The shipped config, ocio/config.ocio, searched in $HSTRACE_DATADIR (the
 * tests point it at the source tree), then the installed data folder
 * (HST_DATADIR), then the folder of the running executable and its data/
 * subfolder (an uninstalled build). Returns buf, or NULL when none exists. */
const char *colour_shipped_config(char *buf, int buflen);

/* Opens the config req selects (colour_config_path), checks it, and builds
 * the processor from the working space to display/view. On failure *out is
 * NULL and err holds a message: for COLOUR_ERR_NAME it lists the valid
 * names. */
ColourStatus colour_display_open(const ColourRequest *req, ColourDisplay **out, char *err, int errlen);
void colour_display_free(ColourDisplay *d);

/* Applies the display transform in place to n packed RGB float triples.
 * Returns 0, or -1 with a message. Thread-safe. */
int colour_display_apply(const ColourDisplay *d, float *rgb, long n, char *err, int errlen);

/* The names in use, after defaults were filled in. */
const char *colour_display_config(const ColourDisplay *d);
const char *colour_display_name(const ColourDisplay *d);
const char *colour_display_view(const ColourDisplay *d);
const char *colour_display_working_space(const ColourDisplay *d);

/* CIE xy of the working space's red, green, blue primaries and white (as
 * the EXR chromaticities attribute holds them), found by converting its unit
 * colours to the config's cie_xyz_d65_interchange role. Returns 0, or -1
 * when the config has no such role or the conversion fails. */
int colour_display_chromaticities(const ColourDisplay *d, float xy[8]);

/* Rec.709 / sRGB primaries and D65 white: the working space without OCIO. */
extern const float colour_rec709_chromaticities[8];

#ifdef __cplusplus
}
#endif

#endif
