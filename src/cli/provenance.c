/* The EXR header's account of how an image was made. */
#include "provenance.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "antialias.h"
#include "aov.h"
#include "config.h"
#include "cost_model.h"
#include "shell_words.h"
#include "volume_plan.h"

int provenance_hash_file(const char *path, uint64_t *hash)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return -1;
    uint64_t h = 0xcbf29ce484222325ULL; /* FNV-1a offset basis and prime */
    unsigned char buf[8192];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0)
        for (size_t i = 0; i < n; i++) {
            h ^= buf[i];
            h *= 0x100000001b3ULL;
        }
    int bad = ferror(f);
    fclose(f);
    if (bad)
        return -1;
    *hash = h;
    return 0;
}

static void *hash_in_background(void *arg)
{
    SceneHash *h = arg;
    h->status = provenance_hash_file(h->path, &h->hash);
    return NULL;
}

void scene_hash_start(SceneHash *h, const char *path, int background)
{
    memset(h, 0, sizeof *h);
    h->path = path;
    h->status = -1;
    if (background && pthread_create(&h->thread, NULL, hash_in_background, h) == 0)
        h->state = 1;
}

int scene_hash_finish(SceneHash *h, uint64_t *hash)
{
    if (h->state == 1)
        pthread_join(h->thread, NULL);
    else if (h->state == 0 && h->path)
        h->status = provenance_hash_file(h->path, &h->hash);
    h->state = 2;
    *hash = h->hash;
    return h->status;
}

static const char *const aov_group_list[AOV_NGROUPS] = { "Z", "N", "P", "shadow", "hst", "depth", "cost" };
static const char *const precision_names[] = { "double", "float", "float-naive" };

/* The shortest %g form that reads back as the same double. */
static void shortest(char *buf, size_t len, double v)
{
    for (int digits = 6; digits <= 17; digits++) {
        snprintf(buf, len, "%.*g", digits, v);
        if (strtod(buf, NULL) == v)
            return;
    }
}

/* Every option in force that can change a pixel, defaults included, as one
 * line: anti-aliasing when on, each Declare=, the clock when the scene sees
 * one, and a partial render's area last (hstrace stitch reads the area back
 * and holds the rest of the line of every part to be the same). */
static char *resolved_options(const Options *opt, const ParseAnimation *anim, const StatsReport *r)
{
    char nth[64], aov[64] = "", tolerance[32];
    shortest(tolerance, sizeof tolerance, opt->tolerance);
    if (opt->nth.mode == NTH_AUTO)
        snprintf(nth, sizeof nth, "auto");
    else if (opt->nth.mode == NTH_PER_POINT)
        snprintf(nth, sizeof nth, "per-point");
    else
        shortest(nth, sizeof nth, opt->nth.value);
    for (int g = 0; g < AOV_NGROUPS; g++)
        if (opt->aov & (1u << g))
            snprintf(aov + strlen(aov), sizeof aov - strlen(aov), "%s%s", aov[0] ? "," : "", aov_group_list[g]);
    /* POV-Ray's own switches and INI keys for anti-aliasing, as given
     * (the render clips the threshold and the jitter to 1). */
    char aa[256] = "";
    if (opt->antialias_on) {
        char threshold[32], gamma[32], jitter[32], block[32] = "";
        shortest(threshold, sizeof threshold, opt->aa_threshold);
        shortest(gamma, sizeof gamma, opt->aa_gamma);
        shortest(jitter, sizeof jitter, opt->jitter_amount);
        /* the blocks it decides in, when not POV-Ray's default */
        if (opt->render_block_size != ANTIALIAS_BLOCK)
            snprintf(block, sizeof block, " +BS%d", opt->render_block_size);
        snprintf(aa, sizeof aa, " +A%s +AM%d +R%d Antialias_Gamma=%s %s%s%s", threshold, opt->aa_method, opt->aa_depth,
                 gamma, opt->jitter_on ? "+J" : "-J", opt->jitter_on ? jitter : "", block);
    }
    char clock[48] = "";
    if (anim && anim->clock_on) {
        char value[32];
        shortest(value, sizeof value, anim->clock);
        snprintf(clock, sizeof clock, " +K%s", value);
    }
    /* A partial render's area, as the rows and columns POV-Ray counts from 1. */
    char area[96] = "";
    if (opt->area_x0 > 0 || opt->area_y0 > 0 || opt->area_x1 < opt->width || opt->area_y1 < opt->height)
        snprintf(area, sizeof area, " +SR%d +ER%d +SC%d +EC%d", opt->area_y0 + 1, opt->area_y1, opt->area_x0 + 1,
                 opt->area_x1);
    size_t len = 1024;
    for (int i = 0; i < opt->ndeclares; i++)
        len += strlen(opt->declares[i].name) + (opt->declares[i].string ? strlen(opt->declares[i].string) : 0) + 48;
    char *s = malloc(len);
    if (!s)
        return NULL;
    int pp = opt->plane_precision >= 0 && opt->plane_precision < 3 ? opt->plane_precision : 0;
    size_t at = (size_t)snprintf(s, len,
             "--width %d --height %d +Q%d --shadows %s --volumes %s --nth %s --pixel-coherence %s --instancing %s "
             "--tolerance %s --plane-precision %s --grid %dx%dx%d --threads %d%s%s%s%s%s%s",
             opt->width, opt->height, opt->quality, opt->shadows, opt->volumes_always ? "always" : "auto", nth,
             opt->pixel_coherence ? "on" : "off", opt->instancing ? "auto" : "off",
             tolerance, precision_names[pp], r->grid[0], r->grid[1], r->grid[2], r->threads,
             opt->exr_float ? " --exr-float" : "",
             opt->verify_shadows == 2 ? " --verify-reference" : opt->verify_shadows ? " --verify-shadows" : "",
             aov[0] ? " --aov " : "", aov, aa, clock);
    /* Declare=NAME=VALUE as POV-Ray's command line takes it: a string in
     * double quotes. */
    for (int i = 0; i < opt->ndeclares && at < len; i++) {
        const OptionDeclare *d = &opt->declares[i];
        char number[32];
        if (!d->string)
            shortest(number, sizeof number, d->number);
        at += (size_t)snprintf(s + at, len - at, " Declare=%s=%s%s%s", d->name, d->string ? "\"" : "",
                               d->string ? d->string : number, d->string ? "\"" : "");
    }
    if (at < len)
        snprintf(s + at, len - at, "%s", area);
    return s;
}

static void add_string(Provenance *p, const char *name, const char *value)
{
    if (p->n < PROVENANCE_MAX_ATTRIBUTES)
        p->attr[p->n++] = (ImageAttribute){ name, IMAGE_ATTR_STRING, value, 0, 0.0 };
}

static void add_int(Provenance *p, const char *name, int value)
{
    if (p->n < PROVENANCE_MAX_ATTRIBUTES)
        p->attr[p->n++] = (ImageAttribute){ name, IMAGE_ATTR_INT, NULL, value, 0.0 };
}

static void add_double(Provenance *p, const char *name, double value)
{
    if (p->n < PROVENANCE_MAX_ATTRIBUTES)
        p->attr[p->n++] = (ImageAttribute){ name, IMAGE_ATTR_DOUBLE, NULL, 0, value };
}

/* Which lights got shadow volumes and why (volume_plan.h), one line:
 * "auto; L1 built and kept; L2 not built: ...". */
static char *plan_summary(const VolumePlan *plan)
{
    size_t len = 32;
    for (int i = 0; i < plan->nlights; i++)
        len += 16 + strlen(volume_plan_decision_name(plan->light[i].decision));
    char *s = malloc(len);
    if (!s)
        return NULL;
    size_t at = (size_t)snprintf(s, len, "%s", plan->mode == VOLUMES_ALWAYS ? "always" : "auto");
    for (int i = 0; i < plan->nlights && at < len; i++)
        at += (size_t)snprintf(s + at, len - at, "; L%d %s", i + 1, volume_plan_decision_name(plan->light[i].decision));
    return s;
}

int provenance_build(Provenance *p, int argc, char **argv, const Options *opt, const ParseAnimation *anim,
                     const StatsReport *r, SceneHash *scene_hash)
{
    memset(p, 0, sizeof *p);
    p->command_line = shell_quote_words(argc, argv);
    p->options = resolved_options(opt, anim, r);
    if (!p->command_line || !p->options) {
        provenance_free(p);
        return -1;
    }
    uint64_t h;
    if (scene_hash_finish(scene_hash, &h) == 0)
        snprintf(p->scene_hash, sizeof p->scene_hash, "fnv1a64:%016llx", (unsigned long long)h);
    else
        snprintf(p->scene_hash, sizeof p->scene_hash, "unreadable");
    add_string(p, "hstrace.version", PACKAGE_VERSION);
    add_string(p, "hstrace.commandLine", p->command_line);
    add_string(p, "hstrace.options", p->options);
    add_string(p, "hstrace.scene", opt->scene);
    add_string(p, "hstrace.sceneHash", p->scene_hash);
    add_string(p, "hstrace.shadows", opt->shadows);
    add_int(p, "hstrace.threads", r->threads);
    add_int(p, "hstrace.lights", r->nlights);
    add_int(p, "hstrace.polygons", r->npolygons);
    if (r->plan) {
        p->volumes = plan_summary(r->plan);
        if (!p->volumes) {
            provenance_free(p);
            return -1;
        }
        add_string(p, "hstrace.volumes", p->volumes);
    }
    if (r->cost) {
        const CostModel *c = r->cost;
        add_double(p, "hstrace.nth", r->nth); /* negative: per shading point */
        add_string(p, "hstrace.nthMode", r->nth_mode);
        add_double(p, "hstrace.nthEq7", c->nth);
        add_double(p, "hstrace.cost.Cs", c->c_s);
        add_double(p, "hstrace.cost.Ci", c->c_i);
        add_double(p, "hstrace.cost.Cc", c->c_c);
        add_double(p, "hstrace.cost.Co", c->c_o);
        add_double(p, "hstrace.cost.p", c->p);
        add_double(p, "hstrace.cost.alpha", c->alpha);
        add_double(p, "hstrace.cost.Nc", c->n_c);
    }
    add_double(p, "hstrace.time.parse", r->parse_seconds);
    add_double(p, "hstrace.time.preprocess", r->preprocess_seconds);
    add_double(p, "hstrace.time.shadowCpu", r->render.shadow.shadow_seconds);
    add_double(p, "hstrace.time.renderCpu", r->render.render_seconds);
    add_double(p, "hstrace.time.wall", r->wall_seconds);
    if (opt->aov & (1u << AOV_HST))
        add_string(p, "hstrace.aov.hstCodes", aov_code_legend);
    if (opt->aov)
        add_string(p, "hstrace.aov.conventions",
                   "lights L1.. in scene order; at the primary hit; Z +inf and hst 0 where no hit; "
                   "shadow 0 where the surface faces away, 1 where untested; depth -1 where unknown; "
                   "cost over the whole pixel");
    return 0;
}

void provenance_free(Provenance *p)
{
    free(p->command_line);
    free(p->options);
    free(p->volumes);
    p->command_line = p->options = p->volumes = NULL;
    p->n = 0;
}
