/* SPDX-License-Identifier: MIT */
/* fixel — the 3D pipeline: per-triangle transform and lighting, homogeneous
 * clipping, integer perspective division and a depth-buffered triangle
 * rasterizer with depth, colour, normal and position interpolation.
 * All drawing of 3D primitives to the surface happens in this file. */
#include "fixel/render3d.h"
#include "fixel/error.h"
#include "fixel/rt.h"
#include "../base/fx_internal.h"

static inline fx16 neg_sat(fx16 v) { return v == INT32_MIN ? INT32_MAX : -v; }

/* Interpolated attributes after the depth: 0-2 colour (or normal for Phong),
 * 3-5 the colour without the shadow light (or eye position for Phong), 6-8
 * the light's screen position and depth for the shadow buffer, 12-14 the
 * vertex colour under Phong shading, 9-11 the texture: s, t (Q16.16) up to projection, then per triangle q, (s - s0) q
 * and (t - t0) q for perspective-correct interpolation (see tex_setup). */
#define A_COL 0
#define A_POS 3
#define A_SM  6
#define A_TEX 9
#define A_VCOL 12 /* Phong with vertex colours: the colour, interpolated */
#define A_OBJ 15  /* solid textures: the object-space point / scale */
/* Several shadow maps (fx3d_shadow_use): map k >= 1 has its light-space
 * position and depth at A_SMK + 3 (k - 1) and, under Gouraud, the colour
 * without its light at A_WOK + 3 (k - 1) (map 0 keeps A_SM and A_POS). Only
 * triangles drawn with more than one map carry them (na = NA). */
#define A_SMK 18
#define A_WOK (A_SMK + 3 * (FX3D_MAX_SHADOWS - 1))
#define NA (A_WOK + 3 * (FX3D_MAX_SHADOWS - 1))

typedef struct cvert { /* clip space */
    int32_t c[4];      /* x, y, z, w in Q16.16 */
    int32_t a[NA];
} cvert;

typedef struct svert { /* screen space */
    int32_t x, y;      /* 24.8, integer values at pixel centres */
    int32_t z;         /* depth, 0 (near) .. 2^30 (far) */
    int32_t w;         /* clip w (Q16.16, > 0), for perspective-correct textures */
    int32_t a[NA];
} svert;

enum { K_DEPTH, K_FLAT, K_GOURAUD, K_PHONG };

/* Eye-space lights, prepared once per draw. */
typedef struct elight {
    int type;
    fx_vec3 pos, dir;
    fx16 cos_cut;
    int32_t exp;
    fx3d_rgb amb, diff, spec;
    int atten;
    fx16 kc, kl, kq;
} elight;

/* What one triangle needs in the rasterizer. */
typedef struct tri_mode {
    uint8_t kind, na, ztest, zwrite;
    uint8_t use_sm;      /* shadow maps tested per pixel (pctx.smv) */
    uint8_t outline;     /* 0 fill, 1 fill and edges, 2 edges only, 3 fill pushed back */
    uint8_t lines_ztest; /* edges depth-tested */
    uint8_t tex;         /* textured: attributes A_TEX.. carry s, t */
    uint8_t vcol;        /* Phong with vertex colours in A_VCOL.. */
    uint8_t solid;       /* solid texture from A_OBJ.. */
    uint8_t bump;        /* Phong normals tilted by the bumps at A_OBJ.. */
    uint8_t frame;       /* Phong highlights along the frame map at A_OBJ.. (fx3d_frame) */
    uint8_t blend, alpha; /* translucent (fx3d_alpha): blended over with alpha 0..254;
                           * blend 2: added with saturation (fx3d_pass) */
    int32_t zbias;
    fx_color flat[2]; /* lit, shadowed (one map) */
    fx3d_rgb flat_full, flat_wo[FX3D_MAX_SHADOWS]; /* flat, several maps */
    /* The texture and solid texture as they were when the triangle was
     * emitted: the painter draws at flush time, after a script may have
     * switched them (or the texture off). */
    const fx_texture *tx;
    uint8_t tex_mode;
    int8_t solid_kind;
    fx_color solid_c[2];
    fx16 obj_scale;         /* A_OBJ holds the object point / obj_scale */
    fx16 bump_h, bump_s;    /* fx3d_bump */
    fx16 bnm[3][3];         /* the normal matrix, for the height's gradient */
    int8_t frame_kind;      /* fx3d_frame */
    fx16 frame_k, frame_s;
    fx16 fmv[3][3];         /* the model-view's linear part: tangents go to eye space by it */
} tri_mode;

/* A face drawn with the notes' scan-line Gouraud (FX3D_GOURAUD_SCAN): its
 * clipped, projected corners (24.8) and their colours (Q16.16), which the
 * rasterizer interpolates along the edges, then across the span, instead of
 * over the triangle. A projected face has at most FX3D_SCAN_MAX_VERTS + 6
 * corners (one more per clip plane). */
#define SCAN_MAXC (FX3D_SCAN_MAX_VERTS + 6)
typedef struct scanpoly {
    int n;
    int32_t x[SCAN_MAXC], y[SCAN_MAXC];
    int32_t c[SCAN_MAXC][3];
} scanpoly;

typedef struct pctx { /* per-draw state */
    fx3d *r;
    const fx_surface *s;
    fx_rect clip;
    void *zb;
    int zbits;
    int32_t zstride;
    int32_t vx, vy, vw, vh; /* viewport */
    int32_t guard;          /* G of the guard band */
    elight el[FX3D_MAX_LIGHTS];
    int nl;
    fx_color wire;
    const fx3d_shadowmap *sm;                   /* smv[0] */
    const fx3d_shadowmap *smv[FX3D_MAX_SHADOWS]; /* maps in use */
    int nsm;
    uint32_t dmask; /* lights whose diffuse and specular this pass adds */
    int amb;        /* whether it adds the ambient terms and emission */
    fx16 kd_in;     /* the share of their diffuse it adds (1 - dim in a light pass after a dim ambient one) */
    fx16 kd_out;    /* the share of the other lights' diffuse (the ambient pass's dim diffuse) */
    const scanpoly *scan; /* the face of the triangles being drawn, under FX3D_GOURAUD_SCAN */
} pctx;

typedef struct ptri { /* a triangle kept for the painter's sort */
    svert v[3];
    tri_mode m;
    int64_t key;
} ptri;

/* ------------------------------------------------------------------ */
/* colour                                                               */

fx3d_rgb fx3d_rgb_from_color(fx_color c)
{
    fx3d_rgb o;
    o.r = fx16_from_ratio((c >> 16) & 255, 255);
    o.g = fx16_from_ratio((c >> 8) & 255, 255);
    o.b = fx16_from_ratio(c & 255, 255);
    return o;
}

static uint32_t chan8(fx16 v)
{
    if (v <= 0)
        return 0;
    if (v >= FX16_ONE)
        return 255;
    return (uint32_t)(((int64_t)v * 255 + 0x8000) >> 16);
}

fx_color fx3d_rgb_to_color(fx3d_rgb c)
{
    return 0xFF000000u | chan8(c.r) << 16 | chan8(c.g) << 8 | chan8(c.b);
}

static fx3d_rgb rgb_mul(fx3d_rgb a, fx3d_rgb b)
{
    fx3d_rgb o = {fx16_mul(a.r, b.r), fx16_mul(a.g, b.g), fx16_mul(a.b, b.b)};
    return o;
}

static void rgb_madd(fx3d_rgb *acc, fx3d_rgb a, fx16 s)
{
    acc->r = fx_sat32((int64_t)acc->r + fx16_mul(a.r, s));
    acc->g = fx_sat32((int64_t)acc->g + fx16_mul(a.g, s));
    acc->b = fx_sat32((int64_t)acc->b + fx16_mul(a.b, s));
}


/* ------------------------------------------------------------------ */
/* lighting                                                             */

static void prepare_lights(const fx3d *r, elight *el, int *nl)
{
    int n = 0;
    for (int i = 0; i < FX3D_MAX_LIGHTS; i++) {
        const fx3d_light *l = &r->light[i];
        elight *e = &el[i];
        e->type = l->type;
        if (l->type == FX3D_LIGHT_OFF)
            continue;
        n = i + 1;
        if (l->type == FX3D_LIGHT_DIRECTIONAL) {
            e->pos = fx_mat4_apply_dir(&r->view, l->pos);
            fx_vec3_normalize(&e->pos);
        } else {
            fx_vec4 p = fx_mat4_apply_point(&r->view, l->pos);
            e->pos = fx_vec3_make(p.x, p.y, p.z);
        }
        e->dir = fx_mat4_apply_dir(&r->view, l->spot_dir);
        fx_vec3_normalize(&e->dir);
        e->cos_cut = fx_cos(l->cutoff);
        e->exp = l->spot_exp;
        e->amb = l->ambient;
        e->diff = l->diffuse;
        e->spec = l->specular;
        e->kc = l->att_const > 0 ? l->att_const : 0;
        e->kl = l->att_linear > 0 ? l->att_linear : 0;
        e->kq = l->att_quad > 0 ? l->att_quad : 0;
        e->atten = l->type != FX3D_LIGHT_DIRECTIONAL && (e->kc | e->kl | e->kq) != 0;
    }
    *nl = n;
}

/* The lighting model of render3d.h at eye-space point P with unit normal
 * N: the diffuse and specular terms of the lights in dmask, and with amb
 * the ambient terms and emission (both: the whole model). vcol, when given, is the vertex colour that stands
 * for the material's ambient and diffuse reflectance (glColorMaterial's
 * GL_AMBIENT_AND_DIFFUSE). */
static fx3d_rgb shade_m(const fx3d *r, const elight *el, int nl, fx_vec3 P, fx_vec3 N, uint32_t dmask, int amb,
                        const fx3d_rgb *vcol, fx16 kd_in, fx16 kd_out, const fx_vec3 *ft, fx16 fk)
{
    fx3d_material mc;
    const fx3d_material *m = &r->mat;
    if (vcol) {
        mc = r->mat;
        mc.ambient = mc.diffuse = *vcol;
        m = &mc;
    }
    fx3d_rgb acc = {0, 0, 0};
    if (amb) {
        acc = m->emission;
        fx3d_rgb ga = rgb_mul(r->ambient, m->ambient);
        rgb_madd(&acc, ga, FX16_ONE);
    }
    fx_vec3 V = fx_vec3_make(0, 0, FX16_ONE);
    int have_v = r->parallel;
    for (int i = 0; i < nl; i++) {
        const elight *e = &el[i];
        if (e->type == FX3D_LIGHT_OFF)
            continue;
        fx_vec3 L = e->pos;
        fx16 sf = FX16_ONE;
        if (e->type != FX3D_LIGHT_DIRECTIONAL) {
            L = fx_vec3_sub(e->pos, P);
            if (e->atten) {
                /* 1 / (kc + kl d + kq d^2) in Q16, the denominator in Q32 */
                int64_t d = fx_vec3_length(L);
                int64_t q = ((int64_t)e->kq * d) >> 16; /* kq d, Q16: below 2^42 */
                int64_t den = ((int64_t)e->kc << 16) + (int64_t)e->kl * d;
                den = q && d > (INT64_MAX / 2) / q ? INT64_MAX / 2 : den + q * d;
                if (den <= 0)
                    continue;
                int64_t a = ((int64_t)1 << 48) / den;
                sf = a > INT32_MAX ? INT32_MAX : (fx16)a;
            }
            if (fx_vec3_normalize(&L) < 0)
                continue;
        }
        if (e->type == FX3D_LIGHT_SPOT) {
            fx16 sd = -fx_vec3_dot(L, e->dir);
            if (sd < e->cos_cut)
                continue;
            sf = fx16_mul(sf, fx16_powi(sd, e->exp));
        }
        fx3d_rgb c = {0, 0, 0};
        if (amb)
            c = rgb_mul(e->amb, m->ambient);
        fx16 ndl = fx_vec3_dot(N, L);
        if (ndl > 0 && !(dmask >> i & 1) && kd_out > 0) /* the notes' dim diffuse in the ambient pass */
            rgb_madd(&c, rgb_mul(e->diff, m->diffuse), fx16_mul(ndl, kd_out));
        if (ndl > 0 && (dmask >> i & 1)) {
            rgb_madd(&c, rgb_mul(e->diff, m->diffuse), kd_in == FX16_ONE ? ndl : fx16_mul(ndl, kd_in));
            if (m->specular.r | m->specular.g | m->specular.b) {
                if (!have_v) {
                    V = fx_vec3_make(fx_sat32(-(int64_t)P.x), fx_sat32(-(int64_t)P.y),
                                     fx_sat32(-(int64_t)P.z)); /* P may sit at INT32_MIN */
                    if (fx_vec3_normalize(&V) < 0)
                        V = fx_vec3_make(0, 0, FX16_ONE);
                    have_v = 1;
                }
                fx_vec3 R = fx_vec3_sub(fx_vec3_scale(N, 2 * ndl), L);
                fx16 rv = fx_vec3_dot(R, V);
                fx16 sp = 0;
                if (rv > 0) {
                    if (rv > FX16_ONE)
                        rv = FX16_ONE;
                    sp = fx16_powi(rv, m->shininess);
                }
                if (ft) { /* frame mapping: Kajiya-Kay's highlight about H (rt.h) */
                    fx_vec3 H = fx_vec3_add(L, V);
                    if (fx_vec3_normalize(&H) == 0)
                        sp = fx_rt_aniso_spec(sp, fk, *ft, H, ndl, m->shininess);
                }
                if (rv > 0 || ft)
                    rgb_madd(&c, rgb_mul(e->spec, m->specular), sp);
            }
        }
        rgb_madd(&acc, c, sf);
    }
    return acc;
}

/* The terms this draw adds (pc->dmask, pc->amb), without the diffuse and
 * specular of the lights in `skip` (a mask). */
static fx3d_rgb pshade(const pctx *pc, fx_vec3 P, fx_vec3 N, uint32_t skip, const fx3d_rgb *vcol)
{
    return shade_m(pc->r, pc->el, pc->nl, P, N, pc->dmask & ~skip, pc->amb, vcol, pc->kd_in, pc->kd_out, NULL, 0);
}

/* pshade with frame mapping's tangent ft (unit, eye space) of strength fk */
static fx3d_rgb pshade_frame(const pctx *pc, fx_vec3 P, fx_vec3 N, uint32_t skip, const fx3d_rgb *vcol,
                             const fx_vec3 *ft, fx16 fk)
{
    return shade_m(pc->r, pc->el, pc->nl, P, N, pc->dmask & ~skip, pc->amb, vcol, pc->kd_in, pc->kd_out, ft, fk);
}

fx3d_rgb fx3d_shade(const fx3d *r, fx_vec3 eye_pos, fx_vec3 eye_normal)
{
    elight el[FX3D_MAX_LIGHTS];
    int nl;
    prepare_lights(r, el, &nl);
    return shade_m(r, el, nl, eye_pos, eye_normal, ~0u, 1, NULL, FX16_ONE, 0, NULL, 0);
}

/* ------------------------------------------------------------------ */
/* set-up                                                               */

int fx3d_init(fx3d *r, const fx_surface *s, fx_mat4 *model_stack, int model_cap,
              fx_mat4 *proj_stack, int proj_cap)
{
    fx_memset(r, 0, sizeof *r);
    int e = fx_mat_stack_init(&r->model, model_stack, model_cap);
    if (e < 0)
        return e;
    e = fx_mat_stack_init(&r->proj, proj_stack, proj_cap);
    if (e < 0)
        return e;
    fx_ctx_init(&r->ctx, s);
    r->viewport = fx_surface_rect(s);
    fx_mat4_identity(&r->view);
    r->shading = FX3D_GOURAUD;
    r->cull = FX3D_CULL_BACK;
    r->polymode = FX3D_FILL;
    r->visibility = FX3D_VIS_NONE;
    r->alpha = 255;
    r->background = 0xFF000000u;
    r->light[0].type = FX3D_LIGHT_DIRECTIONAL;
    r->light[0].pos = fx_vec3_make(0, 0, FX16_ONE);
    r->light[0].diffuse = fx3d_rgb_from_color(0xFFFFFF);
    r->light[0].specular = fx3d_rgb_from_color(0xFFFFFF);
    r->ambient = fx3d_rgb_from_color(0x333333);
    r->mat.ambient = fx3d_rgb_from_color(0xC0C0C0);
    r->mat.diffuse = fx3d_rgb_from_color(0xC0C0C0);
    r->mat.specular = fx3d_rgb_from_color(0x808080);
    r->mat.shininess = 32;
    return 0;
}

void fx3d_viewport(fx3d *r, int32_t x, int32_t y, int32_t w, int32_t h)
{
    /* the far edge saturates: x + w overflowed for x near INT32_MAX (issue #26) */
    fx_rect v = {x, y, fx_sat32((int64_t)x + (w > 0 ? w : 1)), fx_sat32((int64_t)y + (h > 0 ? h : 1))};
    r->viewport = v;
}

size_t fx3d_depth_bytes(const fx_surface *s, int bits)
{
    return (size_t)s->w * (size_t)s->h * (bits == 16 ? 2u : 4u);
}

void fx3d_clear_depth(fx3d *r)
{
    if (!r->depth)
        return;
    int32_t y0 = 0, y1 = r->ctx.surf.h;
    if (r->depth_y1 > r->depth_y0) {
        y0 = FX_MAX(y0, r->depth_y0);
        y1 = FX_MIN(y1, r->depth_y1);
        if (y1 <= y0)
            return;
    }
    size_t row = (size_t)r->ctx.surf.w * (r->depth_bits == 16 ? 2u : 4u);
    fx_memset((uint8_t *)r->depth + row * (size_t)y0, 0xFF, row * (size_t)(y1 - y0));
}

/* One vertex of the cache: valid in the draw numbered gen; its normal in
 * ngen (nok: it normalized, so it does not fall back to the face's); its
 * Gouraud colour seen from the front (lgen[0]) and from behind (lgen[1]). */
typedef struct vcent {
    uint32_t gen, ngen, lgen[2];
    int32_t c[4];
    fx_vec3 ep, n;
    int32_t nok;
    fx3d_rgb col[2];
} vcent;

/* The alignment render3d.h promises callers is enough for the entries. */
_Static_assert(_Alignof(vcent) <= FX3D_VERTEX_CACHE_ALIGN,
               "vcent needs more than FX3D_VERTEX_CACHE_ALIGN");

size_t fx3d_vertex_cache_bytes(int32_t nverts)
{
    size_t n = (size_t)(nverts > 0 ? nverts : 0);
    return n > SIZE_MAX / sizeof(vcent) ? SIZE_MAX : n * sizeof(vcent); /* 32-bit size_t */
}

void fx3d_set_vertex_cache(fx3d *r, void *mem, size_t bytes)
{
    /* misaligned memory: no cache rather than misaligned loads (undefined,
     * and a fault on some cores) */
    int ok = mem && ((uintptr_t)mem & (FX3D_VERTEX_CACHE_ALIGN - 1)) == 0;
    size_t n = ok ? bytes / sizeof(vcent) : 0;
    r->vcache = n ? mem : NULL;
    r->vcache_n = n > INT32_MAX ? INT32_MAX : (int32_t)n;
    r->vcache_gen = 0;
    if (n)
        fx_memset(mem, 0, n * sizeof(vcent));
}

void fx3d_depth_rows(fx3d *r, int32_t y0, int32_t y1)
{
    r->depth_y0 = y0;
    r->depth_y1 = y1;
}

int fx3d_set_depth(fx3d *r, void *buf, int bits)
{
    if (buf && bits != 16 && bits != 32)
        return -FX_EINVAL;
    r->depth = buf;
    r->depth_bits = buf ? bits : 0;
    if (buf) {
        r->visibility = FX3D_VIS_DEPTH;
        fx3d_clear_depth(r);
    } else if (r->visibility == FX3D_VIS_DEPTH) {
        r->visibility = FX3D_VIS_NONE;
    }
    return 0;
}

size_t fx3d_painter_bytes(int32_t ntris) { return (size_t)(ntris > 0 ? ntris : 0) * sizeof(ptri); }

int fx3d_set_painter(fx3d *r, void *mem, size_t bytes)
{
    if (!mem || bytes < sizeof(ptri))
        return -FX_EINVAL;
    r->pbuf = mem;
    r->pcap = (int32_t)FX_MIN(bytes / sizeof(ptri), (size_t)INT32_MAX);
    r->pcount = 0;
    r->pdropped = 0;
    r->visibility = FX3D_VIS_PAINTER;
    return 0;
}

int fx3d_perspective(fx3d *r, fx_angle fovy, fx16 aspect, fx16 zn, fx16 zf)
{
    fx_mat4 m;
    int e = fx_mat4_perspective(&m, fovy, aspect, zn, zf);
    if (e < 0)
        return e;
    fx_mat_stack_load(&r->proj, &m);
    r->parallel = 0;
    return 0;
}

int fx3d_pixel_aspect(fx3d *r, int32_t num, int32_t den)
{
    return fx_mat4_pixel_aspect(fx_mat_stack_top(&r->proj), num, den);
}

int fx3d_ortho(fx3d *r, fx16 l, fx16 rt, fx16 b, fx16 t, fx16 zn, fx16 zf)
{
    fx_mat4 m;
    int e = fx_mat4_ortho(&m, l, rt, b, t, zn, zf);
    if (e < 0)
        return e;
    fx_mat_stack_load(&r->proj, &m);
    r->parallel = 1;
    return 0;
}

int fx3d_oblique(fx3d *r, fx16 l, fx16 rt, fx16 b, fx16 t, fx16 zn, fx16 zf, fx_angle alpha,
                 fx16 len, fx16 plane)
{
    fx_mat4 m;
    int e = fx_mat4_oblique(&m, l, rt, b, t, zn, zf, alpha, len, plane);
    if (e < 0)
        return e;
    fx_mat_stack_load(&r->proj, &m);
    r->parallel = 1;
    return 0;
}

void fx3d_texture(fx3d *r, const fx_texture *tx, fx3d_texmode mode)
{
    r->tex = tx;
    r->tex_mode = mode;
}

void fx3d_sphere_map(fx3d *r, int on) { r->tex_sphere_map = on != 0; }

int fx3d_texture_stack(fx3d *r, fx_mat4 *mem, int cap)
{
    return fx_mat_stack_init(&r->texm, mem, cap);
}

void fx3d_tex_coord(const fx3d *r, fx16 s, fx16 t, fx16 out[2])
{
    out[0] = s, out[1] = t;
    if (!r->texm.slot)
        return;
    const fx_mat4 *m = &r->texm.slot[r->texm.top];
    fx_vec4 v = fx_mat4_apply(m, (fx_vec4){s, t, 0, FX16_ONE});
    out[0] = v.x, out[1] = v.y;
    /* Projective texture matrices only: q == 1 exactly for the affine ones,
     * so those keep the single rounding of the product. */
    if (v.w > 0 && v.w != FX16_ONE) {
        out[0] = fx_sat32(((int64_t)v.x * 65536 + (v.x < 0 ? -(v.w / 2) : v.w / 2)) / v.w);
        out[1] = fx_sat32(((int64_t)v.y * 65536 + (v.y < 0 ? -(v.w / 2) : v.w / 2)) / v.w);
    }
}

/* The sphere map's (s, t) for eye-space point P with unit normal N. */
static void sphere_st(fx_vec3 P, fx_vec3 N, int parallel, int32_t *st)
{
    fx_vec3 u = parallel ? fx_vec3_make(0, 0, -FX16_ONE) : P;
    if (!parallel && fx_vec3_normalize(&u) < 0)
        u = fx_vec3_make(0, 0, -FX16_ONE);
    fx16 nu = fx_vec3_dot(N, u);
    fx_vec3 rr = fx_vec3_sub(u, fx_vec3_scale(N, 2 * nu));
    int64_t rz1 = (int64_t)rr.z + FX16_ONE;
    uint64_t sq = (uint64_t)((int64_t)rr.x * rr.x + (int64_t)rr.y * rr.y + rz1 * rz1); /* Q32 */
    int64_t m = 2 * (int64_t)fx_isqrt64(sq); /* Q16 */
    if (m < 1) { /* r = (0, 0, -1): the map's rim */
        st[0] = st[1] = FX16_HALF;
        return;
    }
    st[0] = (int32_t)((int64_t)rr.x * 65536 / m + FX16_HALF);
    st[1] = (int32_t)((int64_t)rr.y * 65536 / m + FX16_HALF);
}

void fx3d_solid(fx3d *r, int kind, fx_color c0, fx_color c1, fx16 scale)
{
    r->solid = kind;
    r->solid_c0 = c0;
    r->solid_c1 = c1;
    r->solid_scale = scale > 0 ? scale : FX16_ONE;
}

void fx3d_bump(fx3d *r, fx16 height, fx16 scale)
{
    r->bump = height > 0 ? FX_MIN(height, FX16_ONE) : 0;
    r->bump_scale = FX_MIN(FX_MAX(scale, FX16_ONE / 16), 64 * FX16_ONE);
}

/* The eye-space normal N (unit) of a bumped surface at texture point A_OBJ:
 * the height's object-space gradient goes to eye space like a normal (it
 * is a covector), then N loses its tangential part. */
/* The object point at A_OBJ (stored / obj_scale), in the units of a map
 * whose cell is `scale` (the bump or frame map's own scale). */
static fx_vec3 map_point(const tri_mode *m, const int64_t *val, fx16 scale)
{
    int64_t q[3];
    for (int i = 0; i < 3; i++) {
        q[i] = val[1 + A_OBJ + i] >> 16;
        if (m->obj_scale != scale) /* the solid texture's scale */
            q[i] = q[i] * m->obj_scale / scale;
    }
    return fx_vec3_make(fx_sat32(q[0]), fx_sat32(q[1]), fx_sat32(q[2]));
}
/* M v for a Q16.16 3x3 matrix, unsaturated (callers saturate) */
static void mat3_apply(const fx16 M[3][3], fx_vec3 v, int64_t e[3])
{
    for (int i = 0; i < 3; i++)
        e[i] = ((int64_t)M[i][0] * v.x + (int64_t)M[i][1] * v.y + (int64_t)M[i][2] * v.z) >> 16;
}

static fx_vec3 bump_normal(const tri_mode *m, const int64_t *val, fx_vec3 N)
{
    fx_vec3 g = fx_rt_bump_gradient(m->bump_h, m->bump_s, map_point(m, val, m->bump_s));
    int64_t e[3];
    mat3_apply(m->bnm, g, e);
    int64_t gn = (e[0] * N.x + e[1] * N.y + e[2] * N.z) >> 16;
    fx_vec3 o = fx_vec3_make(fx_sat32(N.x - e[0] + ((gn * N.x) >> 16)), fx_sat32(N.y - e[1] + ((gn * N.y) >> 16)),
                             fx_sat32(N.z - e[2] + ((gn * N.z) >> 16)));
    if (fx_vec3_normalize(&o) < 0)
        return N;
    return o;
}

void fx3d_frame(fx3d *r, int kind, fx16 strength, fx16 scale)
{
    r->frame = kind == FX_RT_FRAME_BRUSHED || kind == FX_RT_FRAME_SPUN ? kind : FX_RT_FRAME_NONE;
    r->frame_k = strength > 0 ? FX_MIN(strength, FX16_ONE) : 0;
    r->frame_scale = FX_MIN(FX_MAX(scale, FX16_ONE / 16), 64 * FX16_ONE);
}

/* The eye-space tangent of the frame map at texture point A_OBJ and unit
 * eye-space normal N: the map's object-space grain direction goes to eye
 * space like a position's difference (by the model-view), then loses its
 * normal part (fx_rt_frame). */
static fx_vec3 frame_tangent(const tri_mode *m, const int64_t *val, fx_vec3 N)
{
    fx_vec3 d = fx_rt_frame_dir(m->frame_kind, map_point(m, val, m->frame_s));
    int64_t e[3];
    mat3_apply(m->fmv, d, e);
    fx_vec3 t, b;
    fx_rt_frame(fx_vec3_make(fx_sat32(e[0]), fx_sat32(e[1]), fx_sat32(e[2])), N, &t, &b);
    return t;
}

void fx3d_plane_shadow(fx3d *r, const fx16 plane[4], int light, fx_color c)
{
    for (int i = 0; i < 4; i++)
        r->plane[i] = plane[i];
    r->plane_light = light;
    r->plane_color = c;
    r->plane_shadow = light >= 0 && light < FX3D_MAX_LIGHTS;
}

void fx3d_plane_shadow_off(fx3d *r) { r->plane_shadow = 0; }

int fx3d_shadow_init(fx3d_shadowmap *sm, uint32_t *depth, int32_t size, int light)
{
    if (!depth || size < 1 || size > 8192 || light < 0 || light >= FX3D_MAX_LIGHTS)
        return -FX_EINVAL;
    sm->depth = depth;
    sm->size = size;
    sm->light = light;
    sm->bias = 1u << 21;
    fx_mat4_identity(&sm->view_proj);
    return 0;
}

int fx3d_shadow_aim(fx3d_shadowmap *sm, fx_vec3 from, fx_vec3 at, fx_angle fov, fx16 zn, fx16 zf)
{
    fx_camera c;
    fx_vec3 up = fx_vec3_make(0, FX16_ONE, 0);
    if (fx_camera_set(&c, from, at, up) < 0 &&
        fx_camera_set(&c, from, at, fx_vec3_make(0, 0, FX16_ONE)) < 0)
        return -FX_EDOM;
    fx_mat4 v, p;
    int e = fx_mat4_perspective(&p, fov, FX16_ONE, zn, zf);
    if (e < 0)
        return e;
    fx_camera_view(&c, &v);
    fx_mat4_mul(&sm->view_proj, &p, &v);
    return 0;
}

void fx3d_shadow_begin(fx3d *r, fx3d_shadowmap *sm)
{
    r->sm = sm;
    r->sm_phase = 1;
    fx_memset(sm->depth, 0xFF, (size_t)sm->size * (size_t)sm->size * 4);
}

void fx3d_shadow_end(fx3d *r)
{
    if (r->sm) {
        r->sm_phase = 2;
        r->sm_use[0] = r->sm;
        r->sm_n = 1;
    }
}

void fx3d_shadow_off(fx3d *r)
{
    r->sm = NULL;
    r->sm_phase = 0;
    r->sm_n = 0;
}

int fx3d_shadow_use(fx3d *r, fx3d_shadowmap *const *maps, int n)
{
    if (!maps || n < 1 || n > FX3D_MAX_SHADOWS)
        return -FX_EINVAL;
    for (int i = 0; i < n; i++) {
        if (!maps[i] || !maps[i]->depth || maps[i]->light < 0 || maps[i]->light >= FX3D_MAX_LIGHTS)
            return -FX_EINVAL;
        for (int j = 0; j < i; j++)
            if (maps[j]->light == maps[i]->light)
                return -FX_EINVAL;
    }
    for (int i = 0; i < n; i++)
        r->sm_use[i] = maps[i];
    r->sm_n = n;
    r->sm = maps[0];
    r->sm_phase = 2;
    return 0;
}

int fx3d_pass(fx3d *r, int kind, int light)
{
    if (kind < FX3D_PASS_ALL || kind > FX3D_PASS_LIGHT ||
        (kind == FX3D_PASS_LIGHT && (light < 0 || light >= FX3D_MAX_LIGHTS)))
        return -FX_EINVAL;
    /* a light pass tests depth against the ambient pass's buffer; the
     * painter's sort has none and would light hidden triangles too */
    if (kind == FX3D_PASS_LIGHT && r->visibility == FX3D_VIS_PAINTER)
        return -FX_ENOTSUP;
    r->pass = kind;
    r->pass_light = kind == FX3D_PASS_LIGHT ? light : 0;
    if (kind != FX3D_PASS_LIGHT)
        r->pass_dim = 0; /* a light pass keeps the dim share of the ambient pass before it */
    return 0;
}

int fx3d_pass_ambient_dim(fx3d *r, fx16 dim)
{
    if (dim < 0 || dim > FX16_ONE)
        return -FX_EINVAL;
    int e = fx3d_pass(r, FX3D_PASS_AMBIENT, 0);
    if (e < 0)
        return e;
    r->pass_dim = dim;
    return 0;
}

/* ------------------------------------------------------------------ */
/* rasterizer                                                           */

static int64_t floor_div(int64_t a, int64_t b) /* b > 0 */
{
    int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

static int64_t ceil_div(int64_t a, int64_t b) /* b > 0 */
{
    return -floor_div(-a, b);
}

/* Per-pixel step of a quantity q over the triangle, with 16 fraction
 * bits: the plane through (x_i, y_i, q_i). Gradients beyond 2^45 (a sliver
 * narrower than the attribute's resolution) report failure. */
#define GRAD_LIMIT ((int64_t)1 << 45)

typedef struct plane_set {
    int n;                /* 1 + attributes */
    int64_t base[1 + NA]; /* value at pixel (bx, by), 16 fraction bits */
    int64_t gx[1 + NA], gy[1 + NA];
    int32_t bx, by;
} plane_set;

static void setup_planes(plane_set *ps, const svert *v0, const svert *v1, const svert *v2, int na,
                         int64_t area2)
{
    int64_t dx1 = (int64_t)v1->x - v0->x, dy1 = (int64_t)v1->y - v0->y;
    int64_t dx2 = (int64_t)v2->x - v0->x, dy2 = (int64_t)v2->y - v0->y;
    /* Keep 31 significant bits of the area for the reciprocal. */
    int sh = 0;
    while ((area2 >> sh) >= ((int64_t)1 << 31))
        sh++;
    int64_t inv = ((int64_t)1 << 62) / (area2 >> sh);
    ps->n = 1 + na;
    ps->bx = (int32_t)(((int64_t)v0->x + 128) >> 8);
    ps->by = (int32_t)(((int64_t)v0->y + 128) >> 8);
    int64_t ox = (int64_t)ps->bx * 256 - v0->x, oy = (int64_t)ps->by * 256 - v0->y;
    int flat = 0;
    for (int k = 0; k < ps->n; k++) {
        int64_t q0 = k ? v0->a[k - 1] : v0->z, q1 = k ? v1->a[k - 1] : v1->z,
                q2 = k ? v2->a[k - 1] : v2->z;
        int64_t d1 = q1 - q0, d2 = q2 - q0;
        /* dq/dx = (d1 dy2 - d2 dy1) / area2, per 24.8 unit; times 2^24
         * gives 16 fraction bits per pixel. */
        int64_t nx = (d1 * dy2 - d2 * dy1) >> sh, ny = (d2 * dx1 - d1 * dx2) >> sh;
        int64_t gx = fx_mul64_shift(nx, inv, 38), gy = fx_mul64_shift(ny, inv, 38);
        if (gx > GRAD_LIMIT || gx < -GRAD_LIMIT || gy > GRAD_LIMIT || gy < -GRAD_LIMIT) {
            flat = 1; /* the base below would overflow; the flat set replaces it all */
            break;
        }
        ps->gx[k] = gx;
        ps->gy[k] = gy;
        ps->base[k] = q0 * 65536 + ((gx * ox + gy * oy) >> 8);
    }
    if (flat)
        for (int k = 0; k < ps->n; k++) {
            int64_t q0 = k ? v0->a[k - 1] : v0->z, q1 = k ? v1->a[k - 1] : v1->z,
                    q2 = k ? v2->a[k - 1] : v2->z;
            ps->gx[k] = ps->gy[k] = 0;
            ps->base[k] = (q0 + q1 + q2) * 65536 / 3;
        }
}

static inline int sm_shadowed(const fx3d_shadowmap *sm, const int64_t *val, int at)
{
    int32_t lx = (int32_t)((val[1 + at] >> 16) + 128) >> 8;
    int32_t ly = (int32_t)((val[1 + at + 1] >> 16) + 128) >> 8;
    if (lx < 0 || ly < 0 || lx >= sm->size || ly >= sm->size)
        return 0;
    int64_t d = val[1 + at + 2] >> 16;
    return d > (int64_t)sm->depth[(size_t)ly * (size_t)sm->size + (size_t)lx] + sm->bias;
}

/* Which of the maps in use shadow the pixel: bit k for map k. A triangle
 * kept for fx3d_flush may outlive its maps (shadows turned off before the
 * flush): only the maps still in use are looked at. */
static inline uint32_t sm_mask(const pctx *pc, const tri_mode *m, const int64_t *val)
{
    uint32_t sh = 0;
    for (int k = 0; k < m->use_sm && k < pc->nsm; k++)
        if (sm_shadowed(pc->smv[k], val, k ? A_SMK + 3 * (k - 1) : A_SM))
            sh |= 1u << k;
    return sh;
}

/* full - sum over the maps in sh of (full - without map k's light): the
 * colour without the shadowed lights (exact: the lights' terms were summed
 * without rounding between them). */
static fx3d_rgb sm_remove(fx3d_rgb full, const fx3d_rgb *wo, uint32_t sh)
{
    int64_t c[3] = {full.r, full.g, full.b};
    for (int k = 0; sh; k++, sh >>= 1)
        if (sh & 1) {
            c[0] -= (int64_t)full.r - wo[k].r;
            c[1] -= (int64_t)full.g - wo[k].g;
            c[2] -= (int64_t)full.b - wo[k].b;
        }
    fx3d_rgb o = {fx_sat32(c[0]), fx_sat32(c[1]), fx_sat32(c[2])};
    return o;
}

/* The light mask of the maps in sh. */
static uint32_t sm_lights(const pctx *pc, uint32_t sh)
{
    uint32_t l = 0;
    for (int k = 0; sh; k++, sh >>= 1)
        if (sh & 1)
            l |= 1u << pc->smv[k]->light;
    return l;
}

/* The surface's colour plus c, per channel, saturating at 255. */
static uint32_t add_sat(fx_format f, uint32_t dst, fx_color c)
{
    fx_color d = fx_unpack(f, dst);
    uint32_t o = 0xFF000000u;
    for (int sh = 0; sh < 24; sh += 8) {
        uint32_t v = ((d >> sh) & 255) + ((c >> sh) & 255);
        o |= (v > 255 ? 255 : v) << sh;
    }
    return fx_pack(f, o);
}

static void put_px(const fx_surface *s, uint8_t *row, int32_t x, int32_t y, uint32_t native)
{
    switch (s->format) {
    case FX_FMT_XRGB8888:
    case FX_FMT_ARGB8888:
    case FX_FMT_XBGR8888:
        ((uint32_t *)row)[x] = native;
        break;
    case FX_FMT_RGB565:
    case FX_FMT_BGR565:
        ((uint16_t *)row)[x] = (uint16_t)native;
        break;
    default:
        fx_surface_put_native(s, x, y, native);
        break;
    }
}

/* The textured triangle's attributes A_TEX.. become q = w_min / w in Q22
 * and (s - s0) q, (t - t0) q with s0, t0 vertex 0's coordinates: both are
 * affine in screen space, so the planes interpolate them exactly and
 * s = s0 + ((s - s0) q) / q per pixel is perspective-correct. Relative to
 * s0, the products fit 31 bits unless s spans more than 2^9 units across
 * the triangle, where q's scale drops to keep them in range. */
static void tex_setup(svert *o, const svert *const v[3], int32_t st0[2])
{
    int32_t wmin = v[0]->w;
    for (int i = 1; i < 3; i++)
        wmin = FX_MIN(wmin, v[i]->w);
    int64_t span = 0;
    for (int i = 1; i < 3; i++)
        for (int k = 0; k < 2; k++) {
            int64_t d = (int64_t)v[i]->a[A_TEX + k] - v[0]->a[A_TEX + k];
            span = FX_MAX(span, d < 0 ? -d : d);
        }
    int qbits = 22;
    while (qbits > 8 && (span << qbits) >= ((int64_t)1 << 46))
        qbits--;
    st0[0] = v[0]->a[A_TEX];
    st0[1] = v[0]->a[A_TEX + 1];
    for (int i = 0; i < 3; i++) {
        o[i] = *v[i];
        int64_t q = ((int64_t)wmin << qbits) / (v[i]->w > 0 ? v[i]->w : 1);
        q = q < 1 ? 1 : q;
        int64_t ds = (int64_t)v[i]->a[A_TEX] - st0[0], dt = (int64_t)v[i]->a[A_TEX + 1] - st0[1];
        o[i].a[A_TEX] = (int32_t)q;
        o[i].a[A_TEX + 1] = (int32_t)((ds * q) >> 16);
        o[i].a[A_TEX + 2] = (int32_t)((dt * q) >> 16);
    }
}

static fx_color modulate(fx_color col, fx_color tc)
{
    uint32_t out = 0xFF000000u;
    for (int sh = 0; sh < 24; sh += 8)
        out |= ((((col >> sh) & 255) * ((tc >> sh) & 255) + 127) / 255) << sh;
    return out;
}

/* The texel at the pixel whose planes hold val, combined with the lit
 * colour col as m->tex_mode says. */
static fx_color tex_apply(const tri_mode *m, const int64_t *val, const int32_t st0[2], fx_color col)
{
    int64_t q = val[1 + A_TEX];
    q = q < 1 ? 1 : q;
    int64_t s = st0[0] + fx_mul64_shift(val[1 + A_TEX + 1], ((int64_t)1 << 62) / q, 46);
    int64_t t = st0[1] + fx_mul64_shift(val[1 + A_TEX + 2], ((int64_t)1 << 62) / q, 46);
    fx_color tc = fx_tex_sample(m->tx, fx_sat32(s), fx_sat32(t));
    if (m->tex_mode == FX3D_TEX_REPLACE)
        return tc | 0xFF000000u;
    if (m->tex_mode != FX3D_TEX_DECAL)
        return modulate(col, tc);
    uint32_t out = 0xFF000000u;
    uint32_t ta = tc >> 24;
    for (int sh = 0; sh < 24; sh += 8) {
        uint32_t c = (col >> sh) & 255, x = (tc >> sh) & 255;
        out |= ((c * (255 - ta) + x * ta + 127) / 255) << sh;
    }
    return out;
}

/* round(n / d) for d > 0, halves away from zero */
static int64_t div_round(int64_t n, int64_t d) { return n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d); }

/* One row of a scan-line Gouraud face: the leftmost and rightmost crossings
 * of the row with the face's edges (16 fraction bits of a pixel) and the
 * colours there, interpolated along those edges. */
typedef struct scanrow {
    int ok;
    int64_t xl, xr;
    int64_t cl[3], cr[3];
} scanrow;

/* Colours beyond +-256.0 (lit far past white) are clamped so that the
 * products below stay in int64; they show as white or black either way. */
static int64_t clamp_c(int64_t c) { return c < -(1 << 24) ? -(1 << 24) : c > (1 << 24) ? (1 << 24) : c; }

static void scan_row(const scanpoly *p, int32_t y, scanrow *r)
{
    int64_t py = (int64_t)y * 256;
    r->ok = 0;
    for (int i = 0; i < p->n; i++) {
        int j = i + 1 == p->n ? 0 : i + 1;
        int64_t ya = p->y[i], yb = p->y[j];
        /* a row through a horizontal edge meets its ends on the edges beside it */
        if (ya == yb || py < FX_MIN(ya, yb) || py > FX_MAX(ya, yb))
            continue;
        int64_t dy = yb - ya, t = py - ya;
        int64_t x = (int64_t)p->x[i] * 256 + div_round(((int64_t)p->x[j] - p->x[i]) * t * 256, dy);
        int64_t c[3];
        for (int k = 0; k < 3; k++) {
            int64_t ca = clamp_c(p->c[i][k]), cb = clamp_c(p->c[j][k]);
            c[k] = ca + div_round((cb - ca) * t, dy);
        }
        if (!r->ok || x < r->xl) {
            r->xl = x;
            for (int k = 0; k < 3; k++)
                r->cl[k] = c[k];
        }
        if (!r->ok || x > r->xr) {
            r->xr = x;
            for (int k = 0; k < 3; k++)
                r->cr[k] = c[k];
        }
        r->ok = 1;
    }
}

/* The colour at pixel centre x of the row, across the span. */
static fx3d_rgb scan_at(const scanrow *r, int64_t x)
{
    int64_t w = r->xr - r->xl, t = x * 65536 - r->xl;
    t = t < 0 ? 0 : t > w ? w : t;
    while (w >= ((int64_t)1 << 30)) {
        w >>= 1;
        t >>= 1;
    }
    int64_t c[3];
    for (int k = 0; k < 3; k++)
        c[k] = w > 0 ? r->cl[k] + div_round((r->cr[k] - r->cl[k]) * t, w) : r->cl[k];
    fx3d_rgb o = {fx_sat32(c[0]), fx_sat32(c[1]), fx_sat32(c[2])};
    return o;
}

/* Fill triangle v0 v1 v2 (either orientation) with mode m. */
static void raster_tri(const pctx *pc, const svert *v0, const svert *v1, const svert *v2,
                       const tri_mode *m)
{
    svert tv[3];
    int32_t st0[2] = {0, 0};
    if (m->tex) {
        const svert *vv[3] = {v0, v1, v2};
        tex_setup(tv, vv, st0);
        v0 = &tv[0], v1 = &tv[1], v2 = &tv[2];
    }
    int64_t area2 = ((int64_t)v1->x - v0->x) * ((int64_t)v2->y - v0->y) -
                    ((int64_t)v2->x - v0->x) * ((int64_t)v1->y - v0->y);
    if (area2 == 0)
        return;
    if (area2 < 0) {
        const svert *t = v1;
        v1 = v2;
        v2 = t;
        area2 = -area2;
    }
    /* Edge functions E(p) = A (px - xa) + B (py - ya), >= 0 inside. Ties
     * (E == 0) count for left edges (A > 0) and top edges (A == 0, B > 0). */
    const svert *ea[3] = {v1, v2, v0}, *eb[3] = {v2, v0, v1};
    int64_t A[3], B[3], C[3];
    for (int i = 0; i < 3; i++) {
        A[i] = -((int64_t)eb[i]->y - ea[i]->y);
        B[i] = (int64_t)eb[i]->x - ea[i]->x;
        int tl = A[i] > 0 || (A[i] == 0 && B[i] > 0);
        C[i] = -A[i] * ea[i]->x - B[i] * ea[i]->y - (tl ? 0 : 1);
    }
    int32_t miny = FX_MIN(FX_MIN(v0->y, v1->y), v2->y), maxy = FX_MAX(FX_MAX(v0->y, v1->y), v2->y);
    int32_t minx = FX_MIN(FX_MIN(v0->x, v1->x), v2->x), maxx = FX_MAX(FX_MAX(v0->x, v1->x), v2->x);
    int32_t y0 = (int32_t)ceil_div(miny, 256), y1 = (int32_t)floor_div(maxy, 256);
    int32_t bx0 = (int32_t)ceil_div(minx, 256), bx1 = (int32_t)floor_div(maxx, 256);
    y0 = FX_MAX(y0, pc->clip.y0);
    y1 = FX_MIN(y1, pc->clip.y1 - 1);
    bx0 = FX_MAX(bx0, pc->clip.x0);
    bx1 = FX_MIN(bx1, pc->clip.x1 - 1);
    if (y0 > y1 || bx0 > bx1)
        return;

    plane_set ps;
    setup_planes(&ps, v0, v1, v2, m->na, area2);
    int64_t zbias = m->zbias;
    if (m->outline == 1 || m->outline == 3) {
        /* Hidden-line faces are pushed back by their depth slope plus a
         * constant (glPolygonOffset(1, 1)), so that their own edges, drawn
         * on rounded pixel positions, stay in front of them. */
        int64_t gx = ps.gx[0] < 0 ? -ps.gx[0] : ps.gx[0], gy = ps.gy[0] < 0 ? -ps.gy[0] : ps.gy[0];
        zbias -= ((gx > gy ? gx : gy) >> 16) + (1 << 12);
    }
    const fx_surface *s = pc->s;
    for (int32_t y = y0; y <= y1; y++) {
        int64_t py = (int64_t)y * 256;
        int64_t xl = bx0, xr = bx1;
        for (int i = 0; i < 3; i++) {
            /* A (256 X) + (B py + C) >= 0 */
            int64_t a = A[i] * 256, c = B[i] * py + C[i];
            if (a > 0)
                xl = FX_MAX(xl, ceil_div(-c, a));
            else if (a < 0)
                xr = FX_MIN(xr, floor_div(c, -a));
            else if (c < 0)
                xr = xl - 1;
        }
        if (xl > xr)
            continue;
        scanrow srow = {0, 0, 0, {0, 0, 0}, {0, 0, 0}};
        if (pc->scan && m->kind == K_GOURAUD)
            scan_row(pc->scan, y, &srow);
        int64_t val[1 + NA];
        for (int k = 0; k < ps.n; k++)
            val[k] = ps.base[k] + ps.gx[k] * (xl - ps.bx) + ps.gy[k] * (y - ps.by);
        uint8_t *row = s ? fx_row(s, y) : NULL;
        uint32_t *z32 = pc->zbits == 32 ? (uint32_t *)pc->zb + (size_t)y * (size_t)pc->zstride : NULL;
        uint16_t *z16 = pc->zbits == 16 ? (uint16_t *)pc->zb + (size_t)y * (size_t)pc->zstride : NULL;
        for (int64_t x = xl; x <= xr; x++) {
            int64_t zz = (val[0] >> 16) - zbias;
            uint32_t z = zz < 0 ? 0 : zz > ((int64_t)1 << 30) ? (1u << 30) : (uint32_t)zz;
            int pass = 1;
            if (z32) {
                if (m->ztest == 2 ? z != z32[x] : m->ztest && z >= z32[x])
                    pass = 0;
                else if (m->zwrite)
                    z32[x] = z;
            } else if (z16) {
                uint16_t z1 = (uint16_t)FX_MIN(z >> 14, 0xFFFEu);
                if (m->ztest == 2 ? z1 != z16[x] : m->ztest && z1 >= z16[x])
                    pass = 0;
                else if (m->zwrite)
                    z16[x] = z1;
            }
            if (pass && m->kind != K_DEPTH) {
                uint32_t sh = m->use_sm ? sm_mask(pc, m, val) : 0;
                fx_color col;
                if (m->kind == K_FLAT) {
                    col = m->use_sm > 1 && sh ? fx3d_rgb_to_color(sm_remove(m->flat_full, m->flat_wo, sh))
                                              : m->flat[sh != 0];
                } else if (m->kind == K_GOURAUD) {
                    int o = 1 + (sh && m->use_sm == 1 ? A_POS : A_COL);
                    fx3d_rgb c = {(fx16)(val[o] >> 16), (fx16)(val[o + 1] >> 16), (fx16)(val[o + 2] >> 16)};
                    if (srow.ok) /* the face's colour (no shadow maps: see fx3d_draw) */
                        c = scan_at(&srow, x);
                    if (m->use_sm > 1 && sh) {
                        fx3d_rgb wo[FX3D_MAX_SHADOWS];
                        for (int k = 0; k < m->use_sm; k++) {
                            int ok = 1 + (k ? A_WOK + 3 * (k - 1) : A_POS);
                            wo[k].r = (fx16)(val[ok] >> 16);
                            wo[k].g = (fx16)(val[ok + 1] >> 16);
                            wo[k].b = (fx16)(val[ok + 2] >> 16);
                        }
                        c = sm_remove(c, wo, sh);
                    }
                    col = fx3d_rgb_to_color(c);
                } else {
                    fx_vec3 N = fx_vec3_make((fx16)(val[1] >> 16), (fx16)(val[2] >> 16), (fx16)(val[3] >> 16));
                    fx_vec3 P = fx_vec3_make((fx16)(val[4] >> 16), (fx16)(val[5] >> 16), (fx16)(val[6] >> 16));
                    fx_vec3_normalize(&N);
                    if (m->bump)
                        N = bump_normal(m, val, N);
                    fx3d_rgb vc = {(fx16)(val[1 + A_VCOL] >> 16), (fx16)(val[2 + A_VCOL] >> 16),
                                   (fx16)(val[3 + A_VCOL] >> 16)};
                    if (m->frame) {
                        fx_vec3 ft = frame_tangent(m, val, N);
                        col = fx3d_rgb_to_color(
                            pshade_frame(pc, P, N, sm_lights(pc, sh), m->vcol ? &vc : NULL, &ft, m->frame_k));
                    } else {
                        col = fx3d_rgb_to_color(pshade(pc, P, N, sm_lights(pc, sh), m->vcol ? &vc : NULL));
                    }
                }
                if (m->tex)
                    col = tex_apply(m, val, st0, col);
                if (m->solid) {
                    fx_vec3 q = fx_vec3_make((fx16)(val[1 + A_OBJ] >> 16), (fx16)(val[2 + A_OBJ] >> 16),
                                             (fx16)(val[3 + A_OBJ] >> 16));
                    fx16 w = fx_rt_solid(m->solid_kind, q);
                    col = modulate(col, fx_color_lerp(m->solid_c[0], m->solid_c[1], w));
                }
                if (m->blend == 2)
                    put_px(s, row, (int32_t)x, y, add_sat(s->format, fx_surface_get_native(s, (int32_t)x, y), col));
                else if (m->blend)
                    put_px(s, row, (int32_t)x, y,
                           fx_blend_over(s->format, fx_surface_get_native(s, (int32_t)x, y),
                                         (col & 0xFFFFFFu) | (uint32_t)m->alpha << 24));
                else
                    put_px(s, row, (int32_t)x, y, fx_pack(s->format, col));
            }
            for (int k = 0; k < ps.n; k++)
                val[k] += ps.gx[k];
        }
    }
}

/* A depth-interpolated line between two screen vertices (rounded to pixel
 * centres), lighting max(|dx|, |dy|) + 1 pixels like fx_line; depth-tested
 * with a small tolerance so that edges win over the faces they bound. */
static void raster_line(const pctx *pc, const svert *a, const svert *b, int ztest, fx_color col)
{
    int32_t x0 = (int32_t)(((int64_t)a->x + 128) >> 8), y0 = (int32_t)(((int64_t)a->y + 128) >> 8);
    int32_t x1 = (int32_t)(((int64_t)b->x + 128) >> 8), y1 = (int32_t)(((int64_t)b->y + 128) >> 8);
    int32_t dx = x1 - x0, dy = y1 - y0;
    int32_t adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    int32_t n = FX_MAX(adx, ady);
    int32_t sx = dx < 0 ? -1 : 1, sy = dy < 0 ? -1 : 1;
    int64_t z = (int64_t)a->z << 16, dz = n ? (((int64_t)b->z - a->z) * 65536) / n : 0;
    int32_t err = (adx > ady ? adx : -ady) / 2;
    uint32_t native = fx_pack(pc->s->format, col);
    const int32_t tol = 1 << 10;
    int32_t x = x0, y = y0;
    for (int32_t i = 0; i <= n; i++) {
        if (x >= pc->clip.x0 && x < pc->clip.x1 && y >= pc->clip.y0 && y < pc->clip.y1) {
            int ok = 1;
            uint32_t zz = (uint32_t)(z >> 16);
            if (ztest && pc->zbits == 32)
                ok = (int64_t)zz <= (int64_t)((uint32_t *)pc->zb)[(size_t)y * (size_t)pc->zstride + (size_t)x] + tol;
            else if (ztest && pc->zbits == 16)
                ok = (zz >> 14) <= (uint32_t)((uint16_t *)pc->zb)[(size_t)y * (size_t)pc->zstride + (size_t)x] + (tol >> 14);
            if (ok)
                put_px(pc->s, fx_row(pc->s, y), x, y, native);
        }
        int32_t e2 = err;
        if (e2 > -adx) {
            err -= ady;
            x += sx;
        }
        if (e2 < ady) {
            err += adx;
            y += sy;
        }
        z += dz;
    }
}

/* ------------------------------------------------------------------ */
/* clipping and projection                                              */

/* Distance of c to clip plane p (>= 0 inside). */
static int64_t plane_dist(const pctx *pc, const cvert *v, int p)
{
    int64_t x = v->c[0], y = v->c[1], z = v->c[2], w = v->c[3], g = pc->guard;
    switch (p) {
    case 0: return z + w;     /* near */
    case 1: return w - z;     /* far */
    case 2: return g * w + x; /* guard band */
    case 3: return g * w - x;
    case 4: return g * w + y;
    default: return g * w - y;
    }
}

/* Sutherland-Hodgman in homogeneous space; n in, returns n out (<= n + 6
 * for a convex polygon: a triangle gives at most 9), or -1 when more than
 * cap (<= SCAN_MAXC + 2) vertices would be needed, which a non-planar
 * face crossing a plane several times can ask for. The
 * crossing parameter t = d0 / (d0 - d1) is kept in Q28 (distances stay
 * below 2^34), so a new vertex lies on its plane to within the Q16.16
 * rounding of its coordinates. */
static int clip_poly(const pctx *pc, cvert *v, int n, cvert *tmp, int na, int cap)
{
    for (int p = 0; p < 6 && n >= 3; p++) {
        int64_t d[SCAN_MAXC + 2];
        int out = 0;
        for (int i = 0; i < n; i++) {
            d[i] = plane_dist(pc, &v[i], p);
            out |= d[i] < 0;
        }
        if (!out)
            continue;
        int m = 0;
        for (int i = 0; i < n; i++) {
            int j = i + 1 == n ? 0 : i + 1;
            if (m + 2 > cap)
                return -1;
            if (d[i] >= 0)
                tmp[m++] = v[i];
            if ((d[i] < 0) != (d[j] < 0)) {
                int64_t t = (d[i] * ((int64_t)1 << 28)) / (d[i] - d[j]);
                cvert *o = &tmp[m++];
                /* summed in 64 bits: the step alone may exceed int32 when the
                 * ends have opposite signs; the result lies between them */
                for (int k = 0; k < 4; k++)
                    o->c[k] = (int32_t)(v[i].c[k] + ((((int64_t)v[j].c[k] - v[i].c[k]) * t) >> 28));
                for (int k = 0; k < na; k++)
                    o->a[k] = (int32_t)(v[i].a[k] + ((((int64_t)v[j].a[k] - v[i].a[k]) * t) >> 28));
            }
        }
        n = m;
        for (int i = 0; i < n; i++)
            v[i] = tmp[i];
    }
    return n;
}

static void project(const pctx *pc, const cvert *c, svert *s, int na)
{
    int64_t x = c->c[0], y = c->c[1], z = c->c[2], w = c->c[3];
    if (w <= 0)
        w = 1;
    s->w = (int32_t)w;
    int64_t hx = (int64_t)pc->vw * 128, hy = (int64_t)pc->vh * 128;
    int64_t nx = (x + w) * hx, ny = (w - y) * hy;
    s->x = (int32_t)((int64_t)pc->vx * 256 - 128 + (nx >= 0 ? nx + w / 2 : nx - w / 2) / w);
    s->y = (int32_t)((int64_t)pc->vy * 256 - 128 + (ny >= 0 ? ny + w / 2 : ny - w / 2) / w);
    int64_t d = ((z + w) * ((int64_t)1 << 29)) / w;
    s->z = (int32_t)(d < 0 ? 0 : d > ((int64_t)1 << 30) ? ((int64_t)1 << 30) : d);
    for (int k = 0; k < na; k++)
        s->a[k] = c->a[k];
}

/* The light-space screen position and depth of a world point, for the
 * shadow buffer (written into attributes A_SM..A_SM+2). */
static void sm_coords(const fx3d_shadowmap *sm, fx_vec3 world, int32_t *a)
{
    fx_vec4 c = fx_mat4_apply_point(&sm->view_proj, world);
    int64_t w = c.w;
    if (w <= 0 || c.z < -c.w) {
        a[0] = a[1] = -(1 << 24); /* behind the light: outside the map, lit */
        a[2] = 0;
        return;
    }
    int64_t h = (int64_t)sm->size * 128;
    a[0] = (int32_t)(((int64_t)c.x + w) * h / w - 128);
    a[1] = (int32_t)((w - (int64_t)c.y) * h / w - 128);
    int64_t d = (((int64_t)c.z + w) * ((int64_t)1 << 29)) / w;
    a[2] = (int32_t)(d > ((int64_t)1 << 30) ? ((int64_t)1 << 30) : d);
}

/* Append a triangle to a sort buffer (painter's or translucent), keyed by
 * its summed depth; a full buffer counts it as dropped. */
static void keep_tri(void *buf, int32_t *count, int32_t cap, int32_t *dropped, const svert *a, const svert *b,
                     const svert *c, const tri_mode *m)
{
    if (*count >= cap) {
        (*dropped)++;
        return;
    }
    ptri *t = (ptri *)buf + (*count)++;
    t->v[0] = *a;
    t->v[1] = *b;
    t->v[2] = *c;
    t->m = *m;
    t->key = (int64_t)a->z + b->z + c->z;
}

static void emit_tri(pctx *pc, const svert *a, const svert *b, const svert *c, const tri_mode *m)
{
    fx3d *r = pc->r;
    if (m->blend == 1 && r->tbuf && r->visibility != FX3D_VIS_PAINTER && r->sm_phase != 1) {
        /* translucent: kept for fx3d_flush, drawn after every opaque one */
        keep_tri(r->tbuf, &r->tcount, r->tcap, &r->tdropped, a, b, c, m);
        return;
    }
    if (r->visibility == FX3D_VIS_PAINTER && r->sm_phase != 1) {
        keep_tri(r->pbuf, &r->pcount, r->pcap, &r->pdropped, a, b, c, m);
        return;
    }
    raster_tri(pc, a, b, c, m);
}

/* Clip, project and draw one polygon (a triangle on entry). */
static void draw_clipped(pctx *pc, const cvert *tri, const tri_mode *m)
{
    /* Each of the six planes can add one vertex: at most 9. */
    cvert v[12], tmp[12];
    v[0] = tri[0];
    v[1] = tri[1];
    v[2] = tri[2];
    int n = clip_poly(pc, v, 3, tmp, m->na, 12);
    if (n < 3)
        return;
    if (n > 3)
        pc->r->stat_clipped++;
    svert s[12];
    for (int i = 0; i < n; i++)
        project(pc, &v[i], &s[i], m->na);
    if (m->outline == 1 && pc->r->visibility == FX3D_VIS_PAINTER && pc->r->sm_phase != 1) {
        /* Painter's hidden-line: each fan triangle is kept with an outline
         * flag and outlined when drawn (a polygon cut by the near plane
         * thus also shows its fan diagonals). */
        for (int i = 1; i + 1 < n; i++)
            emit_tri(pc, &s[0], &s[i], &s[i + 1], m);
        return;
    }
    if (m->outline == 2) { /* edges only */
        for (int i = 0; i < n; i++)
            raster_line(pc, &s[i], &s[(i + 1) % n], m->lines_ztest, pc->wire);
        return;
    }
    for (int i = 1; i + 1 < n; i++)
        emit_tri(pc, &s[0], &s[i], &s[i + 1], m);
    if (m->outline == 1)
        for (int i = 0; i < n; i++)
            raster_line(pc, &s[i], &s[(i + 1) % n], pc->zb != NULL, pc->wire);
}

/* ------------------------------------------------------------------ */
/* drawing                                                              */

/* The guard band's G for a viewport (clip_poly): screen coordinates stay
 * within +-2^14 pixels. */
static int32_t guard_for(int32_t vw, int32_t vh)
{
    int32_t big = FX_MAX(FX_MAX(vw, vh), 1);
    return FX_MAX(1, FX_MIN(4, (1 << 13) / big));
}

static void pctx_init(pctx *pc, fx3d *r)
{
    pc->r = r;
    pc->s = &r->ctx.surf;
    pc->clip = fx_rect_intersect(r->ctx.clip, r->viewport);
    pc->zb = r->visibility == FX3D_VIS_DEPTH ? r->depth : NULL;
    pc->zbits = pc->zb ? r->depth_bits : 0;
    pc->zstride = r->ctx.surf.w;
    pc->vx = r->viewport.x0;
    pc->vy = r->viewport.y0;
    pc->vw = r->viewport.x1 - r->viewport.x0;
    pc->vh = r->viewport.y1 - r->viewport.y0;
    pc->guard = guard_for(pc->vw, pc->vh);
    prepare_lights(r, pc->el, &pc->nl);
    pc->wire = r->ctx.color;
    pc->sm = NULL;
    pc->nsm = 0;
    pc->dmask = ~0u;
    pc->amb = 1;
    pc->kd_in = FX16_ONE;
    pc->kd_out = 0;
    pc->scan = NULL;
    if (r->sm_phase == 2 && r->sm) {
        if (r->sm_n > 1) {
            for (int k = 0; k < r->sm_n; k++)
                pc->smv[k] = r->sm_use[k];
            pc->nsm = r->sm_n;
        } else {
            pc->smv[0] = r->sm;
            pc->nsm = 1;
        }
    }
    if (r->pass == FX3D_PASS_AMBIENT) {
        pc->dmask = 0;
        pc->kd_out = r->pass_dim;
        pc->nsm = 0; /* nothing a shadow could remove */
    } else if (r->pass == FX3D_PASS_LIGHT) {
        /* the light's own map only, as map 0 */
        int k = 0;
        while (k < pc->nsm && pc->smv[k]->light != r->pass_light)
            k++;
        if (k < pc->nsm) {
            pc->smv[0] = pc->smv[k];
            pc->nsm = 1;
        } else {
            pc->nsm = 0;
        }
        pc->dmask = 1u << r->pass_light;
        pc->kd_in = FX16_ONE - r->pass_dim; /* the ambient pass gave the rest */
        pc->amb = 0;
    }
    pc->sm = pc->nsm ? pc->smv[0] : NULL;
}

/* Homogeneous facing: the sign of det[x y w] of the three clip vertices is
 * the sign of N . (P0 - centre of projection) in eye space, valid for any
 * w (no division, no clipping needed). Values are scaled to 20 bits first
 * so the triple products fit. */
static int facing(const cvert *v)
{
    int32_t m = 0;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 4; k += (k == 1 ? 2 : 1)) {
            int32_t a = v[i].c[k] < 0 ? -(v[i].c[k] + 1) : v[i].c[k];
            m |= a;
        }
    int sh = 0;
    while ((m >> sh) >= (1 << 20))
        sh++;
    int64_t x[3], y[3], w[3];
    for (int i = 0; i < 3; i++) {
        x[i] = v[i].c[0] >> sh;
        y[i] = v[i].c[1] >> sh;
        w[i] = v[i].c[3] >> sh;
    }
    int64_t d = x[0] * (y[1] * w[2] - w[1] * y[2]) - y[0] * (x[1] * w[2] - w[1] * x[2]) +
                w[0] * (x[1] * y[2] - y[1] * x[2]);
    return d > 0 ? 1 : d < 0 ? -1 : 0;
}

/* Whether a triangle certainly draws nothing in pc->clip, tested on x/w and
 * y/w without a division: every vertex in front of the eye (w >= 1/16) and
 * beyond the same edge of the clip widened by a margin. Such triangles need
 * no lighting: in a band of a frame drawn on several threads most
 * triangles are outside the band, and skipping them changes no pixel.
 *
 * Why the margin suffices. Every vertex the rasterizer receives is
 * R = Q + e, Q a real point of the homogeneous convex hull of v[0..n-1]
 * and |e| <= k units of 2^-16 in each of x, y, w, with k = CLIP_ULPS +
 * slop: clip_poly's new vertex is an exact convex combination (its
 * parameter t, whatever its own rounding, lies in [0, 1]) of two earlier
 * ones, then floored per coordinate, so each of the six planes adds at
 * most one unit to the error of its inputs; slop is the caller's error of
 * the vertices themselves (0 for a triangle's own, see fx3d_hull_away).
 * Where every w > 0, Q projects into the convex hull of the vertices'
 * screen points, so Q lies beyond the edge (the linear test holds for Q
 * since it holds, in integers and strictly, for every vertex). R's screen
 * x differs from Q's by h |e_x - u e_w| / (w_Q + e_w), h = W * 128 (24.8
 * units), u = x_Q / w_Q. R lies inside the guard planes |x| <= G w but for
 * 158 units: 128 from t truncated toward an end outside the plane (plane
 * distances stay below 2^34, t has 28 bits) and G + 1 per later floor; so
 * |x_Q| <= G w_Q + (G + 1) k + 158 and |u| <= G + 1 whenever
 * (G + 1) k + 158 <= w_min (refused otherwise), w_min the least w of v.
 * The error is then at most h k (G + 2) / (w_min - k), plus 1/2 for
 * project's rounding and 1/2 pixel for raster_line, which rounds the ends
 * to pixel centres; the rasterizer covers only pixel centres inside the
 * hull of the vertices it gets. The same holds for y. The margin is that
 * bound, and never less than AWAY_PX pixels. At w_min = 1/16, W = 2^14
 * (G = 1) and k = 6 the bound is 37 pixels: 8 would not be proven there
 * (tests/core/test_3d_cull.c's searches found vertices moved by more than
 * 4 pixels, none by 6). */
#define AWAY_PX 8
#define CLIP_ULPS 6
static int clip_away(const pctx *pc, const int32_t (*v)[4], int n, int64_t slop)
{
    const fx_rect c = pc->clip;
    if (pc->vw > (1 << 14) || pc->vh > (1 << 14) || pc->vw < 1 || pc->vh < 1 || pc->vx < -(1 << 20) ||
        pc->vx > (1 << 20) || pc->vy < -(1 << 20) || pc->vy > (1 << 20) || c.x0 < -(1 << 20) ||
        c.y0 < -(1 << 20) || c.x1 > (1 << 20) || c.y1 > (1 << 20) || slop < 0 || slop > (1 << 10))
        return 0;
    int64_t wmin = INT32_MAX;
    for (int i = 0; i < n; i++) {
        if (v[i][3] < (1 << 12))
            return 0;
        wmin = FX_MIN(wmin, (int64_t)v[i][3]);
    }
    int64_t g = guard_for(pc->vw, pc->vh), k = CLIP_ULPS + slop;
    if ((g + 1) * k + 158 > wmin)
        return 0;
    if (fx_rect_empty(c))
        return 1;
    /* screen x = vx*256 - 128 + (x + w) hx / w, in 24.8 with pixel centres
     * at integers; the same for y with (w - y) */
    int64_t hx = (int64_t)pc->vw * 128, hy = (int64_t)pc->vh * 128;
    int64_t mx = (hx * k * (g + 2) + wmin - k - 1) / (wmin - k) + 129; /* rounded up */
    int64_t my = (hy * k * (g + 2) + wmin - k - 1) / (wmin - k) + 129;
    mx = FX_MAX(mx, (int64_t)AWAY_PX * 256);
    my = FX_MAX(my, (int64_t)AWAY_PX * 256);
    int64_t kx0 = (int64_t)c.x0 * 256 - mx - (int64_t)pc->vx * 256 + 128;
    int64_t kx1 = ((int64_t)c.x1 - 1) * 256 + mx - (int64_t)pc->vx * 256 + 128;
    int64_t ky0 = (int64_t)c.y0 * 256 - my - (int64_t)pc->vy * 256 + 128;
    int64_t ky1 = ((int64_t)c.y1 - 1) * 256 + my - (int64_t)pc->vy * 256 + 128;
    int l = 1, rt = 1, t = 1, b = 1;
    for (int i = 0; i < n; i++) {
        int64_t x = v[i][0], y = v[i][1], w = v[i][3];
        int64_t sx = (x + w) * hx, sy = (w - y) * hy;
        l &= sx < kx0 * w;
        rt &= sx > kx1 * w;
        t &= sy < ky0 * w;
        b &= sy > ky1 * w;
    }
    return l | rt | t | b;
}

static int tri_away(const pctx *pc, const cvert *v)
{
    int32_t c[3][4];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 4; k++)
            c[i][k] = v[i].c[k];
    return clip_away(pc, (const int32_t(*)[4])c, 3, 0);
}

/* Whether a component may have been clamped by fx_mat4_apply's fx_sat32:
 * within `near` units of 2^-16 of a limit (a vertex inside the box, whose
 * exact value lies within the corners' exact ones, rounds to within a few
 * units of the corners' computed values and may reach the limit). */
static int near_sat(int32_t c, int32_t near)
{
    return c >= INT32_MAX - near || c <= INT32_MIN + near;
}

int fx3d_hull_away(fx3d *r, const fx_vec3 *pts, int n)
{
    /* sorted triangles (the set a full buffer drops), a planar shadow (it
     * falls elsewhere) and a shadow-map pass (not drawn in the clip) */
    if (!r || !pts || n < 1 || r->visibility == FX3D_VIS_PAINTER || (r->alpha < 255 && r->tbuf) ||
        r->sm_phase == 1 || r->plane_shadow)
        return 0;
    /* The box of the points, widened by 1/256 of their largest coordinate
     * and 64 units: what is made from them in fixed point (a Bezier patch
     * evaluated with rounded weights) may stray a little outside their
     * hull, and the slack is in object space, so it holds at any zoom. */
    int64_t lo[3], hi[3], big = 0;
    for (int i = 0; i < n; i++) {
        int64_t q[3] = {pts[i].x, pts[i].y, pts[i].z};
        for (int k = 0; k < 3; k++) {
            lo[k] = i == 0 || q[k] < lo[k] ? q[k] : lo[k];
            hi[k] = i == 0 || q[k] > hi[k] ? q[k] : hi[k];
            big = q[k] > big ? q[k] : -q[k] > big ? -q[k] : big;
        }
    }
    int64_t slack = big / 256 + 64;
    for (int k = 0; k < 3; k++) {
        lo[k] -= slack;
        hi[k] += slack;
        if (lo[k] < -(INT64_C(1) << 30) || hi[k] > (INT64_C(1) << 30))
            return 0; /* far beyond any scene: not worth the overflow care */
    }
    pctx pc;
    pc.clip = fx_rect_intersect(r->ctx.clip, r->viewport);
    pc.vx = r->viewport.x0;
    pc.vy = r->viewport.y0;
    pc.vw = r->viewport.x1 - r->viewport.x0;
    pc.vh = r->viewport.y1 - r->viewport.y0;
    fx_mat4 mv;
    fx_mat4_mul(&mv, &r->view, fx_mat_stack_top(&r->model));
    const fx_mat4 *P = fx_mat_stack_top(&r->proj);
    /* A vertex p in the box is transformed by fx3d_draw into A(p) + d_p,
     * A the exact affine map of mv then P, and a corner c into A(c) + d_c:
     * fx_mat4_apply rounds each component to within 1/2 + 2^-12 units, so
     * an eye-space error of that much becomes, through a row of P with
     * absolute sum S (Q16.16), at most S / 2^16 + 1 units in clip space.
     * A(p) lies in the hull of the A(c), so the vertex lies in the hull of
     * the computed corners up to 2 such errors: clip_away's slop. Only
     * without clamping: fx_sat32 moves a corner to a point that is no
     * longer the corner (the hull of the clamped corners need not hold the
     * vertices, which may not clamp at all), so a component at a limit
     * means unsure. */
    int64_t s_max = 0;
    for (int i = 0; i < 4; i += i == 1 ? 2 : 1) { /* rows x, y, w */
        int64_t s = 0;
        for (int j = 0; j < 4; j++)
            s += P->m[i][j] < 0 ? -(int64_t)P->m[i][j] : P->m[i][j];
        s_max = FX_MAX(s_max, s);
    }
    int64_t err = (s_max >> 16) + 2;
    if (err > (1 << 9))
        return 0;
    int32_t c[8][4];
    for (int i = 0; i < 8; i++) { /* the corners, as fx3d_draw transforms a vertex */
        fx_vec3 p = fx_vec3_make((fx16)(i & 1 ? hi[0] : lo[0]), (fx16)(i & 2 ? hi[1] : lo[1]),
                                 (fx16)(i & 4 ? hi[2] : lo[2]));
        fx_vec4 e = fx_mat4_apply_point(&mv, p);
        if (near_sat(e.x, 2) || near_sat(e.y, 2) || near_sat(e.z, 2) || near_sat(e.w, 2))
            return 0;
        e = fx_mat4_apply(P, e);
        if (near_sat(e.x, (int32_t)(2 * err)) || near_sat(e.y, (int32_t)(2 * err)) ||
            near_sat(e.z, (int32_t)(2 * err)) || near_sat(e.w, (int32_t)(2 * err)))
            return 0;
        c[i][0] = e.x, c[i][1] = e.y, c[i][2] = e.z, c[i][3] = e.w;
    }
    return clip_away(&pc, (const int32_t(*)[4])c, 8, 2 * err);
}

static void set_rgb(int32_t *a, fx3d_rgb c)
{
    a[0] = c.r;
    a[1] = c.g;
    a[2] = c.b;
}

static void set_vec(int32_t *a, fx_vec3 v)
{
    a[0] = v.x;
    a[1] = v.y;
    a[2] = v.z;
}

/* The shadow-buffer pass: depth from the light into sm->depth. */
static int draw_shadow_pass(fx3d *r, const fx_mesh *m)
{
    fx3d_shadowmap *sm = r->sm;
    pctx pc;
    fx_memset(&pc, 0, sizeof pc);
    pc.r = r;
    pc.s = NULL;
    fx_rect all = {0, 0, sm->size, sm->size};
    pc.clip = all;
    pc.zb = sm->depth;
    pc.zbits = 32;
    pc.zstride = sm->size;
    pc.vw = pc.vh = sm->size;
    pc.guard = FX_MAX(1, FX_MIN(4, (1 << 13) / sm->size));
    fx_mat4 mvp;
    fx_mat4_mul(&mvp, &sm->view_proj, fx_mat_stack_top(&r->model));
    tri_mode tm;
    fx_memset(&tm, 0, sizeof tm);
    tm.kind = K_DEPTH;
    tm.ztest = tm.zwrite = 1;
    for (int32_t t = 0; t < m->ntris; t++) {
        cvert v[3];
        for (int i = 0; i < 3; i++) {
            uint32_t idx = m->tri[3 * t + i];
            if (idx >= (uint32_t)m->nverts)
                return -FX_EINVAL;
            fx_vec4 c = fx_mat4_apply_point(&mvp, m->pos[idx]);
            v[i].c[0] = c.x;
            v[i].c[1] = c.y;
            v[i].c[2] = c.z;
            v[i].c[3] = c.w;
        }
        /* Only faces turned away from the light go into the map: the lit
         * faces then compare against the far side of their own object and
         * cannot shadow themselves ("acne"). */
        if (facing(v) > 0)
            continue;
        draw_clipped(&pc, v, &tm);
    }
    return 0;
}

/* FX3D_GOURAUD_SCAN: the face being gathered from a fan of triangles
 * (render3d.h says what a face is), drawn when the fan ends. */
typedef struct scanfan {
    int n, f;
    uint32_t idx[FX3D_SCAN_MAX_VERTS];
    cvert v[FX3D_SCAN_MAX_VERTS];
} scanfan;

/* The turn a -> b -> c on the screen, as facing() gives it. */
static int turn3(const cvert *a, const cvert *b, const cvert *c)
{
    cvert t[3];
    for (int k = 0; k < 4; k++) {
        t[0].c[k] = a->c[k];
        t[1].c[k] = b->c[k];
        t[2].c[k] = c->c[k];
    }
    return facing(t);
}

/* The face (n corners, 4..FX3D_SCAN_MAX_VERTS) clipped whole and
 * projected into sp; 0 when nothing is left or its clip would need more
 * corners than it can have (not convex in space). Kept out of line so that
 * its clip arrays are gone before draw_clipped's. */
__attribute__((noinline)) static int face_outline(const pctx *pc, const cvert *face, int n, int na, scanpoly *sp)
{
    cvert v[SCAN_MAXC + 2], tmp[SCAN_MAXC + 2];
    for (int i = 0; i < n; i++)
        v[i] = face[i];
    int nc = clip_poly(pc, v, n, tmp, na, SCAN_MAXC);
    if (nc < 3)
        return 0;
    sp->n = nc;
    for (int i = 0; i < nc; i++) {
        svert s;
        project(pc, &v[i], &s, A_COL + 3);
        sp->x[i] = s.x;
        sp->y[i] = s.y;
        for (int k = 0; k < 3; k++)
            sp->c[i][k] = s.a[A_COL + k];
    }
    return 1;
}

/* Draw a face: its triangles, each clipped and drawn as draw_clipped draws
 * it (so coverage, depth and the other attributes are FX3D_GOURAUD's, also
 * where a non-planar face crosses a clip plane), coloured from the whole
 * face (pc->scan); a face face_outline refuses keeps the triangles'
 * colours. */
static void draw_face(pctx *pc, const cvert *face, int n, const tri_mode *m)
{
    scanpoly sp;
    /* emit_tri keeps triangles for a sort without pc->scan: the painter
     * draws them later with the triangle rule */
    pc->scan = face_outline(pc, face, n, m->na, &sp) ? &sp : NULL;
    for (int i = 1; i + 1 < n; i++) {
        cvert t[3] = {face[0], face[i], face[i + 1]};
        draw_clipped(pc, t, m);
    }
    pc->scan = NULL;
}

static void scan_flush(pctx *pc, scanfan *fan, const tri_mode *m)
{
    if (fan->n == 3)
        draw_clipped(pc, fan->v, m); /* a triangle: exactly FX3D_GOURAUD's */
    else if (fan->n > 3)
        draw_face(pc, fan->v, fan->n, m);
    fan->n = 0;
}

/* Add triangle v (mesh indices idx, facing f) to the face being gathered
 * when it continues its fan and keeps it convex; otherwise draw that face
 * and start another with v. */
static void scan_add(pctx *pc, scanfan *fan, const cvert *v, const uint32_t *idx, int f, const tri_mode *m)
{
    int n = fan->n, grow = n >= 3 && n < FX3D_SCAN_MAX_VERTS && f == fan->f && idx[0] == fan->idx[0] &&
                           idx[1] == fan->idx[n - 1];
    for (int i = 0; grow && i < n; i++)
        grow = idx[2] != fan->idx[i];
    /* the corners at the last vertex, the new one and the first */
    if (grow)
        grow = turn3(&fan->v[n - 2], &fan->v[n - 1], &v[2]) == f && turn3(&fan->v[n - 1], &v[2], &fan->v[0]) == f &&
               turn3(&v[2], &fan->v[0], &fan->v[1]) == f;
    if (grow) {
        fan->v[n] = v[2];
        fan->idx[n] = idx[2];
        fan->n = n + 1;
        return;
    }
    scan_flush(pc, fan, m);
    for (int i = 0; i < 3; i++) {
        fan->v[i] = v[i];
        fan->idx[i] = idx[i];
    }
    fan->n = 3;
    fan->f = f;
}

int fx3d_draw(fx3d *r, const fx_mesh *m)
{
    if (!m || !m->pos || !m->tri || m->ntris < 0 || m->nverts < 0)
        return -FX_EINVAL;
    r->stat_culled = r->stat_drawn = r->stat_clipped = 0;
    if (r->sm_phase == 1 && r->sm)
        return draw_shadow_pass(r, m);

    pctx pc;
    pctx_init(&pc, r);
    const fx_mat4 *model = fx_mat_stack_top(&r->model);
    const fx_mat4 *P = fx_mat_stack_top(&r->proj);
    fx_mat4 mv, nm, inv;
    fx_mat4_mul(&mv, &r->view, model);
    /* Normals go through the inverse transpose, so that non-uniform scales
     * and shears keep them perpendicular to the surface. */
    if (fx_mat4_invert(&inv, &mv) == 0)
        fx_mat4_transpose(&nm, &inv);
    else
        nm = mv;

    /* The planar-shadow matrix in eye space: S = (p . l) I - l p^T with the
     * plane p and the light l (w = 0 for a directional light). */
    fx_mat4 shadow;
    int plane_on = r->plane_shadow && r->light[r->plane_light].type != FX3D_LIGHT_OFF && r->pass != FX3D_PASS_LIGHT;
    if (plane_on) {
        const fx3d_light *L = &r->light[r->plane_light];
        fx_vec4 l;
        if (L->type == FX3D_LIGHT_DIRECTIONAL) {
            fx_vec3 d = fx_mat4_apply_dir(&r->view, L->pos);
            l.x = d.x, l.y = d.y, l.z = d.z, l.w = 0;
        } else {
            l = fx_mat4_apply_point(&r->view, L->pos);
        }
        /* The world plane in eye space: p_eye = inverse(view)^T p_world. */
        fx_mat4 vi, vit;
        fx_vec4 pw = {r->plane[0], r->plane[1], r->plane[2], r->plane[3]};
        if (fx_mat4_invert(&vi, &r->view) < 0)
            plane_on = 0;
        fx_mat4_transpose(&vit, &vi);
        fx_vec4 p = fx_mat4_apply(&vit, pw);
        fx16 pl = fx_sat32(((int64_t)p.x * l.x + (int64_t)p.y * l.y + (int64_t)p.z * l.z +
                            (int64_t)p.w * l.w + 0x8000) >> 16);
        fx16 pv[4] = {p.x, p.y, p.z, p.w}, lv[4] = {l.x, l.y, l.z, l.w};
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++)
                /* in 64 bits: a product of INT32_MIN (a saturated
                 * light or plane) negated overflowed int (fuzz_grammar) */
                shadow.m[i][j] = fx_sat32((int64_t)(i == j ? pl : 0) - fx16_mul(lv[i], pv[j]));
    }

    int smooth = m->nrm != NULL;
    tri_mode tm;
    fx_memset(&tm, 0, sizeof tm);
    tm.ztest = tm.zwrite = pc.zb != NULL;
    tm.use_sm = (uint8_t)pc.nsm;
    if (r->alpha < 255 && r->sm_phase != 1 && r->polymode == FX3D_FILL) {
        /* depth-tested against the opaque surfaces, but never hiding what
         * lies behind: GL's glDepthMask(GL_FALSE) for translucent passes */
        tm.blend = 1;
        tm.alpha = (uint8_t)r->alpha;
        tm.zwrite = 0;
    }
    if (r->pass == FX3D_PASS_LIGHT && r->polymode == FX3D_FILL) {
        /* the surfaces the ambient pass left in the buffer, and only those */
        tm.blend = 2;
        tm.ztest = pc.zb != NULL ? 2 : 0;
        tm.zwrite = 0;
    }
    tm.na = 0;
    if (r->polymode == FX3D_FILL) {
        tm.kind = r->shading == FX3D_FLAT                                         ? K_FLAT
                  : r->shading == FX3D_GOURAUD || r->shading == FX3D_GOURAUD_SCAN ? K_GOURAUD
                                                                                  : K_PHONG;
        tm.na = tm.kind == K_FLAT ? 0 : 6;
        if (tm.use_sm)
            tm.na = 9;
        if (r->tex && (m->uv || r->tex_sphere_map) && r->tex->img.pixels && r->tex->img.w > 0 && r->tex->img.h > 0) {
            tm.tex = 1;
            tm.na = 12;
            tm.tx = r->tex;
            tm.tex_mode = (uint8_t)r->tex_mode;
        }
        if (m->col && tm.kind == K_PHONG) {
            tm.vcol = 1;
            tm.na = 15;
        }
        if (r->solid > 0 && r->solid < 4) {
            tm.solid = 1;
            tm.na = A_SMK;
            tm.solid_kind = (int8_t)r->solid;
            tm.solid_c[0] = r->solid_c0;
            tm.solid_c[1] = r->solid_c1;
        }
        tm.obj_scale = r->solid_scale > 0 ? r->solid_scale : FX16_ONE;
        if (r->bump > 0 && tm.kind == K_PHONG) {
            tm.bump = 1;
            tm.na = A_SMK;
            tm.bump_h = r->bump;
            tm.bump_s = r->bump_scale;
            if (!tm.solid)
                tm.obj_scale = r->bump_scale;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    tm.bnm[i][j] = nm.m[i][j];
        }
        if (r->frame && r->frame_k > 0 && tm.kind == K_PHONG) {
            tm.frame = 1;
            tm.na = FX_MAX(tm.na, A_SMK);
            tm.frame_kind = (int8_t)r->frame;
            tm.frame_k = r->frame_k;
            tm.frame_s = r->frame_scale;
            if (!tm.solid && !tm.bump)
                tm.obj_scale = r->frame_scale;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    tm.fmv[i][j] = mv.m[i][j];
        }
        if (tm.use_sm > 1)
            tm.na = NA;
    } else {
        tm.kind = K_FLAT;
        tm.use_sm = 0;
        tm.outline = r->polymode == FX3D_WIRE ? 2 : 1;
        tm.lines_ztest = r->polymode == FX3D_HIDDEN_LINE && pc.zb != NULL;
        tm.flat[0] = tm.flat[1] = r->background;
    }

    /* Triangles kept for a sort (painter's, translucent) are never skipped:
     * the set a full buffer drops, and the order of equal keys, would
     * change with the clip. */
    int may_skip = r->visibility != FX3D_VIS_PAINTER && !(tm.blend == 1 && r->tbuf);
    /* The notes' scan-line Gouraud gathers faces from fans (not with
     * shadow maps, whose shadowed colours are the triangles'); no triangle
     * of a face is skipped, or the rule of the rest would change with the
     * clip. */
    scanfan fan;
    fan.n = 0;
    int scan = r->shading == FX3D_GOURAUD_SCAN && tm.kind == K_GOURAUD && !tm.use_sm;
    if (scan)
        may_skip = 0;
    /* The vertex cache: entries of an earlier draw have an older gen. */
    vcent *vc = NULL;
    uint32_t gen = 0;
    if (r->vcache && m->nverts <= r->vcache_n) {
        vc = (vcent *)r->vcache;
        if (++r->vcache_gen == 0) {
            fx_memset(vc, 0, (size_t)r->vcache_n * sizeof *vc);
            r->vcache_gen = 1;
        }
        gen = r->vcache_gen;
    }
    /* Hidden lines without the painter: all faces of the mesh first (depth
     * and background), then all edges against that depth. */
    int passes = r->polymode == FX3D_HIDDEN_LINE && r->visibility != FX3D_VIS_PAINTER ? 2 : 1;
    for (int pass = 0; pass < passes; pass++) {
        if (passes == 2)
            tm.outline = pass == 0 ? 3 : 2;
        for (int32_t t = 0; t < m->ntris; t++) {
            cvert v[3];
            fx_vec3 ep[3], wp[3];
            fx_memset(v, 0, sizeof v);
            uint32_t idx[3];
            for (int i = 0; i < 3; i++) {
                idx[i] = m->tri[3 * t + i];
                if (idx[i] >= (uint32_t)m->nverts) {
                    scan_flush(&pc, &fan, &tm); /* what came before is drawn, as without it */
                    return -FX_EINVAL;
                }
                vcent *ce = vc ? &vc[idx[i]] : NULL;
                if (ce && ce->gen == gen) {
                    ep[i] = ce->ep;
                    for (int k = 0; k < 4; k++)
                        v[i].c[k] = ce->c[k];
                    continue;
                }
                fx_vec4 e = fx_mat4_apply_point(&mv, m->pos[idx[i]]);
                ep[i] = fx_vec3_make(e.x, e.y, e.z);
                fx_vec4 c = fx_mat4_apply(P, e);
                v[i].c[0] = c.x;
                v[i].c[1] = c.y;
                v[i].c[2] = c.z;
                v[i].c[3] = c.w;
                if (ce) {
                    ce->ep = ep[i];
                    for (int k = 0; k < 4; k++)
                        ce->c[k] = v[i].c[k];
                    ce->gen = gen;
                }
            }
            int f = facing(v);
            if (f == 0 || (r->cull == FX3D_CULL_BACK && f < 0) || (r->cull == FX3D_CULL_FRONT && f > 0)) {
                r->stat_culled++;
                continue;
            }
            r->stat_drawn++;
            cvert keep[3];
            if (may_skip && tri_away(&pc, v)) {
                /* its planar shadow may still fall into the clip */
                if (!(plane_on && f > 0))
                    continue;
                for (int i = 0; i < 3; i++)
                    keep[i] = v[i];
            } else {
                fx_vec3 fn = fx_vec3_cross(fx_vec3_sub(ep[1], ep[0]), fx_vec3_sub(ep[2], ep[0]));
                if (fx_vec3_normalize(&fn) < 0) {
                    /* Too small for Q16.16 cross products: scale up and retry. */
                    fn = fx_vec3_cross(fx_vec3_scale(fx_vec3_sub(ep[1], ep[0]), 256 << 16),
                                       fx_vec3_sub(ep[2], ep[0]));
                    fx_vec3_normalize(&fn);
                }
                /* Back faces seen through openings are lit from their own side. */
                int flip = f < 0;
                if (flip)
                    fn = fx_vec3_make(-fn.x, -fn.y, -fn.z);
                if (tm.solid || tm.bump || tm.frame)
                    for (int i = 0; i < 3; i++) {
                        fx_vec3 o = m->pos[idx[i]];
                        fx16 sc = tm.obj_scale;
                        v[i].a[A_OBJ] = fx_sat32((int64_t)o.x * 65536 / sc);
                        v[i].a[A_OBJ + 1] = fx_sat32((int64_t)o.y * 65536 / sc);
                        v[i].a[A_OBJ + 2] = fx_sat32((int64_t)o.z * 65536 / sc);
                    }
                if (tm.tex)
                    for (int i = 0; i < 3; i++) {
                        if (r->tex_sphere_map) {
                            fx_vec3 n = fn;
                            if (smooth) {
                                n = fx_mat4_apply_dir(&nm, m->nrm[idx[i]]);
                                if (fx_vec3_normalize(&n) < 0)
                                    n = fn;
                            }
                            sphere_st(ep[i], n, r->parallel, &v[i].a[A_TEX]);
                        } else {
                            v[i].a[A_TEX] = m->uv[2 * idx[i]];
                            v[i].a[A_TEX + 1] = m->uv[2 * idx[i] + 1];
                        }
                        if (r->texm.slot) {
                            fx16 st[2];
                            fx3d_tex_coord(r, v[i].a[A_TEX], v[i].a[A_TEX + 1], st);
                            v[i].a[A_TEX] = st[0], v[i].a[A_TEX + 1] = st[1];
                        }
                    }
                if (tm.use_sm) {
                    for (int i = 0; i < 3; i++) {
                        fx_vec4 w4 = fx_mat4_apply_point(model, m->pos[idx[i]]);
                        wp[i] = fx_vec3_make(w4.x, w4.y, w4.z);
                        for (int k = 0; k < tm.use_sm; k++)
                            sm_coords(pc.smv[k], wp[i], &v[i].a[k ? A_SMK + 3 * (k - 1) : A_SM]);
                    }
                }
                if (r->polymode == FX3D_FILL) {
                    if (tm.kind == K_FLAT) {
                        fx_vec3 cen = fx_vec3_make(
                            (fx16)(((int64_t)ep[0].x + ep[1].x + ep[2].x) / 3),
                            (fx16)(((int64_t)ep[0].y + ep[1].y + ep[2].y) / 3),
                            (fx16)(((int64_t)ep[0].z + ep[1].z + ep[2].z) / 3));
                        /* GL's flat shading takes the last vertex's colour */
                        fx3d_rgb pv, *pvc = NULL;
                        if (m->col) {
                            pv = fx3d_rgb_from_color(m->col[idx[2]]);
                            pvc = &pv;
                        }
                        tm.flat_full = pshade(&pc, cen, fn, 0, pvc);
                        tm.flat[0] = fx3d_rgb_to_color(tm.flat_full);
                        for (int k = 0; k < tm.use_sm; k++)
                            tm.flat_wo[k] = pshade(&pc, cen, fn, 1u << pc.smv[k]->light, pvc);
                        tm.flat[1] = tm.use_sm ? fx3d_rgb_to_color(tm.flat_wo[0]) : tm.flat[0];
                    } else {
                        for (int i = 0; i < 3; i++) {
                            vcent *ce = vc ? &vc[idx[i]] : NULL;
                            fx_vec3 n = fn;
                            int nok = 0;
                            if (smooth && ce && ce->ngen == gen) {
                                nok = ce->nok;
                                if (nok)
                                    n = ce->n;
                            } else if (smooth) {
                                n = fx_mat4_apply_dir(&nm, m->nrm[idx[i]]);
                                nok = fx_vec3_normalize(&n) >= 0;
                                if (ce) {
                                    ce->n = n;
                                    ce->nok = nok;
                                    ce->ngen = gen;
                                }
                                if (!nok)
                                    n = fn;
                            }
                            if (nok && flip)
                                n = fx_vec3_make(-n.x, -n.y, -n.z);
                            fx3d_rgb vcl, *vcp = NULL;
                            if (m->col) {
                                vcl = fx3d_rgb_from_color(m->col[idx[i]]);
                                vcp = &vcl;
                            }
                            if (tm.kind == K_GOURAUD && ce && nok && !tm.use_sm) {
                                /* a function of the vertex and its side alone */
                                if (ce->lgen[flip] != gen) {
                                    ce->col[flip] = pshade(&pc, ep[i], n, 0, vcp);
                                    ce->lgen[flip] = gen;
                                }
                                set_rgb(&v[i].a[A_COL], ce->col[flip]);
                            } else if (tm.kind == K_GOURAUD) {
                                set_rgb(&v[i].a[A_COL], pshade(&pc, ep[i], n, 0, vcp));
                                for (int k = 0; k < tm.use_sm; k++)
                                    set_rgb(&v[i].a[k ? A_WOK + 3 * (k - 1) : A_POS],
                                            pshade(&pc, ep[i], n, 1u << pc.smv[k]->light, vcp));
                            } else {
                                set_vec(&v[i].a[A_COL], n);
                                set_vec(&v[i].a[A_POS], ep[i]);
                                if (vcp)
                                    set_rgb(&v[i].a[A_VCOL], vcl);
                            }
                        }
                    }
                }
                if (plane_on && f > 0)
                    for (int i = 0; i < 3; i++)
                        keep[i] = v[i];
                if (scan)
                    scan_add(&pc, &fan, v, idx, f, &tm);
                else
                    draw_clipped(&pc, v, &tm);
            }

            if (plane_on && f > 0) {
                tri_mode sm_mode;
                fx_memset(&sm_mode, 0, sizeof sm_mode);
                sm_mode.kind = K_FLAT;
                sm_mode.flat[0] = sm_mode.flat[1] = r->plane_color;
                sm_mode.ztest = pc.zb != NULL;
                sm_mode.zbias = 1 << 15;
                for (int i = 0; i < 3; i++) {
                    fx_vec4 e = {ep[i].x, ep[i].y, ep[i].z, FX16_ONE};
                    fx_vec4 q = fx_mat4_apply(&shadow, e);
                    if (q.w < 0) { /* the same projective point, w > 0; saturating:
                                    * a saturated product may be INT32_MIN */
                        q.x = neg_sat(q.x), q.y = neg_sat(q.y), q.z = neg_sat(q.z), q.w = neg_sat(q.w);
                    }
                    fx_vec4 c = fx_mat4_apply(P, q);
                    keep[i].c[0] = c.x;
                    keep[i].c[1] = c.y;
                    keep[i].c[2] = c.z;
                    keep[i].c[3] = c.w;
                }
                draw_clipped(&pc, keep, &sm_mode);
            }
        }
        scan_flush(&pc, &fan, &tm);
    }
    return 0;
}

/* ------------------------------------------------------------------ */
/* painter's sort                                                       */

static void ptri_swap(ptri *a, ptri *b)
{
    ptri t = *a;
    *a = *b;
    *b = t;
}

/* Heap sort, deepest first: O(n log n) without extra memory. */
static void sift(ptri *t, int32_t i, int32_t n)
{
    for (;;) {
        int32_t c = 2 * i + 1;
        if (c >= n)
            return;
        /* min-heap on key, so that the sorted array descends */
        if (c + 1 < n && t[c + 1].key < t[c].key)
            c++;
        if (t[i].key <= t[c].key)
            return;
        ptri_swap(&t[i], &t[c]);
        i = c;
    }
}

static void sort_far_first(ptri *t, int32_t n)
{
    for (int32_t i = n / 2 - 1; i >= 0; i--)
        sift(t, i, n);
    for (int32_t e = n - 1; e > 0; e--) {
        ptri_swap(&t[0], &t[e]);
        sift(t, 0, e);
    }
}

/* The translucent triangles, farthest first, depth-tested (when a depth
 * buffer is on) without writing depth, each blended over what is there. */
static void flush_translucent(fx3d *r)
{
    if (!r->tbuf || r->tcount == 0)
        return;
    ptri *t = r->tbuf;
    int32_t n = r->tcount;
    sort_far_first(t, n);
    pctx pc;
    pctx_init(&pc, r);
    for (int32_t i = 0; i < n; i++) {
        tri_mode m = t[i].m;
        m.ztest = pc.zb != NULL;
        m.zwrite = 0;
        raster_tri(&pc, &t[i].v[0], &t[i].v[1], &t[i].v[2], &m);
    }
    r->tcount = 0;
}

void fx3d_alpha(fx3d *r, int alpha) { r->alpha = alpha < 0 ? 0 : alpha > 255 ? 255 : alpha; }

int fx3d_set_translucent(fx3d *r, void *mem, size_t bytes)
{
    if (!mem) {
        r->tbuf = NULL;
        r->tcap = r->tcount = 0;
        return 0;
    }
    if (bytes < sizeof(ptri))
        return -FX_EINVAL;
    r->tbuf = mem;
    r->tcap = (int32_t)FX_MIN(bytes / sizeof(ptri), (size_t)INT32_MAX);
    r->tcount = 0;
    r->tdropped = 0;
    return 0;
}

void fx3d_flush(fx3d *r)
{
    if (!r->pbuf || r->pcount == 0) {
        flush_translucent(r);
        return;
    }
    ptri *t = r->pbuf;
    int32_t n = r->pcount;
    sort_far_first(t, n);
    pctx pc;
    pctx_init(&pc, r);
    pc.zb = NULL;
    pc.zbits = 0;
    for (int32_t i = 0; i < n; i++) {
        tri_mode m = t[i].m;
        m.ztest = m.zwrite = 0;
        raster_tri(&pc, &t[i].v[0], &t[i].v[1], &t[i].v[2], &m);
        if (m.outline == 1)
            for (int k = 0; k < 3; k++)
                raster_line(&pc, &t[i].v[k], &t[i].v[(k + 1) % 3], 0, pc.wire);
    }
    r->pcount = 0;
}
