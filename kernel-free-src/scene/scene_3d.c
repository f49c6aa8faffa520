/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of the 3D pipeline: camera, projections, the
 * model matrix stack, lights, materials, shading and visibility modes,
 * meshes, planar shadows and the shadow buffer. State lives in the arena
 * (sc->mod[FX_SCENE_MOD_3D]); the first 3D command creates it. */
#include "scene_frame.h"
#include "fixel/error.h"
#include "fixel/render3d.h"
#include "fixel/scene.h"
#include "scene_mesh.h"
#include "scene_shared.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

typedef struct s3d {
    fx3d r;
    fx_mat4 mstack[32], pstack[4];
    fx_mat4 tstack[8];     /* texture matrices, attached by the first 'texmatrix' */
    fx_camera cam;
    void *zbuf[2];         /* 16- and 32-bit depth buffers, made on demand */
    void *pbuf;
    size_t pbytes;
    void *tbuf;            /* translucent triangles, made by the first 'alpha3d' */
    size_t tbytes;
    void *mesh_mem;        /* reused by every mesh command that fits */
    size_t mesh_bytes;
    /* Shadow maps: 'shadowmap begin' fills one per light, up to
     * FX3D_MAX_SHADOWS before 'shadowmap end' puts them all in use. */
    fx3d_shadowmap sm[FX3D_MAX_SHADOWS];
    uint32_t *smbuf[FX3D_MAX_SHADOWS];
    int32_t smsize[FX3D_MAX_SHADOWS];
    int nsm;
    int sm_filling; /* a begin since the last end or off */
} s3d;

static int get(fx_scene *sc, s3d **out)
{
    TRY(fx_scene_surface(sc));
    s3d *s = sc->mod[FX_SCENE_MOD_3D];
    if (!s) {
        s = fx_scene_alloc(sc, sizeof *s);
        if (!s)
            return fx_scene_error(sc, "out of scene memory for the 3D state");
        fx_surface scr = fx_scene_screen_surf(&sc->ctx);
        fx3d_init(&s->r, &scr, s->mstack, 32, s->pstack, 4);
        fx_camera_set(&s->cam, fx_vec3_make(0, 0, 5 * FX16_ONE), fx_vec3_make(0, 0, 0),
                      fx_vec3_make(0, FX16_ONE, 0));
        fx_camera_view(&s->cam, &s->r.view);
        fx_mat4 p;
        fx_mat4_perspective(&p, fx_angle_from_deg(45), fx16_from_ratio(sc->w, sc->h), FX16_ONE / 10,
                            100 * FX16_ONE);
        int32_t pn, pd;
        fx_scene_pixel_aspect(sc, &pn, &pd); /* a 'pixelaspect' before the first 3D command */
        fx_mat4_pixel_aspect(&p, pn, pd);
        fx_mat_stack_load(&s->r.proj, &p);
        sc->mod[FX_SCENE_MOD_3D] = s;
    }
    fx_scene_band_clip(sc, &s->r.ctx.clip);
    /* every clip of a band lies in its rows: the rest of the depth buffer
     * is never read, so clearing it in every band would only repeat work */
    if (sc->banded) {
        fx3d_depth_rows(&s->r, sc->band.y0, sc->band.y1);
    } else if (s->r.depth_y1 > s->r.depth_y0) {
        /* the scene goes on unbanded (after fx_scene_run_mt): the rows its
         * band never cleared become far, and clears cover every row again */
        int32_t y0 = s->r.depth_y0, y1 = s->r.depth_y1;
        fx3d_depth_rows(&s->r, 0, y0);
        fx3d_clear_depth(&s->r);
        fx3d_depth_rows(&s->r, y1, INT32_MAX);
        fx3d_clear_depth(&s->r);
        fx3d_depth_rows(&s->r, 0, 0);
    }
    *out = s;
    return 0;
}

static int args_fx(fx_scene *sc, fx16 *v, int n)
{
    for (int i = 0; i < n; i++)
        TRY(fx_scene_arg_fx16(sc, &v[i]));
    return fx_scene_end(sc);
}

#define GET(s)                   \
    s3d *s;                      \
    TRY(get(sc, &s))

static int cmd_viewport(fx_scene *sc)
{
    GET(s);
    int32_t v[4];
    for (int i = 0; i < 4; i++)
        TRY(fx_scene_arg_int(sc, &v[i]));
    TRY(fx_scene_end(sc));
    if (v[2] < 1 || v[3] < 1 || v[2] > 16384 || v[3] > 16384)
        return fx_scene_error(sc, "viewport3d size %dx%d out of range (1..16384)", v[2], v[3]);
    fx3d_viewport(&s->r, v[0], v[1], v[2], v[3]);
    return 0;
}

static int cmd_depth(fx_scene *sc)
{
    GET(s);
    static const char *const ch[] = {"16", "32", "off", NULL};
    int c;
    TRY(c = fx_scene_arg_choice(sc, ch));
    TRY(fx_scene_end(sc));
    if (c == 2)
        return fx3d_set_depth(&s->r, NULL, 0);
    if (!s->zbuf[c]) {
        /* not zeroed: fx3d_set_depth clears it (the rows a band reads) */
        s->zbuf[c] = fx_scene_alloc_raw(sc, fx3d_depth_bytes(&sc->ctx.surf, c ? 32 : 16));
        if (!s->zbuf[c])
            return fx_scene_error(sc, "out of scene memory for a depth buffer");
    }
    return fx3d_set_depth(&s->r, s->zbuf[c], c ? 32 : 16);
}

static int cmd_cleardepth(fx_scene *sc)
{
    GET(s);
    TRY(fx_scene_end(sc));
    fx3d_clear_depth(&s->r);
    return 0;
}

static int cmd_painter(fx_scene *sc)
{
    GET(s);
    int32_t n = 32768;
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_int(sc, &n));
    TRY(fx_scene_end(sc));
    if (n < 1 || n > (1 << 20))
        return fx_scene_error(sc, "painter capacity %d out of range (1..1048576)", n);
    size_t need = fx3d_painter_bytes(n);
    if (need > s->pbytes) {
        s->pbuf = fx_scene_alloc(sc, need);
        if (!s->pbuf)
            return fx_scene_error(sc, "out of scene memory for %d painter's triangles", n);
        s->pbytes = need;
    }
    return fx3d_set_painter(&s->r, s->pbuf, s->pbytes);
}

static int cmd_flush(fx_scene *sc)
{
    GET(s);
    TRY(fx_scene_end(sc));
    s->r.ctx = fx_scene_screen_ctx(&sc->ctx);
    fx3d_flush(&s->r);
    if (s->r.pdropped)
        return fx_scene_error(sc, "%d triangles did not fit the painter's buffer", s->r.pdropped);
    if (s->r.tdropped)
        return fx_scene_error(sc, "%d translucent triangles did not fit the 'alpha3d' buffer", s->r.tdropped);
    return 0;
}

/* Opacity of the meshes drawn next (1 opaque). Translucent triangles wait
 * for 'flush', which draws them after the opaque ones, farthest first,
 * depth-tested without writing depth (fx3d_alpha). */
static int cmd_alpha3d(fx_scene *sc)
{
    GET(s);
    fx16 a;
    int32_t n = 4096;
    TRY(fx_scene_arg_fx16(sc, &a));
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_int(sc, &n));
    TRY(fx_scene_end(sc));
    if (a < 0 || a > FX16_ONE)
        return fx_scene_error(sc, "alpha3d: opacity out of range (0..1)");
    if (n < 1 || n > (1 << 20))
        return fx_scene_error(sc, "alpha3d: capacity %d out of range (1..1048576)", n);
    size_t need = fx3d_painter_bytes(n);
    if (a < FX16_ONE && need > s->tbytes) {
        if (s->r.tcount)
            return fx_scene_error(sc, "alpha3d: 'flush' before growing the translucent buffer");
        s->tbuf = fx_scene_alloc(sc, need);
        if (!s->tbuf)
            return fx_scene_error(sc, "out of scene memory for %d translucent triangles", n);
        s->tbytes = need;
        TRY(fx3d_set_translucent(&s->r, s->tbuf, s->tbytes));
    }
    fx3d_alpha(&s->r, (int)(((int64_t)a * 255 + 0x8000) >> 16));
    return 0;
}

static int cmd_camera(fx_scene *sc)
{
    GET(s);
    fx16 v[9];
    TRY(args_fx(sc, v, 9));
    if (fx_camera_set(&s->cam, fx_vec3_make(v[0], v[1], v[2]), fx_vec3_make(v[3], v[4], v[5]),
                      fx_vec3_make(v[6], v[7], v[8])) < 0)
        return fx_scene_error(sc, "camera: eye equals look, or up is parallel to the view");
    fx_camera_view(&s->cam, &s->r.view);
    return 0;
}

int fx_scene_3d_camera(fx_scene *sc, fx_vec3 eye, fx_vec3 look, fx_vec3 up)
{
    GET(s);
    if (fx_camera_set(&s->cam, eye, look, up) < 0)
        return fx_scene_error(sc, "camera: eye equals look, or up is parallel to the view");
    fx_camera_view(&s->cam, &s->r.view);
    return 0;
}

int fx_scene_3d_model(fx_scene *sc, const fx_mat4 *m)
{
    GET(s);
    fx_mat_stack_mult(&s->r.model, m);
    return 0;
}

static int cmd_slide(fx_scene *sc)
{
    GET(s);
    fx16 v[3];
    TRY(args_fx(sc, v, 3));
    fx_camera_slide(&s->cam, v[0], v[1], v[2]);
    fx_camera_view(&s->cam, &s->r.view);
    return 0;
}

static int cam_turn(fx_scene *sc, void (*fn)(fx_camera *, fx_angle))
{
    GET(s);
    fx16 d;
    TRY(args_fx(sc, &d, 1));
    fn(&s->cam, fx_angle_from_deg16(d));
    fx_camera_view(&s->cam, &s->r.view);
    return 0;
}

static int cmd_roll(fx_scene *sc) { return cam_turn(sc, fx_camera_roll); }
static int cmd_pitch(fx_scene *sc) { return cam_turn(sc, fx_camera_pitch); }
static int cmd_yaw(fx_scene *sc) { return cam_turn(sc, fx_camera_yaw); }

static fx16 vp_aspect(const s3d *s)
{
    return fx16_from_ratio(s->r.viewport.x1 - s->r.viewport.x0, s->r.viewport.y1 - s->r.viewport.y0);
}

/* The script's 'pixelaspect' on the projection just loaded. */
static int apply_par(fx_scene *sc, s3d *s)
{
    int32_t n, d;
    fx_scene_pixel_aspect(sc, &n, &d);
    return n == d ? 0 : fx3d_pixel_aspect(&s->r, n, d);
}

static int cmd_perspective(fx_scene *sc)
{
    GET(s);
    fx16 v[3];
    TRY(args_fx(sc, v, 3));
    fx_angle fov = fx_angle_from_deg16(v[0]);
    if (v[0] <= 0 || v[0] >= 180 * FX16_ONE || fx3d_perspective(&s->r, fov, vp_aspect(s), v[1], v[2]) < 0)
        return fx_scene_error(sc, "perspective needs 0 < FOVY < 180 and 0 < NEAR < FAR");
    return apply_par(sc, s);
}

static int cmd_ortho(fx_scene *sc)
{
    GET(s);
    fx16 v[6];
    TRY(args_fx(sc, v, 6));
    if (fx3d_ortho(&s->r, v[0], v[1], v[2], v[3], v[4], v[5]) < 0)
        return fx_scene_error(sc, "ortho: empty view volume");
    return apply_par(sc, s);
}

static int cmd_oblique(fx_scene *sc)
{
    GET(s);
    static const char *const ch[] = {"cavalier", "cabinet", NULL};
    int c;
    TRY(c = fx_scene_arg_choice(sc, ch));
    fx16 v[8];
    for (int i = 0; i < 7; i++)
        TRY(fx_scene_arg_fx16(sc, &v[i]));
    v[7] = v[5];
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_fx16(sc, &v[7]));
    TRY(fx_scene_end(sc));
    if (fx3d_oblique(&s->r, v[1], v[2], v[3], v[4], v[5], v[6], fx_angle_from_deg16(v[0]),
                     c ? FX_OBLIQUE_CABINET : FX_OBLIQUE_CAVALIER, v[7]) < 0)
        return fx_scene_error(sc, "oblique: empty view volume");
    return apply_par(sc, s);
}

/* ---- model transforms ---- */

static int cmd_identity(fx_scene *sc)
{
    GET(s);
    TRY(fx_scene_end(sc));
    fx_mat4 m;
    fx_mat4_identity(&m);
    fx_mat_stack_load(&s->r.model, &m);
    return 0;
}

static int cmd_push(fx_scene *sc)
{
    GET(s);
    TRY(fx_scene_end(sc));
    if (fx_mat_stack_push(&s->r.model) < 0)
        return fx_scene_error(sc, "matrix stack full (32 levels)");
    return 0;
}

static int cmd_pop(fx_scene *sc)
{
    GET(s);
    TRY(fx_scene_end(sc));
    if (fx_mat_stack_pop(&s->r.model) < 0)
        return fx_scene_error(sc, "'pop3d' without a matching 'push3d'");
    return 0;
}

static int cmd_translate(fx_scene *sc)
{
    GET(s);
    fx16 v[3];
    TRY(args_fx(sc, v, 3));
    fx_mat4 m;
    fx_mat4_translate(&m, v[0], v[1], v[2]);
    fx_mat_stack_mult(&s->r.model, &m);
    return 0;
}

static int cmd_scale(fx_scene *sc)
{
    GET(s);
    fx16 v[3];
    TRY(fx_scene_arg_fx16(sc, &v[0]));
    v[1] = v[2] = v[0];
    if (fx_scene_more(sc)) {
        TRY(fx_scene_arg_fx16(sc, &v[1]));
        TRY(fx_scene_arg_fx16(sc, &v[2]));
    }
    TRY(fx_scene_end(sc));
    fx_mat4 m;
    fx_mat4_scale(&m, v[0], v[1], v[2]);
    fx_mat_stack_mult(&s->r.model, &m);
    return 0;
}

static int cmd_rotate(fx_scene *sc)
{
    GET(s);
    fx16 v[4];
    TRY(args_fx(sc, v, 4));
    fx_mat4 m;
    if (fx_mat4_rotate(&m, fx_angle_from_deg16(v[0]), fx_vec3_make(v[1], v[2], v[3])) < 0)
        return fx_scene_error(sc, "rotate: the axis is zero");
    fx_mat_stack_mult(&s->r.model, &m);
    return 0;
}

static int rot_axis(fx_scene *sc, void (*fn)(fx_mat4 *, fx_angle))
{
    GET(s);
    fx16 d;
    TRY(args_fx(sc, &d, 1));
    fx_mat4 m;
    fn(&m, fx_angle_from_deg16(d));
    fx_mat_stack_mult(&s->r.model, &m);
    return 0;
}

static int cmd_rotatex(fx_scene *sc) { return rot_axis(sc, fx_mat4_rotate_x); }
static int cmd_rotatey(fx_scene *sc) { return rot_axis(sc, fx_mat4_rotate_y); }
static int cmd_rotatez(fx_scene *sc) { return rot_axis(sc, fx_mat4_rotate_z); }

static int cmd_shear(fx_scene *sc)
{
    GET(s);
    fx16 v[2];
    TRY(args_fx(sc, v, 2));
    fx_mat4 m;
    fx_mat4_shear_z(&m, v[0], v[1]);
    fx_mat_stack_mult(&s->r.model, &m);
    return 0;
}

static int cmd_reflect(fx_scene *sc)
{
    GET(s);
    fx16 v[4];
    TRY(args_fx(sc, v, 4));
    fx_mat4 m;
    if (fx_mat4_reflect(&m, fx_vec3_make(v[0], v[1], v[2]), v[3]) < 0)
        return fx_scene_error(sc, "reflect: the plane normal is zero");
    fx_mat_stack_mult(&s->r.model, &m);
    return 0;
}

/* ---- lights, materials, modes ---- */

static int cmd_light(fx_scene *sc)
{
    GET(s);
    int32_t i;
    TRY(fx_scene_arg_int(sc, &i));
    if (i < 0 || i >= FX3D_MAX_LIGHTS)
        return fx_scene_error(sc, "light number %d out of range (0..%d)", i, FX3D_MAX_LIGHTS - 1);
    static const char *const ch[] = {"off", "directional", "point", "spot", NULL};
    int c;
    TRY(c = fx_scene_arg_choice(sc, ch));
    fx3d_light l;
    l.type = (fx3d_light_type)c;
    l.pos = l.spot_dir = fx_vec3_make(0, -FX16_ONE, 0);
    l.cutoff = FX_ANGLE_45;
    l.spot_exp = 0;
    fx_color col = 0xFFFFFF;
    if (c != 0) {
        fx16 v[3];
        for (int k = 0; k < 3; k++)
            TRY(fx_scene_arg_fx16(sc, &v[k]));
        l.pos = fx_vec3_make(v[0], v[1], v[2]);
        if (c == 3) {
            fx16 d[5];
            for (int k = 0; k < 5; k++)
                TRY(fx_scene_arg_fx16(sc, &d[k]));
            l.spot_dir = fx_vec3_make(d[0], d[1], d[2]);
            if (d[3] <= 0 || d[3] >= 90 * FX16_ONE || d[4] < 0 || d[4] > 128 * FX16_ONE)
                return fx_scene_error(sc, "spot needs 0 < CUTOFF < 90 and 0 <= EXPONENT <= 128");
            l.cutoff = fx_angle_from_deg16(d[3]);
            l.spot_exp = fx16_round(d[4]);
        }
        TRY(fx_scene_arg_color(sc, &col));
    }
    TRY(fx_scene_end(sc));
    if (c == 1 && l.pos.x == 0 && l.pos.y == 0 && l.pos.z == 0)
        return fx_scene_error(sc, "a directional light needs a non-zero direction");
    l.ambient = fx3d_rgb_from_color(0);
    l.diffuse = l.specular = fx3d_rgb_from_color(col);
    /* as glLight: a new position or colour keeps the attenuation */
    l.att_const = s->r.light[i].att_const;
    l.att_linear = s->r.light[i].att_linear;
    l.att_quad = s->r.light[i].att_quad;
    s->r.light[i] = l;
    return 0;
}

static int cmd_attenuation(fx_scene *sc)
{
    GET(s);
    int32_t i;
    fx16 k[3];
    TRY(fx_scene_arg_int(sc, &i));
    for (int j = 0; j < 3; j++)
        TRY(fx_scene_arg_fx16(sc, &k[j]));
    TRY(fx_scene_end(sc));
    if (i < 0 || i >= FX3D_MAX_LIGHTS)
        return fx_scene_error(sc, "light number %d out of range (0..%d)", i, FX3D_MAX_LIGHTS - 1);
    if (k[0] < 0 || k[1] < 0 || k[2] < 0)
        return fx_scene_error(sc, "attenuation factors must be >= 0");
    s->r.light[i].att_const = k[0];
    s->r.light[i].att_linear = k[1];
    s->r.light[i].att_quad = k[2];
    return 0;
}

static int cmd_ambient(fx_scene *sc)
{
    GET(s);
    fx_color c;
    TRY(fx_scene_arg_color(sc, &c));
    TRY(fx_scene_end(sc));
    s->r.ambient = fx3d_rgb_from_color(c);
    return 0;
}

static int cmd_material(fx_scene *sc)
{
    GET(s);
    fx_color a, d, sp, e = 0;
    int32_t sh;
    TRY(fx_scene_arg_color(sc, &a));
    TRY(fx_scene_arg_color(sc, &d));
    TRY(fx_scene_arg_color(sc, &sp));
    TRY(fx_scene_arg_int(sc, &sh));
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_color(sc, &e));
    TRY(fx_scene_end(sc));
    if (sh < 0 || sh > 128)
        return fx_scene_error(sc, "shininess %d out of range (0..128)", sh);
    fx3d_material *m = &s->r.mat;
    m->ambient = fx3d_rgb_from_color(a);
    m->diffuse = fx3d_rgb_from_color(d);
    m->specular = fx3d_rgb_from_color(sp);
    m->emission = fx3d_rgb_from_color(e);
    m->shininess = sh;
    return 0;
}

static int choice_cmd(fx_scene *sc, const char *const *ch, int *out)
{
    int c;
    TRY(c = fx_scene_arg_choice(sc, ch));
    TRY(fx_scene_end(sc));
    *out = c;
    return 0;
}

static int cmd_shading(fx_scene *sc)
{
    GET(s);
    /* in fx3d_shading's order: gouraudscan is FX3D_GOURAUD_SCAN */
    static const char *const ch[] = {"flat", "gouraud", "phong", "gouraudscan", NULL};
    int c;
    TRY(choice_cmd(sc, ch, &c));
    s->r.shading = (fx3d_shading)c;
    return 0;
}

static int cmd_cull(fx_scene *sc)
{
    GET(s);
    static const char *const ch[] = {"none", "back", "front", NULL};
    int c;
    TRY(choice_cmd(sc, ch, &c));
    s->r.cull = (fx3d_cull)c;
    return 0;
}

static int cmd_polygon(fx_scene *sc)
{
    GET(s);
    static const char *const ch[] = {"fill", "wire", "hidden", NULL};
    int c;
    TRY(choice_cmd(sc, ch, &c));
    s->r.polymode = (fx3d_polymode)c;
    return 0;
}

static int cmd_background(fx_scene *sc)
{
    GET(s);
    fx_color c;
    TRY(fx_scene_arg_color(sc, &c));
    TRY(fx_scene_end(sc));
    s->r.background = c;
    return 0;
}

/* ---- meshes ---- */

int fx_scene_mesh_alloc(fx_scene *sc, int32_t nv, int32_t nt, int want_uv, fx_mesh *m)
{
    s3d *s;
    TRY(get(sc, &s));
    if (nt > FX_SCENE_MAX_TRIANGLES)
        return fx_scene_error(sc, "%d triangles: more than the %d one command may draw", nt, FX_SCENE_MAX_TRIANGLES);
    size_t need = (size_t)nv * 2 * sizeof(fx_vec3) + (size_t)nt * 3 * sizeof(uint32_t);
    if (want_uv)
        need += (size_t)nv * 2 * sizeof(fx16);
    if (need > s->mesh_bytes) {
        /* on failure the smaller block stays: a later, smaller mesh uses it */
        void *mem = fx_scene_alloc(sc, need);
        if (!mem)
            return fx_scene_error(sc, "out of scene memory for a mesh of %d vertices", nv);
        s->mesh_mem = mem;
        s->mesh_bytes = need;
    }
    fx_mesh z = {0};
    *m = z;
    m->pos = s->mesh_mem;
    m->nrm = m->pos + nv;
    m->tri = (uint32_t *)(m->nrm + nv);
    m->cap_verts = nv;
    m->cap_tris = nt;
    m->uv = want_uv ? (fx16 *)(m->tri + 3 * (size_t)nt) : NULL;
    return 0;
}

int fx_scene_mesh_draw(fx_scene *sc, fx_mesh *m)
{
    s3d *s;
    TRY(get(sc, &s));
    s->r.ctx = fx_scene_screen_ctx(&sc->ctx);
    /* Each vertex transformed and lit once, not once per triangle (a band
     * of a frame on several threads repeats this part). The cache is
     * scratch: taken from the free arena for this draw only (zeroed: the
     * renderer's generation count starts anew) and given back after it, so
     * a script that fitted before still fits; without room for it the
     * pixels are the same, only slower. */
    size_t mark = sc->arena_used, need = fx3d_vertex_cache_bytes(m->nverts);
    void *mem = need ? fx_scene_alloc_raw(sc, need) : NULL; /* zeroed by fx3d_set_vertex_cache */
    if (mem)
        fx3d_set_vertex_cache(&s->r, mem, need);
    int rc = fx3d_draw(&s->r, m);
    if (mem) {
        fx3d_set_vertex_cache(&s->r, NULL, 0);
        sc->arena_used = mark;
    }
    return rc;
}

int fx_scene_object_view(fx_scene *sc, fx_vec3 *eye, int *parallel)
{
    s3d *s;
    TRY(get(sc, &s));
    fx_mat4 mv, inv;
    fx_mat4_mul(&mv, &s->r.view, fx_mat_stack_top(&s->r.model));
    if (fx_mat4_invert(&inv, &mv) < 0)
        return fx_scene_error(sc, "the model-view matrix has no inverse");
    *parallel = s->r.parallel;
    if (*parallel) {
        *eye = fx_mat4_apply_dir(&inv, fx_vec3_make(0, 0, -FX16_ONE));
    } else {
        fx_vec4 e = fx_mat4_apply_point(&inv, fx_vec3_make(0, 0, 0));
        *eye = fx_vec3_make(e.x, e.y, e.z);
    }
    return 0;
}

/* The mesh block for the shape p describes (sizes checked, not yet made). */
static int mesh_for(fx_scene *sc, s3d *s, const fx_mesh_params *p, fx_mesh *m)
{
    int32_t nv, nt;
    if (fx_mesh_size(p, &nv, &nt) < 0)
        return fx_scene_error(sc, "tessellation out of range");
    return fx_scene_mesh_alloc(sc, nv, nt, s->r.tex != 0, m);
}

static int draw_params(fx_scene *sc, s3d *s, const fx_mesh_params *p)
{
    fx_mesh m;
    TRY(mesh_for(sc, s, p, &m));
    TRY(fx_mesh_make(&m, p));
    return fx_scene_mesh_draw(sc, &m);
}

static int hull_away(void *u, const fx_vec3 *pts, int n) { return fx3d_hull_away(u, pts, n); }

/* The teapot without the patches that cannot reach the clip (a band of a
 * frame on several threads tessellates only its own). */
static int draw_teapot(fx_scene *sc, s3d *s, const fx_mesh_params *p)
{
    fx_mesh m;
    TRY(mesh_for(sc, s, p, &m));
    s->r.ctx = fx_scene_screen_ctx(&sc->ctx); /* the clip fx3d_draw will have */
    TRY(fx_mesh_make_teapot(&m, p->a, p->n, hull_away, &s->r));
    return fx_scene_mesh_draw(sc, &m);
}

static int mesh_cmd(fx_scene *sc, fx_mesh_kind kind, int nfx, int nint)
{
    GET(s);
    fx_mesh_params p = {kind, 0, 0, 0, 0, 0};
    fx16 *f[3] = {&p.a, &p.b, &p.c};
    int32_t *iv[2] = {&p.n, &p.k};
    for (int i = 0; i < nfx; i++)
        TRY(fx_scene_arg_fx16(sc, f[i]));
    for (int i = 0; i < nint; i++)
        TRY(fx_scene_arg_int(sc, iv[i]));
    TRY(fx_scene_end(sc));
    return kind == FX_MESH_TEAPOT ? draw_teapot(sc, s, &p) : draw_params(sc, s, &p);
}

static int cmd_cube(fx_scene *sc) { return mesh_cmd(sc, FX_MESH_CUBE, 1, 0); }
static int cmd_tetra(fx_scene *sc) { return mesh_cmd(sc, FX_MESH_TETRAHEDRON, 1, 0); }
static int cmd_octa(fx_scene *sc) { return mesh_cmd(sc, FX_MESH_OCTAHEDRON, 1, 0); }
static int cmd_dodeca(fx_scene *sc) { return mesh_cmd(sc, FX_MESH_DODECAHEDRON, 1, 0); }
static int cmd_icosa(fx_scene *sc) { return mesh_cmd(sc, FX_MESH_ICOSAHEDRON, 1, 0); }
static int cmd_sphere(fx_scene *sc) { return mesh_cmd(sc, FX_MESH_SPHERE, 1, 2); }
static int cmd_ellipsoid(fx_scene *sc) { return mesh_cmd(sc, FX_MESH_ELLIPSOID, 3, 2); }
static int cmd_torus(fx_scene *sc) { return mesh_cmd(sc, FX_MESH_TORUS, 2, 2); }
static int cmd_cone(fx_scene *sc) { return mesh_cmd(sc, FX_MESH_CONE, 2, 1); }
static int cmd_cylinder(fx_scene *sc) { return mesh_cmd(sc, FX_MESH_CYLINDER, 2, 1); }
static int cmd_teapot(fx_scene *sc) { return mesh_cmd(sc, FX_MESH_TEAPOT, 1, 1); }
static int cmd_floor(fx_scene *sc) { return mesh_cmd(sc, FX_MESH_PLANE, 1, 1); }

int fx_scene_obj_mesh(fx_scene *sc, fx_mesh *out)
{
    char path[256];
    TRY(fx_scene_arg_string(sc, path, sizeof path));
    TRY(fx_scene_end(sc));
    if (!sc->host.load_file)
        return fx_scene_error(sc, "files not available");
    const uint8_t *data;
    size_t len;
    int e = sc->host.load_file(sc->host.user, path, &data, &len);
    if (e < 0)
        return fx_scene_error(sc, "cannot read '%s': %s", path, fx_strerror(e));
    fx_obj_error err;
    int32_t nv, nt;
    if (fx_mesh_obj_size((const char *)data, len, &nv, &nt, &err) < 0)
        return fx_scene_error(sc, "%s: %s", path, err.msg);
    if (nt > FX_SCENE_MAX_TRIANGLES) /* the work bound: ~2 us per lit triangle */
        return fx_scene_error(sc, "%s: %d triangles, more than the %d one command may draw", path, nt,
                              FX_SCENE_MAX_TRIANGLES);
    size_t need = (size_t)nv * 2 * sizeof(fx_vec3) + (size_t)nt * 3 * sizeof(uint32_t);
    fx_vec3 *mem = fx_scene_alloc(sc, need);
    if (!mem)
        return fx_scene_error(sc, "out of scene memory for '%s' (%d vertices)", path, nv);
    fx_mesh m = {mem, mem + nv, (uint32_t *)(mem + 2 * nv), 0, 0, nv, nt, NULL, NULL};
    if (fx_mesh_obj_parse(&m, (const char *)data, len, &err) < 0)
        return fx_scene_error(sc, "%s: %s", path, err.msg);
    *out = m;
    return 0;
}

static int cmd_obj(fx_scene *sc)
{
    GET(s);
    fx_mesh m = {0};
    TRY(fx_scene_obj_mesh(sc, &m));
    s->r.ctx = fx_scene_screen_ctx(&sc->ctx);
    return fx3d_draw(&s->r, &m);
}

/* A convex polygon with a colour per vertex, e.g. the course's quad with
 * four colours, lit with the vertex colours as ambient and diffuse
 * reflectance (texture coordinates: none). */
static int cmd_polygon3d(fx_scene *sc)
{
    GET(s);
    fx_vec3 pos[16];
    uint32_t col[16], tri[3 * 14];
    int n = 0;
    while (fx_scene_more(sc)) {
        if (n == 16)
            return fx_scene_error(sc, "more than 16 vertices");
        fx16 v[3];
        for (int k = 0; k < 3; k++)
            TRY(fx_scene_arg_fx16(sc, &v[k]));
        TRY(fx_scene_arg_color(sc, &col[n]));
        pos[n++] = fx_vec3_make(v[0], v[1], v[2]);
    }
    if (n < 3)
        return fx_scene_error(sc, "polygon3d needs at least 3 vertices (X Y Z #RRGGBB each)");
    for (int i = 1; i + 1 < n; i++) {
        tri[3 * (i - 1)] = 0;
        tri[3 * (i - 1) + 1] = (uint32_t)i;
        tri[3 * (i - 1) + 2] = (uint32_t)i + 1;
    }
    fx_mesh m = {pos, NULL, tri, n, n - 2, n, n - 2, NULL, col};
    s->r.ctx = fx_scene_screen_ctx(&sc->ctx);
    return fx3d_draw(&s->r, &m);
}

/* ---- textures ---- */

static int cmd_texgen(fx_scene *sc)
{
    GET(s);
    static const char *const ch[] = {"off", "sphere", NULL};
    int c;
    TRY(c = fx_scene_arg_choice(sc, ch));
    TRY(fx_scene_end(sc));
    fx3d_sphere_map(&s->r, c);
    return 0;
}

static int cmd_solid3d(fx_scene *sc)
{
    GET(s);
    static const char *const ch[] = {"off", "wood", "marble", "checker", NULL};
    int c;
    TRY(c = fx_scene_arg_choice(sc, ch));
    fx_color c0 = 0, c1 = 0;
    fx16 scale = FX16_ONE;
    if (c != 0) {
        TRY(fx_scene_arg_color(sc, &c0));
        TRY(fx_scene_arg_color(sc, &c1));
        TRY(fx_scene_arg_fx16(sc, &scale));
        if (scale < FX16_ONE / 16 || scale > 64 * FX16_ONE)
            return fx_scene_error(sc, "scale out of range (0.0625..64)");
    }
    TRY(fx_scene_end(sc));
    /* the choice order is rt.h's: none, wood, marble, checker */
    fx3d_solid(&s->r, c, c0, c1, scale);
    return 0;
}

static int cmd_bump3d(fx_scene *sc)
{
    GET(s);
    fx16 h = 0, scale = FX16_ONE;
    int i = sc->pos;
    while (i < sc->len && (sc->text[i] == ' ' || sc->text[i] == '\t'))
        i++;
    if (i < sc->len && sc->text[i] == 'o') {
        static const char *const off[] = {"off", NULL};
        TRY(fx_scene_arg_choice(sc, off));
    } else {
        TRY(fx_scene_arg_fx16(sc, &h));
        TRY(fx_scene_arg_fx16(sc, &scale));
        if (h < 0 || h > FX16_ONE || scale < FX16_ONE / 16 || scale > 64 * FX16_ONE)
            return fx_scene_error(sc, "bump3d: HEIGHT 0..1, SCALE 0.0625..64");
    }
    TRY(fx_scene_end(sc));
    fx3d_bump(&s->r, h, scale);
    return 0;
}

/* frame3d off | frame3d brushed|spun STRENGTH SCALE (fx3d_frame) */
static int cmd_frame3d(fx_scene *sc)
{
    GET(s);
    static const char *const ch[] = {"off", "brushed", "spun", NULL};
    int kind;
    TRY(kind = fx_scene_arg_choice(sc, ch));
    fx16 k = 0, scale = FX16_ONE;
    if (kind) {
        TRY(fx_scene_arg_fx16(sc, &k));
        TRY(fx_scene_arg_fx16(sc, &scale));
        if (k < 0 || k > FX16_ONE || scale < FX16_ONE / 16 || scale > 64 * FX16_ONE)
            return fx_scene_error(sc, "frame3d: STRENGTH 0..1, SCALE 0.0625..64");
    }
    TRY(fx_scene_end(sc));
    /* the choice order is rt.h's fx_rt_frame_kind */
    fx3d_frame(&s->r, kind, k, scale);
    return 0;
}

/* The texture matrix stack (OpenGL's GL_TEXTURE mode): moves, turns and
 * tiles the textures of the meshes drawn next; see fx3d_texture_stack. */
static int cmd_texmatrix(fx_scene *sc)
{
    GET(s);
    static const char *const ch[] = {"identity", "push", "pop", "translate", "scale", "rotate", NULL};
    int c;
    TRY(c = fx_scene_arg_choice(sc, ch));
    fx16 v[2] = {0, 0};
    if (c == 3 || c == 5)
        TRY(fx_scene_arg_fx16(sc, &v[0]));
    if (c == 3)
        TRY(fx_scene_arg_fx16(sc, &v[1]));
    if (c == 4) {
        TRY(fx_scene_arg_fx16(sc, &v[0]));
        v[1] = v[0];
        if (fx_scene_more(sc))
            TRY(fx_scene_arg_fx16(sc, &v[1]));
    }
    TRY(fx_scene_end(sc));
    if (!s->r.texm.slot)
        fx3d_texture_stack(&s->r, s->tstack, 8);
    fx_mat_stack *t = &s->r.texm;
    fx_mat4 m;
    switch (c) {
    case 0: fx_mat4_identity(&m), fx_mat_stack_load(t, &m); break;
    case 1:
        if (fx_mat_stack_push(t) < 0)
            return fx_scene_error(sc, "texture matrix stack full (8 levels)");
        break;
    case 2:
        if (fx_mat_stack_pop(t) < 0)
            return fx_scene_error(sc, "'texmatrix pop' without a matching 'texmatrix push'");
        break;
    case 3: fx_mat4_translate(&m, v[0], v[1], 0), fx_mat_stack_mult(t, &m); break;
    case 4: fx_mat4_scale(&m, v[0], v[1], FX16_ONE), fx_mat_stack_mult(t, &m); break;
    default: fx_mat4_rotate_z(&m, fx_angle_from_deg16(v[0])), fx_mat_stack_mult(t, &m); break;
    }
    return 0;
}

/* Bind the 2D module's current texture (the 'texture' command) to the
 * meshes drawn next; later 'texture filter|wrap' lines apply to it too. */
static int cmd_texture3d(fx_scene *sc)
{
    GET(s);
    static const char *const ch[] = {"modulate", "replace", "decal", "off", NULL};
    int c;
    TRY(c = fx_scene_arg_choice(sc, ch));
    TRY(fx_scene_end(sc));
    if (c == 3) {
        fx3d_texture(&s->r, NULL, FX3D_TEX_MODULATE);
        return 0;
    }
    const fx_texture *tx = fx_scene_texture(sc);
    if (!tx)
        return fx_scene_error(sc, "no texture yet (use 'texture' first)");
    fx3d_texture(&s->r, tx, (fx3d_texmode)c);
    return 0;
}

/* ---- shadows ---- */

static int cmd_shadowplane(fx_scene *sc)
{
    GET(s);
    if (fx_scene_more(sc)) {
        char w[64];
        int save = sc->pos;
        if (fx_scene_arg_word(sc, w, sizeof w) >= 0 && w[0] == 'o' && w[1] == 'f' && w[2] == 'f' && !w[3]) {
            TRY(fx_scene_end(sc));
            fx3d_plane_shadow_off(&s->r);
            return 0;
        }
        sc->pos = save;
    }
    fx16 p[4];
    for (int i = 0; i < 4; i++)
        TRY(fx_scene_arg_fx16(sc, &p[i]));
    int32_t li;
    fx_color c;
    TRY(fx_scene_arg_int(sc, &li));
    TRY(fx_scene_arg_color(sc, &c));
    TRY(fx_scene_end(sc));
    if (li < 0 || li >= FX3D_MAX_LIGHTS)
        return fx_scene_error(sc, "light number %d out of range (0..%d)", li, FX3D_MAX_LIGHTS - 1);
    fx3d_plane_shadow(&s->r, p, li, c);
    return 0;
}

static int cmd_shadowmap(fx_scene *sc)
{
    GET(s);
    static const char *const ch[] = {"begin", "end", "off", NULL};
    int c;
    TRY(c = fx_scene_arg_choice(sc, ch));
    if (c != 0) {
        TRY(fx_scene_end(sc));
        if (c == 1) {
            if (!s->r.sm || !s->nsm)
                return fx_scene_error(sc, "'shadowmap end' without 'shadowmap begin'");
            if (s->nsm == 1) {
                fx3d_shadow_end(&s->r);
            } else {
                fx3d_shadowmap *maps[FX3D_MAX_SHADOWS];
                for (int i = 0; i < s->nsm; i++)
                    maps[i] = &s->sm[i];
                TRY(fx3d_shadow_use(&s->r, maps, s->nsm));
            }
        } else {
            fx3d_shadow_off(&s->r);
            s->nsm = 0;
        }
        s->sm_filling = 0;
        return 0;
    }
    int32_t size, li;
    fx16 v[6];
    TRY(fx_scene_arg_int(sc, &size));
    TRY(fx_scene_arg_int(sc, &li));
    TRY(args_fx(sc, v, 6));
    if (size < 16 || size > 4096)
        return fx_scene_error(sc, "shadow map size %d out of range (16..4096)", size);
    if (li < 0 || li >= FX3D_MAX_LIGHTS || s->r.light[li].type == FX3D_LIGHT_OFF ||
        s->r.light[li].type == FX3D_LIGHT_DIRECTIONAL)
        return fx_scene_error(sc, "the shadow map needs a point or spot light");
    if (!s->sm_filling)
        s->nsm = 0; /* a new set of maps */
    int k = 0;
    while (k < s->nsm && s->sm[k].light != li)
        k++; /* a light's second map replaces its first */
    if (k == FX3D_MAX_SHADOWS)
        return fx_scene_error(sc, "more than %d shadow maps at once (one per light)", FX3D_MAX_SHADOWS);
    if (size > s->smsize[k]) {
        s->smbuf[k] = fx_scene_alloc(sc, (size_t)size * (size_t)size * 4);
        if (!s->smbuf[k])
            return fx_scene_error(sc, "out of scene memory for a %dx%d shadow map", size, size);
        s->smsize[k] = size;
    }
    fx3d_shadow_init(&s->sm[k], s->smbuf[k], size, li);
    if (v[3] <= 0 || v[3] >= 180 * FX16_ONE ||
        fx3d_shadow_aim(&s->sm[k], s->r.light[li].pos, fx_vec3_make(v[0], v[1], v[2]),
                        fx_angle_from_deg16(v[3]), v[4], v[5]) < 0)
        return fx_scene_error(sc, "shadowmap: bad aim (target = light, or bad FOV/NEAR/FAR)");
    if (k == s->nsm)
        s->nsm++;
    s->sm_filling = 1;
    fx3d_shadow_begin(&s->r, &s->sm[k]);
    return 0;
}

/* The course's multi-pass lighting (fx3d_pass). */
static int cmd_pass3d(fx_scene *sc)
{
    GET(s);
    static const char *const ch[] = {"off", "ambient", "light", NULL};
    int c;
    TRY(c = fx_scene_arg_choice(sc, ch));
    int32_t li = 0;
    fx16 dim = 0;
    if (c == 2)
        TRY(fx_scene_arg_int(sc, &li));
    if (c == 1 && fx_scene_more(sc)) /* the notes' dim diffuse, issue #44 */
        TRY(fx_scene_arg_fx16(sc, &dim));
    TRY(fx_scene_end(sc));
    if (c == 2 && (li < 0 || li >= FX3D_MAX_LIGHTS))
        return fx_scene_error(sc, "light number %d out of range (0..%d)", li, FX3D_MAX_LIGHTS - 1);
    if (c == 1 && dim)
        return fx3d_pass_ambient_dim(&s->r, dim) < 0 ? fx_scene_error(sc, "DIM out of range (0..1)") : 0;
    if (fx3d_pass(&s->r, c == 0 ? FX3D_PASS_ALL : c == 1 ? FX3D_PASS_AMBIENT : FX3D_PASS_LIGHT, li) < 0)
        return fx_scene_error(sc, "pass3d light needs the depth buffer ('depth 16|32'), not the painter's sort");
    return 0;
}

#define D FX_SCENE_DRAWS
const fx_scene_cmd fx_scene_cmds_3d[] = {
    {"viewport3d", cmd_viewport, "viewport3d X Y W H", D},
    {"depth", cmd_depth, "depth 16|32|off", D},
    {"cleardepth", cmd_cleardepth, "cleardepth", D},
    {"painter", cmd_painter, "painter [MAXTRIANGLES]", D},
    {"flush", cmd_flush, "flush", D},
    {"camera", cmd_camera, "camera EX EY EZ LX LY LZ UX UY UZ", D},
    {"slide", cmd_slide, "slide DU DV DN", D},
    {"roll", cmd_roll, "roll DEG", D},
    {"pitch", cmd_pitch, "pitch DEG", D},
    {"yaw", cmd_yaw, "yaw DEG", D},
    {"perspective", cmd_perspective, "perspective FOVY NEAR FAR", D},
    {"ortho", cmd_ortho, "ortho L R B T NEAR FAR", D},
    {"oblique", cmd_oblique, "oblique cavalier|cabinet ALPHA L R B T NEAR FAR [PLANE]", D},
    {"identity3d", cmd_identity, "identity3d", D},
    {"push3d", cmd_push, "push3d", D},
    {"pop3d", cmd_pop, "pop3d", D},
    {"translate3d", cmd_translate, "translate3d X Y Z", D},
    {"scale3d", cmd_scale, "scale3d S | scale3d SX SY SZ", D},
    {"rotate3d", cmd_rotate, "rotate3d DEG AX AY AZ", D},
    {"rotatex", cmd_rotatex, "rotatex DEG", D},
    {"rotatey", cmd_rotatey, "rotatey DEG", D},
    {"rotatez", cmd_rotatez, "rotatez DEG", D},
    {"shear3d", cmd_shear, "shear3d A B", D},
    {"reflect3d", cmd_reflect, "reflect3d NX NY NZ D", D},
    {"light", cmd_light,
     "light I off | directional DX DY DZ #RGB | point X Y Z #RGB | spot X Y Z DX DY DZ CUTOFF EXP #RGB", D},
    {"ambient", cmd_ambient, "ambient #RRGGBB", D},
    {"material", cmd_material, "material #AMB #DIFF #SPEC SHININESS [#EMISSION]", D},
    {"shading", cmd_shading,
     "shading flat|gouraud|phong|gouraudscan   (gouraudscan: the notes' scan-line Gouraud, along each face's edges "
     "then across the span; gouraud splits faces into triangles)",
     D},
    {"cull", cmd_cull, "cull none|back|front", D},
    {"polymode", cmd_polygon, "polymode fill|wire|hidden", D},
    {"background", cmd_background, "background #RRGGBB", D},
    {"cube", cmd_cube, "cube EDGE", D},
    {"tetrahedron", cmd_tetra, "tetrahedron RADIUS", D},
    {"octahedron", cmd_octa, "octahedron RADIUS", D},
    {"dodecahedron", cmd_dodeca, "dodecahedron RADIUS", D},
    {"icosahedron", cmd_icosa, "icosahedron RADIUS", D},
    {"sphere", cmd_sphere, "sphere R SLICES STACKS", D},
    {"ellipsoid", cmd_ellipsoid, "ellipsoid RX RY RZ SLICES STACKS", D},
    {"torus", cmd_torus, "torus R r SIDES RINGS", D},
    {"cone", cmd_cone, "cone R H SLICES", D},
    {"cylinder", cmd_cylinder, "cylinder R H SLICES", D},
    {"teapot", cmd_teapot, "teapot SIZE N", D},
    {"floor", cmd_floor, "floor SIZE N", D},
    {"obj", cmd_obj, "obj \"FILE\"", D},
    {"shadowplane", cmd_shadowplane, "shadowplane A B C D LIGHT #RGB | shadowplane off", D},
    {"polygon3d", cmd_polygon3d, "polygon3d X0 Y0 Z0 #C0 X1 Y1 Z1 #C1 X2 Y2 Z2 #C2 ... (convex, <= 16)", D},
    {"texgen", cmd_texgen, "texgen sphere|off", D},
    {"alpha3d", cmd_alpha3d, "alpha3d OPACITY [MAXTRIANGLES]", D},
    {"texmatrix", cmd_texmatrix,
     "texmatrix identity|push|pop | texmatrix translate S T | texmatrix scale SS [ST] | texmatrix rotate DEG", D},
    {"solid3d", cmd_solid3d, "solid3d wood|marble|checker #C0 #C1 SCALE | solid3d off", D},
    {"bump3d", cmd_bump3d, "bump3d HEIGHT SCALE | bump3d off", D},
    {"frame3d", cmd_frame3d, "frame3d brushed|spun STRENGTH SCALE | frame3d off   (Phong: anisotropic highlights)", D},
    {"attenuation", cmd_attenuation, "attenuation LIGHT KC KL KQ", D},
    {"texture3d", cmd_texture3d, "texture3d modulate|replace|decal | texture3d off", D},
    {"shadowmap", cmd_shadowmap, "shadowmap begin SIZE LIGHT TX TY TZ FOV NEAR FAR | shadowmap end | shadowmap off", D},
    {"pass3d", cmd_pass3d,
     "pass3d ambient [DIM] | pass3d light LIGHT | pass3d off   (DIM: the share of each light's diffuse the ambient "
     "pass adds, the notes' dim diffuse in shadow; the light passes add the rest)",
     D},
    {0, 0, 0, 0},
};
