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
 *   ptabcull on|off          the commands above build the course's polygon
 *                            tables of their mesh and drop the back faces
 *                            by the plane test from the eye (in object
 *                            coordinates) before drawing; --trace prints
 *                            the tables' sizes and the faces dropped
 *   octree blob ISO K SCALE SX SY X0 Y0 Z0 SIDE
 *   octree supertoroid R r E1 E2 SIDES RINGS K SCALE SX SY X0 Y0 Z0 SIDE
 *                            the blob's field (> ISO) or the supertoroid's
 *                            mesh (its axis turned from y to z) through its
 *                            polygon tables (ray parity),
 *                            as 2^K voxels of the cube from (X0, Y0, Z0),
 *                            as an octree, drawn front to back looking
 *                            along +z (y up), SCALE pixels a voxel, at
 *                            (SX, SY) on the surface, grey by depth
 * The balls, the grid's work block and the tables live in the arena
 * (sc->mod[FX_SCENE_MOD_OBJECTS]). */
#include "fixel/error.h"
#include "fixel/objects.h"
#include "fixel/scene.h"
#include "../base/fx_internal.h"
#include "scene_mesh.h"
#include "scene_vsd.h"


typedef struct sobj {
    fx_blob_ball ball[FX_BLOBBY_MAX_BALLS];
    int32_t nball;
    void *work;
    size_t work_bytes;
    int cull;
    void *tab;
    size_t tab_bytes;
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

/* A block of the arena kept for reuse: grown when too small. */
static void *reuse(fx_scene *sc, void **blk, size_t *have, size_t need)
{
    if (need > *have) {
        void *b = fx_scene_alloc(sc, need);
        if (!b)
            return 0;
        *blk = b;
        *have = need;
    }
    return *blk;
}

/* The mesh's polygon tables in the arena (vertex, edge, polygon and
 * edge-use tables sized for it). */
static int tables(fx_scene *sc, sobj *o, const fx_mesh *m, fx_ptab *t)
{
    size_t nv = (size_t)m->nverts, nt = (size_t)m->ntris;
    size_t need = nv * sizeof(fx_ptab_vertex) + 3 * nt * sizeof(fx_ptab_edge) + nt * sizeof(fx_ptab_poly) +
                  3 * nt * sizeof(int32_t);
    uint8_t *b = reuse(sc, &o->tab, &o->tab_bytes, need);
    if (!b)
        return fx_scene_error(sc, "out of scene memory for the polygon tables of %d triangles", m->ntris);
    fx_ptab_poly *pp = (fx_ptab_poly *)b;
    fx_ptab_edge *ee = (fx_ptab_edge *)(pp + nt);
    fx_ptab_vertex *vv = (fx_ptab_vertex *)(ee + 3 * nt);
    int32_t *uu = (int32_t *)(vv + nv);
    fx_ptab_init(t, vv, (int32_t)nv, ee, 3 * (int32_t)nt, pp, (int32_t)nt, uu, 3 * (int32_t)nt);
    int32_t r = fx_ptab_from_mesh(t, m, 0);
    if (r < 0)
        return fx_scene_error(sc, "the mesh is not a consistent polyhedron for the polygon tables (%s)",
                              fx_strerror(r));
    return 0;
}

/* Draw, after dropping the back faces by the polygon tables' plane test
 * when ptabcull is on. */
static int finish(fx_scene *sc, fx_mesh *m)
{
    sobj *o = sc->mod[FX_SCENE_MOD_OBJECTS];
    if (!o || !o->cull)
        return fx_scene_mesh_draw(sc, m);
    fx_ptab t;
    TRY(tables(sc, o, m, &t));
    fx_vec3 eye;
    int parallel;
    TRY(fx_scene_object_view(sc, &eye, &parallel));
    int32_t kept = 0;
    for (int32_t p = 0; p < t.npoly; p++) {
        if (parallel ? fx_ptab_back_face_dir(&t, p, eye) : fx_ptab_back_face(&t, p, eye))
            continue;
        const uint32_t *src = &m->tri[3 * t.poly[p].attr];
        uint32_t a = src[0], b = src[1], c = src[2];
        m->tri[3 * kept] = a, m->tri[3 * kept + 1] = b, m->tri[3 * kept + 2] = c;
        kept++;
    }
    if (sc->ctx.trace)
        fx_trace(&sc->ctx, "ptab: %d vertices, %d edges (%d open), %d polygons; %d back faces by the plane test, %d drawn",
                 t.nvert, t.nedge, fx_ptab_open_edges(&t), t.npoly, t.npoly - kept, kept);
    m->ntris = kept;
    return fx_scene_mesh_draw(sc, m);
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
    if (fx_quadric_size(q, &nv, &nt) < 0) {
        if (q->a <= 0 || q->b <= 0 || (q->kind != FX_QUADRIC_SUPERTOROID && q->kind != FX_QUADRIC_PARABOLOID && q->c <= 0) ||
            (q->kind <= FX_QUADRIC_HYPERBOLOID2 && q->h <= 0))
            return fx_scene_error(sc, "sizes must be above 0");
        if (q->kind == FX_QUADRIC_HYPERBOLOID2 && q->h <= q->c)
            return fx_scene_error(sc, "hyperboloid 2: H must exceed C (the sheets begin at |y| = C)");
        if (q->kind == FX_QUADRIC_HYPERBOLOID1 || q->kind == FX_QUADRIC_HYPERBOLOID2)
            return fx_scene_error(sc, "hyperboloid: H at most 256 C, and the rim within 1024");
        if (q->kind == FX_QUADRIC_SUPERTOROID)
            return fx_scene_error(sc, "supertoroid: R + r within 1024, at least 3 sides and rings");
        return fx_scene_error(sc, "tessellation out of range");
    }
    fx_mesh m;
    TRY(fx_scene_mesh_alloc(sc, nv, nt, 0, &m));
    TRY(fx_quadric_make(&m, q));
    return finish(sc, &m);
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
    return finish(sc, &m);
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
    return finish(sc, &m);
}

static int cmd_ptabcull(fx_scene *sc)
{
    static const char *const ch[] = {"off", "on", NULL};
    sobj *o = 0;
    int c;
    TRY(c = fx_scene_arg_choice(sc, ch));
    TRY(fx_scene_end(sc));
    TRY(get(sc, &o));
    o->cull = c;
    return 0;
}

/* coloursolid rgb|hsv|hls SIZE: the colour models as solids, each vertex
 * its colour, lit flat with the 3D state (mesh.h fx_colour_solid_make) */
static int cmd_coloursolid(fx_scene *sc)
{
    static const char *const ch[] = {"rgb", "hsv", "hls", NULL};
    int k;
    fx16 size;
    TRY(k = fx_scene_arg_choice(sc, ch));
    TRY(fx_scene_arg_fx16(sc, &size));
    TRY(fx_scene_end(sc));
    if (size <= 0 || size > 1024 * FX16_ONE)
        return fx_scene_error(sc, "size out of range (0 < SIZE <= 1024)");
    fx_vec3 pos[FX_COLOUR_SOLID_VERTS];
    uint32_t col[FX_COLOUR_SOLID_VERTS], tri[3 * FX_COLOUR_SOLID_TRIS];
    fx_mesh m = {pos, NULL, tri, 0, 0, FX_COLOUR_SOLID_VERTS, FX_COLOUR_SOLID_TRIS, NULL, col};
    if (fx_colour_solid_make(&m, (fx_colour_solid)k, size) < 0)
        return fx_scene_error(sc, "bad colour solid");
    return fx_scene_mesh_draw(sc, &m);
}

static fx16 blob_inside(const void *user, fx_vec3 p)
{
    const fx_blobby *b = user;
    return fx_blobby_field(b, p) - b->iso;
}

static int cmd_octree(fx_scene *sc)
{
    static const char *const ch[] = {"blob", "supertoroid", NULL};
    sobj *o = 0;
    int kind;
    fx16 iso = 0, f[4] = {0};
    int32_t seg[2] = {0}, k, scale, sx, sy;
    fx16 c[4];
    TRY(kind = fx_scene_arg_choice(sc, ch));
    if (kind == 0) {
        TRY(fx_scene_arg_fx16(sc, &iso));
    } else {
        for (int i = 0; i < 4; i++)
            TRY(fx_scene_arg_fx16(sc, &f[i]));
        for (int i = 0; i < 2; i++)
            TRY(fx_scene_arg_int(sc, &seg[i]));
    }
    TRY(fx_scene_arg_int(sc, &k));
    TRY(fx_scene_arg_int(sc, &scale));
    TRY(fx_scene_arg_int(sc, &sx));
    TRY(fx_scene_arg_int(sc, &sy));
    for (int i = 0; i < 4; i++)
        TRY(fx_scene_arg_fx16(sc, &c[i]));
    TRY(fx_scene_end(sc));
    TRY(fx_scene_surface(sc));
    TRY(get(sc, &o));
    int32_t n = (int32_t)1 << k;
    uint8_t *vox = fx_scene_alloc(sc, (size_t)n * (size_t)n * (size_t)n);
    if (!vox)
        return fx_scene_error(sc, "octree: out of scene memory");
    fx_vec3 org = fx_vec3_make(c[0], c[1], c[2]);
    int e;
    if (kind == 0) {
        fx_blobby b = {o->ball, o->nball, iso, org, FX16_ONE, 1, 1, 1};
        if (iso <= 0)
            return fx_scene_error(sc, "octree blob: ISO must be above 0");
        e = fx_voxels_from_implicit(vox, k, org, c[3], blob_inside, &b);
    } else {
        fx_quadric q = {FX_QUADRIC_SUPERTOROID, f[0], f[1], 0, 0, f[2], f[3], seg[0], seg[1]};
        int32_t nv, nt;
        if (fx_quadric_size(&q, &nv, &nt) < 0)
            return fx_scene_error(sc, "octree supertoroid: size, exponent or tessellation out of range");
        fx_mesh m;
        TRY(fx_scene_mesh_alloc(sc, nv, nt, 0, &m));
        TRY(fx_quadric_make(&m, &q));
        /* the ring turned to face the viewer: y and z trade places, and the
         * triangles turn the other way to stay counter-clockwise outside */
        for (int32_t i = 0; i < m.nverts; i++) {
            fx16 y = m.pos[i].y;
            m.pos[i].y = m.pos[i].z, m.pos[i].z = y;
        }
        for (int32_t i = 0; i < m.ntris; i++) {
            uint32_t tmp = m.tri[3 * i + 1];
            m.tri[3 * i + 1] = m.tri[3 * i + 2], m.tri[3 * i + 2] = tmp;
        }
        fx_ptab t;
        TRY(tables(sc, o, &m, &t));
        e = fx_voxels_from_ptab(vox, k, org, c[3], &t);
    }
    if (e < 0)
        return fx_scene_error(sc, "octree: the cube lies beyond +-1024");
    /* rows top down on the screen: y up in the solid */
    for (int32_t z = 0; z < n; z++)
        for (int32_t y = 0; y < n / 2; y++)
            for (int32_t x = 0; x < n; x++) {
                uint8_t *a = &vox[((size_t)z * (size_t)n + (size_t)y) * (size_t)n + (size_t)x];
                uint8_t *b = &vox[((size_t)z * (size_t)n + (size_t)(n - 1 - y)) * (size_t)n + (size_t)x];
                uint8_t tmp = *a;
                *a = *b, *b = tmp;
            }
    int32_t visited, nodes = 0;
    TRY(visited = fx_scene_octree_draw(sc, vox, k, scale, sx, sy, &nodes));
    if (sc->ctx.trace)
        fx_trace(&sc->ctx, "octree: %d nodes for %d voxels, %d visited front to back", nodes, n * n * n, visited);
    return 0;
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
    {"ptabcull", cmd_ptabcull, "ptabcull on|off", 0},
    {"coloursolid", cmd_coloursolid, "coloursolid rgb|hsv|hls SIZE", D},
    {"octree", cmd_octree,
     "octree blob ISO K SCALE SX SY X0 Y0 Z0 SIDE | octree supertoroid R r E1 E2 SIDES RINGS K SCALE SX SY X0 Y0 Z0 SIDE", D},
    {0, 0, 0, 0},
};
