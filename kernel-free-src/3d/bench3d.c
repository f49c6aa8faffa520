/* SPDX-License-Identifier: MIT */
/* fixel — the 3D benchmark frame: a Gouraud teapot on a surface of any
 * size, everything in caller memory (see fx3d_bench_teapot in render3d.h). */
#include "fixel/error.h"
#include "fixel/render3d.h"
#include "../base/fx_internal.h"

#define BENCH_N 8

typedef struct bench_mem {
    fx_mat4 ms[4], ps[2];
    fx3d r;
} bench_mem;

static size_t align8(size_t n) { return (n + 7) & ~(size_t)7; }

size_t fx3d_bench_teapot_bytes(const fx_surface *s)
{
    fx_mesh_params p = {FX_MESH_TEAPOT, FX16_ONE, 0, 0, BENCH_N, 0};
    int32_t nv, nt;
    fx_mesh_size(&p, &nv, &nt);
    return align8(sizeof(bench_mem)) + align8(fx3d_depth_bytes(s, 32)) +
           align8((size_t)nv * 2 * sizeof(fx_vec3)) + align8((size_t)nt * 3 * sizeof(uint32_t));
}

int fx3d_bench_teapot(const fx_surface *s, void *mem, size_t bytes, fx_angle angle)
{
    if (!mem || bytes < fx3d_bench_teapot_bytes(s) || ((uintptr_t)mem & 7))
        return -FX_EINVAL;
    uint8_t *p = mem;
    bench_mem *b = (bench_mem *)p;
    p += align8(sizeof *b);
    void *z = p;
    p += align8(fx3d_depth_bytes(s, 32));
    fx_mesh_params mp = {FX_MESH_TEAPOT, FX16_ONE, 0, 0, BENCH_N, 0};
    int32_t nv, nt;
    fx_mesh_size(&mp, &nv, &nt);
    fx_mesh m;
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
