/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of the ray tracer (fixel/rt.h): camera, lights,
 * materials and solid textures, a transform stack, the generic shapes, CSG
 * nodes over the last two objects, `raytrace` (a tile or the whole surface)
 * and `rttrace` (one pixel's ray tree to the host's trace). State lives in
 * the arena (sc->mod[FX_SCENE_MOD_RT]); the first rt command creates it. */
#include "scene_frame.h"
#include "fixel/error.h"
#include "fixel/rt.h"
#include "fixel/scene.h"
#include "fixel/sdl.h"
#include "fixel/render3d.h"
#include "../base/fx_internal.h"
#include "scene_mesh.h"

#define RT_OBJECTS 256
#define RT_STACK 16

typedef struct srt {
    fx_rt_scene s;
    fx_rt_object obj[RT_OBJECTS];
    fx_mat4 stack[RT_STACK];
    int top;
    fx_rt_material mat;
} srt;

static int get(fx_scene *sc, srt **out)
{
    srt *r = sc->mod[FX_SCENE_MOD_RT];
    if (!r) {
        r = fx_scene_alloc(sc, sizeof *r);
        if (!r)
            return fx_scene_error(sc, "out of scene memory for the ray tracer");
        fx_rt_scene_init(&r->s, r->obj, RT_OBJECTS);
        fx_mat4_identity(&r->stack[0]);
        r->mat.ambient = fx3d_rgb_from_color(0x333333);
        r->mat.diffuse = fx3d_rgb_from_color(0xC0C0C0);
        r->mat.specular = fx3d_rgb_from_color(0x808080);
        r->mat.shininess = 20;
        r->mat.ior = FX16_ONE;
        r->s.ambient = fx3d_rgb_from_color(0x404040);
        sc->mod[FX_SCENE_MOD_RT] = r;
    }
    *out = r;
    return 0;
}

#define GET(r)                   \
    srt *r;                      \
    TRY(get(sc, &r))

static int fxs(fx_scene *sc, fx16 *v, int n)
{
    for (int i = 0; i < n; i++)
        TRY(fx_scene_arg_fx16(sc, &v[i]));
    return 0;
}

static fx_vec3 v3(const fx16 *v) { return fx_vec3_make(v[0], v[1], v[2]); }

static int cmd_camera(fx_scene *sc)
{
    GET(r);
    fx16 v[10];
    TRY(fxs(sc, v, 10));
    TRY(fx_scene_end(sc));
    if (fx_rt_set_camera(&r->s, v3(v), v3(v + 3), v3(v + 6), v[9]) < 0)
        return fx_scene_error(sc, "rtcamera: eye equals look, up is parallel to the view, or FOVY is not 1..179");
    return 0;
}

static int cmd_light(fx_scene *sc)
{
    GET(r);
    fx16 v[3], att = 0;
    fx_color c;
    TRY(fxs(sc, v, 3));
    TRY(fx_scene_arg_color(sc, &c));
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_fx16(sc, &att));
    TRY(fx_scene_end(sc));
    int e = fx_rt_add_light(&r->s, v3(v), fx3d_rgb_from_color(c), att);
    if (e == -FX_ENOSPC)
        return fx_scene_error(sc, "rtlight: at most %d lights", FX_RT_MAX_LIGHTS);
    if (e < 0 && (att < 0 || att > FX16_ONE))
        return fx_scene_error(sc, "rtlight: ATTEN 0..1");
    return e < 0 ? fx_scene_error(sc, "rtlight: position outside the scene limit") : 0;
}

/* A colour argument as linear RGB, ending the line. */
static int rgb_line(fx_scene *sc, fx3d_rgb *out)
{
    fx_color c;
    TRY(fx_scene_arg_color(sc, &c));
    TRY(fx_scene_end(sc));
    *out = fx3d_rgb_from_color(c);
    return 0;
}

static int cmd_ambient(fx_scene *sc)
{
    GET(r);
    return rgb_line(sc, &r->s.ambient);
}

static int cmd_background(fx_scene *sc)
{
    GET(r);
    return rgb_line(sc, &r->s.background);
}

static int cmd_material(fx_scene *sc)
{
    GET(r);
    fx_color a, d, sp;
    int32_t f;
    TRY(fx_scene_arg_color(sc, &a));
    TRY(fx_scene_arg_color(sc, &d));
    TRY(fx_scene_arg_color(sc, &sp));
    TRY(fx_scene_arg_int(sc, &f));
    fx16 k[3] = {0, 0, FX16_ONE};
    if (fx_scene_more(sc))
        TRY(fxs(sc, k, 3));
    TRY(fx_scene_end(sc));
    if (f < 0 || f > 256 || k[0] < 0 || k[0] > FX16_ONE || k[1] < 0 || k[1] > FX16_ONE || k[2] < FX16_ONE ||
        k[2] > 4 * FX16_ONE)
        return fx_scene_error(sc, "rtmaterial: SHININESS 0..256, REFLECT and TRANSP 0..1, IOR 1..4");
    r->mat.ambient = fx3d_rgb_from_color(a);
    r->mat.diffuse = fx3d_rgb_from_color(d);
    r->mat.specular = fx3d_rgb_from_color(sp);
    r->mat.shininess = f;
    r->mat.reflectivity = k[0];
    r->mat.transparency = k[1];
    r->mat.ior = k[2];
    return 0;
}

static int cmd_texture(fx_scene *sc)
{
    GET(r);
    static const char *const ch[] = {"none", "wood", "marble", "checker", NULL};
    int t;
    TRY(t = fx_scene_arg_choice(sc, ch));
    fx_color c = 0;
    fx16 scale = FX16_ONE;
    if (t) {
        TRY(fx_scene_arg_color(sc, &c));
        TRY(fx_scene_arg_fx16(sc, &scale));
        if (scale < FX16_ONE / 16 || scale > 64 * FX16_ONE)
            return fx_scene_error(sc, "rttexture: SCALE 0.0625..64");
    }
    TRY(fx_scene_end(sc));
    r->mat.texture = (fx_rt_texture)t;
    r->mat.tex_color = fx3d_rgb_from_color(c);
    r->mat.tex_scale = scale;
    return 0;
}

static int cmd_bump(fx_scene *sc)
{
    GET(r);
    static const char *const none[] = {"none", NULL};
    fx16 k[2] = {0, FX16_ONE};
    int i = sc->pos;
    while (i < sc->len && (sc->text[i] == ' ' || sc->text[i] == '\t'))
        i++;
    if (i < sc->len && sc->text[i] == 'n') {
        TRY(fx_scene_arg_choice(sc, none));
    } else {
        TRY(fxs(sc, k, 2));
        if (k[0] < 0 || k[0] > FX16_ONE || k[1] < FX16_ONE / 16 || k[1] > 64 * FX16_ONE)
            return fx_scene_error(sc, "rtbump: HEIGHT 0..1, SCALE 0.0625..64");
    }
    TRY(fx_scene_end(sc));
    r->mat.bump = k[0];
    r->mat.bump_scale = k[1];
    return 0;
}

/* rtframe none | rtframe brushed|spun STRENGTH SCALE: frame mapping of
 * the shapes that follow (rt.h, fx_rt_frame_dir) */
static int cmd_frame(fx_scene *sc)
{
    GET(r);
    static const char *const ch[] = {"none", "brushed", "spun", NULL};
    int kind;
    TRY(kind = fx_scene_arg_choice(sc, ch));
    fx16 k[2] = {0, FX16_ONE};
    if (kind) {
        TRY(fxs(sc, k, 2));
        if (k[0] < 0 || k[0] > FX16_ONE || k[1] < FX16_ONE / 16 || k[1] > 64 * FX16_ONE)
            return fx_scene_error(sc, "rtframe: STRENGTH 0..1, SCALE 0.0625..64");
    }
    TRY(fx_scene_end(sc));
    /* the choice order is rt.h's fx_rt_frame_kind */
    r->mat.frame = kind;
    r->mat.frame_k = k[0];
    r->mat.frame_scale = k[1];
    return 0;
}

static int cmd_depth(fx_scene *sc)
{
    GET(r);
    int32_t d;
    fx16 cut = r->s.cutoff;
    TRY(fx_scene_arg_int(sc, &d));
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_fx16(sc, &cut));
    TRY(fx_scene_end(sc));
    if (d < 0 || d > FX_RT_MAX_RECURSION || cut < 0 || cut > FX16_ONE)
        return fx_scene_error(sc, "rtdepth: DEPTH 0..%d, CUTOFF 0..1", FX_RT_MAX_RECURSION);
    r->s.max_depth = d;
    r->s.cutoff = cut;
    return 0;
}

static void mult(srt *r, const fx_mat4 *m)
{
    fx_mat4 t;
    fx_mat4_mul(&t, &r->stack[r->top], m);
    r->stack[r->top] = t;
}

static int cmd_identity(fx_scene *sc)
{
    GET(r);
    TRY(fx_scene_end(sc));
    fx_mat4_identity(&r->stack[r->top]);
    return 0;
}

static int cmd_push(fx_scene *sc)
{
    GET(r);
    TRY(fx_scene_end(sc));
    if (r->top + 1 >= RT_STACK)
        return fx_scene_error(sc, "rtpush: stack full (%d)", RT_STACK);
    r->stack[r->top + 1] = r->stack[r->top];
    r->top++;
    return 0;
}

static int cmd_pop(fx_scene *sc)
{
    GET(r);
    TRY(fx_scene_end(sc));
    if (r->top == 0)
        return fx_scene_error(sc, "rtpop without rtpush");
    r->top--;
    return 0;
}

/* translate (0) or scale (1) by three values */
static int xyz_cmd(fx_scene *sc, int scale)
{
    GET(r);
    fx16 v[3];
    TRY(fxs(sc, v, 3));
    TRY(fx_scene_end(sc));
    fx_mat4 m;
    if (scale)
        fx_mat4_scale(&m, v[0], v[1], v[2]);
    else
        fx_mat4_translate(&m, v[0], v[1], v[2]);
    mult(r, &m);
    return 0;
}

static int cmd_translate(fx_scene *sc) { return xyz_cmd(sc, 0); }
static int cmd_scale(fx_scene *sc) { return xyz_cmd(sc, 1); }

static int cmd_rotate(fx_scene *sc)
{
    GET(r);
    fx16 v[4];
    TRY(fxs(sc, v, 4));
    TRY(fx_scene_end(sc));
    fx_mat4 m;
    if (fx_mat4_rotate(&m, fx_angle_from_deg16(v[0]), v3(v + 1)) < 0)
        return fx_scene_error(sc, "rtrotate: the axis is zero");
    mult(r, &m);
    return 0;
}

static int cmd_shape(fx_scene *sc)
{
    GET(r);
    static const char *const ch[] = {"sphere", "cube", "square", "plane", "cylinder", "cone", "taper", "torus", NULL};
    int k;
    TRY(k = fx_scene_arg_choice(sc, ch));
    fx16 s = k == 5 ? 0 : FX16_ONE;
    if (k >= 6)
        TRY(fx_scene_arg_fx16(sc, &s));
    TRY(fx_scene_end(sc));
    fx_rt_kind kind = k == 7 ? FX_RT_TORUS : k >= 4 ? FX_RT_CYLINDER : (fx_rt_kind)k;
    int e = fx_rt_add_shape(&r->s, kind, s, &r->stack[r->top], &r->mat);
    if (e == -FX_ENOSPC)
        return fx_scene_error(sc, "rtshape: at most %d objects", RT_OBJECTS);
    if (e == -FX_EDOM)
        return fx_scene_error(sc, "rtshape: the transform is singular or scales an axis below 1/16");
    if (e == -FX_ERANGE)
        return fx_scene_error(sc, "rtshape: the shape leaves the scene limit (+-%d units)", FX_RT_WORLD);
    if (e < 0 && kind == FX_RT_TORUS)
        return fx_scene_error(sc, "rtshape: torus tube radius r 0.0625..1");
    return e < 0 ? fx_scene_error(sc, "rtshape: TAPER 0..2") : 0;
}

/* Arena memory for a mesh of nv vertices and nt triangles, its BVH, and
 * the object that refers to it. */
static int add_mesh(fx_scene *sc, srt *r, fx_mesh *m, const char *what)
{
    fx_rt_mesh *rm = fx_scene_alloc(sc, sizeof *rm);
    fx_rt_bvh_node *nodes = fx_scene_alloc(sc, (size_t)m->ntris * 2 * sizeof *nodes);
    uint32_t *order = fx_scene_alloc(sc, (size_t)m->ntris * sizeof *order);
    fx_mesh *keep = fx_scene_alloc(sc, sizeof *keep);
    if (!rm || !nodes || !order || !keep)
        return fx_scene_error(sc, "out of scene memory for the %s's BVH (%d triangles)", what, m->ntris);
    *keep = *m;
    int e = fx_rt_mesh_build(rm, keep, nodes, m->ntris * 2, order);
    if (e == -FX_ERANGE)
        return fx_scene_error(sc, "rtmesh: the %s has a vertex beyond +-%d units", what, FX_RT_MESH_LIMIT);
    if (e < 0)
        return fx_scene_error(sc, "rtmesh: the %s cannot be built (%s)", what, fx_strerror(e));
    e = fx_rt_add_mesh(&r->s, rm, &r->stack[r->top], &r->mat);
    if (e == -FX_ENOSPC)
        return fx_scene_error(sc, "rtmesh: at most %d objects", RT_OBJECTS);
    if (e == -FX_EDOM)
        return fx_scene_error(sc, "rtmesh: the transform is singular or scales an axis below 1/16");
    return e < 0 ? fx_scene_error(sc, "rtmesh: the %s leaves the scene limit (+-%d units)", what, FX_RT_WORLD) : 0;
}

static int cmd_mesh(fx_scene *sc)
{
    GET(r);
    static const char *const ch[] = {"teapot", "torus", "obj", NULL};
    int k;
    TRY(k = fx_scene_arg_choice(sc, ch));
    fx_mesh m = {0};
    if (k == 2) {
        TRY(fx_scene_obj_mesh(sc, &m));
        if (m.ntris < 1)
            return fx_scene_error(sc, "rtmesh: the OBJ file has no triangles");
        return add_mesh(sc, r, &m, "OBJ mesh");
    }
    fx_mesh_params p = {k == 0 ? FX_MESH_TEAPOT : FX_MESH_TORUS, FX16_ONE, 0, 0, 0, 0};
    if (k == 0) {
        TRY(fx_scene_arg_int(sc, &p.n));
    } else {
        TRY(fx_scene_arg_fx16(sc, &p.a));
        TRY(fx_scene_arg_fx16(sc, &p.b));
        TRY(fx_scene_arg_int(sc, &p.n));
        TRY(fx_scene_arg_int(sc, &p.k));
    }
    TRY(fx_scene_end(sc));
    int32_t nv, nt;
    if (fx_mesh_size(&p, &nv, &nt) < 0)
        return fx_scene_error(sc, "rtmesh: bad tessellation");
    fx_vec3 *mem = fx_scene_alloc(sc, (size_t)nv * 2 * sizeof(fx_vec3) + (size_t)nt * 3 * sizeof(uint32_t));
    if (!mem)
        return fx_scene_error(sc, "out of scene memory for the mesh (%d vertices)", nv);
    m = (fx_mesh){mem, mem + nv, (uint32_t *)(mem + 2 * nv), 0, 0, nv, nt, NULL, NULL};
    if (fx_mesh_make(&m, &p) < 0)
        return fx_scene_error(sc, "rtmesh: bad tessellation");
    return add_mesh(sc, r, &m, k == 0 ? "teapot" : "torus");
}

static int cmd_csg(fx_scene *sc)
{
    GET(r);
    static const char *const ch[] = {"union", "intersection", "difference", NULL};
    int k;
    TRY(k = fx_scene_arg_choice(sc, ch));
    TRY(fx_scene_end(sc));
    /* the last two top-level objects, in the order they were made */
    int b = r->s.n - 1;
    while (b >= 0 && !r->obj[b].top)
        b--;
    int a = b - 1;
    while (a >= 0 && !r->obj[a].top)
        a--;
    if (a < 0)
        return fx_scene_error(sc, "rtcsg needs two objects");
    int e = fx_rt_add_csg(&r->s, (fx_rt_kind)(FX_RT_UNION + k), a, b);
    if (e == -FX_ENOSPC)
        return fx_scene_error(sc, "rtcsg: at most %d objects", RT_OBJECTS);
    return e < 0 ? fx_scene_error(sc, "rtcsg: the tree would be deeper than %d", FX_RT_MAX_DEPTH) : 0;
}

static void *sdl_alloc(void *user, size_t n) { return fx_scene_alloc(user, n); }

static int sdl_load(void *user, const char *path, const uint8_t **data, size_t *len)
{
    fx_scene *sc = user;
    return sc->host.load_file(sc->host.user, path, data, len);
}

/* The textbook's SDL file: its lights, settings and objects join the
 * scene; its camera is fx_sdl_default_camera's (SDL has none), which a
 * later rtcamera replaces. */
static int cmd_sdl(fx_scene *sc)
{
    GET(r);
    char path[256];
    TRY(fx_scene_arg_string(sc, path, sizeof path));
    TRY(fx_scene_end(sc));
    if (!sc->host.load_file)
        return fx_scene_error(sc, "files not available");
    const uint8_t *data;
    size_t len;
    int e = sc->host.load_file(sc->host.user, path, &data, &len);
    if (e < 0)
        return fx_scene_error(sc, "sdl: cannot read '%s': %s", path, fx_strerror(e));
    fx_sdl_env env = {sc, sdl_alloc, sdl_load};
    fx_sdl_error err;
    if (fx_sdl_read(&r->s, (const char *)data, len, path, &env, &err) < 0)
        return fx_scene_error(sc, "sdl: %s", err.msg);
    fx_sdl_default_camera(&r->s, 45 * FX16_ONE);
    return 0;
}

/* ---- rtpreview: the ray tracer's scene drawn by the z-buffer rasterizer,
 * a quick look before the trace. Each leaf is tessellated in its own
 * object space and placed by its object-to-world matrix; a union draws
 * both sides, an intersection or difference only its left side (the
 * rasterizer has no CSG); reflection, refraction and shadows are absent. */
#define PV_SEG 24
#define PV_RINGS 12
#define PV_VERTS 1200
#define PV_TRIS 1200

typedef struct preview {
    fx3d r;
    fx_mat4 mstack[2], pstack[2];
    fx_mesh m;
} preview;

static void pv_vert(fx_mesh *m, fx16 x, fx16 y, fx16 z, fx16 nx, fx16 ny, fx16 nz)
{
    fx_vec3 n = fx_vec3_make(nx, ny, nz);
    fx_vec3_normalize(&n);
    m->pos[m->nverts] = fx_vec3_make(x, y, z);
    m->nrm[m->nverts++] = n;
}

static void pv_tri(fx_mesh *m, int32_t a, int32_t b, int32_t c)
{
    uint32_t *t = m->tri + m->ntris++ * 3;
    t[0] = (uint32_t)a, t[1] = (uint32_t)b, t[2] = (uint32_t)c;
}

/* x^2 + y^2 <= (1 + (s - 1) z)^2, 0 <= z <= 1, with its caps */
static void pv_taper(fx_mesh *m, fx16 s)
{
    for (int i = 0; i <= PV_SEG; i++) {
        fx_angle a = (fx_angle)((uint64_t)i * 0x100000000ull / PV_SEG);
        fx16 c = fx_cos(a), sn = fx_sin(a);
        pv_vert(m, c, sn, 0, c, sn, FX16_ONE - s);
        pv_vert(m, fx16_mul(c, s), fx16_mul(sn, s), FX16_ONE, c, sn, FX16_ONE - s);
    }
    for (int i = 0; i < PV_SEG; i++)
        pv_tri(m, 2 * i, 2 * i + 2, 2 * i + 3), pv_tri(m, 2 * i, 2 * i + 3, 2 * i + 1);
    for (int cap = 0; cap < 2; cap++) {
        fx16 z = cap ? FX16_ONE : 0, rr = cap ? s : FX16_ONE, nz = cap ? FX16_ONE : -FX16_ONE;
        int32_t c0 = m->nverts;
        pv_vert(m, 0, 0, z, 0, 0, nz);
        for (int i = 0; i <= PV_SEG; i++) {
            fx_angle a = (fx_angle)((uint64_t)i * 0x100000000ull / PV_SEG);
            pv_vert(m, fx16_mul(fx_cos(a), rr), fx16_mul(fx_sin(a), rr), z, 0, 0, nz);
        }
        for (int i = 0; i < PV_SEG; i++)
            pv_tri(m, c0, c0 + 1 + i, c0 + 2 + i);
    }
}

/* ring radius 1 about z, tube r */
static void pv_torus(fx_mesh *m, fx16 r)
{
    for (int i = 0; i <= PV_SEG; i++)
        for (int j = 0; j <= PV_RINGS; j++) {
            fx_angle u = (fx_angle)((uint64_t)i * 0x100000000ull / PV_SEG);
            fx_angle v = (fx_angle)((uint64_t)j * 0x100000000ull / PV_RINGS);
            fx16 cu = fx_cos(u), su = fx_sin(u), cv = fx_cos(v), sv = fx_sin(v);
            fx16 rad = FX16_ONE + fx16_mul(r, cv);
            pv_vert(m, fx16_mul(rad, cu), fx16_mul(rad, su), fx16_mul(r, sv), fx16_mul(cv, cu), fx16_mul(cv, su),
                    sv);
        }
    for (int i = 0; i < PV_SEG; i++)
        for (int j = 0; j < PV_RINGS; j++) {
            int32_t a = i * (PV_RINGS + 1) + j, b = a + PV_RINGS + 1;
            pv_tri(m, a, b, b + 1), pv_tri(m, a, b + 1, a + 1);
        }
}

/* z = 0, |x|, |y| <= h, in n x n cells */
static void pv_sheet(fx_mesh *m, fx16 h, int n)
{
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++)
            pv_vert(m, (fx16)(-h + (int64_t)2 * h * i / n), (fx16)(-h + (int64_t)2 * h * j / n), 0, 0, 0, FX16_ONE);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            int32_t a = i * (n + 1) + j, b = a + n + 1;
            pv_tri(m, a, b, b + 1), pv_tri(m, a, b + 1, a + 1);
        }
}

static void pv_draw(preview *p, const fx_rt_scene *s, int i)
{
    const fx_rt_object *o = &s->obj[i];
    if (o->kind >= FX_RT_UNION) {
        pv_draw(p, s, o->left);
        if (o->kind == FX_RT_UNION)
            pv_draw(p, s, o->right);
        return;
    }
    fx_mat4 M;
    if (fx_mat4_invert(&M, &o->inv) < 0)
        return;
    fx_mat_stack_load(&p->r.model, &M);
    const fx_rt_material *mt = &o->mat;
    p->r.mat = (fx3d_material){mt->ambient, mt->diffuse, mt->specular, mt->emissive,
                               mt->shininess > 128 ? 128 : mt->shininess};
    fx_mesh *m = &p->m;
    m->nverts = m->ntris = 0;
    const fx_mesh *draw = m;
    switch (o->kind) {
    case FX_RT_SPHERE:
    case FX_RT_CUBE: {
        fx_mesh_params mp = {o->kind == FX_RT_SPHERE ? FX_MESH_SPHERE : FX_MESH_CUBE,
                             o->kind == FX_RT_SPHERE ? FX16_ONE : 2 * FX16_ONE, 0, 0, PV_SEG, PV_RINGS};
        if (fx_mesh_make(m, &mp) < 0)
            return;
        break;
    }
    case FX_RT_SQUARE: pv_sheet(m, FX16_ONE, 4); break;
    case FX_RT_PLANE: pv_sheet(m, 120 * FX16_ONE, 24); break;
    case FX_RT_CYLINDER: pv_taper(m, o->taper); break;
    case FX_RT_TORUS: pv_torus(m, o->taper); break;
    case FX_RT_MESH: draw = o->mesh->mesh; break;
    default: return;
    }
    fx3d_draw(&p->r, draw);
}

static int cmd_preview(fx_scene *sc)
{
    GET(r);
    static const char *const ch[] = {"flat", "gouraud", "phong", NULL};
    int shading = FX3D_PHONG;
    if (fx_scene_more(sc))
        TRY(shading = fx_scene_arg_choice(sc, ch));
    TRY(fx_scene_end(sc));
    TRY(fx_scene_surface(sc));
    preview *p = fx_scene_alloc(sc, sizeof *p);
    fx_vec3 *mem = fx_scene_alloc(sc, (size_t)PV_VERTS * 2 * sizeof(fx_vec3) + (size_t)PV_TRIS * 3 * sizeof(uint32_t));
    void *depth = fx_scene_alloc_raw(sc, fx3d_depth_bytes(&sc->ctx.surf, 32));
    if (!p || !mem || !depth)
        return fx_scene_error(sc, "out of scene memory for rtpreview");
    p->m = (fx_mesh){mem, mem + PV_VERTS, (uint32_t *)(mem + 2 * PV_VERTS), 0, 0, PV_VERTS, PV_TRIS, NULL, NULL};
    fx_surface scr = fx_scene_screen_surf(&sc->ctx);
    fx3d_init(&p->r, &scr, p->mstack, 2, p->pstack, 2);
    fx_scene_band_clip(sc, &p->r.ctx.clip);
    if (sc->banded)
        fx3d_depth_rows(&p->r, sc->band.y0, sc->band.y1);
    fx3d_set_depth(&p->r, depth, 32);
    p->r.visibility = FX3D_VIS_DEPTH;
    p->r.cull = FX3D_CULL_NONE; /* sheets are seen from both sides */
    p->r.shading = (fx3d_shading)shading;
    fx_camera_view(&r->s.cam, &p->r.view);
    fx_mat4 proj;
    fx_angle fovy = fx_atan2(r->s.tan_half, FX16_ONE) * 2;
    fx_mat4_perspective(&proj, fovy, fx16_from_ratio(sc->ctx.surf.w, sc->ctx.surf.h), FX16_ONE / 10,
                        512 * FX16_ONE);
    fx_mat_stack_load(&p->r.proj, &proj);
    p->r.ambient = r->s.ambient;
    for (int i = 0; i < FX3D_MAX_LIGHTS; i++)
        p->r.light[i].type = FX3D_LIGHT_OFF;
    for (int i = 0; i < r->s.nlights; i++) {
        fx3d_light *L = &p->r.light[i];
        L->type = FX3D_LIGHT_POINT;
        L->pos = r->s.light[i].pos;
        L->ambient = (fx3d_rgb){0, 0, 0};
        L->diffuse = L->specular = r->s.light[i].color;
    }
    fx_ctx c = p->r.ctx;
    c.color = fx3d_rgb_to_color(r->s.background);
    fx_clear(&c);
    for (int i = 0; i < r->s.n; i++)
        if (r->obj[i].top)
            pv_draw(p, &r->s, i);
    return 0;
}

static int cmd_raytrace(fx_scene *sc)
{
    GET(r);
    int32_t v[4] = {0, 0, sc->ctx.surf.w, sc->ctx.surf.h};
    if (fx_scene_more(sc))
        for (int i = 0; i < 4; i++)
            TRY(fx_scene_arg_int(sc, &v[i]));
    TRY(fx_scene_end(sc));
    fx_surface scr = fx_scene_screen_surf(&sc->ctx);
    if (sc->banded && !sc->raytrace) {
        /* the part of the rectangle inside the band; each pixel's rays are
         * its own, so the part is the same pixels as in the whole (a host
         * renderer gets the whole rectangle: fx_scene_run_mt's traces it
         * once, on all threads together) */
        int64_t x0 = v[0], x1 = (int64_t)v[0] + v[2], y0 = v[1], y1 = (int64_t)v[1] + v[3];
        x0 = x0 > sc->band.x0 ? x0 : sc->band.x0;
        x1 = x1 < sc->band.x1 ? x1 : sc->band.x1;
        y0 = y0 > sc->band.y0 ? y0 : sc->band.y0;
        y1 = y1 < sc->band.y1 ? y1 : sc->band.y1;
        if (x0 >= x1 || y0 >= y1)
            return 0;
        v[0] = (int32_t)x0, v[1] = (int32_t)y0, v[2] = (int32_t)(x1 - x0), v[3] = (int32_t)(y1 - y0);
    }
    if (sc->raytrace) {
        int e = sc->raytrace(sc->host.user, &r->s, &scr, v[0], v[1], v[2], v[3]);
        return e < 0 ? fx_scene_error(sc, "raytrace: the host's renderer failed (%d)", e) : 0;
    }
    fx_rt_render(&r->s, &scr, v[0], v[1], v[2], v[3]);
    return 0;
}

static int cmd_trace(fx_scene *sc)
{
    GET(r);
    int32_t x, y;
    TRY(fx_scene_arg_int(sc, &x));
    TRY(fx_scene_arg_int(sc, &y));
    TRY(fx_scene_end(sc));
    if (x < 0 || y < 0 || x >= sc->ctx.surf.w || y >= sc->ctx.surf.h)
        return fx_scene_error(sc, "rttrace: pixel (%d, %d) is outside the %dx%d surface", x, y, sc->ctx.surf.w,
                              sc->ctx.surf.h);
    if (sc->host.trace) {
        char line[64];
        fx_fmt(line, sizeof line, "rttrace pixel (%d, %d)", x, y);
        sc->host.trace(sc->host.user, line);
    }
    fx_color c = fx_rt_trace_pixel(&r->s, sc->ctx.surf.w, sc->ctx.surf.h, x, y, sc->host.trace, sc->host.user);
    if (sc->host.trace) {
        char line[64];
        fx_fmt(line, sizeof line, "rttrace pixel (%d, %d) = #%06X", x, y, (unsigned)(c & 0xFFFFFF));
        sc->host.trace(sc->host.user, line);
    }
    return 0;
}

#define D FX_SCENE_DRAWS
const fx_scene_cmd fx_scene_cmds_rt[] = {
    {"rtcamera", cmd_camera, "rtcamera EX EY EZ LX LY LZ UX UY UZ FOVY", D},
    {"rtlight", cmd_light, "rtlight X Y Z #RGB [ATTEN]", D},
    {"rtambient", cmd_ambient, "rtambient #RGB", D},
    {"rtbackground", cmd_background, "rtbackground #RGB", D},
    {"rtmaterial", cmd_material, "rtmaterial #AMB #DIFF #SPEC SHININESS [REFLECT TRANSP IOR]", D},
    {"rttexture", cmd_texture, "rttexture none | wood|marble|checker #RGB SCALE", D},
    {"rtbump", cmd_bump, "rtbump none | rtbump HEIGHT SCALE", D},
    {"rtframe", cmd_frame, "rtframe none | rtframe brushed|spun STRENGTH SCALE   (anisotropic highlights along the grain)", D},
    {"rtdepth", cmd_depth, "rtdepth DEPTH [CUTOFF]", D},
    {"rtidentity", cmd_identity, "rtidentity", D},
    {"rtpush", cmd_push, "rtpush", D},
    {"rtpop", cmd_pop, "rtpop", D},
    {"rttranslate", cmd_translate, "rttranslate X Y Z", D},
    {"rtscale", cmd_scale, "rtscale SX SY SZ", D},
    {"rtrotate", cmd_rotate, "rtrotate DEG AX AY AZ", D},
    {"rtshape", cmd_shape, "rtshape sphere|cube|square|plane|cylinder|cone | rtshape taper S | rtshape torus r", D},
    {"rtmesh", cmd_mesh, "rtmesh teapot N | rtmesh torus R r SIDES RINGS | rtmesh obj \"FILE\"", D},
    {"rtcsg", cmd_csg, "rtcsg union|intersection|difference", D},
    {"sdl", cmd_sdl, "sdl \"FILE\" (the textbook's scene description language; docs/RAYTRACE.md)", D},
    {"rtpreview", cmd_preview, "rtpreview [flat|gouraud|phong] (the scene rasterized: unions whole, other CSG its left side; no reflection or shadows)", D},
    {"raytrace", cmd_raytrace, "raytrace [X Y W H]", D},
    {"rttrace", cmd_trace, "rttrace X Y", D},
    {0, 0, 0, 0},
};
