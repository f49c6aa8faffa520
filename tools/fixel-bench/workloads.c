/* SPDX-License-Identifier: MIT */
/* fixel-bench — the teapot frame and the W9 picture (see workloads.h),
 * everything in caller memory, through the public API. */
#include "workloads.h"

#include <stdint.h>

#include <fixel/error.h>
#include <fixel/fractal_mt.h>
#include <fixel/mesh.h>

#define TEAPOT_N 8

typedef struct teapot_mem {
    fx_mat4 ms[4], ps[2];
    fx3d r;
} teapot_mem;

static size_t align8(size_t n) { return (n + 7) & ~(size_t)7; }

size_t bench_teapot_bytes(const fx_surface *s)
{
    fx_mesh_params p = {FX_MESH_TEAPOT, FX16_ONE, 0, 0, TEAPOT_N, 0};
    int32_t nv, nt;
    fx_mesh_size(&p, &nv, &nt);
    return align8(sizeof(teapot_mem)) + align8(fx3d_depth_bytes(s, 32)) +
           align8((size_t)nv * 2 * sizeof(fx_vec3)) + align8((size_t)nt * 3 * sizeof(uint32_t));
}

int bench_teapot(const fx_surface *s, void *mem, size_t bytes, fx_angle angle)
{
    if (!mem || bytes < bench_teapot_bytes(s) || ((uintptr_t)mem & 7))
        return -FX_EINVAL;
    uint8_t *p = mem;
    teapot_mem *b = (teapot_mem *)p;
    p += align8(sizeof *b);
    void *z = p;
    p += align8(fx3d_depth_bytes(s, 32));
    fx_mesh_params mp = {FX_MESH_TEAPOT, FX16_ONE, 0, 0, TEAPOT_N, 0};
    int32_t nv, nt;
    fx_mesh_size(&mp, &nv, &nt);
    fx_mesh m = {0};
    m.pos = (fx_vec3 *)p;
    m.nrm = m.pos + nv;
    p += align8((size_t)nv * 2 * sizeof(fx_vec3));
    m.tri = (uint32_t *)p;
    m.cap_verts = nv;
    m.cap_tris = nt;
    int e = fx_mesh_make(&m, &mp);
    if (e < 0)
        return e;

    fx3d *r = &b->r;
    e = fx3d_init(r, s, b->ms, 4, b->ps, 2);
    if (e < 0)
        return e;
    fx_surface_clear(s, 0xFF182028);
    fx3d_set_depth(r, z, 32);
    /* The camera circles the teapot at a fixed height. */
    fx16 c = fx_cos(angle), sn = fx_sin(angle);
    fx_camera cam;
    fx_camera_set(&cam, fx_vec3_make(fx16_mul(sn, 7 * FX16_ONE), 3 * FX16_ONE, fx16_mul(c, 7 * FX16_ONE)),
                  fx_vec3_make(0, FX16_ONE + FX16_HALF, 0), fx_vec3_make(0, FX16_ONE, 0));
    fx_camera_view(&cam, &r->view);
    fx3d_perspective(r, fx_angle_from_deg(40), fx16_from_ratio(s->w, s->h), FX16_ONE / 2,
                     50 * FX16_ONE);
    r->light[0].type = FX3D_LIGHT_DIRECTIONAL;
    r->light[0].pos = fx_vec3_make(FX16_ONE, FX16_ONE, FX16_ONE);
    r->light[1].type = FX3D_LIGHT_POINT;
    r->light[1].pos = fx_vec3_make(-4 * FX16_ONE, 5 * FX16_ONE, 3 * FX16_ONE);
    r->light[1].diffuse = r->light[1].specular = fx3d_rgb_from_color(0x6080FF);
    r->mat.ambient = r->mat.diffuse = fx3d_rgb_from_color(0xC04020);
    r->mat.specular = fx3d_rgb_from_color(0xFFFFFF);
    r->mat.shininess = 40;
    r->shading = FX3D_GOURAUD;
    return fx3d_draw(r, &m);
}

static fx_fractal_view w9_view(const fx_surface *s)
{
    return fx_mandel_view(-(FX56_ONE / 2), 0, 3 * FX56_ONE, s->w, s->h, 256);
}

/* The W9 set-up both entry points share; mt picks fx_fractal_render_mt
 * (with nthreads) over fx_fractal_render. */
static inline int mandel_w9(const fx_surface *s, int mt, int nthreads)
{
    if (!s)
        return -FX_EINVAL;
    uint32_t lut[65];
    fx_dwell_pal pal;
    fx_dwell_pal_w9(&pal, lut, s->format);
    fx_fractal_view v = w9_view(s);
    if (!mt)
        return fx_fractal_render(s, fx_surface_rect(s), &v, &pal);
    return fx_fractal_render_mt(s, fx_surface_rect(s), &v, &pal, nthreads);
}

int bench_mandel_w9(const fx_surface *s) { return mandel_w9(s, 0, 0); }

int bench_mandel_w9_mt(const fx_surface *s, int nthreads) { return mandel_w9(s, 1, nthreads); }
