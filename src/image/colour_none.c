/* Colour management when hstrace is built without OpenColorIO (configure
 * --without-ocio): PNG and PPM keep POV-Ray's encoding, and asking for a
 * config, display, view or colour space is an error that says why. */
#include "colour.h"

#include <stdio.h>

#define WITHOUT_OCIO "hstrace was built without OpenColorIO (configure --without-ocio)"

int colour_ocio_available(void)
{
    return 0;
}

const char *colour_ocio_version(void)
{
    return "no OpenColorIO (configure --without-ocio)";
}

ColourStatus colour_display_open(const ColourRequest *req, ColourDisplay **out, char *err, int errlen)
{
    (void)req;
    *out = NULL;
    if (err != NULL && errlen > 0)
        snprintf(err, (size_t)errlen, "%s", WITHOUT_OCIO);
    return COLOUR_ERR_UNAVAILABLE;
}

void colour_display_free(ColourDisplay *d)
{
    (void)d;
}

int colour_display_apply(const ColourDisplay *d, float *rgb, long n, char *err, int errlen)
{
    (void)d;
    (void)rgb;
    (void)n;
    if (err != NULL && errlen > 0)
        snprintf(err, (size_t)errlen, "%s", WITHOUT_OCIO);
    return -1;
}

const char *colour_display_config(const ColourDisplay *d)
{
    (void)d;
    return "";
}

const char *colour_display_name(const ColourDisplay *d)
{
    (void)d;
    return "";
}

const char *colour_display_view(const ColourDisplay *d)
{
    (void)d;
    return "";
}

const char *colour_display_working_space(const ColourDisplay *d)
{
    (void)d;
    return "";
}

int colour_display_chromaticities(const ColourDisplay *d, float xy[8])
{
    (void)d;
    (void)xy;
    return -1;
}
