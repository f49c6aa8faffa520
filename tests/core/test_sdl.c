/* SPDX-License-Identifier: MIT */
/* The textbook's Scene Description Language (fixel/sdl.h): what each
 * keyword does to the scene, the prefix CSG, the macros, 3VN mesh files,
 * the default camera, and the error messages with their places. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/rt.h"
#include "fixel/sdl.h"
#include "fx_test.h"

#define NOBJ 64
static fx_rt_object objs[NOBJ];
static fx_rt_scene scene;
static _Alignas(16) unsigned char arena[8 << 20];
static size_t used;
static fx_sdl_error err;

static void *bump(void *user, size_t n)
{
    (void)user;
    n = (n + 15) & ~(size_t)15;
    if (n > sizeof arena - used)
        return NULL;
    void *p = arena + used;
    memset(p, 0, n);
    used += n;
    return p;
}

/* in-memory files for mesh FILE */
static const char *file_name, *file_text;
static char asked[256];

static int load(void *user, const char *path, const uint8_t **data, size_t *len)
{
    (void)user;
    snprintf(asked, sizeof asked, "%s", path);
    if (!file_name || strcmp(path, file_name))
        return -FX_ENOENT;
    *data = (const uint8_t *)file_text;
    *len = strlen(file_text);
    return 0;
}

static int read_cap(const char *text, int cap)
{
    fx_rt_scene_init(&scene, objs, cap);
    used = 0;
    fx_sdl_env env = {NULL, bump, load};
    return fx_sdl_read(&scene, text, strlen(text), "t.sdl", &env, &err);
}

static int rd(const char *text) { return read_cap(text, NOBJ); }

static const fx16 ONE = FX16_ONE;

FX_TEST(sdl_attributes_set_the_scene_and_the_material)
{
    int n = rd("! a comment line\n"
               "light 1 2 3  1 0.5 0   ! trailing comment\n"
               "light -4 5 6 0.25 0.25 0.25\n"
               "globalAmbient 0.5 0.25 0\n"
               "background 0 0.5 1\n"
               "maxRecursionDepth 5 minReflectivity 0.25 minTransparency 0.125\n"
               "ambient 0.5 0.5 0.5 diffuse 1 0 0 specular 0 1 0 emissive 0 0 0.5\n"
               "specularExponent 20.6 reflectivity 0.75 transparency 0.5 speedOfLight 0.5\n"
               "sphere\n"
               "defaultMaterials cube\n");
    FX_CHECK_EQ(n, 2);
    FX_CHECK_EQ(scene.nlights, 2);
    FX_CHECK_EQ(scene.light[0].pos.x, ONE);
    FX_CHECK_EQ(scene.light[0].pos.z, 3 * ONE);
    FX_CHECK_EQ(scene.light[0].color.g, ONE / 2);
    FX_CHECK_EQ(scene.light[1].pos.x, -4 * ONE);
    FX_CHECK_EQ(scene.light[1].color.b, ONE / 4);
    FX_CHECK_EQ(scene.ambient.g, ONE / 4);
    FX_CHECK_EQ(scene.background.b, ONE);
    FX_CHECK_EQ(scene.max_depth, 5);
    FX_CHECK_EQ(scene.cutoff, ONE / 8); /* the smaller of the two */
    const fx_rt_material *m = &objs[0].mat;
    FX_CHECK_EQ(objs[0].kind, FX_RT_SPHERE);
    FX_CHECK_EQ(m->ambient.r, ONE / 2);
    FX_CHECK_EQ(m->diffuse.r, ONE);
    FX_CHECK_EQ(m->diffuse.g, 0);
    FX_CHECK_EQ(m->specular.g, ONE);
    FX_CHECK_EQ(m->emissive.b, ONE / 2);
    FX_CHECK_EQ(m->shininess, 21);
    FX_CHECK_EQ(m->reflectivity, 3 * ONE / 4);
    FX_CHECK_EQ(m->transparency, ONE / 2);
    FX_CHECK_EQ(m->ior, 2 * ONE); /* 1 / speedOfLight */
    /* defaultMaterials: ambient 0.1, diffuse 0.8, no specular, nothing else */
    m = &objs[1].mat;
    FX_CHECK_EQ(objs[1].kind, FX_RT_CUBE);
    FX_CHECK_EQ(m->ambient.r, ONE / 10);
    FX_CHECK_EQ(m->diffuse.r, ONE * 8 / 10);
    FX_CHECK_EQ(m->specular.g, 0);
    FX_CHECK_EQ(m->emissive.b, 0);
    FX_CHECK_EQ(m->reflectivity, 0);
    FX_CHECK_EQ(m->ior, ONE);
}

FX_TEST(sdl_defaults_without_settings)
{
    FX_CHECK_EQ(rd("sphere"), 1);
    FX_CHECK_EQ(scene.ambient.r, ONE / 10);
    FX_CHECK_EQ(scene.max_depth, 3);
    FX_CHECK_EQ(scene.background.r, 0);
    FX_CHECK_EQ(objs[0].mat.diffuse.g, ONE * 8 / 10);
    FX_CHECK_EQ(objs[0].mat.shininess, 1);
    FX_CHECK_EQ(rd(""), 0);
    FX_CHECK_EQ(rd("! only a comment"), 0);
}

/* The world box of the only object. */
static void box_of(const char *text, fx16 lo[3], fx16 hi[3])
{
    int n = rd(text);
    FX_CHECK_MSG(n == 1, "%s: %d objects (%s)", text, n, err.msg);
    for (int k = 0; k < 3; k++)
        lo[k] = objs[scene.n - 1].box.lo[k], hi[k] = objs[scene.n - 1].box.hi[k];
}

static int near(fx16 a, fx16 b) { return a - b < 64 && b - a < 64; }

FX_TEST(sdl_transforms_compose_as_in_gl)
{
    fx16 lo[3], hi[3];
    /* the last transform written applies first */
    box_of("translate 2 0 0 scale 2 2 2 sphere", lo, hi);
    FX_CHECK(near(lo[0], 0) && near(hi[0], 4 * ONE) && near(lo[1], -2 * ONE));
    box_of("scale 2 2 2 translate 2 0 0 sphere", lo, hi);
    FX_CHECK(near(lo[0], 2 * ONE) && near(hi[0], 6 * ONE));
    /* rotate angle ux uy uz, degrees: x goes to y about z */
    box_of("rotate 90 0 0 1 translate 3 0 0 cube", lo, hi);
    FX_CHECK(near(lo[1], 2 * ONE) && near(hi[1], 4 * ONE) && near(lo[0], -ONE));
    /* push and pop restore; identityAffine resets */
    box_of("translate 5 0 0 push translate 0 5 0 pop cube", lo, hi);
    FX_CHECK(near(lo[0], 4 * ONE) && near(lo[1], -ONE));
    box_of("translate 5 0 0 identityAffine translate 0 0 -3 cube", lo, hi);
    FX_CHECK(near(lo[0], -ONE) && near(lo[2], -4 * ONE));
}

FX_TEST(sdl_shapes_map_to_the_tracer)
{
    FX_CHECK_EQ(rd("sphere cube plane square cylinder cone taperedCylinder 0.5 torus"), 8);
    static const int kind[] = {FX_RT_SPHERE, FX_RT_CUBE, FX_RT_PLANE, FX_RT_SQUARE,
                               FX_RT_CYLINDER, FX_RT_CYLINDER, FX_RT_CYLINDER, FX_RT_TORUS};
    static const fx16 taper[] = {0, 0, 0, 0, FX16_ONE, 0, FX16_ONE / 2, FX16_ONE / 5};
    for (int i = 0; i < 8; i++) {
        FX_CHECK_EQ(objs[i].kind, kind[i]);
        if (objs[i].kind == FX_RT_CYLINDER || objs[i].kind == FX_RT_TORUS)
            FX_CHECK_EQ(objs[i].taper, taper[i]);
    }
    FX_CHECK_EQ(rd("teapot tetrahedron octahedron dodecahedron icosahedron buckyball teapot"), 7);
    for (int i = 0; i < 7; i++)
        FX_CHECK_EQ(objs[i].kind, FX_RT_MESH);
    FX_CHECK(objs[0].mesh == objs[6].mesh); /* built once, shared */
    FX_CHECK_EQ(objs[1].mesh->mesh->ntris, 4);
    FX_CHECK_EQ(objs[2].mesh->mesh->ntris, 8);
    FX_CHECK_EQ(objs[4].mesh->mesh->ntris, 20);
}

FX_TEST(sdl_buckyball_is_a_closed_truncated_icosahedron)
{
    FX_CHECK_EQ(rd("buckyball"), 1);
    const fx_mesh *m = objs[0].mesh->mesh;
    FX_CHECK_EQ(m->nverts, 60);
    FX_CHECK_EQ(m->ntris, 12 * 3 + 20 * 4); /* pentagons and hexagons as fans */
    for (int i = 0; i < m->nverts; i++)
        FX_CHECK(near(fx_vec3_length(m->pos[i]), ONE));
    /* closed: every directed edge appears once and its reverse once */
    static int count[60][60];
    memset(count, 0, sizeof count);
    for (int t = 0; t < m->ntris; t++)
        for (int k = 0; k < 3; k++)
            count[m->tri[t * 3 + k]][m->tri[t * 3 + (k + 1) % 3]]++;
    int bad = 0;
    for (int a = 0; a < 60; a++)
        for (int b = 0; b < 60; b++)
            bad += count[a][b] > 1 || count[a][b] != count[b][a];
    FX_CHECK_EQ(bad, 0);
    /* all 90 polyhedron edges have length 2/3 of the icosahedron's edge, scaled */
    int edges = 0;
    for (int a = 0; a < 60; a++)
        for (int b = a + 1; b < 60; b++)
            if (count[a][b] && abs(fx_vec3_length(fx_vec3_sub(m->pos[a], m->pos[b])) - 26447) < 256)
                edges++; /* 0.40355 = 4 / sqrt(58 + 18 sqrt 5): edge / circumradius */
    FX_CHECK_EQ(edges, 90);
}

FX_TEST(sdl_csg_is_prefix)
{
    FX_CHECK_EQ(rd("difference union sphere translate 1 0 0 cube scale 0.5 0.5 0.5 sphere"), 1);
    int root = scene.n - 1;
    FX_CHECK_EQ(objs[root].kind, FX_RT_DIFFERENCE);
    FX_CHECK_EQ(objs[objs[root].left].kind, FX_RT_UNION);
    FX_CHECK_EQ(objs[objs[root].right].kind, FX_RT_SPHERE);
    int tops = 0;
    for (int i = 0; i < scene.n; i++)
        tops += objs[i].top;
    FX_CHECK_EQ(tops, 1);
    /* attributes between the operands apply to the next operand */
    FX_CHECK_EQ(rd("intersection diffuse 1 0 0 sphere diffuse 0 1 0 cube sphere"), 2);
    FX_CHECK_EQ(objs[0].mat.diffuse.r, ONE);
    FX_CHECK_EQ(objs[1].mat.diffuse.g, ONE);
}

FX_TEST(sdl_macros_expand_in_place)
{
    int n = rd("def ball { sphere ! a } in a comment\n }\n"
               "def two { use ball translate 2 0 0 use ball }\n"
               "use two cube use ball");
    FX_CHECK_MSG(n == 4, "%d (%s)", n, err.msg);
    FX_CHECK_EQ(objs[0].kind, FX_RT_SPHERE);
    FX_CHECK_EQ(objs[1].kind, FX_RT_SPHERE);
    FX_CHECK_EQ(objs[2].kind, FX_RT_CUBE);
    FX_CHECK(near(objs[1].box.lo[0], ONE)); /* the translate inside the macro stays in effect */
    FX_CHECK(near(objs[2].box.lo[0], ONE));
    /* a macro may hold half of a CSG expression */
    FX_CHECK_EQ(rd("def op { union sphere } use op cube"), 1);
    FX_CHECK_EQ(objs[2].kind, FX_RT_UNION);
    /* braces need no spaces */
    FX_CHECK_EQ(rd("def a{cube}use a"), 1);
}

FX_TEST(sdl_mesh_file_3vn)
{
    file_name = "dir/pyr.3vn";
    file_text = "5 5 5\n0 1 0  -1 0 -1  1 0 -1  1 0 1  -1 0 1\n"
                "0 0.7 -0.7  0.7 0.7 0  0 0.7 0.7  -0.7 0.7 0  0 -1 0\n"
                "3 0 2 1 0 0 0\n3 0 3 2 1 1 1\n3 0 4 3 2 2 2\n3 0 1 4 3 3 3\n4 1 2 3 4 4 4 4 4\n";
    fx_rt_scene_init(&scene, objs, NOBJ);
    used = 0;
    fx_sdl_env env = {NULL, bump, load};
    const char *t = "mesh pyr.3vn";
    int n = fx_sdl_read(&scene, t, strlen(t), "dir/s.sdl", &env, &err);
    FX_CHECK_MSG(n == 1, "%d (%s)", n, err.msg);
    FX_CHECK_EQ(strcmp(asked, "dir/pyr.3vn"), 0); /* relative to the SDL file */
    FX_CHECK_EQ(objs[0].mesh->mesh->ntris, 6);
    FX_CHECK_EQ(objs[0].mesh->mesh->nverts, 16);
    FX_CHECK(objs[0].mesh->mesh->nrm != NULL);
    /* a ray down the y axis meets the apex face at y = 1 - small */
    fx_rt_hit h;
    fx_vec3 nrm;
    FX_CHECK(fx_rt_first_hit(&scene, fx_vec3_make(0, 5 * ONE, 0), fx_vec3_make(0, -ONE, 0), 0, &h, &nrm));
    FX_CHECK(near(h.t, 4 * ONE));
    file_name = NULL;
}

FX_TEST(sdl_default_camera_sees_the_scene)
{
    FX_CHECK_EQ(rd("translate 20 3 -10 scale 4 4 4 sphere plane"), 2);
    FX_CHECK_EQ(fx_sdl_default_camera(&scene, 45 * ONE), 0);
    fx_vec3 S, c;
    fx_rt_hit h;
    fx_rt_primary(&scene, 100, 100, 50, 50, &S, &c);
    FX_CHECK(fx_rt_first_hit(&scene, S, c, 0, &h, NULL));
    FX_CHECK_EQ(h.obj, 0);
    /* the sphere fits: the corners of the picture miss it */
    fx_rt_primary(&scene, 100, 100, 0, 0, &S, &c);
    FX_CHECK(!fx_rt_first_hit(&scene, S, c, 0, &h, NULL) || h.obj != 0);
    /* the eye is above, to the right, in front */
    FX_CHECK(S.x > 20 * ONE && S.y > 3 * ONE && S.z > -10 * ONE);
    /* a far scene keeps the eye inside the world */
    FX_CHECK_EQ(rd("translate 100 0 0 scale 20 20 20 sphere"), 1);
    FX_CHECK_EQ(fx_sdl_default_camera(&scene, 45 * ONE), 0);
    fx_rt_primary(&scene, 100, 100, 50, 50, &S, &c);
    FX_CHECK(S.x <= 128 * ONE && S.z <= 128 * ONE);
    FX_CHECK(fx_rt_first_hit(&scene, S, c, 0, &h, NULL));
}

/* ---- the error messages: each names the file, line and column ---- */
typedef struct bad {
    const char *text, *msg;
} bad;

FX_TEST(sdl_errors_name_the_place)
{
    static char many[4096], deep[4096], wide[4096];
    /* 33 pushes, 17 nested macros, a doubling macro chain */
    strcpy(many, "");
    for (int i = 0; i < 33; i++)
        strcat(many, "push ");
    strcpy(deep, "def m0 { sphere }\n");
    for (int i = 1; i <= 17; i++)
        sprintf(deep + strlen(deep), "def m%d { use m%d }\n", i, i - 1);
    strcat(deep, "use m17");
    strcpy(wide, "def w0 { identityAffine identityAffine }\n");
    for (int i = 1; i <= 9; i++) /* 2 * 4^9 tokens */
        sprintf(wide + strlen(wide), "def w%d { use w%d use w%d use w%d use w%d }\n", i, i - 1, i - 1, i - 1, i - 1);
    strcat(wide, "use w9");
    const bad cases[] = {
        {"translate 1 2 x", "t.sdl:1:15: translate: expected a number, found 'x'"},
        {"sphere\nscale 1.2.3 1 1", "t.sdl:2:7: scale: expected a number, found '1.2.3'"},
        {"translate 1e3 0 0", "t.sdl:1:11: translate: expected a number, found '1e3'"},
        {"translate 40000 0 0", "t.sdl:1:11: translate: number '40000' out of range"},
        {"light 1 2", "t.sdl:1:1: light: expected a number, found the end of the file"},
        {"  sphre", "t.sdl:1:3: unknown keyword 'sphre'"},
        {"sphere 1 2", "t.sdl:1:8: a number '1' where a keyword belongs"},
        {"cube }", "t.sdl:1:6: '}' without a def"},
        {"{ cube", "t.sdl:1:1: '{' outside a def"},
        {"\ndef a { sphere", "t.sdl:2:1: def a: no closing '}'"},
        {"def a { def b { cube } }", "t.sdl:1:15: def a: '{' inside a def body"},
        {"def a { cube }", NULL},
        {"def a { cube } def a { sphere }", "t.sdl:1:20: def a: already defined"},
        {"def sphere { cube }", "t.sdl:1:5: def: expected a name"},
        {"def a cube", "def a: expected '{' after the name"},
        {"use nothing", "t.sdl:1:5: use nothing: not defined"},
        {"def a { cube use a }\nuse a", "t.sdl:1:18: use a: recursive (it is being expanded already) (in 'use a' at 2:1)"},
        {"def a { use b }\ndef b { use a }\nuse b", "use b: recursive"},
        {deep, "use: macros nested deeper than 16"},
        {wide, "macro expansion longer than 200000 tokens"},
        {"pop", "t.sdl:1:1: pop without push"},
        {"push pop pop", "t.sdl:1:10: pop without push"},
        {many, "t.sdl:1:156: push: more than 31 pushes without a pop"},
        {"light 0 0 0 1 1 1 light 0 0 0 1 1 1 light 0 0 0 1 1 1 light 0 0 0 1 1 1 light 0 0 0 1 1 1",
         "t.sdl:1:73: light: more than 4 lights (the ray tracer's limit)"},
        {"light 500 0 0 1 1 1", "light: the position leaves the scene limit"},
        {"maxRecursionDepth 9", "t.sdl:1:19: maxRecursionDepth: a whole number 0..8"},
        {"maxRecursionDepth 2.5", "maxRecursionDepth: a whole number 0..8"},
        {"diffuse 1.5 0 0", "t.sdl:1:1: diffuse: colour components are 0..1"},
        {"speedOfLight 0.1", "speedOfLight: 0.25..1"},
        {"specularExponent 300", "specularExponent: 0..256"},
        {"taperedCylinder 3", "taperedCylinder: the small radius S is 0..2"},
        {"scale 0 1 1 sphere", "t.sdl:1:13: sphere: the transform is singular"},
        {"translate 200 0 0 sphere", "sphere: the shape leaves the scene limit"},
        {"rotate 30 0 0 0", "rotate: the axis is zero"},
        {"union sphere", "t.sdl:1:1: union: the end of the file before its second object"},
        {"difference", "difference: the end of the file before its first object"},
        {"texture 1 cube", "t.sdl:1:1: 'texture' is not supported by fixel's SDL reader"},
        {"diamond", "'diamond' is not supported"},
        {"surfaceRoughness 0.5", "'surfaceRoughness' is not supported"},
        {"mesh", "mesh: expected a file name"},
        {"mesh none.3vn", "t.sdl:1:6: mesh: cannot read 'none.3vn'"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        int r = rd(cases[i].text);
        if (!cases[i].msg) {
            FX_CHECK_MSG(r >= 0, "case %zu: %s", i, err.msg);
            continue;
        }
        FX_CHECK_MSG(r < 0, "case %zu '%.40s' was accepted", i, cases[i].text);
        FX_CHECK_MSG(strstr(err.msg, cases[i].msg) != NULL, "case %zu: got '%s', want '%s'", i, err.msg,
                     cases[i].msg);
    }
    /* A body of blanks costs no token but is read again at every use: the
     * reader counts its bytes (review: 60,000 uses of 2 MB of blanks ran
     * for minutes under the token limit alone). 64 KiB of blanks used 200
     * times is 13 MB to read, over FX_SDL_MAX_SCAN, in 200 tokens. */
    {
        size_t blank = 65536, uses = 200, n = 0;
        char *big = malloc(blank + 32 + uses * 6 + 1);
        FX_CHECK(big != NULL);
        if (big) {
            n += (size_t)sprintf(big, "def b { ");
            memset(big + n, ' ', blank);
            n += blank;
            n += (size_t)sprintf(big + n, " }\n");
            for (size_t u = 0; u < uses; u++)
                n += (size_t)sprintf(big + n, "use b ");
            int r = rd(big);
            FX_CHECK_MSG(r < 0, "200 uses of 64 KiB of blanks were accepted");
            FX_CHECK_MSG(strstr(err.msg, "macro expansion reads more than") != NULL, "%s", err.msg);
            free(big);
        }
    }
    /* the object limit is the scene's */
    FX_CHECK(read_cap("sphere sphere sphere", 2) < 0);
    FX_CHECK_MSG(strstr(err.msg, "t.sdl:1:15: sphere: more than 2 objects") != NULL, "%s", err.msg);
}

FX_TEST(sdl_mesh_file_errors)
{
    static const struct {
        const char *file, *msg;
    } cases[] = {
        {"3 0 1\n0 0 0 1 0 0 0 1 0\n3 0 1 5 0 0 0", "mesh: m.3vn:3:7: vertex index: a whole number 0..2"},
        {"99999999 0 1", "mesh: m.3vn:1:1: number out of range"},
        {"30000 0 1", "mesh: m.3vn:1:1: numVerts: a whole number 1..20000"},
        {"3 0 20001", "mesh: m.3vn:1:5: numFaces: a whole number 1..20000"},
        {"3 0 1\n0 0 0 1 0 0 0 1 0\n2 0 1 0 0", "corners of a face: a whole number 3..64"},
        {"3 0 1\n0 0 0 1 0 x 0 1 0\n", "mesh: m.3vn:2:11: expected a number"},
        {"3 0 1\n0 0 0 1 0 0\n", "unexpected end of the file"},
        {"3 1 1\n0 0 0 1 0 0 0 1 0\n0 0 0\n3 0 1 2 0 0 0", "normal 0 has no length"},
        {"3 0 1\n0 0 0 40 0 0 0 1 0\n3 0 1 2 0 0 0", "mesh: a vertex lies beyond +-32 units"},
    };
    file_name = "m.3vn";
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        file_text = cases[i].file;
        int r = rd("\n  mesh m.3vn");
        FX_CHECK_MSG(r < 0, "case %zu accepted", i);
        FX_CHECK_MSG(strstr(err.msg, cases[i].msg) && strstr(err.msg, "t.sdl:2:3:"), "case %zu: got '%s'", i,
                     err.msg);
    }
    file_name = NULL;
}

FX_TEST(sdl_emissive_glows_without_light)
{
    /* no lights, no ambient: only the emission is left (Iamb = emissive + ambient light . ka) */
    FX_CHECK_EQ(rd("globalAmbient 0 0 0 emissive 0.5 0.25 0 sphere"), 1);
    FX_CHECK_EQ(fx_sdl_default_camera(&scene, 45 * ONE), 0);
    fx_vec3 S, c;
    fx_rt_primary(&scene, 64, 64, 32, 32, &S, &c);
    fx3d_rgb I = fx_rt_trace_ray(&scene, S, c, NULL, NULL);
    FX_CHECK_EQ(I.r, ONE / 2);
    FX_CHECK_EQ(I.g, ONE / 4);
    FX_CHECK_EQ(I.b, 0);
    /* and the background where the ray misses */
    FX_CHECK_EQ(rd("background 0 0 1 globalAmbient 0 0 0 emissive 0.5 0.25 0 translate 50 0 0 sphere"), 1);
    I = fx_rt_trace_ray(&scene, fx_vec3_make(0, 0, 5 * ONE), fx_vec3_make(0, 0, -ONE), NULL, NULL);
    FX_CHECK_EQ(I.b, ONE);
}
