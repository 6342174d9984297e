/* How POV-Ray 3.7 takes a picture's colours into the scene (image_map,
 * bump_map, material_map): which curve decodes the file's values and which
 * working gamma they are then encoded with.
 *
 * POV-Ray decides this when it parses the picture (Parse_Image in
 * parstxtr.cpp), from the gamma mode the scene is in at that moment
 * (SceneData::gammaMode). It starts as None (scene.cpp); the first
 * assumed_gamma sets AssumedGamma36 or AssumedGamma37 by the language
 * version in effect (global_settings in parse.cpp; EffectiveLanguageVersion()
 * is 3.62 until a #version is seen); each #version moves None and
 * AssumedGamma37Implied to one another, and AssumedGamma36 and
 * AssumedGamma37 to one another, by the version it sets (tokenize.cpp).
 *
 *   - None (no assumed_gamma yet, version below 3.7): the file is not gamma
 *     corrected at all: its values are used as stored.
 *   - AssumedGamma37Implied (no assumed_gamma yet, a #version of 3.7 or
 *     more, also restored by a standard include's closing #version): the
 *     file's own curve or its type's default, decoded to linear (the working
 *     gamma is still unset during the parse; at its end it becomes 1.0).
 *   - AssumedGamma36: a file that names no gamma of its own is taken to be
 *     encoded with the working gamma (ReadOptions.defaultGamma =
 *     workingGamma), so its values stay as stored.
 *   - AssumedGamma37: the file's curve or its type's default (the readers
 *     in base/image: PNG's sRGB, then gAMA chunk, else sRGB; JPEG, Targa,
 *     BMP sRGB; PPM and PGM none; EXR and HDR linear), then encoded with
 *     the working gamma.
 *
 * `gamma G` in the picture's block (gammaOverride) decodes the file with G
 * whatever its type and the mode; the result is encoded with the working
 * gamma, which in the None and Implied modes is none (linear).
 *
 * Data (bump_map, material_map: GammaCorrect false in Parse_Image) are
 * never taken to the working gamma: the values as stored, or decoded with a
 * `gamma` given. */
#include "grammar.h"

#include <math.h>

/* The language version in effect: 3.62 without a #version. Compared in
 * hundredths, as POV-Ray rounds it (3.699999 is 3.70); any version, 1e46
 * or NaN included, is compared without a conversion to int (which would
 * be undefined beyond its range). */
static int below_3_7(const Parser *p)
{
    double version = p->version_given ? p->version : 3.62;
    return floor(version * 100.0 + 0.5) < 370.0;
}

void gram_assumed_gamma_seen(Parser *p, double gamma)
{
    if (p->gram->gamma_mode == GAMMA_MODE_36 || p->gram->gamma_mode == GAMMA_MODE_37)
        return; /* POV-Ray: "New instance of assumed_gamma ignored" */
    p->gamma_set = 1;
    p->assumed_gamma = gamma;
    p->gram->gamma_mode = below_3_7(p) ? GAMMA_MODE_36 : GAMMA_MODE_37;
}

void gram_version_seen(Parser *p)
{
    if (p->gram->gamma_mode == GAMMA_MODE_NONE || p->gram->gamma_mode == GAMMA_MODE_37_IMPLIED)
        p->gram->gamma_mode = below_3_7(p) ? GAMMA_MODE_NONE : GAMMA_MODE_37_IMPLIED;
    else
        p->gram->gamma_mode = below_3_7(p) ? GAMMA_MODE_36 : GAMMA_MODE_37;
}

ImageGammaPlan gram_image_gamma_plan(const Parser *p, int gamma_correct, int override_given, double override)
{
    ImageGammaPlan plan = { .decode = 1.0, .untagged = IMAGE_GAMMA_FILE_DEFAULT, .working = 1.0 };
    const int assumed = p->gram->gamma_mode == GAMMA_MODE_36 || p->gram->gamma_mode == GAMMA_MODE_37;
    if (override_given) {
        plan.decode = override;
        if (gamma_correct && assumed)
            plan.working = p->assumed_gamma;
    } else if (gamma_correct && p->gram->gamma_mode != GAMMA_MODE_NONE) {
        plan.decode = IMAGE_GAMMA_FILE_DEFAULT;
        if (p->gram->gamma_mode == GAMMA_MODE_36)
            plan.untagged = p->assumed_gamma;
        if (assumed)
            plan.working = p->assumed_gamma;
    }
    /* else: the values as the file stores them (decode 1, working 1) */
    return plan;
}
