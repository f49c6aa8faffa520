/* SPDX-License-Identifier: MIT */
/* fixel — the colour models as solids (contract in mesh.h). */
#include "fixel/mesh.h"
#include "fixel/error.h"

/* the hexagon's hues in order: red, yellow, green, cyan, blue, magenta */
static const uint32_t hues[6] = {0xFFFF0000u, 0xFFFFFF00u, 0xFF00FF00u, 0xFF00FFFFu, 0xFF0000FFu, 0xFFFF00FFu};
/* cos, sin of 60k degrees in Q16 */
static const int32_t hcos[6] = {65536, 32768, -32768, -65536, -32768, 32768};
static const int32_t hsin[6] = {0, 56756, 56756, 0, -56756, -56756};

static void put_tri(fx_mesh *m, int32_t t, uint32_t a, uint32_t b, uint32_t c)
{
    /* wind (a, b, c) so that its normal points away from the origin, which
     * is inside each (convex) solid: outward is counter-clockwise from outside */
    const fx_vec3 *p = m->pos;
    int64_t ux = (int64_t)p[b].x - p[a].x, uy = (int64_t)p[b].y - p[a].y, uz = (int64_t)p[b].z - p[a].z;
    int64_t vx = (int64_t)p[c].x - p[a].x, vy = (int64_t)p[c].y - p[a].y, vz = (int64_t)p[c].z - p[a].z;
    /* edges < 2^28: products < 2^57, n < 2^42 after the shift */
    int64_t nx = (uy * vz - uz * vy) >> 16, ny = (uz * vx - ux * vz) >> 16, nz = (ux * vy - uy * vx) >> 16;
    int64_t gx = (int64_t)p[a].x + p[b].x + p[c].x, gy = (int64_t)p[a].y + p[b].y + p[c].y,
            gz = (int64_t)p[a].z + p[b].z + p[c].z;
    /* |g| < 2^29: for a large solid shifted to 2^17 so each product stays
     * under 2^59; a small one (edges under 2^21, n under 2^28) needs no shift */
    int sh = gx > (1 << 22) || gx < -(1 << 22) || gy > (1 << 22) || gy < -(1 << 22) || gz > (1 << 22) ||
                     gz < -(1 << 22) || nx > (1 << 30) || nx < -(1 << 30) || ny > (1 << 30) || ny < -(1 << 30) ||
                     nz > (1 << 30) || nz < -(1 << 30)
                 ? 12
                 : 0;
    if ((nx * (gx >> sh) + ny * (gy >> sh) + nz * (gz >> sh)) < 0) {
        uint32_t s = b;
        b = c;
        c = s;
    }
    m->tri[3 * t] = a;
    m->tri[3 * t + 1] = b;
    m->tri[3 * t + 2] = c;
}

int fx_colour_solid_make(fx_mesh *m, fx_colour_solid kind, fx16 size)
{
    if (!m || !m->pos || !m->tri || !m->col || m->cap_verts < FX_COLOUR_SOLID_VERTS ||
        m->cap_tris < FX_COLOUR_SOLID_TRIS || size <= 0 || size > 2048 * FX16_ONE || kind < 0 ||
        kind >= FX_SOLID_COUNT)
        return -FX_EINVAL;
    fx16 h = size / 2;
    m->nrm = 0;
    m->nverts = FX_COLOUR_SOLID_VERTS;
    m->ntris = FX_COLOUR_SOLID_TRIS;
    if (kind == FX_SOLID_RGB_CUBE) {
        /* vertex i = (r, g, b) bits 2, 1, 0 */
        for (uint32_t i = 0; i < 8; i++) {
            int r = (i >> 2) & 1, g = (i >> 1) & 1, b = i & 1;
            m->pos[i] = fx_vec3_make(r ? h : -h, g ? h : -h, b ? h : -h);
            m->col[i] = 0xFF000000u | (r ? 0xFF0000u : 0) | (g ? 0xFF00u : 0) | (b ? 0xFFu : 0);
        }
        /* two triangles per face: the face of axis bit `ax` at value v */
        int32_t t = 0;
        for (int ax = 0; ax < 3; ax++)
            for (uint32_t v = 0; v < 2; v++) {
                uint32_t o1 = ax == 0 ? 2 : 4, o2 = ax == 2 ? 2 : 1; /* the other two bits */
                uint32_t base = v << (2 - ax);
                uint32_t q[4] = {base, base | o1, base | o1 | o2, base | o2};
                put_tri(m, t++, q[0], q[1], q[2]);
                put_tri(m, t++, q[0], q[2], q[3]);
            }
        return 0;
    }
    /* the hexagon: radius h, at y = h (hexcone) or y = 0 (double cone) */
    fx16 hy = kind == FX_SOLID_HSV_HEXCONE ? h : 0;
    for (int k = 0; k < 6; k++) {
        m->pos[k] = fx_vec3_make((fx16)(((int64_t)h * hcos[k]) >> 16), hy, (fx16)(-(((int64_t)h * hsin[k]) >> 16)));
        m->col[k] = hues[k];
    }
    m->pos[6] = fx_vec3_make(0, -h, 0); /* black apex */
    m->col[6] = 0xFF000000u;
    m->pos[7] = fx_vec3_make(0, h, 0); /* white: top centre or apex */
    m->col[7] = 0xFFFFFFFFu;
    for (uint32_t k = 0; k < 6; k++) {
        put_tri(m, (int32_t)k, 6, k, (k + 1) % 6);
        put_tri(m, (int32_t)k + 6, 7, k, (k + 1) % 6);
    }
    return 0;
}
