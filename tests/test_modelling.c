/* Modelling what scenes commonly need: pigment patterns (checker, hexagon,
 * gradient, colour maps), texture binding, layered textures, sky_sphere,
 * the approximations hstrace makes (reported only for what the scene uses,
 * refused by --strict) and the "not supported" errors. Images against
 * POV-Ray are in tests/modelling.sh; here the description and the pattern
 * values, against POV-Ray's definitions worked by hand. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "big_memory.h"
#include "parser.h"
#include "pigment.h"
#include "tap.h"
#include "world.h"

static const char *const pov_dirs[] = { "/usr/share/povray-3.7/include" };
static ParseOptions opts = { .include_dirs = pov_dirs, .ninclude_dirs = 1, .image_width = 320, .image_height = 240 };
static ParseOptions strict_opts = { .include_dirs = pov_dirs, .ninclude_dirs = 1, .image_width = 320,
                                    .image_height = 240, .strict = 1 };
static ParseError err;

static Scene *parse_with(const char *text, const ParseOptions *o)
{
    Scene *s = parse_scene_string("t.pov", text, o, &err);
    if (!s)
        tap_diag("parse error: %s:%d:%d: %s", err.file, err.line, err.column, err.message);
    return s;
}

static Scene *parse(const char *text) { return parse_with(text, &opts); }

static int near(double a, double b) { return fabs(a - b) < 1e-9; }
static int colour_is(Colour c, double r, double g, double b, double f, double t)
{
    return near(c.r, r) && near(c.g, g) && near(c.b, b) && near(c.filter, f) && near(c.transmit, t);
}

static void expect_error_with(const ParseOptions *o, const char *text, int line, int col, const char *msg,
                              const char *what)
{
    Scene *s = parse_scene_string("t.pov", text, o, &err);
    int ok = !s && err.line == line && err.column == col && strstr(err.message, msg) != NULL;
    tap_ok(ok, "error: %s", what);
    if (!ok)
        tap_diag("got %s -> %s:%d:%d: %s", s ? "a scene" : "error", err.file, err.line, err.column, err.message);
    scene_free(s);
}

static void expect_error(const char *text, int line, int col, const char *msg, const char *what)
{
    expect_error_with(&opts, text, line, col, msg, what);
}

static void test_pattern_values(void)
{
    Pigment checker = { .kind = PIGMENT_CHECKER };
    /* POV-Ray adds EPSILON (1e-10) before each floor: a point a hair below
     * a cell face (rounding on a floor at y = 0) counts as above it. */
    tap_ok(pattern_value(&checker, v3(0.5, 0.0, 0.5)) == 0.0 && pattern_value(&checker, v3(1.5, 0.0, 0.5)) == 1.0 &&
               pattern_value(&checker, v3(1.5, 0.0, 1.5)) == 0.0 && pattern_value(&checker, v3(-0.5, 0.0, 0.5)) == 1.0,
           "checker alternates by unit cells, negative cells too");
    tap_ok(pattern_value(&checker, v3(0.5, -1e-11, 0.5)) == 0.0 && pattern_value(&checker, v3(0.5, -1e-9, 0.5)) == 1.0,
           "checker: EPSILON 1e-10 below a face still counts as above it, 1e-9 does not");
    Pigment hex = { .kind = PIGMENT_HEXAGON };
    /* Hand-worked from hexagon_pattern: x/0.5, z/(sqrt(3)/2) index a 6x6
     * grid of blocks; (0.1, 0.1): block (0,0) -> 0; (0.1, 1.0): block
     * (0,1) -> 1; (0.1, 2.7): block (0,3) -> 2; (1.1, 0.1): block (2,0) -> 2;
     * (0.6, 0.05): block (1,0), xl 0.2, zl 0.058, below the diagonal -> 0;
     * (0.6, 0.8): block (1,0), zl 0.92 above -> 2; negative x mirrors. */
    tap_ok(pattern_value(&hex, v3(0.1, 0, 0.1)) == 0.0 && pattern_value(&hex, v3(0.1, 0, 1.0)) == 1.0 &&
               pattern_value(&hex, v3(0.1, 0, 2.7)) == 2.0 && pattern_value(&hex, v3(1.1, 0, 0.1)) == 2.0,
           "hexagon: the straight blocks of POV-Ray's grid");
    tap_ok(pattern_value(&hex, v3(0.6, 0, 0.05)) == 0.0 && pattern_value(&hex, v3(0.6, 0, 0.8)) == 2.0 &&
               pattern_value(&hex, v3(-0.6, 0, 0.8)) == 2.0,
           "hexagon: split blocks on either side of the diagonal, mirrored in x");
    Pigment grad = { .kind = PIGMENT_GRADIENT, .gradient = { 0, 1, 0 }, .frequency = 1.0 };
    tap_ok(near(pattern_value(&grad, v3(0, 0.25, 0)), 0.25) && near(pattern_value(&grad, v3(0, 1.75, 0)), 0.75) &&
               near(pattern_value(&grad, v3(0, -0.25, 0)), 0.75),
           "gradient: fractional part, negative values wrap");
    ColourMapEntry map[3] = { { 0.0, { 0, 0, 0, 0, 0 }, NULL }, { 0.5, { 1, 0, 0, 0, 0 }, NULL },
                              { 0.5, { 0, 0, 1, 0, 0 }, NULL } };
    tap_ok(colour_is(colour_map_at(map, 3, 0.25), 0.5, 0, 0, 0, 0) && colour_is(colour_map_at(map, 3, 0.5), 0, 0, 1, 0, 0) &&
               colour_is(colour_map_at(map, 3, 0.75), 0, 0, 1, 0, 0) && colour_is(colour_map_at(map, 3, -1), 0, 0, 0, 0, 0),
           "colour map: interpolation; at or past the last value the last entry, as Search_Blend_Map; clamped ends");
    ColourMapEntry step[3] = { { 0.5, { 1, 0, 0, 0, 0 }, NULL }, { 0.5, { 0, 0, 1, 0, 0 }, NULL },
                               { 1.0, { 0, 1, 0, 0, 0 }, NULL } };
    tap_ok(colour_is(colour_map_at(step, 3, 0.5), 1, 0, 0, 0, 0),
           "colour map: a sharp step before the last value takes its first entry at the step");
}

static void test_pigments(void)
{
    Scene *s = parse("box { 0, 1 pigment { checker } }\n"
                     "box { 0, 1 pigment { checker rgb 1 } }\n"
                     "box { 0, 1 pigment { hexagon color rgb <1,0,0>, rgb <0,1,1> } }\n"
                     "box { 0, 1 pigment { hexagon pigment { rgb 1 } pigment { rgb 0.5 } pigment { rgb 0.25 } } }\n"
                     "box { 0, 1 pigment { gradient <0, 2, 0> color_map { [0 rgb 0] [1 rgb 1] } scale 2 } }\n"
                     "box { 0, 1 pigment { gradient x color_map { [0.2 0.6 color rgb 1 color rgb 0] } } }\n");
    tap_ok(s && s->nobjects == 6, "checker, hexagon and gradient pigments parse");
    if (s && s->nobjects == 6) {
        const Pigment *p0 = &s->objects[0]->texture->pigment, *p1 = &s->objects[1]->texture->pigment;
        tap_ok(p0->kind == PIGMENT_CHECKER && p0->nmap == 2 && colour_is(p0->map[0].colour, 0, 0, 1, 0, 0) &&
                   colour_is(p0->map[1].colour, 0, 1, 0, 0, 0),
               "checker without colours: POV-Ray's blue and green");
        tap_ok(colour_is(p1->map[0].colour, 1, 1, 1, 0, 0) && colour_is(p1->map[1].colour, 0, 1, 0, 0, 0),
               "checker with one colour: the second is the default green");
        const Pigment *h = &s->objects[2]->texture->pigment;
        tap_ok(h->kind == PIGMENT_HEXAGON && h->nmap == 3 && colour_is(h->map[0].colour, 1, 0, 0, 0, 0) &&
                   colour_is(h->map[1].colour, 0, 1, 1, 0, 0) && colour_is(h->map[2].colour, 1, 0, 0, 0, 0),
               "hexagon: two colours, the third is the default red");
        const Pigment *h2 = &s->objects[3]->texture->pigment;
        tap_ok(h2->nmap == 3 && near(h2->map[2].colour.r, 0.25), "hexagon with three pigment items");
        const Pigment *g = &s->objects[4]->texture->pigment;
        tap_ok(g->kind == PIGMENT_GRADIENT && near(g->gradient.y, 1.0) && g->nmap == 2 &&
                   near(transform_point(&g->transform, v3(0, 1, 0)).y, 2.0),
               "gradient: vector normalised, colour map, pattern transform kept");
        const Pigment *o = &s->objects[5]->texture->pigment;
        /* map values in single precision, as POV-Ray keeps them (SNGL) */
        tap_ok(o->nmap == 2 && o->map[0].value == (double)0.2f && o->map[1].value == (double)0.6f &&
                   colour_is(o->map[1].colour, 0, 0, 0, 0, 0),
               "old-style colour map entry [v1 v2 colour c1 colour c2]");
        tap_ok(s->napproximations == 0, "evaluated patterns are no approximation");
    }
    scene_free(s);
}

/* POV-Ray moves a texture with the transforms written after it, not with
 * those before it; a union's transform moves its children's textures. */
static void test_texture_binding(void)
{
    Scene *s = parse("box { 0, 1 translate x*5 pigment { checker } }\n"
                     "box { 0, 1 pigment { checker } translate x*5 }\n"
                     "#declare B = box { 0, 1 pigment { checker } translate y*2 }\n"
                     "union { object { B translate z*3 } scale 2 }\n");
    World w;
    WorldError we;
    int built = s && world_build(&w, s, &we) == 0;
    tap_ok(built && w.nmaterials == 3, "three patterned materials");
    if (built && w.nmaterials == 3) {
        Vec3 a = inverse_transform_point(&w.materials[0].pattern_to_world, v3(5.5, 0.5, 0.5));
        Vec3 b = inverse_transform_point(&w.materials[1].pattern_to_world, v3(5.5, 0.5, 0.5));
        Vec3 c = inverse_transform_point(&w.materials[2].pattern_to_world, v3(1, 4 + 1, 6 + 1));
        tap_ok(near(a.x, 5.5), "transform before the texture leaves the pattern in place (%g)", a.x);
        tap_ok(near(b.x, 0.5), "transform after the texture moves the pattern (%g)", b.x);
        tap_ok(near(c.x, 0.5) && near(c.y, 0.5) && near(c.z, 0.5),
               "declared, copied and unioned: every later transform moves it (%g %g %g)", c.x, c.y, c.z);
        Colour at = material_colour_at(&w, &w.materials[1], -1, v3(6.5, 0.5, 0.5));
        tap_ok(colour_is(at, 0, 1, 0, 0, 0), "material colour at a point follows the moved pattern");
        world_free(&w);
    }
    scene_free(s);
}

static void test_layers(void)
{
    /* POV-Ray's layered textures: the last texture written lies on top,
     * each layer kept with its own pigment (ComputeLightedTexture lights
     * them one by one; tests/layered-textures.sh holds the images to
     * POV-Ray's), nothing blended and nothing reported as approximated. */
    Scene *s = parse("triangle { 0, x, y texture { pigment { rgb <1,0,0> } } texture { pigment { rgbt <0,0,1,0.5> } } }\n"
                     "triangle { 0, x, y texture { pigment { rgbt <0,0,1,0.5> } } texture { pigment { rgb <0,1,0> } } }\n"
                     "#declare T = texture { pigment { rgb 1 } } texture { pigment { rgbf <1,0,0,1> } }\n"
                     "triangle { 0, x, y texture { T } }\n");
    tap_ok(s && s->nobjects == 3, "layered textures parse (objects and #declare)");
    if (s && s->nobjects == 3) {
        const SceneTexture *a = s->objects[0]->texture, *b = s->objects[1]->texture, *c = s->objects[2]->texture;
        tap_ok(colour_is(a->pigment.colour, 0, 0, 1, 0, 0.5) && a->below &&
                   colour_is(a->below->pigment.colour, 1, 0, 0, 0, 0) && !a->below->below,
               "see-through layer over an opaque one: two layers, the last written on top");
        tap_ok(colour_is(b->pigment.colour, 0, 1, 0, 0, 0) && !b->below,
               "an opaque top layer of one colour: the layers under it, which POV-Ray never reaches, dropped");
        tap_ok(colour_is(c->pigment.colour, 1, 0, 0, 1, 0) && c->below && colour_is(c->below->pigment.colour, 1, 1, 1, 0, 0),
               "a declared layered texture keeps its layers");
        tap_ok(s->napproximations == 0, "layered textures are not reported as approximated (%d notes)",
               s->napproximations);
        World w;
        WorldError we;
        int built = world_build(&w, s, &we) == 0;
        int layered = 0, top = -1;
        for (int i = 0; built && i < w.nmaterials; i++)
            if (w.materials[i].below >= 0) {
                layered++;
                if (w.materials[i].pigment.filter == 1.0)
                    top = i;
            }
        tap_ok(built && layered == 2, "the two layered textures' materials have the ones below them (%d)", layered);
        if (built) {
            /* a filtering red layer over an opaque white one lets no light
             * through: the product of the layers' filters (ComputeShadowTexture) */
            tap_ok(top >= 0 && w.materials[top].opaque, "a filter over an opaque layer is opaque to shadows");
            world_free(&w);
        }
    }
    scene_free(s);
}

/* quick_color: below +Q6 POV-Ray shows it instead of the pigment
 * (checked against POV-Ray's renders of a checker with and without one:
 * at +Q3 to +Q5 the one with a quick colour is that colour, the other its
 * checker); at +Q6 and above it is ignored. */
static void test_quick_colour(void)
{
    const char *text = "triangle { 0, x, y pigment { checker rgb <1,0,0>, rgb <0,0,1> quick_color rgb <0,1,0> } }\n"
                       "triangle { 0, x, y pigment { checker rgb <1,0,0>, rgb <0,0,1> } }\n";
    Scene *s = parse(text);
    tap_ok(s && s->nobjects == 2 && s->objects[0]->texture->pigment.kind != PIGMENT_SOLID,
           "quick_color at full quality: the checker is kept");
    scene_free(s);
    ParseOptions quick = opts;
    quick.quick_colours = 1;
    s = parse_with(text, &quick);
    tap_ok(s && s->nobjects == 2 && s->objects[0]->texture->pigment.kind == PIGMENT_SOLID &&
               colour_is(s->objects[0]->texture->pigment.colour, 0, 1, 0, 0, 0) &&
               s->objects[1]->texture->pigment.kind != PIGMENT_SOLID,
           "quick_color below +Q6: the quick colour stands for the pigment, a pigment without one is kept");
    scene_free(s);
}

static void test_sky(void)
{
    Scene *s = parse("background { rgb <0, 0, 1> }\n"
                     "sky_sphere { pigment { gradient y color_map { [0 rgb 0] [1 rgb <1,1,0>] } }\n"
                     "             pigment { rgbt <1, 0, 0, 0.5> } }\n");
    World w;
    WorldError we;
    int built = s && world_build(&w, s, &we) == 0;
    tap_ok(built && w.sky && w.sky->npigments == 2, "sky_sphere with two pigments");
    if (built) {
        /* Straight up (value 1 -> <1,1,0>) under the half-transparent red on
         * top: 0.5 red + 0.5 * <1,1,0>; the background does not show. */
        RGB up = sky_colour(&w, v3(0, 1, 0));
        tap_ok(near(up.r, 1.0) && near(up.g, 0.5) && near(up.b, 0.0), "sky straight up: layers as POV-Ray 3.7 adds them");
        RGB half = sky_colour(&w, v3(0, 0.5, sqrt(0.75)));
        tap_ok(near(half.r, 0.75) && near(half.g, 0.25) && near(half.b, 0.0), "sky at 30 degrees: colour map at 0.5");
        world_free(&w);
    }
    scene_free(s);
}

static void test_approximations(void)
{
    /* Declared but unused: nothing to report (include files declare much). */
    Scene *s = parse("#declare P = pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } }\n"
                     "#declare T = texture { pigment { rgb 1 } normal { bumps 0.5 } }\n"
                     "box { 0, 1 }\n");
    tap_ok(s && s->napproximations == 0, "approximations declared but unused are not reported");
    scene_free(s);
    s = parse("#include \"colors.inc\"\n#include \"textures.inc\"\n#include \"stones.inc\"\n#include \"skies.inc\"\nbox { 0, 1 }\n");
    tap_ok(s && s->napproximations == 0, "textures.inc, stones.inc, skies.inc: nothing reported when unused");
    scene_free(s);
    s = parse("#declare P = pigment { tiling 3 color_map { [0 rgb 0] [1 rgb <1,0,0>] } }\n"
              "box { 0, 1 pigment { P } }\nbox { 0, 1 pigment { P } }\n"
              "box { 0, 1 normal { facets 0.5 } }\n"
              "light_source { 0, 1 photons { refraction on } }\n"
              "global_settings { radiosity { } photons { count 100 } }\n"
              "box { 0, 1 photons { target reflection on } }\n");
    tap_ok(s != NULL, "approximated features parse");
    if (s) {
        int pattern = -1, normal = -1, photons = -1, rad = -1;
        for (int i = 0; i < s->napproximations; i++) {
            const SceneApproximation *a = &s->approximations[i];
            if (a->kind == APPROX_PATTERN) pattern = i;
            if (a->kind == APPROX_NORMAL) normal = i;
            if (a->kind == APPROX_PHOTONS) photons = i;
            if (a->kind == APPROX_RADIOSITY) rad = i;
        }
        tap_ok(s->napproximations == 4, "four kinds reported (%d)", s->napproximations);
        tap_ok(pattern >= 0 && s->approximations[pattern].count == 1 && s->approximations[pattern].first.line == 1 &&
                   s->approximations[pattern].first.column == 24 && strcmp(s->approximations[pattern].what, "'tiling'") == 0,
               "a declared pattern used twice: one place, at its declaration 1:24");
        tap_ok(normal >= 0 && s->approximations[normal].first.line == 4, "object normal (facets) at line 4");
        tap_ok(photons >= 0 && rad >= 0 && s->approximations[photons].count == 3 &&
                   s->approximations[photons].first.line == 7,
               "photons (global, light and target: 3 places, the first at the target, line 7) and radiosity reported");
        tap_ok(colour_is(s->objects[0]->texture->pigment.colour, 0.5, 0, 0, 0, 0) &&
                   s->objects[0]->texture->pigment.kind == PIGMENT_SOLID,
               "an approximated pattern shows its colour map at 0.5");
    }
    scene_free(s);
    s = parse("box { 0, 1 pigment { mandel 30 interior 1, 1 color_map { [0 rgb 1] [1 rgb 0] } } }\n"
              "box { 0, 1 pigment { julia <.3, .44> 30 } }\n"
              "box { 0, 1 pigment { brick color rgb 1, color rgb 0 brick_size <1, 0.5, 0.5> mortar 0.1 } }\n"
              "box { 0, 1 pigment { checker rgb 1, rgb 0 turbulence 0.5 octaves 3 warp { turbulence 1 } warp { repeat x } } }\n"
              "box { 0, 1 pigment { uv_mapping spiral2 8 color_map { [0.5 rgb 1] [0.5 rgb 0] } scale 0.8 } }\n");
    tap_ok(s && s->nobjects == 5, "pattern arguments and modifiers are read past");
    if (s && s->nobjects == 5) {
        const Pigment *c = &s->objects[3]->texture->pigment;
        tap_ok(c->kind == PIGMENT_CHECKER && c->nturbulence == 2 && c->turbulence[0].classic &&
                   c->turbulence[0].octaves == 3 && !c->turbulence[1].classic && c->turbulence[1].amount.y == 1.0,
               "checker with turbulence stays a checker, its two turbulences kept in order");
        int warp = 0, what = 0;
        for (int i = 0; i < s->napproximations; i++)
            if (s->approximations[i].kind == APPROX_WARP) {
                warp++;
                what = strcmp(s->approximations[i].what, "'warp'") == 0;
            }
        tap_ok(warp == 1 && what, "the repeat warp alone is reported as ignored");
        const Pigment *u = &s->objects[4]->texture->pigment;
        tap_ok(u->kind == PIGMENT_SPIRAL2 && u->uv_mapping && u->arms == 8 &&
                   near(transform_point(&u->transform, v3(1, 0, 0)).x, 0.8),
               "uv_mapping spiral2 8: uv-mapped, 8 arms, its own scale");
    }
    scene_free(s);
}

static void test_strict(void)
{
    expect_error_with(&strict_opts, "box { 0, 1 pigment { tiling 3 } }", 1, 22,
                      "'tiling' is only approximated by hstrace (pattern shown as one colour", "--strict: pattern");
    expect_error_with(&strict_opts, "box { 0, 1 pigment { bozo warp { repeat x } } }", 1, 27,
                      "'warp' is only approximated by hstrace", "--strict: a warp other than turbulence");
    Scene *ok = parse_with("box { 0, 1 pigment { bozo turbulence 0.5 warp { turbulence 1 } } }\n"
                           "box { 0, 1 pigment { uv_mapping spiral2 8 } }\n", &strict_opts);
    tap_ok(ok != NULL, "--strict accepts bozo, turbulence, spiral2 and uv_mapping (evaluated, not approximated)");
    scene_free(ok);
    expect_error_with(&strict_opts, "box { 0, 1\n  normal { facets 0.4 } }", 2, 12, "'facets' is only approximated",
                      "--strict: a normal pattern hstrace does not evaluate");
    Scene *bumps = parse_with("box { 0, 1 normal { bumps 0.4 scale 0.1 } }\n"
                              "box { 0, 1 normal { granite slope_map { [0 <0, 1>] [1 <1, 0>] } } }\n",
                              &strict_opts);
    tap_ok(bumps != NULL, "--strict accepts bumps and a granite slope_map (evaluated, not approximated)");
    scene_free(bumps);
    Scene *area = parse_with("light_source { 0, 1 area_light x, y, 2, 2 jitter circular orient adaptive 1 }\n",
                             &strict_opts);
    tap_ok(area != NULL, "--strict accepts an area_light (sampled as POV-Ray samples it, not approximated)");
    scene_free(area);
    expect_error_with(&strict_opts, "global_settings { photons { count 100 } }\nbox { 0, 1 photons { target 0.5 } }", 2, 12,
                      "'photons' is only approximated",
                      "--strict: photons, where global_settings turns them on and an object is a target");
    {
        /* Photon mapping changes nothing in POV-Ray 3.7 without both: accepted. */
        static const char *const silent[] = {
            "box { 0, 1 photons { target reflection on refraction on collect off pass_through } }\n"
            "light_source { 0, 1 photons { refraction on reflection on } }",
            "global_settings { photons { count 100 } }\nbox { 0, 1 photons { collect off } }",
            "global_settings { photons { spacing 0.1 } }\nbox { 0, 1 photons { target 0 } }",
            "global_settings { photons { count 100 } }\n#declare B = box { 0, 1 photons { target } }\nbox { 0, 1 }",
        };
        for (size_t i = 0; i < sizeof silent / sizeof silent[0]; i++) {
            Scene *quiet = parse_with(silent[i], &strict_opts);
            tap_ok(quiet && quiet->napproximations == 0, "--strict accepts photons that change nothing (case %zu)", i + 1);
            scene_free(quiet);
        }
    }
    expect_error_with(&strict_opts, "box { 0, 1 photons { target bogus } }", 1, 29, "expected",
                      "photons { }: what POV-Ray does not take is an error at its position");
    expect_error_with(&strict_opts, "camera { location -z aperture 0.4 focal_point 0 }", 1, 22,
                      "'aperture' is only approximated", "--strict: focal blur");
    expect_error_with(&strict_opts, "#declare T = texture { normal { facets 1 } }\n\nbox { 0, 1 texture { T } }", 3, 22,
                      "'facets' is only approximated by hstrace; --strict makes it an error (declared at t.pov:1)",
                      "--strict: a declared approximation fails at its use, naming the declaration");
    Scene *s = parse_with("#declare T = texture { normal { facets 1 } }\n#include \"textures.inc\"\nbox { 0, 1 }", &strict_opts);
    tap_ok(s != NULL, "--strict: unused approximations in declarations and include files are fine");
    scene_free(s);
    s = parse_with("#include \"colors.inc\"\n#include \"metals.inc\"\n#include \"finish.inc\"\n"
                   "#include \"textures.inc\"\n"
                   "box { 0, 1 texture { T_Gold_1A } }\n"
                   "box { 0, 1 texture { pigment { Red } finish { Shiny } } }\n"
                   "box { 0, 1 texture { Polished_Chrome } }\n",
                   &strict_opts);
    tap_ok(s && s->nobjects == 3, "--strict: plain-colour textures of metals.inc, textures.inc, finish.inc render exactly");
    scene_free(s);
}

static void test_unsupported(void)
{
    expect_error("#declare I = isosurface { function { x } }\n\nobject { I }", 3, 10,
                 "'isosurface' is not supported by hstrace (declared at t.pov:1)", "declared isosurface, used");
    expect_error("ovus { 1, 0.5 }", 1, 1, "'ovus' is not supported by hstrace", "ovus");
    expect_error("camera { mesh_camera { 1 0 } }", 1, 10, "'mesh_camera' is not supported by hstrace", "mesh camera");
    expect_error("light_source { 0, 1 projected_through { box { 0, 1 } } }", 1, 21,
                 "'projected_through' is not supported by hstrace", "projected_through");
    expect_error("box { 0, 1 interior { media { } } }", 1, 23, "'media' is not supported by hstrace", "media");
    expect_error("rainbow { angle 42 width 5 distance 100 }", 1, 1, "'rainbow' is not supported by hstrace", "rainbow");
    expect_error("box { 0, 1 pigment { image_map { png \"x.png\" } } }", 1, 22, "'image_map' is not supported",
                 "image_map");
    expect_error("box { 0, 1 texture { material_map { png \"x.png\" } } }", 1, 22, "'material_map' is not supported",
                 "material_map without the image layer");
    expect_error("#declare S = sky_sphere { pigment { image_map { png \"x.png\" } } }\nsky_sphere { S }", 2, 14,
                 "'image_map' is not supported by hstrace (declared at", "a declared sky_sphere using image_map");
    /* POV-Ray ignores jitter without an area_light, but refuses circular */
    expect_error("light_source { 0, 1 jitter circular }", 1, 28, "'circular' without an area_light",
                 "circular without area_light");
}

static void test_flags(void)
{
    Scene *s = parse("polygon { 4, <0,0>, <1,0>, <1,1>, <0,1> inverse hollow no_shadow no_image }\n"
                     "mesh { triangle { 0, x, y } inside_vector z }\n"
                     "mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0,1,2> } inside_vector <0,0,1> }\n"
                     "camera { orthographic location <0,0,-5> look_at 0 }\n");
    tap_ok(s && s->nobjects == 3 && s->objects[0]->inverse && s->objects[0]->hollow && s->objects[0]->no_shadow &&
               s->objects[0]->no_image && s->camera.kind == CAMERA_ORTHOGRAPHIC,
           "inverse, hollow, no_shadow, no_image, inside_vector and the orthographic camera parse");
    scene_free(s);
}

/* hstrace's own colors.inc (data/include) against POV-Ray's: every name it
 * declares has POV-Ray's value. */
static void test_fallback_colors(void)
{
    const char *top = getenv("top_srcdir");
    char own_dir[1024], path[1100];
    snprintf(own_dir, sizeof own_dir, "%s/data/include", top && top[0] ? top : ".");
    snprintf(path, sizeof path, "%s/colors.inc", own_dir);
    FILE *f = fopen(path, "r");
    tap_ok(f != NULL, "hstrace's colors.inc is at %s", path);
    if (!f)
        return;
    static char scene[65536];
    int len = snprintf(scene, sizeof scene, "#include \"colors.inc\"\n"), names = 0;
    char line[256];
    while (fgets(line, sizeof line, f)) {
        char name[64];
        if (sscanf(line, "#declare %63[A-Za-z0-9_] =", name) == 1 && strcmp(name, "Colors_Inc_Temp") != 0) {
            len += snprintf(scene + len, sizeof scene - (size_t)len, "box { 0, 1 pigment { %s } }\n", name);
            names++;
        }
    }
    fclose(f);
    const char *own[] = { own_dir };
    ParseOptions o = { .include_dirs = own, .ninclude_dirs = 1 };
    Scene *mine = parse_with(scene, &o);
    tap_ok(mine && mine->nobjects == names && names > 100, "hstrace's colors.inc alone: %d colour names", names);
    if (access("/usr/share/povray-3.7/include/colors.inc", R_OK) != 0) {
        tap_diag("POV-Ray's colors.inc is not installed: values not compared");
    } else {
        Scene *pov = parse(scene);
        int differ = 0;
        for (int i = 0; mine && pov && i < names && i < pov->nobjects; i++) {
            Colour a = mine->objects[i]->texture->pigment.colour, b = pov->objects[i]->texture->pigment.colour;
            if (fabs(a.r - b.r) > 1e-6 || fabs(a.g - b.g) > 1e-6 || fabs(a.b - b.b) > 1e-6 ||
                fabs(a.filter - b.filter) > 1e-6 || fabs(a.transmit - b.transmit) > 1e-6) {
                differ++;
                tap_diag("colour %d differs", i);
            }
        }
        tap_ok(pov && mine && differ == 0, "every colour equals POV-Ray's colors.inc value");
        scene_free(pov);
    }
    scene_free(mine);
}

/* A big mesh's faces are made on several threads (flatten.c, fill_faces):
 * the world must be the one-thread world, bit for bit: degenerate faces
 * dropped in place, face textures, a mesh before and an object after. */
static void test_mesh_threads(void)
{
    const int n = 160; /* n x n quads: 51,200 triangles, four times: up to 4 runs of faces */
    size_t cap = (size_t)n * n * 4 * 64 + (size_t)(n + 1) * (n + 1) * 32 + 4096;
    char *text = malloc(cap);
    if (!text) {
        tap_ok(0, "memory for the mesh");
        return;
    }
    size_t len = (size_t)snprintf(text, cap, "triangle { 0, x, y }\nmesh2 { vertex_vectors { %d", (n + 1) * (n + 1));
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++)
            len += (size_t)snprintf(text + len, cap - len, ", <%d, %g, %d>", i, ((i * 7 + j * 13) % 11) * 0.05, j);
    len += (size_t)snprintf(text + len, cap - len, " }\n texture_list { 2, texture { pigment { rgb x } } "
                                                   "texture { pigment { rgb y } } }\n face_indices { %d", 8 * n * n);
    for (int r = 0; r < 4; r++) /* every face four times: 204,800 faces */
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
                /* every 97th face degenerate: a vertex twice */
                int k = (r * n + j) * n + i;
                len += (size_t)snprintf(text + len, cap - len, ", <%d, %d, %d>, %d, <%d, %d, %d>", a, b,
                                        k % 97 ? d : b, k % 3 == 0, a, d, c);
            }
    snprintf(text + len, cap - len, " }\n rotate <10, 20, 30> }\nbox { -1, 1 }\n");
    Scene *s = parse(text);
    free(text);
    World one;
    WorldError we;
    int built = s && world_build_threads(&one, s, 1, &we) == 0;
    tap_ok(built && one.npolygons > 200000 && one.ndegenerate > 1000,
           "a mesh of 204,800 faces builds on one thread (%d polygons, %d degenerate)", built ? one.npolygons : 0,
           built ? one.ndegenerate : 0);
    static const int counts[] = { 2, 3, 8 };
    for (int k = 0; built && k < 3; k++) {
        World many;
        int ok = world_build_threads(&many, s, counts[k], &we) == 0;
        ok = ok && many.npolygons == one.npolygons && many.npoints == one.npoints &&
             many.ndegenerate == one.ndegenerate &&
             memcmp(&many.bounds_min, &one.bounds_min, sizeof one.bounds_min) == 0 &&
             memcmp(&many.bounds_max, &one.bounds_max, sizeof one.bounds_max) == 0 &&
             memcmp(many.polygons, one.polygons, sizeof *one.polygons * (size_t)one.npolygons) == 0 &&
             memcmp(many.points, one.points, sizeof *one.points * (size_t)one.npoints) == 0;
        tap_ok(ok, "... and on %d threads: the same polygons, points, degenerate count and bounds, bit for bit",
               counts[k]);
        world_free(&many);
    }
    /* Once the world is made, the mesh's lists go back (scene.h) and the
     * mesh keeps none (the world has copies of its own: under the
     * sanitizers a render after the release would catch a use of them). */
    if (built) {
        SceneObject *mesh = s->nobjects == 3 ? s->objects[1] : NULL;
        scene_release_mesh_lists(s);
        tap_ok(mesh && mesh->kind == OBJ_MESH && mesh->u.mesh.nvertices == 0 && mesh->u.mesh.nfaces == 0 &&
                   !mesh->u.mesh.vertices && !mesh->u.mesh.faces,
               "the mesh's lists released after the world is built");
    }
    /* Only an allocation with a block to itself is given back, once. */
    Arena *a = arena_new();
    char *big = a ? arena_alloc(a, 1 << 20) : NULL, *small = a ? arena_alloc(a, 64) : NULL;
    tap_ok(big && small && arena_release(a, big) == 1 && arena_release(a, big) == 0 && arena_release(a, small) == 0 &&
               arena_release(a, small + 16) == 0,
           "arena_release: a big allocation goes back, once; a small one or a pointer into one stays");
    arena_free(a);
    if (built)
        world_free(&one);
    scene_free(s);
}

/* Whether the kernel marks [p, p + bytes) as asking for huge pages: the
 * smaps entry of the mapping that holds p says "hg" among its VmFlags.
 * -1 when this system does not tell (no /proc/self/smaps). */
static int marked_huge(const void *p)
{
    FILE *f = fopen("/proc/self/smaps", "r");
    if (!f)
        return -1;
    char line[512];
    int inside = 0, marked = 0;
    while (fgets(line, sizeof line, f)) {
        unsigned long lo, hi;
        if (sscanf(line, "%lx-%lx ", &lo, &hi) == 2 && strchr(line, '-') < strchr(line, ' '))
            inside = (unsigned long)p >= lo && (unsigned long)p < hi;
        else if (inside && strncmp(line, "VmFlags:", 8) == 0)
            marked = strstr(line, " hg") != NULL;
    }
    fclose(f);
    return marked;
}

/* big_malloc and big_realloc are malloc and realloc whose big arrays ask
 * for huge pages; where the system offers them on request (THP "madvise"
 * or "always"), the kernel must have taken the advice for the array's
 * inside, and a grown array keeps its contents. */
static void test_big_memory(void)
{
    const size_t n = BIG_MEMORY_MIN / sizeof(double) + 1000;
    double *a = big_malloc(n * sizeof *a);
    for (size_t i = 0; a && i < n; i++)
        a[i] = (double)i * 0.5;
    double *b = a ? big_realloc(a, 3 * n * sizeof *b) : NULL;
    int kept = b != NULL;
    for (size_t i = 0; kept && i < n; i++)
        kept = b[i] == (double)i * 0.5;
    tap_ok(kept, "big_realloc keeps a %zu-byte array's contents as it grows it", n * sizeof *a);
    char mode[128] = "";
    FILE *f = fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    if (f) {
        if (!fgets(mode, sizeof mode, f))
            mode[0] = 0;
        fclose(f);
    }
    int offered = strstr(mode, "[madvise]") || strstr(mode, "[always]");
    int marked = b ? marked_huge((const char *)b + n * sizeof *b) : 0;
    if (offered && marked >= 0)
        tap_ok(marked == 1, "a grown big array asks for huge pages (VmFlags hg; the system's mode: %.*s)",
               (int)strcspn(mode, "\n"), mode);
    else
        tap_ok(1, "a grown big array asks for huge pages # SKIP this system offers none on request");
    /* Small arrays and pointers anywhere in a page are taken as they are. */
    char *small = big_malloc(100);
    big_memory_advise(small ? small + 1 : NULL, 99);
    big_memory_advise(b ? (char *)b + 3 : NULL, 3 * n * sizeof *b - 7);
    tap_ok(small != NULL, "small arrays and unaligned ranges are taken as they are");
    free(small);
    free(b);
}

/* Copies of a declared object share their material where nothing tells
 * them apart (a union of copies, doubled twelve times: 4096 boxes), and
 * keep their own where something does (a pigment or no_shadow of the copy's
 * own): a material is over a kilobyte, and twenty doublings made 1.4 GB of
 * them (issue 39). The images are those of one material an object
 * (tests/regress.sh, tests/exporters.sh). */
static void test_shared_materials(void)
{
    Scene *s = parse("#declare U = box { 0, 1 }\n"
                     "#for (I, 1, 12)\n"
                     "  #declare U = union { object { U } object { U translate x * pow(2, I - 1) } }\n"
                     "#end\n"
                     "object { U }\n"
                     "object { U pigment { rgb x } translate y * 2 }\n"
                     "object { U no_shadow translate y * 4 }\n");
    World w;
    WorldError we;
    int built = s && world_build_threads(&w, s, 2, &we) == 0;
    tap_ok(built && w.npolygons == 3 * 4096 * 6, "three unions of 4096 boxes: %d polygons",
           built ? w.npolygons : 0);
    int distinct = 0;
    for (int i = 0; built && i < w.nmaterials; i++) {
        int same = 0;
        for (int j = 0; j < i && !same; j++)
            same = w.materials[j].no_shadow == w.materials[i].no_shadow &&
                   w.materials[j].pigment.r == w.materials[i].pigment.r &&
                   w.materials[j].pigment.g == w.materials[i].pigment.g;
        distinct += !same;
    }
    /* two positions of the copies (the two object statements) times the
     * three unions' distinct looks */
    tap_ok(built && w.nmaterials <= 6 && distinct == 3,
           "their 12288 boxes share %d materials, of 3 distinct looks (%d)", built ? w.nmaterials : 0, distinct);
    if (built)
        world_free(&w);
    scene_free(s);
}

int main(void)
{
    test_shared_materials();
    test_big_memory();
    test_mesh_threads();
    test_pattern_values();
    test_pigments();
    test_texture_binding();
    test_layers();
    test_quick_colour();
    test_sky();
    test_approximations();
    test_strict();
    test_unsupported();
    test_flags();
    test_fallback_colors();
    return tap_done();
}
