/* The scene-language parser: values, directives, objects, camera, errors,
 * and robustness against truncated and mutated input. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "parser.h"
#include "tap.h"

static const char *const pov_dirs[] = { "/usr/share/povray-3.7/include" };
/* A small loop limit keeps the runaway and fuzz tests fast. */
static ParseOptions opts = { .include_dirs = pov_dirs, .ninclude_dirs = 1, .image_width = 320, .image_height = 240, .max_loop_iterations = 100000 };
static ParseError err;

static Scene *parse(const char *text)
{
    Scene *s = parse_scene_string("t.pov", text, &opts, &err);
    if (!s)
        tap_diag("parse error: %s:%d:%d: %s", err.file, err.line, err.column, err.message);
    return s;
}

static int near(double a, double b) { return fabs(a - b) < 1e-9; }
static int near_tol(double a, double b, double tol) { return fabs(a - b) < tol; }
static int vnear(Vec3 a, double x, double y, double z) { return near(a.x, x) && near(a.y, y) && near(a.z, z); }
static int vnear_tol(Vec3 a, double x, double y, double z, double tol)
{
    return near_tol(a.x, x, tol) && near_tol(a.y, y, tol) && near_tol(a.z, z, tol);
}

/* The box corner2.x of the first object: tests evaluate expressions there. */
static double value_of(const char *expr)
{
    char buf[512];
    snprintf(buf, sizeof buf, "box { 0, <%s, 0, 0> }", expr);
    Scene *s = parse(buf);
    double v = s ? s->objects[0]->u.box.corner2.x : NAN;
    scene_free(s);
    return v;
}

static Vec3 vector_of(const char *decl)
{
    char buf[512];
    snprintf(buf, sizeof buf, "%s\nbox { 0, V }", decl);
    Scene *s = parse(buf);
    Vec3 v = s ? s->objects[0]->u.box.corner2 : v3(NAN, NAN, NAN);
    scene_free(s);
    return v;
}

/* Parses text expecting failure at line:col with msg in the message. */
static void expect_error(const char *text, int line, int col, const char *msg, const char *what)
{
    Scene *s = parse_scene_string("t.pov", text, &opts, &err);
    int ok = !s && err.line == line && err.column == col && strstr(err.message, msg) != NULL;
    tap_ok(ok, "error: %s", what);
    if (!ok)
        tap_diag("got %s -> %s:%d:%d: %s", s ? "a scene" : "error", err.file, err.line, err.column, err.message);
    scene_free(s);
}

static void test_expressions(void)
{
    tap_ok(near(value_of("1 + 2 * 3"), 7), "precedence: 1 + 2 * 3 = 7");
    tap_ok(near(value_of("(1 + 2) * 3"), 9), "parentheses");
    tap_ok(near(value_of("-2 * 3 + 1"), -5), "unary minus binds tightest");
    tap_ok(near(value_of("- - 4"), 4), "double unary minus");
    tap_ok(near(value_of("10 / 4 - 1"), 1.5), "division");
    tap_ok(near(value_of("sqrt(16) + pow(2, 3) + abs(-1)"), 13), "sqrt pow abs");
    tap_ok(near(value_of("max(1, 5, 3) - min(4, 2)"), 3), "variadic max/min");
    tap_ok(near(value_of("sin(pi / 2) + cos(0)"), 2), "sin cos pi");
    tap_ok(near(value_of("mod(7, 3) + int(2.7) + floor(-0.5) + ceil(0.2)"), 3), "mod int floor ceil");
    tap_ok(near(value_of("degrees(pi) + radians(180)"), 180 + M_PI), "degrees radians");
    tap_ok(near(value_of("(2 < 3) + (3 <= 3) + (1 = 1) + (1 != 1) + (2 > 3)"), 3), "comparisons");
    tap_ok(near(value_of("(1 & 0) + (1 | 0) + !0"), 2), "logic");
    tap_ok(near(value_of("(1 > 0 ? 10 : 20)"), 10), "conditional");
    tap_ok(near(value_of("true + yes + on + false + no + off"), 3), "boolean keywords");
    tap_ok(near(value_of("image_width + image_height"), 560), "image_width/height from options");
    tap_ok(near(value_of("vlength(<3, 4, 0>) + vdot(x, y)"), 5), "vlength vdot");
    tap_ok(near(value_of("select(-1, 1, 2, 3) + select(1, 1, 2, 3)"), 4), "select");
    tap_ok(near(value_of("atan2(1, 1) * 4"), M_PI), "atan2");
    tap_ok(near(value_of("<1, 2, 3>.y + clock"), 2), "component access, clock = 0");
    tap_ok(vnear(vector_of("#declare V = 2 * <1, 2, 3> + 1;"), 3, 5, 7), "float promotes to vector");
    tap_ok(vnear(vector_of("#declare V = <1, 2, 3> * <2, 2, 0.5>;"), 2, 4, 1.5), "componentwise product");
    tap_ok(vnear(vector_of("#declare V = vcross(x, y) - z + vnormalize(<0, 0, 5>);"), 0, 0, 1), "vcross vnormalize");
    tap_ok(vnear(vector_of("#declare V = <1, 2>;"), 1, 2, 0), "2-D vector pads with 0");
    /* values printed by POV-Ray 3.7 with #debug vstr(...) */
    tap_ok(vnear(vector_of("#declare V = vaxis_rotate(x, y, 30) - vrotate(x, 30 * y);"), 0, 0, 0) &&
               vnear(vector_of("#declare V = vrotate(x, <0, 30, 0>);"), cos(M_PI / 6), 0, -0.5),
           "vrotate and vaxis_rotate as POV-Ray");
    tap_ok(vnear(vector_of("#declare V = 1 + <1, 2>;"), 2, 3, 0), "float + 2-D vector as POV-Ray");
    Scene *s = parse("box { 0, 1 + <1, 2> }");
    /* In vector context the float is already three wide: <2,3,1> in POV-Ray */
    tap_ok(s && vnear(s->objects[0]->u.box.corner2, 2, 3, 1), "vector context promotes the float first");
    scene_free(s);
}

static const Colour *pigment_of(const Scene *s, int i) { return &s->objects[i]->texture->pigment.colour; }

static int colour_is(const Colour *c, double r, double g, double b, double f, double t)
{
    return near_tol(c->r, r, 1e-6) && near_tol(c->g, g, 1e-6) && near_tol(c->b, b, 1e-6) &&
           near_tol(c->filter, f, 1e-6) && near_tol(c->transmit, t, 1e-6);
}

static void test_colours(void)
{
    Scene *s = parse("#include \"colors.inc\"\n"
                     "global_settings { assumed_gamma 1 }\n"
                     "box { 0, 1 pigment { Red } }\n"
                     "box { 0, 1 pigment { color Red filter 0.5 } }\n"
                     "box { 0, 1 pigment { rgb <1, 2, 3, 4, 5> } }\n"
                     "box { 0, 1 pigment { rgbt <1, 2, 3, 4> } }\n"
                     "box { 0, 1 pigment { color 0.5 } }\n"
                     "box { 0, 1 pigment { srgb 0.5 } }\n"
                     "box { 0, 1 pigment { color red 0.1 green 0.2 blue 0.3 } }\n"
                     "box { 0, 1 pigment { rgb 0.5 filter 0.3 red 0.1 } }\n"
                     "box { 0, 1 pigment { Gray50 * 2 } }\n");
    tap_ok(s != NULL, "colors.inc parses; colour forms parse");
    if (s) {
        tap_ok(colour_is(pigment_of(s, 0), 1, 0, 0, 0, 0), "pigment { Red }");
        tap_ok(colour_is(pigment_of(s, 1), 1, 0, 0, 0.5, 0), "color Red filter 0.5");
        tap_ok(colour_is(pigment_of(s, 2), 1, 2, 3, 4, 5), "rgb with five components keeps all five");
        tap_ok(colour_is(pigment_of(s, 3), 1, 2, 3, 0, 4), "rgbt puts the 4th into transmit");
        tap_ok(colour_is(pigment_of(s, 4), 0.5, 0.5, 0.5, 0.5, 0.5), "color 0.5 fills all five (POV-Ray)");
        tap_ok(colour_is(pigment_of(s, 5), 0.214041, 0.214041, 0.214041, 0, 0), "srgb decodes to linear");
        tap_ok(colour_is(pigment_of(s, 6), 0.1, 0.2, 0.3, 0, 0), "red/green/blue keywords");
        tap_ok(colour_is(pigment_of(s, 7), 0.1, 0.5, 0.5, 0.3, 0), "rgb then filter then red");
        tap_ok(colour_is(pigment_of(s, 8), 1, 1, 1, 0, 0), "colour identifier arithmetic");
    }
    scene_free(s);
    expect_error("box { 0, 1 pigment { srgb 1 } }", 1, 22, "assumed_gamma", "srgb before assumed_gamma");
}

static void test_finish_texture(void)
{
    Scene *s = parse("#include \"finish.inc\"\n"
                     "#declare T = texture { pigment { rgb <0, 1, 0> } finish { Shiny ambient 0.2 } }\n"
                     "box { 0, 1 texture { T } }\n"
                     "box { 0, 1 finish { phong 1 reflection { 0.1, 0.5 fresnel } metallic } }\n"
                     "box { 0, 1 finish { reflection 0.3 diffuse 0.7 brilliance 2 emission rgb 1 } }\n"
                     "box { 0, 1 interior { ior 1.5 } }\n"
                     "box { 0, 1 }\n");
    tap_ok(s != NULL, "finish.inc parses; textures parse");
    if (s) {
        const SceneTexture *t = s->objects[0]->texture;
        tap_ok(t && colour_is(&t->pigment.colour, 0, 1, 0, 0, 0), "declared texture pigment");
        tap_ok(t && near(t->finish.specular, 1) && near(t->finish.roughness, 0.001) && near(t->finish.ambient[1], 0.2),
               "finish identifier then a change");
        const Finish *f = &s->objects[1]->texture->finish;
        tap_ok(near(f->phong, 1) && near(f->reflection_min[0], 0.1) && near(f->reflection_max[2], 0.5) &&
                   f->reflection_fresnel && near(f->metallic, 1) && near(f->diffuse, 0.6),
               "finish-only object gets default texture plus finish");
        tap_ok(colour_is(&s->objects[1]->texture->pigment.colour, 0, 0, 0, 0, 0), "default pigment is black");
        f = &s->objects[2]->texture->finish;
        tap_ok(near(f->reflection_min[1], 0.3) && near(f->reflection_max[1], 0.3) && near(f->diffuse, 0.7) &&
                   near(f->brilliance, 2) && near(f->emission[2], 1),
               "old reflection syntax, diffuse, brilliance, emission");
        tap_ok(s->objects[3]->interior && near(s->objects[3]->interior->ior, 1.5) && !s->objects[3]->texture,
               "interior ior, no texture");
        tap_ok(s->objects[4]->texture == NULL, "object without texture has NULL texture");
    }
    scene_free(s);
}

static void test_directives(void)
{
    Scene *s = parse("#declare I = 0;\n"
                     "#while (I < 5)\n"
                     "  box { 0, 1 translate I * x }\n"
                     "  #declare I = I + 1;\n"
                     "#end\n"
                     "#if (I = 5) plane { y, 1 } #else plane { y, 2 } #end\n"
                     "#if (0) plane { y, 3 } #elseif (1) plane { y, 4 } #else plane { y, 5 } #end\n"
                     "#ifdef (I) plane { y, 6 } #end\n"
                     "#ifndef (Nope) plane { y, 7 } #end\n"
                     "#for (J, 1, 3) triangle { 0, x, y } #end\n"
                     "/* nested /* comment */ still comment */\n");
    tap_ok(s != NULL, "#while/#if/#for scene parses");
    if (s) {
        tap_ok(s->nobjects == 5 + 4 + 3, "#while made 5 boxes, #if chain 4 planes, #for 3 triangles (%d)", s->nobjects);
        tap_ok(s->nobjects >= 5 && near(s->objects[4]->transform.m[3][0], 4), "last box translated by 4");
        tap_ok(s->nobjects >= 9 && near(s->objects[5]->u.plane.distance, 1) && near(s->objects[6]->u.plane.distance, 4) &&
                   near(s->objects[7]->u.plane.distance, 6) && near(s->objects[8]->u.plane.distance, 7),
               "#if/#else/#elseif/#ifdef/#ifndef choose the right branches");
    }
    scene_free(s);

    s = parse("#declare A = 1;\n#if (1)\n #local A = 2;\n#end\nbox { 0, A }\n#undef A\n#ifndef(A) plane { y, 0 } #end\n");
    tap_ok(s && s->nobjects == 2 && near(s->objects[0]->u.box.corner2.x, 2), "#local at top level, #undef");
    scene_free(s);

    s = parse("#macro Foo(a) ovus { a, 1 } #end\n#declare S = ovus { 1, 0.5 }\n"
              "#declare F = function { x * y }\n#declare A = array[3];\nbox { 0, 1 }\n");
    tap_ok(s && s->nobjects == 1, "unsupported declarations are parsed past");
    scene_free(s);

    s = parse("#include \"colors.inc\"\n#include \"textures.inc\"\n#include \"metals.inc\"\n#include \"shapes.inc\"\n"
              "#include \"woods.inc\"\n#include \"glass.inc\"\n#include \"stones.inc\"\n"
              "box { 0, 1 texture { T_Gold_1A } }\n");
    tap_ok(s && s->nobjects == 1, "textures, metals, shapes, woods, glass, stones .inc parse");
    scene_free(s);
    /* textures.inc's Jade is a pigment (marble with a declared color_map):
     * POV-Ray takes a pigment identifier in a texture, as the texture's
     * pigment; its color_map identifier is no texture */
    s = parse("#include \"textures.inc\"\nbox { 0, 1 texture { Jade } }");
    tap_ok(s && s->nobjects == 1 && s->objects[0]->texture && s->objects[0]->texture->pigment.kind == PIGMENT_MARBLE &&
               s->objects[0]->texture->pigment.nmap == 4,
           "texture { Jade }: textures.inc's pigment (marble, its declared 4-entry color_map) as the texture's");
    scene_free(s);
    expect_error("#include \"textures.inc\"\nbox { 0, 1 texture { Jade_Map } }", 2, 22,
                 "'Jade_Map' cannot be used in a texture", "a color_map identifier in a texture");
}

static void test_objects(void)
{
    Scene *s = parse("#declare P = polygon { 10, <0,0>, <4,0>, <4,4>, <0,4>, <0,0>,\n"
                     "  <1,1>, <2,1>, <2,2>, <1,2>, <1,1> pigment { rgb 1 } }\n"
                     "object { P translate <1, 0, 0> }\n"
                     "object { P scale 2 }\n"
                     "polygon { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
                     "union { box { 0, 1 } plane { y, 0 pigment { rgb x } } translate y pigment { rgb z } }\n");
    tap_ok(s != NULL && s->nobjects == 4, "polygon, object{}, union");
    if (s && s->nobjects == 4) {
        const SceneObject *o = s->objects[0];
        tap_ok(o->kind == OBJ_POLYGON && o->u.polygon.noutlines == 2 && o->u.polygon.npoints == 10 &&
                   o->u.polygon.outline_start[1] == 5 && o->u.polygon.outline_start[2] == 10,
               "polygon with a hole: two outlines of five points");
        tap_ok(vnear(o->u.polygon.points[6], 2, 1, 0), "2-D polygon points get z = 0");
        tap_ok(near(o->transform.m[3][0], 1) && o->texture && near(o->texture->pigment.colour.r, 1),
               "object{} keeps the declared texture and adds a transform");
        tap_ok(near(s->objects[1]->transform.m[0][0], 2) && near(s->objects[1]->transform.m[3][0], 0),
               "second copy has its own transform");
        o = s->objects[2];
        tap_ok(o->u.polygon.noutlines == 1 && o->u.polygon.npoints == 4 && vnear(o->u.polygon.points[3], 0, 0, 0),
               "unclosed polygon is closed");
        o = s->objects[3];
        tap_ok(o->kind == OBJ_UNION && o->u.csg.nchildren == 2 && near(o->transform.m[3][1], 1) &&
                   o->u.csg.children[0]->texture == NULL && near(o->u.csg.children[1]->texture->pigment.colour.r, 1) &&
                   near(o->texture->pigment.colour.b, 1),
               "union children keep their own texture and transform");
    }
    scene_free(s);

    s = parse("mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }\n"
              "  normal_vectors { 1, z }\n"
              "  texture_list { 2, texture { pigment { rgb x } } texture { pigment { rgb y } } }\n"
              "  face_indices { 2, <0,1,2>, 1, <0,2,3>, 0 }\n"
              "  normal_indices { 2, <0,0,0>, <0,0,0> }\n"
              "  uv_vectors { 1, <0,0> } uv_indices { 2, <0,0,0>, <0,0,0> }\n"
              "  translate z }\n"
              "mesh { triangle { 0, x, y } smooth_triangle { 0, z, x, z, y, z texture { pigment { rgb 1 } } }\n"
              "  inside_vector z }\n");
    tap_ok(s && s->nobjects == 2, "mesh2 and mesh parse");
    if (s && s->nobjects == 2) {
        const SceneObject *m = s->objects[0];
        tap_ok(m->kind == OBJ_MESH && m->u.mesh.nvertices == 4 && m->u.mesh.nfaces == 2 && m->u.mesh.ntextures == 2,
               "mesh2 counts");
        tap_ok(m->u.mesh.faces[1].v[2] == 3 && m->u.mesh.faces[0].texture == 1 && m->u.mesh.faces[1].texture == 0 &&
                   m->u.mesh.faces[1].n[1] == 0,
               "mesh2 indices, texture indices, normal indices");
        tap_ok(near(m->transform.m[3][2], 1), "mesh2 transform");
        m = s->objects[1];
        tap_ok(m->u.mesh.nfaces == 2 && m->u.mesh.nvertices == 6 && m->u.mesh.faces[0].n[0] == -1 &&
                   m->u.mesh.faces[1].n[2] == 2 && m->u.mesh.faces[1].texture == 0 && m->u.mesh.faces[0].texture == -1,
               "mesh triangles become indexed faces");
    }
    scene_free(s);

    s = parse("triangle { <0,0,0>, <1,0,0>, <0,1,0> no_shadow double_illuminate }\n"
              "smooth_triangle { 0, y, x, y, z, y hollow no_image no_reflection }\n"
              "box { -1, 1 rotate <0, 90, 0> matrix <1,0,0, 0,1,0, 0,0,1, 0,0,5> transform { scale 2 inverse } }\n");
    tap_ok(s && s->nobjects == 3, "triangle, smooth_triangle, box with matrix and transform");
    if (s && s->nobjects == 3) {
        tap_ok(s->objects[0]->no_shadow && s->objects[0]->double_illuminate, "flags");
        tap_ok(s->objects[1]->u.triangle.has_normals && vnear(s->objects[1]->u.triangle.n[2], 0, 1, 0) &&
                   s->objects[1]->hollow && s->objects[1]->no_image && s->objects[1]->no_reflection,
               "smooth_triangle normals and flags");
        Vec3 q = transform_point(&s->objects[2]->transform, v3(1, 0, 0));
        tap_ok(vnear(q, 0, 0, -1.0 / 2 + 2.5), "rotate, matrix, inverse transform in order (%g %g %g)", q.x, q.y, q.z);
    }
    scene_free(s);
}

static void test_camera_lights(void)
{
    Scene *s = parse("camera { location <0, 2, -5> look_at <0, 1, 0> angle 60 }\n"
                     "light_source { <10, 10, -10>, rgb 1 }\n"
                     "light_source { <0, 1, 0> color rgb <1, 0.5, 0> parallel point_at <0, 0, 0> translate x shadowless "
                     "fade_distance 3 fade_power 2 }\n"
                     "background { rgb <0.1, 0.2, 0.3> }\n"
                     "global_settings { assumed_gamma 1.0 max_trace_level 7 ambient_light rgb 0.5 radiosity { count 10 } }\n");
    tap_ok(s != NULL, "camera, lights, background, global_settings");
    if (s) {
        const SceneCamera *c = &s->camera;
        /* direction length 1.33/2/tan(30 deg); values checked against POV-Ray's formulas */
        double dl = 1.33 / 2.0 / tan(M_PI / 6);
        Vec3 d = v3_normalize(v3(0, -1, 5));
        tap_ok(s->has_camera && vnear(c->location, 0, 2, -5), "camera location");
        tap_ok(vnear(c->direction, d.x * dl, d.y * dl, d.z * dl), "look_at + angle direction");
        tap_ok(vnear(c->right, 1.33, 0, 0), "right keeps length and handedness");
        Vec3 up = v3_cross(d, v3(1, 0, 0));
        tap_ok(vnear(c->up, up.x, up.y, up.z), "up is perpendicular");
        tap_ok(s->nlights == 2 && s->lights[1].kind == LIGHT_PARALLEL && vnear(s->lights[1].location, 1, 1, 0) &&
                   vnear(s->lights[1].point_at, 1, 0, 0) && s->lights[1].shadowless &&
                   near(s->lights[1].fade_distance, 3) && near(s->lights[1].colour.g, 0.5),
               "parallel light with transform applied");
        tap_ok(near(s->background.b, 0.3) && near(s->background.transmit, 0), "background");
        tap_ok(s->globals.has_assumed_gamma && near(s->globals.assumed_gamma, 1) && s->globals.max_trace_level == 7 &&
                   near(s->globals.ambient_light.g, 0.5),
               "global settings");
    }
    scene_free(s);

    s = parse("box { 0, 1 }");
    tap_ok(s && !s->has_camera && vnear(s->camera.right, 1.33, 0, 0) && vnear(s->camera.direction, 0, 0, 1) &&
               near(s->background.transmit, 1),
           "default camera and background");
    scene_free(s);

    /* left-handed right flips when right is given negative (a right-handed camera) */
    s = parse("camera { right -x * 4 / 3 up y location <3, 3, 3> look_at 0 sky z }");
    if (s) {
        const SceneCamera *c = &s->camera;
        Vec3 d = v3_normalize(v3(-3, -3, -3));
        Vec3 r = v3_scale(v3_normalize(v3_cross(v3(0, 0, 1), d)), -4.0 / 3.0);
        tap_ok(vnear(c->right, r.x, r.y, r.z), "negative right with sky z");
        tap_ok(vnear(c->direction, d.x, d.y, d.z), "direction keeps unit length");
    } else {
        tap_ok(0, "negative right with sky z");
        tap_ok(0, "direction keeps unit length");
    }
    scene_free(s);

    s = parse("camera { orthographic location <0, 0, -10> look_at 0 }\n"
              "#declare C = camera { location <1, 2, 3> }\ncamera { C translate x }\n");
    tap_ok(s && vnear(s->camera.location, 2, 2, 3), "declared camera with transform");
    scene_free(s);
    /* A light_source in a union moves with the union's transforms and its
     * parents'; each copy of a declared union brings its own lights; lights
     * come in POV-Ray's order (depth first, as written, after the lights
     * written before the union). tests/modelling.sh renders this against
     * POV-Ray. */
    s = parse("#declare U = union { light_source { <1, 0, 0> rgb 1 } box { 0, 1 }\n"
              "  union { light_source { <0, 2, 0> rgb 0.5 } translate z } light_source { <0, 0, 3> rgb 1 } translate x }\n"
              "light_source { <9, 9, 9> rgb 1 }\nobject { U scale 2 }\nobject { U }\n"
              "object { light_source { <0, 1, 0>, rgb 1 } translate <0, 0, 5> }\n");
    tap_ok(s && s->nobjects == 2 && s->nlights == 8 && vnear(s->lights[0].location, 9, 9, 9) &&
               vnear(s->lights[1].location, 4, 0, 0) && vnear(s->lights[2].location, 2, 4, 2) &&
               near(s->lights[2].colour.r, 0.5) && vnear(s->lights[3].location, 2, 0, 6) &&
               vnear(s->lights[4].location, 2, 0, 0) && vnear(s->lights[5].location, 1, 2, 1) &&
               vnear(s->lights[6].location, 1, 0, 3) && vnear(s->lights[7].location, 0, 1, 5),
           "light_sources in unions and object { }: moved by the transforms around them, one set per copy");
    if (s && s->nlights != 8)
        tap_diag("%d lights", s->nlights);
    scene_free(s);
    /* After any object keyword's '{', a declared object or light is a copy,
     * as `object { ID ... }` (POV-Ray's Parse_Object_Id; radiosity/cornell.pov
     * writes `light_source { SubPatch translate ... }`). povray renders this
     * scene and the one with `object` in place of `light_source` and `union`
     * identically. */
    s = parse("#declare L = light_source { <0, 4, -1> rgb 1 }\n"
              "#declare U = union { light_source { <0, 3, 0> rgb 1 } box { 0, 1 } }\n"
              "light_source { L translate x * -2 }\nunion { U translate <1.5, 0, 0.5> }\n");
    tap_ok(s && s->nlights == 2 && vnear(s->lights[0].location, -2, 4, -1) && vnear(s->lights[1].location, 1.5, 3, 0.5) &&
               s->nobjects == 1 && s->objects[0]->kind == OBJ_UNION && s->objects[0]->u.csg.nchildren == 1,
           "light_source { L ... } and union { U ... } copy the declared light and union");
    scene_free(s);
    expect_error("#declare S = ovus { 1, 0.5 }\nunion { S }\n", 2, 9, "'ovus' is not supported by hstrace (declared at t.pov:1)",
                 "union { DeclaredSphere }: the error names the use and the declaration");
    /* but an unsupported float or vector after '{' is the object's own
     * first item: the unsupported object keyword is named first */
    expect_error("#declare F = function { x }\n#declare V = <F(1, 2, 3), 0, 0>;\novus { V, 1 }\n", 3, 1,
                 "'ovus' is not supported by hstrace", "ovus { UnsupportedVector, 1 }: the ovus is the error");
    s = parse("camera { orthographic location <0, 0, -10> look_at 0 }");
    tap_ok(s && s->camera.kind == CAMERA_ORTHOGRAPHIC && vnear(s->camera.right, 13.3, 0, 0) &&
               vnear(s->camera.up, 0, 10, 0),
           "orthographic camera sizes right/up like POV-Ray");
    scene_free(s);
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}


/* The scene `prelude` then checks that string expression `expr` equals
 * `want`: a mismatch stops the parse with #error, whose message shows what
 * the expression gave. */
static void string_is(const char *prelude, const char *expr, const char *want, const char *what)
{
    char buf[1024];
    snprintf(buf, sizeof buf,
             "%s\n#declare Got = %s;\n#if (strcmp(Got, \"%s\") != 0) #error concat(\"got [\", Got, \"]\") #end\n"
             "box { 0, 1 }\n",
             prelude, expr, want);
    Scene *s = parse(buf);
    tap_ok(s != NULL, "%s: %s is \"%s\"", what, expr, want);
    scene_free(s);
}

/* The first box's corner2.x after `text` (which ends in a box using the
 * value), or NAN. */
static double box_x(const char *text)
{
    Scene *s = parse(text);
    double v = s && s->nobjects > 0 ? s->objects[0]->u.box.corner2.x : NAN;
    scene_free(s);
    return v;
}

static void test_macros(void)
{
    /* expands to an object, at top level and inside an object's body */
    Scene *s = parse("#macro Tri(P, S) triangle { P, P + S * x, P + S * y } #end\n"
                     "Tri(<1, 0, 0>, 2)\n"
                     "union { Tri(0, 1) Tri(y, 1) }\n");
    tap_ok(s && s->nobjects == 2 && s->objects[0]->kind == OBJ_TRIANGLE && vnear(s->objects[0]->u.triangle.v[1], 3, 0, 0),
           "a macro expands to an object, at top level and in a union");
    scene_free(s);

    /* expands to a value and to a partial token stream */
    tap_ok(near(box_x("#macro Sq(A) (A) * (A) #end\nbox { 0, <Sq(2 + 1), 1, 1> }"), 9), "a macro as a value: Sq(2 + 1) = 9");
    tap_ok(near(box_x("#macro Corners() 0, <4, 1, 1> #end\nbox { Corners() }"), 4),
           "a macro expanding to part of an object's body");
    tap_ok(near(box_x("#macro Plus() + 1 #end\n#declare V = 2 Plus() Plus();\nbox { 0, V }"), 4),
           "a macro expanding to the rest of an expression");

    /* a plain identifier is passed by reference, anything else by value */
    tap_ok(near(box_x("#macro Twice(A) #declare A = A * 2; #end\n#declare V = 3;\nTwice(V)\nbox { 0, V }"), 6),
           "#declare of a parameter passed as an identifier changes the caller's variable");
    tap_ok(near(box_x("#macro Twice(A) #local A = A * 2; #end\n#declare V = 3;\nTwice(V)\nbox { 0, V }"), 6),
           "#local of a by-reference parameter also writes the caller's variable, as in POV-Ray");
    tap_ok(near(box_x("#macro Twice(A) #declare A = A * 2; #end\n#declare V = 3;\nTwice(V + 0)\nbox { 0, V }"), 3),
           "an expression argument is passed by value");
    tap_ok(near(box_x("#macro Set(A) #declare A = 5; #end\n#macro Outer(B) Set(B) #end\n#declare V = 1;\nOuter(V)\nbox { 0, V }"), 5),
           "a reference passed on through two macros");

    /* scope */
    s = parse("#declare L = 1;\n#macro M() #local L = 2; #local Only = 3; box { 0, L } #end\nM()\n"
              "#ifdef (Only) plane { y, 0 } #end\nbox { 0, L }\n");
    tap_ok(s && s->nobjects == 2 && near(s->objects[0]->u.box.corner2.x, 2) && near(s->objects[1]->u.box.corner2.x, 1),
           "#local in a macro is local to the call; the caller's L is untouched");
    scene_free(s);
    tap_ok(near(box_x("#macro M() #declare G = 7; #end\nM()\nbox { 0, G }"), 7), "#declare in a macro makes a global");
    tap_ok(near(box_x("#macro Get() Cv #end\n#declare Cv = 4;\nbox { 0, Get() }"), 4),
           "a macro body sees the identifiers of its caller");

    /* recursion and nesting */
    tap_ok(near(box_x("#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end\nbox { 0, Fact(5) }"), 120),
           "recursion: Fact(5) = 120");
    s = parse("#macro Row(N) #if (N > 0) triangle { 0, x, y translate N * x } Row(N - 1) #end #end\nRow(300)\n");
    tap_ok(s && s->nobjects == 300, "a macro recursing 300 deep");
    scene_free(s);
    tap_ok(near(box_x("#macro Add(A, B) (A + B) #end\nbox { 0, Add(Add(1, 2), Add(3, Add(4, 5))) }"), 15),
           "nested calls in arguments");
    expect_error("#macro Loop(N) Loop(N + 1) #end\nLoop(0)\n", 1, 16,
                 "macro 'Loop' called more than 1000 levels deep: is its recursion endless?", "endless recursion");

    /* wrong calls */
    expect_error("#macro M(A, B) box { A, B } #end\nM(1)\n", 2, 4, "macro 'M' takes 2 parameters but 1 was given",
                 "too few arguments");
    expect_error("#macro M(A) box { 0, A } #end\nM(1, 2)\n", 2, 4, "macro 'M' takes 1 parameter but more were given",
                 "too many arguments");
    expect_error("#macro M(A) box { 0, A } #end\nM(Nope)\n", 2, 3,
                 "undeclared identifier 'Nope' passed as parameter 'A' of macro 'M'", "undeclared argument");
    expect_error("#macro M(A) box { 0, A } #end\n#declare M = 1;\n", 2, 10, "'M' is a macro (declared at t.pov:1) and cannot be redeclared",
                 "redeclaring a macro");
    expect_error("#macro M(A) box { 0, A }\n", 1, 1, "#macro has no matching #end", "#macro without #end");

    /* unsupported things inside macros and arguments stay lazy */
    s = parse("#macro Ball(R) ovus { R, 0.5 } #end\n#declare B = Ball(1);\n#macro Id(X) X #end\n"
              "#declare S = Id(ovus { 1, 0.5 });\nbox { 0, 1 }\n");
    tap_ok(s && s->nobjects == 1, "a macro declaring an unsupported object, and one as an argument, are parsed past");
    scene_free(s);

    /* error positions: in the macro's file, and a note for each call */
    expect_error("#macro Inner(A)\n  box { 0, A Oops }\n#end\n#macro Outer()\n  Inner(1)\n#end\nOuter()\n", 2, 14,
                 "expected", "an error inside a macro body is at the body's token");
    tap_ok(strcmp(err.notes, "t.pov:5:3: note: in macro 'Inner' called here\nt.pov:7:1: note: in macro 'Outer' called here\n") == 0,
           "the notes name each macro call, innermost first");
    if (strcmp(err.notes, "t.pov:5:3: note: in macro 'Inner' called here\nt.pov:7:1: note: in macro 'Outer' called here\n") != 0)
        tap_diag("notes: [%s]", err.notes);
}

static void test_arrays(void)
{
    tap_ok(near(box_x("#declare A = array[3] {10, 20, 30};\nbox { 0, A[1] + A[2] }"), 50), "array with initialiser");
    tap_ok(near(box_x("#declare A = array[2][3] { {1, 2, 3}, {4, 5, 6} }\nbox { 0, A[1][2] * 10 + A[0][1] }"), 62),
           "two-dimensional array");
    tap_ok(near(box_x("#declare A = array[4];\n#for (I, 0, 3) #declare A[I] = I * I; #end\nbox { 0, A[3] }"), 9),
           "#declare A[i] in a loop");
    tap_ok(near(box_x("#declare A = array[2][5][7];\nbox { 0, dimensions(A) * 100 + dimension_size(A, 2) * 10 + dimension_size(A, 3) }"),
                357),
           "dimensions and dimension_size");
    tap_ok(near(box_x("#declare A = array[2] {1, 2}\n#declare B = A;\n#declare B[0] = 9;\nbox { 0, A[0] }"), 1),
           "#declare B = A copies the array");
    tap_ok(near(box_x("#declare A = array[2] {1, 2}\n#macro Put(Arr) #declare Arr[1] = 8; #end\nPut(A)\nbox { 0, A[1] }"), 8),
           "an array passed by reference to a macro");
    Scene *s = parse("#declare Objs = array[2] { box { 0, 1 }, triangle { 0, x, y } }\nobject { Objs[1] }\n"
                     "#declare Names = array[2] {\"a\", \"bc\"}\nbox { 0, strlen(Names[1]) }\n");
    tap_ok(s && s->nobjects == 2 && s->objects[0]->kind == OBJ_TRIANGLE && near(s->objects[1]->u.box.corner2.x, 2),
           "arrays of objects and of strings");
    scene_free(s);
    s = parse("#declare A = array[3];\n#declare A[1] = 1;\n#ifdef (A[1]) box { 0, 1 } #end\n#ifndef (A[2]) box { 0, 2 } #end\n"
              "#if (defined(A[0])) plane { y, 0 } #end\n");
    tap_ok(s && s->nobjects == 2, "#ifdef, #ifndef and defined() of array elements");
    scene_free(s);
    string_is("#declare A = array[3] {\"x\", \"y\", \"z\"}", "concat(A[2], A[0])", "zx", "string elements");

    expect_error("#declare A = array[3];\n#declare A[0] = 1;\nbox { 0, A[1] }\n", 3, 10,
                 "array element 'A[1]' is used before it is given a value", "uninitialised element");
    expect_error("#declare A = array[3];\nbox { 0, A[3] }\n", 2, 12, "index 3 is out of range for 'A' (array[3]: 0 to 2)",
                 "index out of range");
    expect_error("#declare A = array[2][2];\n#declare A[0][-1] = 1;\n", 2, 15,
                 "index -1 is out of range for dimension 2 of 'A' (0 to 1)", "negative index");
    expect_error("#declare A = array[3] {1, 2};\n", 1, 28, "this array initialiser has 2 elements where 3 are needed",
                 "short initialiser");
    expect_error("#declare A = array[2] {1, 2, 3};\n", 1, 30, "expected '}' after the 2 elements of the array initialiser",
                 "long initialiser");
    /* POV-Ray reads a declared value as sums and products only (its
     * Parse_RValue): a '<' after a vector element starts the next element,
     * so a line end without ',' is accepted (grenadine/lemon.inc; povray
     * prints A[1] = <3, 4>). */
    s = parse("#declare A = array[3] {\n <1, 2>, <5, 6>\n <3, 4>\n}\nbox { 0, <A[2].u, A[2].v, A[1].u> }");
    tap_ok(s && vnear(s->objects[0]->u.box.corner2, 3, 4, 5), "array elements '<1, 2> <3, 4>' without a comma, as POV-Ray");
    scene_free(s);
    expect_error("#declare A = array[0];\n", 1, 20, "invalid array size 0", "zero size");
    expect_error("#declare A = 1;\n#declare A[0] = 1;\n", 2, 11, "'A' is not an array", "indexing a float");
}

/* Numbers are read to the same double strtod() gives (the lexer has a fast
 * path for short decimals): many random spellings, compared exactly. */
static void test_number_lexing(void)
{
    unsigned seed = 2024;
    int bad = 0, tried = 0;
    char text[512], num[64];
    for (int i = 0; i < 3000; i++) {
        seed = seed * 1103515245u + 12345u;
        unsigned r = seed >> 4;
        double v = (double)(r % 100000007u) / (double)(1u << (r % 23));
        int digits = (int)(r % 19);
        switch (i % 4) {
        case 0: snprintf(num, sizeof num, "%.*f", digits, v); break;
        case 1: snprintf(num, sizeof num, "%.*e", digits, v); break;
        case 2: snprintf(num, sizeof num, "%.*g", digits + 1, v * 1e-7); break;
        default: snprintf(num, sizeof num, "%u", r); break;
        }
        snprintf(text, sizeof text, "box { 0, <%s, 1, 1> }", num);
        Scene *s = parse_scene_string("t.pov", text, &opts, &err);
        tried++;
        if (!s || s->objects[0]->u.box.corner2.x != strtod(num, NULL)) {
            if (bad++ < 5)
                tap_diag("%s read as %.17g, strtod gives %.17g", num, s ? s->objects[0]->u.box.corner2.x : NAN,
                         strtod(num, NULL));
        }
        scene_free(s);
    }
    tap_ok(bad == 0, "%d numbers read exactly as strtod reads them (%d differ)", tried, bad);
}

/* Plain vectors, `<1, -2.5, 3e2>`, are read straight from the text (the
 * lexer's fast path); anything else by the expression parser. Each text
 * here must give the bits the expression parser gives it in parentheses,
 * where the fast path never applies, whichever of the two reads it. */
static void test_plain_vectors(void)
{
    static const char *const cases[] = {
        "<1, -2.5, 3e2>", "< 1 ,2,3 >", "<\n1,\n-\n2,3\n>", "</*a*/1,/*b*/2//c\n,3/*d*/>", "<-0, +0, .5>",
        "<1e-3,1E+3,0.000001>", "<-1e-300, 1e300, 123456789012345678901234567890>", "<1, 2, 3> + x",
        "<1, 2, 3>*2", "<1, 2, 3> - <1, 1, 1>", "<1,2,3>/2", "<1, 2>", "<x.x, 2, 3>", "<1, - -2, 3>",
        "<1, 2, 3 + 1>", "<1 + 1, 2, 3>", "<1, 2, 3.>", "<1.5.5, 2>", "<2*3, 2, 3>", "<1, 2 3>",
    };
    int same = 0, n = (int)(sizeof cases / sizeof cases[0]);
    for (int i = 0; i < n; i++) {
        char text[256], ref[256];
        snprintf(text, sizeof text, "box { 0, %s }", cases[i]);
        snprintf(ref, sizeof ref, "box { 0, (%s) }", cases[i]);
        ParseError e1, e2;
        Scene *a = parse_scene_string("t.pov", text, &opts, &e1);
        Scene *b = parse_scene_string("t.pov", ref, &opts, &e2);
        int ok = a && b && memcmp(&a->objects[0]->u.box.corner2, &b->objects[0]->u.box.corner2, sizeof(Vec3)) == 0;
        if (!ok)
            tap_diag("%s: %s", cases[i], a && b ? "differs" : !a ? e1.message : e2.message);
        same += ok;
        scene_free(a);
        scene_free(b);
    }
    tap_ok(same == n, "%d vectors read straight from the text or by the expression parser give the same bits (%d differ)",
           n, n - same);
    /* what the fast path gives up on is reported where the general path reports it */
    static const struct {
        const char *text;
        int line, column;
    } errors[] = {
        { "box { 0, <1, 2, 3 }", 1, 19 },
        { "box { 0, <1, 2, 1e309> }", 1, 10 },
        { "box {\n 0, <1,\n 2, } }", 3, 5 },
    };
    for (int i = 0; i < 3; i++) {
        ParseError e;
        Scene *a = parse_scene_string("t.pov", errors[i].text, &opts, &e);
        tap_ok(!a && e.line == errors[i].line && e.column == errors[i].column, "%s: error at %d:%d (%s at %d:%d)",
               errors[i].text, errors[i].line, errors[i].column, a ? "none" : e.message, a ? 0 : e.line,
               a ? 0 : e.column);
        scene_free(a);
    }
}

/* A mesh2 of nv vertices and nf faces, written as exporters write them
 * (blanks, newlines, signs, exponents), with `lead` right after each
 * list's count and `tail` after the mesh. */
static char *big_mesh2(int nv, int nf, const char *lead, const char *tail)
{
    size_t cap = (size_t)nv * 48 + (size_t)nf * 40 + 4096, len = 0;
    char *t = malloc(cap);
    if (!t)
        return NULL;
    unsigned seed = 7;
    len += (size_t)snprintf(t + len, cap - len, "mesh2 {\n  vertex_vectors { %d,%s", nv, lead);
    for (int i = 0; i < nv; i++) {
        seed = seed * 1103515245u + 12345u;
        double x = (double)(seed >> 8) / 65536.0 - 128.0, y = (double)(seed % 1000) * 1e-3;
        len += (size_t)snprintf(t + len, cap - len, i % 5 == 0 ? "\n    <%.6g, %g, -%de-2>," : " <%.9g,%g , %d>,",
                                x, y, i % 1000);
    }
    len += (size_t)snprintf(t + len, cap - len, "\n  }\n  face_indices { %d,%s", nf, lead);
    for (int i = 0; i < nf; i++)
        len += (size_t)snprintf(t + len, cap - len, i % 7 == 0 ? "\n<%d, %d, %d>," : " <%d,%d,%d>", i % nv,
                                (i * 7 + 1) % nv, (i * 13 + 2) % nv);
    snprintf(t + len, cap - len, "\n  }\n}\n%s", tail);
    return t;
}

/* mesh2's long lists are read on several threads (plain_lists.c): the same
 * scene as item by item (a comment before the first item makes the reading
 * item by item), for 1 to 8 threads, with the lexer where item by item
 * leaves it (an error after the mesh is reported at the same place); and
 * what the fast reading gives up on is read, or reported, as before. */
static void test_plain_lists(void)
{
    const int nv = 60000, nf = 120000; /* about 4 MB: up to 4 pieces */
    char *ref_text = big_mesh2(nv, nf, " /* item by item */", "bogus");
    ParseError e;
    ParseOptions o = opts;
    Scene *ref = ref_text ? parse_scene_string("t.pov", ref_text, &o, &e) : NULL;
    int ref_line = ref ? 0 : e.line, ref_col = ref ? 0 : e.column;
    free(ref_text);
    o.max_loop_iterations = 0;
    /* the reference read again, to have its scene (the text ends in an error) */
    ref_text = big_mesh2(nv, nf, " /* item by item */", "");
    ref = ref_text ? parse_scene_string("t.pov", ref_text, &opts, &e) : NULL;
    free(ref_text);
    tap_ok(ref && ref->nobjects == 1 && ref->objects[0]->u.mesh.nvertices == nv &&
               ref->objects[0]->u.mesh.nfaces == nf && ref_line > 0,
           "a mesh2 of %d vertices and %d faces, item by item (then an error at %d:%d)", nv, nf, ref_line, ref_col);
    static const int counts[] = { 1, 2, 3, 8 };
    for (int k = 0; ref && k < 4; k++) {
        o = opts;
        o.threads = counts[k];
        char *text = big_mesh2(nv, nf, "", "");
        Scene *s = text ? parse_scene_string("t.pov", text, &o, &e) : NULL;
        free(text);
        const SceneObject *a = s && s->nobjects == 1 ? s->objects[0] : NULL, *r = ref->objects[0];
        int same = a && a->u.mesh.nvertices == nv && a->u.mesh.nfaces == nf &&
                   memcmp(a->u.mesh.vertices, r->u.mesh.vertices, sizeof(Vec3) * (size_t)nv) == 0 &&
                   memcmp(a->u.mesh.faces, r->u.mesh.faces, sizeof(MeshFace) * (size_t)nf) == 0;
        scene_free(s);
        text = big_mesh2(nv, nf, "", "bogus");
        s = text ? parse_scene_string("t.pov", text, &o, &e) : NULL;
        free(text);
        tap_ok(same && !s && e.line == ref_line && e.column == ref_col,
               "... on %d thread%s: the same vertices and faces, bit for bit, and the error after at %d:%d", counts[k],
               counts[k] == 1 ? "" : "s", s ? 0 : e.line, s ? 0 : e.column);
        scene_free(s);
    }
    scene_free(ref);
    /* what the fast reading leaves to the item-by-item one (the positions
     * are those hstrace reported before lists had a fast reading) */
    static const struct {
        const char *text, *what;
        int ok, line, column;
    } cases[] = {
        { "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0> x, <0,1,0> } face_indices { 1, <0,1,2> } }", "an identifier",
          0, 1, 49 },
        { "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0>, <1,1,0> } face_indices { 1, <0,1,2> } }",
          "one vector too many", 0, 1, 56 },
        { "mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } }",
          "one vector too few", 0, 1, 55 },
        { "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,3> } }",
          "a face index out of range", 0, 1, 75 },
        { "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>+x, <0,1,0> } face_indices { 1, <0,1,2> } }",
          "an operator after a vector", 1, 0, 0 },
        { "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0> // a comment\n, <0,1,0> } face_indices { 1, <0,1,2>, } }",
          "a comment inside", 1, 0, 0 },
    };
    for (int i = 0; i < 6; i++) {
        o = opts;
        o.threads = 2;
        Scene *s = parse_scene_string("t.pov", cases[i].text, &o, &e);
        ParseError e1;
        Scene *s1 = parse_scene_string("t.pov", cases[i].text, &opts, &e1);
        int ok = cases[i].ok ? s != NULL && s1 != NULL
                             : !s && !s1 && e.line == cases[i].line && e.column == cases[i].column &&
                                   strcmp(e.message, e1.message) == 0;
        tap_ok(ok, "mesh2 with %s: %s (%s at %d:%d)", cases[i].what, cases[i].ok ? "read" : "the same error",
               s ? "no error" : e.message, s ? 0 : e.line, s ? 0 : e.column);
        scene_free(s);
        scene_free(s1);
    }
}

static void test_switch(void)
{
    const char *scene = "#switch (V)\n"
                        "  #case (1) box { 0, 1 }\n"
                        "  #case (2) box { 0, 2 } #break\n"
                        "  #range (3, 5) box { 0, 3 }\n"
                        "  #case (6) box { 0, 6 } #break\n"
                        "  #else box { 0, 9 }\n"
                        "#end\n"
                        "plane { y, 0 }\n";
    static const struct { double v; int n; double first, second; } cases[] = {
        { 1, 3, 1, 2 }, /* falls through into #case (2), stops at #break */
        { 2, 2, 2, 0 },
        { 4, 3, 3, 6 }, /* a #range, falling through into #case (6) */
        { 6, 2, 6, 0 },
        { 7, 2, 9, 0 }, /* #else */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char buf[600];
        snprintf(buf, sizeof buf, "#declare V = %g;\n%s", cases[i].v, scene);
        Scene *s = parse(buf);
        int ok = s && s->nobjects == cases[i].n && near(s->objects[0]->u.box.corner2.x, cases[i].first) &&
                 (cases[i].n < 3 || near(s->objects[1]->u.box.corner2.x, cases[i].second));
        tap_ok(ok, "#switch with V = %g: %d objects", cases[i].v, cases[i].n);
        scene_free(s);
    }
    /* POV-Ray 3.7's tolerance, as povray shows it: 1e-10 */
    Scene *s = parse("#if (1e-7) box { 0, 1 } #end\n#if (1e-11) box { 0, 2 } #end\n"
                     "#if (1 = 1 + 1e-9) box { 0, 3 } #end\n#if (1 = 1 + 1e-11) box { 0, 4 } #end\n"
                     "#switch (1 + 1e-7) #case (1) box { 0, 5 } #end\n#switch (1 + 1e-11) #case (1) box { 0, 6 } #end\n");
    tap_ok(s && s->nobjects == 3 && near(s->objects[0]->u.box.corner2.x, 1) && near(s->objects[1]->u.box.corner2.x, 4) &&
               near(s->objects[2]->u.box.corner2.x, 6),
           "conditions, = and #case compare within POV-Ray's 1e-10");
    scene_free(s);
    s = parse("#switch (3) #case (1) box { 0, 1 } #end plane { y, 0 }\n");
    tap_ok(s && s->nobjects == 1, "no #case matches and there is no #else");
    scene_free(s);
    s = parse("#switch (1)\n#case (1)\n #switch (2) #case (2) box { 0, 2 } #break #case (3) box { 0, 3 } #end\n"
              " #if (1) box { 0, 1 } #break box { 0, 5 } #end\n box { 0, 7 }\n#end\n");
    tap_ok(s && s->nobjects == 2 && near(s->objects[1]->u.box.corner2.x, 1),
           "nested #switch; #break inside an #if leaves the #switch");
    scene_free(s);
    s = parse("#declare I = 0;\n#while (1) #declare I = I + 1; #if (I = 4) #break #end #end\nbox { 0, I }\n");
    tap_ok(s && near(s->objects[0]->u.box.corner2.x, 4), "#break leaves a #while");
    scene_free(s);
    expect_error("#case (1)\n", 1, 2, "#case without a matching #switch", "#case alone");
    expect_error("#switch (1) box { 0, 1 } #case (1) #end\n", 1, 13, "#switch must be followed by #case, #range, #else or #end",
                 "text before the first #case");
    expect_error("box { 0, 1 }\n#break\n", 2, 1, "#break outside #switch, #while, #for and #macro", "stray #break");
}

static void test_strings_and_functions(void)
{
    string_is("", "concat(\"a\", \"bc\", str(1.5, 0, 2))", "abc1.50", "concat, str");
    string_is("", "str(3.14159, -8, 3)", "0003.142", "str with a zero-padded width");
    string_is("", "str(2, 5, 0)", "    2", "str with a width");
    string_is("", "str(0.1, 0, -1)", "0.100000", "str with the default precision");
    string_is("", "chr(65)", "A", "chr");
    string_is("", "substr(\"abcdef\", 2, 3)", "bcd", "substr");
    string_is("", "strupr(\"MiXed\")", "MIXED", "strupr");
    string_is("", "strlwr(\"MiXed\")", "mixed", "strlwr");
    string_is("", "vstr(3, <1, 2, 3>, \", \", 0, 1)", "1.0, 2.0, 3.0", "vstr");
    string_is("", "vstr(2, <1, 2, 3>, \"/\", -4, 0)", "0001/0002", "vstr pads with zeros, two components at least");
    string_is("#declare S = \"x\";\n#macro Add(T) #declare S = concat(S, T); #end\nAdd(\"y\") Add(\"z\")", "S", "xyz",
              "a string passed by reference");
    tap_ok(near(value_of("strlen(\"hello\") + asc(\"A\") + val(\"2.5\")"), 5 + 65 + 2.5), "strlen asc val");
    tap_ok(near(value_of("strcmp(\"a\", \"b\") * 10 + strcmp(\"b\", \"b\")"), -10), "strcmp");
    tap_ok(near(value_of("vlength(vnormalize(<3, 4, 0>)) + vdot(vcross(x, y), z)"), 2), "vnormalize vcross vdot");
    tap_ok(near(value_of("vrotate(x, <0, 0, 90>).y"), 1), "vrotate");
    tap_ok(near(value_of("div(7, 2) + mod(-7, 2) + pow(2, 10)"), 3 - 1 + 1024), "div mod pow");

    /* POV-Ray 3.7's numbers for the same scene (printed with #debug):
     * seed(42) gives 0.7235829112 then 0.3299792596; rand.inc with seed(7)
     * gives VRand <0.95393288, 0.61046628, 0.16685214>, then
     * RRand(2, 5) 2.10460125, then Rand_Normal(0, 1) -0.27153477. */
    tap_ok(near_tol(value_of("rand(seed(42))"), 0.7235829112, 1e-10), "rand: POV-Ray's first number for seed 42");
    tap_ok(near_tol(box_x("#declare R = seed(42);\n#declare A = rand(R);\nbox { 0, rand(R) }"), 0.3299792596, 1e-10),
           "rand: POV-Ray's second number for seed 42");
    tap_ok(near_tol(box_x("#declare R1 = seed(42);\n#declare R2 = seed(42);\n#declare A = rand(R1);\nbox { 0, rand(R2) }"),
                    0.7235829112, 1e-10),
           "streams are independent");
    Scene *s = parse("#include \"rand.inc\"\n#declare S = seed(7);\n#declare V = VRand(S);\n#declare F = RRand(2, 5, S);\n"
                     "#declare N = Rand_Normal(0, 1, S);\nbox { V, <F, N, 0> }\n");
    tap_ok(s && vnear_tol(s->objects[0]->u.box.corner1, 0.95393288, 0.61046628, 0.16685214, 1e-8) &&
               near_tol(s->objects[0]->u.box.corner2.x, 2.10460125, 1e-8) &&
               near_tol(s->objects[0]->u.box.corner2.y, -0.27153477, 1e-8),
           "rand.inc's VRand, RRand, Rand_Normal give POV-Ray's numbers");
    scene_free(s);
    expect_error("#declare A = rand(3);\n", 1, 19, "rand needs a stream made by seed(), not 3", "rand without seed");
}

static void test_errors(void)
{
    expect_error("polygon foo", 1, 9, "expected '{' after 'polygon', found 'foo'", "missing brace");
    expect_error("box { 0, 1\n", 2, 1, "found the end of the file", "unclosed block");
    expect_error("box { 0, Nope }", 1, 10, "undeclared identifier 'Nope'", "unknown identifier");
    expect_error("ovus { 1, 0.5 }", 1, 1, "'ovus' is not supported by hstrace", "unsupported object");
    expect_error("light_source { 0, 1 projected_through { box { 0, 1 } } }", 1, 21,
                 "'projected_through' is not supported", "projected_through");
    {
        /* POV-Ray ignores area_light's modifiers on a point light (orient
         * and area_illumination with a warning; advanced/diffract.pov writes
         * jitter outside its #if (Area_Light)), and takes them before the
         * area_light too; circular without one it refuses. */
        Scene *s = parse("light_source { 0, 1 jitter adaptive 1 orient area_illumination on }\n"
                         "light_source { x, 1 circular orient area_light x, y, 3, 3 }\n");
        tap_ok(s && s->nlights == 2 && vnear(s->lights[1].location, 1, 0, 0),
               "jitter, adaptive, orient, area_illumination without an area_light, and before it, as POV-Ray");
        tap_ok(s && s->lights[0].area.size1 == 0 && !s->lights[0].area.jitter && !s->lights[0].area.orient,
               "... and on a point light they change nothing");
        tap_ok(s && s->lights[1].area.size1 == 3 && s->lights[1].area.size2 == 3 && s->lights[1].area.circular &&
                   s->lights[1].area.orient && s->lights[1].area.adaptive == 100 && !s->lights[1].area.jitter,
               "circular and orient before the area_light are its own; adaptive 100 (every sample) unless given");
        scene_free(s);
    }
    {
        /* Sizes truncated as POV-Ray's (int)Parse_Float; the axes turn and
         * scale with the light as directions, not as points. */
        Scene *s = parse("light_source { <1, 2, 3>, 1 area_light <2, 0, 0>, <0, 0, 1>, 4.9, 2.2 adaptive 2.7 jitter "
                         "area_illumination off rotate 90*z translate <5, 0, 0> scale 2 }\n");
        const SceneLight *l = s ? &s->lights[0] : NULL;
        tap_ok(l && l->area.size1 == 4 && l->area.size2 == 2 && l->area.adaptive == 2 && l->area.jitter &&
                   !l->area.full_area,
               "area_light: sizes and adaptive truncated, jitter, area_illumination off");
        tap_ok(l && vnear(l->area.axis1, 0, 4, 0) && vnear(l->area.axis2, 0, 0, 2) && vnear(l->location, 6, 2, 6),
               "area_light: the axes rotated and scaled, not translated");
        scene_free(s);
    }
    {
        /* POV-Ray's Parse_Object_Mods: orient makes the light circular,
         * unless an axis has one sample (then it warns, and neither) */
        Scene *s = parse("light_source { 0, 1 area_light x, 2*z, 3, 3 orient }\n"
                         "light_source { 0, 1 area_light x, z, 1, 3 orient }\n");
        tap_ok(s && s->lights[0].area.circular && s->lights[0].area.orient && !s->lights[1].area.circular,
               "orient makes an area light circular, unless an axis has one sample, as POV-Ray");
        scene_free(s);
    }
    expect_error("light_source { 0, 1 area_light x, y, 0, 3 }", 1, 38, "area size must be greater than zero",
                 "an area_light of 0 samples, as POV-Ray");
    expect_error("light_source { 0, 1 area_light x, y, 3, -2 }", 1, 41, "area size must be greater than zero",
                 "an area_light of negative samples");
    expect_error("light_source { 0, 1 area_light x, y, 2000, 2000 }", 1, 21, "more than hstrace's limit",
                 "an area_light of 4 million samples");
    expect_error("light_source { 0, 1 area_light x, y, 1, 5 circular }", 1, 43,
                 "'circular' with an area_light of 1 point along an axis",
                 "circular with 1 point along an axis, as POV-Ray");
    expect_error("light_source { 0, 1 circular jitter }", 1, 21, "'circular' without an area_light",
                 "circular without an area_light, as POV-Ray");
    expect_error("#declare I = 0;\n#while (1)\n#end\n", 2, 1, "loop iterations", "runaway #while");
    expect_error("#declare A = sqr(3);\n", 1, 14, "'sqr' is only allowed inside function { }",
                 "sqr outside a function, as POV-Ray 3.7 says");
    expect_error("#include \"nonexistent.inc\"\n", 1, 10, "cannot open include file 'nonexistent.inc' (searched: ",
                 "missing include file");
    tap_ok(err.is_io, "missing include file is an I/O error");
    expect_error("#if (1)\nbox { 0, 1 }\n", 1, 1, "no matching #end", "#if without #end");
    expect_error("#declare X = 1\nbox { 0, X }", 2, 1, "expected ';'", "missing semicolon after a float");
    /* povray: "All #declares of float, vector, and color require semi-colon"
     * for each of these; comparisons, logic and '?:' need parentheses in a
     * declared value. */
    expect_error("#version 3.7;\n#declare C = 1 < 3;\n", 2, 16, "expected ';' after the declared value, found '<'",
                 "a comparison outside parentheses in #declare, as POV-Ray");
    {
        /* A '#' before a token that is not a directive is dropped, silently,
         * by POV-Ray 3.7 (language/image_size.pov: `look_at <0,2,0>#` then
         * '}'); povray renders this scene with both objects and no warning. */
        Scene *s = parse("camera { location -3 * z look_at 0 #}\n#box { -1, 1 }\n#declare V = <1, 2, 3>;\n"
                         "triangle { 0, x, #V }\n#");
        tap_ok(s && s->nobjects == 2 && s->objects[0]->kind == OBJ_BOX && vnear(s->objects[1]->u.triangle.v[2], 1, 2, 3),
               "a stray '#' before '}', an object, a vector identifier or the end of the file is dropped, as POV-Ray");
        scene_free(s);
    }
    /* but before a float identifier or function povray stops: "Expected
     * 'object or directive.', float function 'sin' found instead" */
    expect_error("#declare X = 1;\n#X\n", 2, 2, "expected a directive after '#', found 'X'",
                 "'#' before a float identifier, as POV-Ray");
    expect_error("box { 0, 1 }\n# sin(1)\n", 2, 3, "expected a directive after '#', found 'sin'",
                 "'#' before a float function, as POV-Ray");
    expect_error("#declare C = <1, 2> <3, 4>;\n", 1, 21, "expected ';' after the declared value, found '<'",
                 "two vectors in #declare, as POV-Ray");
    expect_error("#declare C = 1 & 0;\n", 1, 16, "found '&'", "'&' outside parentheses in #declare, as POV-Ray");
    expect_error("#declare C = 1 ? 2 : 3;\n", 1, 16, "found '?'", "'?:' outside parentheses in #declare, as POV-Ray");
    tap_ok(near(box_x("#declare C = (1 < 3) + (1 & 0) + (0 ? 2 : 3);\nbox { 0, C }"), 4),
           "comparison, logic and '?:' in parentheses in #declare");
    /* Components of a value that is already unsupported (math.inc's
     * vGradient of a user function): the use names the function. */
    expect_error("#declare F = function { x }\n#declare V = <F(1,2,3), 2, 3>;\n#declare W = <V.x, V.y, 0>;\n"
                 "triangle { 0, x, y translate W }",
                 4, 30, "'function' is not supported by hstrace (declared at t.pov:1)",
                 "a component of an unsupported value: error at the use, naming the function");
    {
        /* POV-Ray 3.7 accepts a string declaration without ';' (checked
         * with povray: the scene renders). */
        Scene *s = parse("#version 3.7;\n#declare S = \"x\"\nbox { 0, strlen(S) }");
        tap_ok(s && s->nobjects == 1, "a string declaration needs no ';' (as in POV-Ray 3.7)");
        scene_free(s);
        /* An array declared without ';', then a directive using it (as
         * POV-Ray's portfolio/html_gen.inc does). */
        s = parse("#declare N = 3;\n#local A = array[N]\n#local A[0] = 1;\n#local A[2] = A[0] + 1;\n"
                  "triangle { 0, x, y translate A[2] * x }");
        tap_ok(s && s->nobjects == 1, "an array declared without ';' is stored before the next directive runs");
        scene_free(s);
        /* The older spelling of #default, which POV-Ray 3.7 still reads. */
        s = parse("default { finish { ambient 0.3 } }\ntriangle { 0, x, y }");
        tap_ok(s && near(s->default_texture.finish.ambient[0], 0.3), "'default { }' without '#' is #default");
        scene_free(s);
    }
    expect_error("box { 0, 1 } }", 1, 14, "expected an object", "stray brace");
    expect_error("triangle { 0, x, y clipped_by { sphere { 0, 1 } } }", 1, 20,
                 "'clipped_by' on a 'triangle' is not supported", "clipped_by on a triangle");
    /* without ParseOptions.load_image (a parse with no image layer) */
    expect_error("box { 0, 1 texture { pigment { image_map { png \"a.png\" } } } }", 1, 32,
                 "'image_map' is not supported", "image_map without an image reader");
    expect_error("box { 0, 1 texture { pigment { image_pattern { png \"a.png\" } } } }", 1, 32,
                 "'image_pattern' is not supported", "image pattern");
    expect_error("#error \"stop here\"\n", 1, 1, "#error: stop here", "#error");
    expect_error("box { 0, <1, 2, 3 }", 1, 19, "expected", "unclosed vector");
    expect_error("box { 0, ((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((("
                 "((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((("
                 "(((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((1",
                 1, 110, "nested too deeply", "deep nesting is an error, not a crash");

    /* an unsupported object declared in an include file, used in the scene */
    char dir[] = "/tmp/hst_parser_testXXXXXX";
    if (!mkdtemp(dir)) {
        tap_ok(0, "temporary folder");
        return;
    }
    char inc[300], main_file[300], loop_a[300], loop_b[300];
    snprintf(inc, sizeof inc, "%s/shapes_x.inc", dir);
    snprintf(main_file, sizeof main_file, "%s/main.pov", dir);
    snprintf(loop_a, sizeof loop_a, "%s/a.inc", dir);
    snprintf(loop_b, sizeof loop_b, "%s/b.inc", dir);
    write_file(inc, "// shapes\n#declare Ball =\n  union { box { 0, 1 } ovus { 1, 0.5 } }\n#declare Plate = box { 0, 1 }\n");
    write_file(main_file, "#include \"shapes_x.inc\"\nobject { Plate }\n  object { Ball }\n");
    Scene *s = parse_scene_file(main_file, &opts, &err);
    char want[400];
    snprintf(want, sizeof want, "'ovus' is not supported by hstrace (declared at %s:3)", inc);
    tap_ok(!s && err.line == 3 && err.column == 12 && strcmp(err.message, want) == 0 && strstr(err.file, "main.pov"),
           "unsupported object from an include file: error at its use");
    if (s || strcmp(err.message, want) != 0)
        tap_diag("got %s:%d:%d: %s", err.file, err.line, err.column, err.message);
    scene_free(s);

    write_file(loop_a, "#include \"b.inc\"\n");
    write_file(loop_b, "box { 0, 1 }\n#include \"a.inc\"\n");
    s = parse_scene_file(loop_a, &opts, &err);
    tap_ok(!s && strstr(err.message, "includes itself") && strstr(err.file, ".inc"), "include cycle is reported");
    if (s || !strstr(err.message, "includes itself"))
        tap_diag("got %s:%d:%d: %s", err.file, err.line, err.column, err.message);
    scene_free(s);

    s = parse_scene_file("/nonexistent/scene.pov", &opts, &err);
    tap_ok(!s && err.is_io && strstr(err.message, "cannot open"), "unreadable scene file is an I/O error");
    scene_free(s);

    remove(inc);
    remove(main_file);
    remove(loop_a);
    remove(loop_b);
    rmdir(dir);
}

/* A macro defined in an include file, called after that file has closed;
 * an error in its body names the include file's line and the call. */
static void test_macro_files(void)
{
    char dir[] = "/tmp/hst_macro_testXXXXXX";
    if (!mkdtemp(dir)) {
        tap_ok(0, "temporary folder");
        return;
    }
    char inc[300], main_file[300], want[600];
    snprintf(inc, sizeof inc, "%s/tiles.inc", dir);
    snprintf(main_file, sizeof main_file, "%s/main.pov", dir);
    write_file(inc, "// tiles\n#macro Tile(P)\n  triangle { P, P + x, P + y }\n#end\n"
                    "#macro Bad(P)\n  triangle { P, P + x, Nope }\n#end\n");
    write_file(main_file, "#include \"tiles.inc\"\nTile(<1, 0, 0>)\n#for (I, 0, 2)\n  Tile(I * y)\n#end\n");
    Scene *s = parse_scene_file(main_file, &opts, &err);
    tap_ok(s && s->nobjects == 4 && vnear(s->objects[0]->u.triangle.v[2], 1, 1, 0),
           "a macro from an include file, called after the file closed");
    scene_free(s);

    write_file(main_file, "#include \"tiles.inc\"\nTile(0)\n  Bad(y)\n");
    s = parse_scene_file(main_file, &opts, &err);
    snprintf(want, sizeof want, "%s:3:3: note: in macro 'Bad' called here\n", main_file);
    tap_ok(!s && strcmp(err.file, inc) == 0 && err.line == 6 && err.column == 24 &&
               strcmp(err.message, "undeclared identifier 'Nope'") == 0 && strcmp(err.notes, want) == 0,
           "an error in an included macro: at the macro's line, with a note at the call");
    if (s || strcmp(err.notes, want) != 0 || err.line != 6 || err.column != 24)
        tap_diag("got %s:%d:%d: %s / %s", err.file, err.line, err.column, err.message, err.notes);
    scene_free(s);
    remove(inc);
    remove(main_file);
    rmdir(dir);
}

static void test_includes(void)
{
    Scene *s = parse("#include \"colors.inc\"\n#include \"finish.inc\"\n#include \"colors.inc\"\n"
                     "box { 0, 1 pigment { Coral } finish { Mirror } }\n");
    tap_ok(s && near(s->objects[0]->texture->pigment.colour.g, 0.498039) &&
               near(s->objects[0]->texture->finish.reflection_max[0], 1),
           "colors.inc and finish.inc, included twice");
    scene_free(s);
}

/* Truncated and mutated scenes: an error or a scene, never a crash. */
static void test_robustness(void)
{
    const char *base = "#version 3.7;\n#include \"colors.inc\"\nglobal_settings { assumed_gamma 1 }\n"
                       "camera { location <0, 1, -3> look_at 0 angle 50 }\n"
                       "light_source { <2, 4, -3>, White }\n"
                       "#declare I = 0;\n#while (I < 3)\n"
                       "  polygon { 5, <0,0>, <1,0>, <1,1>, <0,1>, <0,0> translate I*x pigment { rgb <1, I/3, 0> } }\n"
                       "  #declare I = I + 1;\n#end\n"
                       "mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 2> } }\n"
                       "union { box { -1, 1 finish { phong 1 } } plane { y, -1 } rotate 30*y }\n"
                       "/* c /* nested */ */ #if (I > 2) box { 0, 1 } #else triangle { 0, x, y } #end\n";
    size_t n = strlen(base);
    char *buf = malloc(n + 1);
    int scenes = 0, errors = 0;
    for (size_t cut = 0; cut <= n; cut++) {
        memcpy(buf, base, cut);
        buf[cut] = '\0';
        Scene *s = parse_scene_string("t.pov", buf, &opts, &err);
        if (s)
            scenes++;
        else
            errors++;
        scene_free(s);
    }
    tap_ok(scenes + errors == (int)n + 1, "every truncation returns (%d scenes, %d errors)", scenes, errors);
    static const char junk[] = "{}()<>#,;\"/*x0.9-";
    unsigned seed = 12345;
    scenes = errors = 0;
    for (int round = 0; round < 3000; round++) {
        memcpy(buf, base, n + 1);
        for (int k = 0; k < 1 + round % 4; k++) {
            seed = seed * 1103515245u + 12345u;
            size_t at = (seed >> 8) % n;
            seed = seed * 1103515245u + 12345u;
            buf[at] = (seed >> 9) % 3 ? junk[(seed >> 12) % (sizeof junk - 1)] : (char)((seed >> 12) & 0xff);
        }
        buf[n] = '\0';
        Scene *s = parse_scene_string("t.pov", buf, &opts, &err);
        if (s)
            scenes++;
        else
            errors++;
        scene_free(s);
    }
    tap_ok(scenes + errors == 3000, "every mutation returns (%d scenes, %d errors)", scenes, errors);
    free(buf);

    /* the same for the directive language: macros, arrays, #switch */
    const char *lang = "#macro Tri(P, S) triangle { P, P + S * x, P + S * y } #end\n"
                       "#macro Twice(A) #declare A = A * 2; #end\n"
                       "#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end\n"
                       "#declare Arr = array[2][2] { {1, 2}, {3, 4} }\n#declare V = 1;\nTwice(V)\n"
                       "#declare R = seed(3);\n#switch (V)\n #case (1) Tri(0, 1)\n #case (2) Tri(x, Arr[1][0]) #break\n"
                       " #range (3, 5) Tri(y, rand(R))\n #else union { Tri(z, Fact(4)) }\n#end\n"
                       "#for (I, 0, 1) #declare Arr[I][1] = strlen(concat(\"ab\", str(I, 0, 0))); #end\n";
    n = strlen(lang);
    buf = malloc(n + 1);
    scenes = errors = 0;
    for (size_t cut = 0; cut <= n; cut++) {
        memcpy(buf, lang, cut);
        buf[cut] = '\0';
        Scene *s = parse_scene_string("t.pov", buf, &opts, &err);
        scenes += s != NULL;
        errors += s == NULL;
        scene_free(s);
    }
    Scene *whole = parse_scene_string("t.pov", lang, &opts, &err);
    tap_ok(whole && whole->nobjects == 1, "the directive-language scene parses whole (%d objects)", whole ? whole->nobjects : -1);
    scene_free(whole);
    for (int round = 0; round < 3000; round++) {
        memcpy(buf, lang, n + 1);
        for (int k = 0; k < 1 + round % 4; k++) {
            seed = seed * 1103515245u + 12345u;
            size_t at = (seed >> 8) % n;
            seed = seed * 1103515245u + 12345u;
            buf[at] = (seed >> 9) % 3 ? junk[(seed >> 12) % (sizeof junk - 1)] : (char)((seed >> 12) & 0xff);
        }
        buf[n] = '\0';
        Scene *s = parse_scene_string("t.pov", buf, &opts, &err);
        scenes += s != NULL;
        errors += s == NULL;
        scene_free(s);
    }
    tap_ok(scenes + errors == (int)n + 1 + 3000, "macros, arrays, #switch: every truncation and mutation returns (%d scenes, %d errors)",
           scenes, errors);
    free(buf);
}

/* The whole of a small file, or "" (static buffer). */
static const char *file_text(const char *path)
{
    static char buf[4096];
    buf[0] = '\0';
    FILE *f = fopen(path, "rb");
    if (f) {
        size_t n = fread(buf, 1, sizeof buf - 1, f);
        buf[n] = '\0';
        fclose(f);
    }
    return buf;
}

static void test_file_io(void)
{
    char dir[] = "/tmp/hst_fileio_testXXXXXX";
    if (!mkdtemp(dir)) {
        tap_ok(0, "temporary folder");
        return;
    }
    char data[300], text[2048];
    snprintf(data, sizeof data, "%s/data.txt", dir);

    /* #write: strings as they are, numbers with %g, vectors as "<x,y,z> "
     * (the bytes POV-Ray 3.7 writes for the same directives) */
    snprintf(text, sizeof text,
             "#declare S = \"two\";\n#fopen F \"%s\" write\n"
             "#write (F, \"\\\"one\\\",\", 1/3, \",\", <1, 2.5, 123456789>, \",\" S, \",\", -2.5e-7, \",\", <1,2>, \"\\n\")\n"
             "#fclose F\nbox { 0, 1 }\n",
             data);
    Scene *s = parse(text);
    const char *want = "\"one\",0.333333,<1,2.5,1.23457e+08> ,two,-2.5e-07,<1,2> \n";
    tap_ok(s && strcmp(file_text(data), want) == 0, "#write: strings, floats and vectors as POV-Ray writes them");
    if (strcmp(file_text(data), want) != 0)
        tap_diag("file holds [%s]", file_text(data));
    scene_free(s);

    /* append, then binary integers rounded and clamped */
    snprintf(text, sizeof text,
             "#fopen F \"%s\" append\n#write (F, concat(\"x\", str(2, 0, 1)), uint8 <65.6, 300, -4>, sint16be 258, sint16le -2)\n"
             "box { 0, 1 }\n",
             data);
    s = parse(text);
    char want2[200];
    snprintf(want2, sizeof want2, "%sx2.0B\xff%c\x01\x02\xfe\xff", want, 0);
    tap_ok(s && memcmp(file_text(data), want2, strlen(want) + 10) == 0,
           "#fopen append adds to the file; uint8, sint16be, sint16le write binary integers");
    scene_free(s);

    /* #read: a string, floats and vectors back into variables */
    write_file(data, "\"one\", 0.5, <1, -2.5, 3>,\n// a comment\n-4 \"two\" <1,2,3,4,5>\n");
    snprintf(text, sizeof text,
             "#declare V = 7;\n#fopen F \"%s\" read\n#read (F, S, A, V, B, T, C)\n"
             "#if (strcmp(S, \"one\") != 0 | strcmp(T, \"two\") != 0) #error \"strings\" #end\n"
             "box { <A, B, C.t>, V }\n#if (defined(F)) #error \"F still open\" #end\n",
             data);
    s = parse(text);
    tap_ok(s && vnear(s->objects[0]->u.box.corner1, 0.5, -4, 4) && vnear(s->objects[0]->u.box.corner2, 1, -2.5, 3),
           "#read: strings, signed floats and 3- and 5-component vectors, with comments and optional commas; the "
           "file closes at its end");
    scene_free(s);

    /* Escapes in a string read back are resolved, as POV-Ray's scene
     * tokeniser does (povray: "a\tb\"c" reads as 5 characters). */
    write_file(data, "\"a\\tb\\\"c\"\n");
    snprintf(text, sizeof text, "#fopen F \"%s\" read\n#read (F, S)\nbox { 0, strlen(S) }\n", data);
    s = parse(text);
    tap_ok(s && vnear(s->objects[0]->u.box.corner2, 5, 5, 5), "#read: escapes in strings are resolved, as in POV-Ray");
    scene_free(s);

    /* #while (defined(F)): every value once; a trailing comma gives one
     * more round in which the variable keeps its value, as in POV-Ray */
    write_file(data, "1, 2,\n3");
    snprintf(text, sizeof text,
             "#declare N = 0; #declare Sum = 0;\n#fopen F \"%s\" read\n"
             "#while (defined(F))\n  #read (F, X)\n  #declare N = N + 1; #declare Sum = Sum + X;\n#end\n"
             "box { 0, <N, Sum, 1> }\n",
             data);
    s = parse(text);
    tap_ok(s && vnear(s->objects[0]->u.box.corner2, 3, 6, 1), "#while (defined(F)) #read reads each value once");
    scene_free(s);
    write_file(data, "1, 2,\n3,\n");
    s = parse(text);
    tap_ok(s && vnear(s->objects[0]->u.box.corner2, 4, 9, 1), "a trailing comma: one more round, value unchanged");
    scene_free(s);

    /* #fclose twice, and of a file closed at its end, is accepted */
    snprintf(text, sizeof text,
             "#fopen F \"%s\" read\n#read (F, A, B, C, D)\n#fclose F\n#fclose F\n#fclose Never\nbox { 0, A }\n", data);
    s = parse(text);
    tap_ok(s && near(s->objects[0]->u.box.corner2.x, 1), "#fclose of an already closed file is accepted");
    scene_free(s);

    /* errors */
    char missing[300];
    snprintf(missing, sizeof missing, "%s/none/x.txt", dir);
    snprintf(text, sizeof text, "box { 0, 1 }\n  #fopen F \"%s\" read\n", missing);
    s = parse_scene_string("t.pov", text, &opts, &err);
    tap_ok(!s && err.is_io && err.line == 2 && err.column == 12 && strstr(err.message, "cannot open") &&
               strstr(err.message, "for reading"),
           "error: a missing file to read is an I/O error at its name");
    scene_free(s);
    snprintf(text, sizeof text, "#fopen F \"%s\" write\n", missing);
    s = parse_scene_string("t.pov", text, &opts, &err);
    tap_ok(!s && err.is_io && err.line == 1 && err.column == 10 && strstr(err.message, "for writing"),
           "error: a file that cannot be created is an I/O error at its name");
    scene_free(s);

    snprintf(text, sizeof text, "#fopen F \"%s\" write\n#read (F, X)\n", data);
    expect_error(text, 2, 8, "cannot read from 'F'", "#read from a file open for writing");
    snprintf(text, sizeof text, "#fopen F \"%s\" read\n\n #write (F, 1)\n", data);
    expect_error(text, 3, 10, "cannot write to 'F'", "#write to a file open for reading");
    expect_error("#declare X = 1;\n#read (Nope, X)\n", 2, 8, "'Nope' is not an open file", "#read of an undeclared file");
    expect_error("#declare G = 1;\n#write (G, 1)\n", 2, 9, "expected a file identifier", "#write to a float");
    write_file(data, "1");
    snprintf(text, sizeof text, "#fopen F \"%s\" read\n#read (F, A)\n#read (F, B)\n", data);
    expect_error(text, 3, 8, "'F' is not an open file", "#read past the end of the file");
    snprintf(text, sizeof text, "#fopen F \"%s\" update\n", data);
    expect_error(text, 1, 10 + (int)strlen(data) + 3, "'read', 'write' or 'append'", "#fopen with a wrong mode");
    expect_error("#declare F = 1;\n#fopen F \"x\" read\n", 2, 8, "already declared", "#fopen of a declared name");

    /* bad data: FILE:LINE:COLUMN in the data file */
    write_file(data, "1,\n  <1, 2, oops>\n");
    snprintf(text, sizeof text, "#fopen F \"%s\" read\n#read (F, A, B)\n", data);
    s = parse_scene_string("t.pov", text, &opts, &err);
    tap_ok(!s && !err.is_io && strcmp(err.file, data) == 0 && err.line == 2 && err.column == 10 &&
               strstr(err.message, "expected a vector component or '>'"),
           "error: bad data is reported at its place in the data file");
    if (s || err.line != 2 || err.column != 10)
        tap_diag("got %s:%d:%d: %s", err.file, err.line, err.column, err.message);
    scene_free(s);

    /* a parse error while a file is open for writing: the file is closed
     * (ASan's leak check in the sanitizer build) and what was written is
     * in it */
    snprintf(text, sizeof text, "#fopen F \"%s\" write\n#write (F, \"partial\")\nbox { 0, Nope }\n", data);
    s = parse_scene_string("t.pov", text, &opts, &err);
    tap_ok(!s && err.line == 3 && strcmp(file_text(data), "partial") == 0,
           "an error with a file open for writing closes it, its text written");
    scene_free(s);

    remove(data);
    rmdir(dir);
}

/* texture_map in the description: entries as written (not sorted), their
 * values in single precision, declared and patterned entries, the depth of
 * nested maps, transforms after the map on its pattern, checker's list. */
static void test_texture_map(void)
{
    Scene *s = parse("#declare A = texture { pigment { rgb <1, 0, 0> } finish { phong 0.5 } }\n"
                     "triangle { 0, x, y texture { gradient y texture_map { [0.7 A] [0.1 pigment { rgb 0.5 }] "
                     "[0.3 bozo texture_map { [0 A] [1 A] }] } scale 2 } }\n"
                     "triangle { 0, x, y texture { checker texture { A } scale 3 } }\n");
    tap_ok(s != NULL, "texture_map: parses");
    if (!s)
        return;
    const SceneTexture *t = s->objects[0]->texture;
    tap_ok(t->nmap == 3 && t->map_depth == 2, "three entries, two levels of maps (got %d, %d)", t->nmap, t->map_depth);
    tap_ok(t->nmap == 3 && t->map[0].value == (double)0.7f && t->map[1].value == (double)0.1f &&
               t->map[2].value == (double)0.3f,
           "entries in the order written, values in single precision");
    tap_ok(t->nmap == 3 && t->map[0].texture->nmap == 0 && t->map[0].texture->finish.phong == 0.5 &&
               t->map[0].texture->pigment.colour.r == 1.0,
           "a declared texture as an entry");
    tap_ok(t->nmap == 3 && t->map[2].texture->nmap == 2 && t->map[2].texture->pigment.kind == PIGMENT_BOZO,
           "an entry patterned by a texture_map of its own");
    tap_ok(t->pigment.kind == PIGMENT_GRADIENT && vnear(t->pigment.gradient, 0, 1, 0) &&
               vnear(transform_point(&t->pigment.transform, v3(1, 1, 1)), 2, 2, 2),
           "the map's pattern, with the transform written after the map");
    const SceneTexture *c = s->objects[1]->texture;
    tap_ok(c->nmap == 2 && c->pigment.kind == PIGMENT_CHECKER && c->map[0].value == 0.0 && c->map[1].value == 1.0 &&
               c->map[0].texture->finish.phong == 0.5 && c->map[1].texture->finish.phong == 0.0,
           "checker with one texture: the second the default texture");
    scene_free(s);
}

int main(void)
{
    test_expressions();
    test_colours();
    test_finish_texture();
    test_texture_map();
    test_directives();
    test_objects();
    test_camera_lights();
    test_macros();
    test_arrays();
    test_switch();
    test_number_lexing();
    test_plain_vectors();
    test_plain_lists();
    test_strings_and_functions();
    test_errors();
    test_macro_files();
    test_includes();
    test_file_io();
    test_robustness();
    return tap_done();
}
