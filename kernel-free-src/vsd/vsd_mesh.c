/* SPDX-License-Identifier: MIT */
/* fixel — meshes of the 3D pipeline as visible-surface input (fixel/vsd.h). */
#include "vsd_int.h"
#include "fixel/fixed.h"

/* round(num / den), den > 0 */
static int64_t rdiv(int64_t num, int64_t den)
{
    return num >= 0 ? (num + den / 2) / den : -((-num + den / 2) / den);
}

static int project(const fx_vsd_scene *s, const fx_mat4 *mvp, fx_vec3 p, fx_vsd_vertex *v)
{
    fx_vec4 c = fx_mat4_apply_point(mvp, p);
    if (c.w <= 0)
        return 0;
    int64_t w = c.w;
    int64_t x = rdiv(((int64_t)c.x + w) * s->w, 2 * w);
    int64_t y = rdiv((w - (int64_t)c.y) * s->h, 2 * w);
    int64_t z = rdiv(((int64_t)c.z + w) * FX_VSD_COORD_MAX, 2 * w);
    if (x < 0 || y < 0 || z < 0 || x >= s->w || y >= s->h || z > FX_VSD_COORD_MAX)
        return 0;
    v->x = (int32_t)x;
    v->y = (int32_t)y;
    v->z = (int32_t)z;
    return 1;
}

static fx_color shade(fx_color c, const fx_vsd_vertex *v)
{
    int64_t ax = v[1].x - v[0].x, ay = v[1].y - v[0].y, az = v[1].z - v[0].z;
    int64_t bx = v[2].x - v[0].x, by = v[2].y - v[0].y, bz = v[2].z - v[0].z;
    int64_t nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
    /* the depth axis spans 2047 units over the view volume, the screen
     * axes W and H: compare directions with depth scaled like x */
    uint64_t len = fx_isqrt64((uint64_t)(nx * nx + ny * ny + nz * nz));
    int64_t k = len ? (nz < 0 ? -nz : nz) * 256 / (int64_t)len : 256;
    if (k < 64)
        k = 64;
    uint32_t r = (uint32_t)(((c >> 16) & 255) * k / 256), g = (uint32_t)(((c >> 8) & 255) * k / 256),
             b = (uint32_t)((c & 255) * k / 256);
    return (c & 0xFF000000u) | r << 16 | g << 8 | b;
}

int fx_vsd_add_mesh(fx_vsd_scene *s, const fx_mat4 *mvp, const fx_mesh *m, fx_color color)
{
    if (!s || !mvp || !m || (m->ntris && (!m->tri || !m->pos)))
        return -FX_EINVAL;
    for (int32_t t = 0; t < m->ntris; t++) {
        fx_vsd_vertex v[3];
        int ok = 1;
        for (int i = 0; i < 3 && ok; i++) {
            uint32_t k = m->tri[3 * t + i];
            ok = k < (uint32_t)m->nverts && project(s, mvp, m->pos[k], &v[i]);
        }
        if (ok) {
            int e = fx_vsd_add(s, v, 3, shade(color, v));
            if (e == -FX_ENOSPC)
                return e;
            ok = e == 0;
        }
        if (!ok)
            s->culled++;
    }
    return 0;
}
