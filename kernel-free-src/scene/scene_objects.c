/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of the course's remaining objects (fixel/objects.h),
 * drawn with the 3D state (camera, model matrix, lights, material):
 *   paraboloid A B H SLICES ROWS
 *   hyperboloid 1|2 A B C H SLICES ROWS
 *   superellipsoid A B C E1 E2 SLICES STACKS
 *   supertoroid R r E1 E2 SIDES RINGS
 *   blobball X Y Z R W       add a soft ball to the blob being built
 *   blobclear                forget the balls
 *   blobby ISO X0 Y0 Z0 STEP NX NY NZ
 *                            polygonize the balls over that grid, draw
 *   patch bezier|bspline N X Y Z (x16)
 *                            one bicubic patch, n x n quads
 * The balls and the grid's work block live in the arena
 * (sc->mod[FX_SCENE_MOD_OBJECTS]). */
#include "fixel/error.h"
#include "fixel/objects.h"
#include "fixel/scene.h"
#include "scene_mesh.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

typedef struct sobj {
    fx_blob_ball ball[FX_BLOBBY_MAX_BALLS];
    int32_t nball;
    void *work;
    size_t work_bytes;
} sobj;

static int get(fx_scene *sc, sobj **out)
{
    sobj *o = sc->mod[FX_SCENE_MOD_OBJECTS];
    if (!o) {
        o = fx_scene_alloc(sc, sizeof *o);
        if (!o)
            return fx_scene_error(sc, "out of scene memory for the blob's balls");
        sc->mod[FX_SCENE_MOD_OBJECTS] = o;
    }
    *out = o;
    return 0;
}

static int args(fx_scene *sc, fx16 *f, int nf, int32_t *iv, int ni)
{
    for (int i = 0; i < nf; i++)
        TRY(fx_scene_arg_fx16(sc, &f[i]));
    for (int i = 0; i < ni; i++)
        TRY(fx_scene_arg_int(sc, &iv[i]));
    return fx_scene_end(sc);
}

static int draw_quadric(fx_scene *sc, const fx_quadric *q)
{
    int32_t nv, nt;
    if (fx_quadric_size(q, &nv, &nt) < 0)
        return fx_scene_error(sc, "size, exponent or tessellation out of range (fixel/objects.h)");
    fx_mesh m;
    TRY(fx_scene_mesh_alloc(sc, nv, nt, 0, &m));
    TRY(fx_quadric_make(&m, q));
    return fx_scene_mesh_draw(sc, &m);
}

static int cmd_paraboloid(fx_scene *sc)
{
    fx16 f[3];
    int32_t iv[2];
    TRY(args(sc, f, 3, iv, 2));
    fx_quadric q = {FX_QUADRIC_PARABOLOID, f[0], f[1], 0, f[2], 0, 0, iv[0], iv[1]};
    return draw_quadric(sc, &q);
}

static int cmd_hyperboloid(fx_scene *sc)
{
    int32_t sheets;
    fx16 f[4];
    int32_t iv[2];
    TRY(fx_scene_arg_int(sc, &sheets));
    TRY(args(sc, f, 4, iv, 2));
    fx_quadric q = {sheets == 2 ? FX_QUADRIC_HYPERBOLOID2 : FX_QUADRIC_HYPERBOLOID1, f[0], f[1], f[2], f[3], 0, 0,
                    iv[0], iv[1]};
    return draw_quadric(sc, &q);
}

static int cmd_superellipsoid(fx_scene *sc)
{
    fx16 f[5];
    int32_t iv[2];
    TRY(args(sc, f, 5, iv, 2));
    fx_quadric q = {FX_QUADRIC_SUPERELLIPSOID, f[0], f[1], f[2], 0, f[3], f[4], iv[0], iv[1]};
    return draw_quadric(sc, &q);
}

static int cmd_supertoroid(fx_scene *sc)
{
    fx16 f[4];
    int32_t iv[2];
    TRY(args(sc, f, 4, iv, 2));
    fx_quadric q = {FX_QUADRIC_SUPERTOROID, f[0], f[1], 0, 0, f[2], f[3], iv[0], iv[1]};
    return draw_quadric(sc, &q);
}

static int cmd_blobball(fx_scene *sc)
{
    sobj *o = 0;
    fx16 f[5];
    TRY(args(sc, f, 5, 0, 0));
    TRY(get(sc, &o));
    if (o->nball == FX_BLOBBY_MAX_BALLS)
        return fx_scene_error(sc, "more than %d balls (blobclear forgets them)", FX_BLOBBY_MAX_BALLS);
    fx_blob_ball b = {fx_vec3_make(f[0], f[1], f[2]), f[3], f[4]};
    o->ball[o->nball++] = b;
    return 0;
}

static int cmd_blobclear(fx_scene *sc)
{
    sobj *o = 0;
    TRY(fx_scene_end(sc));
    TRY(get(sc, &o));
    o->nball = 0;
    return 0;
}

static int cmd_blobby(fx_scene *sc)
{
    sobj *o = 0;
    fx16 f[5];
    int32_t n[3];
    TRY(args(sc, f, 5, n, 3));
    TRY(get(sc, &o));
    fx_blobby b = {o->ball, o->nball, f[0], fx_vec3_make(f[1], f[2], f[3]), f[4], n[0], n[1], n[2]};
    size_t need = fx_blobby_work_bytes(&b);
    if (!need)
        return fx_scene_error(sc, "grid out of range: its far corner beyond +-1024, or a ball out of range");
    if (need > o->work_bytes) {
        void *w = fx_scene_alloc(sc, need);
        if (!w)
            return fx_scene_error(sc, "out of scene memory for a %dx%dx%d grid", n[0], n[1], n[2]);
        o->work = w;
        o->work_bytes = need;
    }
    fx_mesh m = {0};
    TRY(fx_blobby_make(&m, &b, o->work, o->work_bytes)); /* counts */
    if (m.ntris == 0)
        return 0;
    int32_t nv = m.nverts, nt = m.ntris;
    TRY(fx_scene_mesh_alloc(sc, nv, nt, 0, &m));
    TRY(fx_blobby_make(&m, &b, o->work, o->work_bytes));
    return fx_scene_mesh_draw(sc, &m);
}

static int cmd_patch(fx_scene *sc)
{
    static const char *const ch[] = {"bezier", "bspline", NULL};
    int basis;
    int32_t n;
    TRY(basis = fx_scene_arg_choice(sc, ch));
    TRY(fx_scene_arg_int(sc, &n));
    fx_vec3 P[16];
    for (int i = 0; i < 16; i++) {
        fx16 c[3];
        for (int k = 0; k < 3; k++)
            TRY(fx_scene_arg_fx16(sc, &c[k]));
        P[i] = fx_vec3_make(c[0], c[1], c[2]);
    }
    TRY(fx_scene_end(sc));
    fx_mesh m;
    TRY(fx_scene_mesh_alloc(sc, (n + 1) * (n + 1), 2 * n * n, 0, &m));
    int e = fx_patch_tessellate(&m, P, (fx_patch_basis)basis, n);
    if (e == -FX_EDOM)
        return fx_scene_error(sc, "the patch has no normal (its control points are degenerate)");
    if (e < 0)
        return fx_scene_error(sc, "patch: %s", fx_strerror(e));
    return fx_scene_mesh_draw(sc, &m);
}

#define D FX_SCENE_DRAWS

const fx_scene_cmd fx_scene_cmds_objects[] = {
    {"paraboloid", cmd_paraboloid, "paraboloid A B H SLICES ROWS", D},
    {"hyperboloid", cmd_hyperboloid, "hyperboloid 1|2 A B C H SLICES ROWS", D},
    {"superellipsoid", cmd_superellipsoid, "superellipsoid A B C E1 E2 SLICES STACKS", D},
    {"supertoroid", cmd_supertoroid, "supertoroid R r E1 E2 SIDES RINGS", D},
    {"blobball", cmd_blobball, "blobball X Y Z R W", 0},
    {"blobclear", cmd_blobclear, "blobclear", 0},
    {"blobby", cmd_blobby, "blobby ISO X0 Y0 Z0 STEP NX NY NZ", D},
    {"patch", cmd_patch, "patch bezier|bspline N X Y Z (16 control points, row by row)", D},
    {0, 0, 0, 0},
};
