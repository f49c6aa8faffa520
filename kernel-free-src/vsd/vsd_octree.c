/* SPDX-License-Identifier: MIT */
/* fixel — the octree method (fixel/vsd.h). */
#include "vsd_int.h"

/* Fill node slot for the cube of side n at (x0, y0, z0); a mixed node's
 * 8 children are allocated together after everything so far. */
static int build(fx_vsd_octree *o, const uint8_t *vox, int32_t size, int32_t x0, int32_t y0, int32_t z0,
                 int32_t n, int32_t slot)
{
    int32_t solid = 0;
    for (int32_t z = z0; z < z0 + n; z++)
        for (int32_t y = y0; y < y0 + n; y++)
            for (int32_t x = x0; x < x0 + n; x++)
                solid += vox[((size_t)z * (size_t)size + (size_t)y) * (size_t)size + (size_t)x] != 0;
    if (solid == 0 || solid == n * n * n) {
        o->node[slot].kind = solid != 0;
        o->node[slot].child = -1;
        return 0;
    }
    if (o->nnode > o->cap - 8)
        return -FX_ENOSPC;
    int32_t first = o->nnode, h = n / 2;
    o->nnode += 8;
    o->node[slot].kind = 2;
    o->node[slot].child = first;
    for (int32_t q = 0; q < 8; q++) {
        int e = build(o, vox, size, x0 + (q & 1) * h, y0 + ((q >> 1) & 1) * h, z0 + ((q >> 2) & 1) * h, h,
                      first + q);
        if (e < 0)
            return e;
    }
    return 0;
}

int fx_vsd_octree_build(fx_vsd_octree *o, fx_vsd_onode *mem, int32_t cap, const uint8_t *vox, int32_t k)
{
    if (!o || !mem || !vox || k < 0 || k > 8 || cap < 1)
        return -FX_EINVAL;
    o->node = mem;
    o->cap = cap;
    o->nnode = 1;
    o->k = k;
    return build(o, vox, (int32_t)1 << k, 0, 0, 0, (int32_t)1 << k, 0);
}

typedef struct orend {
    const fx_vsd_octree *o;
    int32_t scale, w, h, *depth, visited;
} orend;

static int painted(const orend *r, int32_t x0, int32_t y0, int32_t n)
{
    int32_t x1 = x0 + n > r->w ? r->w : x0 + n, y1 = y0 + n > r->h ? r->h : y0 + n;
    for (int32_t y = y0; y < y1; y++)
        for (int32_t x = x0; x < x1; x++)
            if (r->depth[(size_t)y * (size_t)r->w + (size_t)x] < 0)
                return 0;
    return 1;
}

static void visit(orend *r, int32_t nd, int32_t vx, int32_t vy, int32_t vz, int32_t n)
{
    const fx_vsd_onode *N = &r->o->node[nd];
    r->visited++;
    if (N->kind == 0)
        return;
    int32_t sx = vx * r->scale, sy = vy * r->scale, sn = n * r->scale;
    if (sx >= r->w || sy >= r->h || painted(r, sx, sy, sn))
        return; /* hidden by what is in front, with everything inside it */
    if (N->kind == 1) {
        int32_t x1 = sx + sn > r->w ? r->w : sx + sn, y1 = sy + sn > r->h ? r->h : sy + sn;
        for (int32_t y = sy; y < y1; y++)
            for (int32_t x = sx; x < x1; x++) {
                int32_t *d = &r->depth[(size_t)y * (size_t)r->w + (size_t)x];
                if (*d < 0)
                    *d = vz; /* the front face of the node: its nearest voxels */
            }
        return;
    }
    int32_t h = n / 2;
    for (int32_t q = 0; q < 8; q++) /* bit 2 (z) is the slowest: near four first */
        visit(r, N->child + q, vx + (q & 1) * h, vy + ((q >> 1) & 1) * h, vz + ((q >> 2) & 1) * h, h);
}

int32_t fx_vsd_octree_render(const fx_vsd_octree *o, int32_t scale, int32_t *depth, int32_t w, int32_t h)
{
    if (!o || !depth || scale < 1 || w < 1 || h < 1 || !o->nnode)
        return -FX_EINVAL;
    for (size_t i = 0; i < (size_t)w * (size_t)h; i++)
        depth[i] = -1;
    orend r = {o, scale, w, h, depth, 0};
    visit(&r, 0, 0, 0, 0, (int32_t)1 << o->k);
    return r.visited;
}

void fx_vsd_demo_solid(uint8_t *vox, int32_t k)
{
    int32_t n = (int32_t)1 << k, c = n / 2, rad = n * 3 / 8;
    for (int32_t z = 0; z < n; z++)
        for (int32_t y = 0; y < n; y++)
            for (int32_t x = 0; x < n; x++) {
                int32_t dx = 2 * x + 1 - 2 * c, dy = 2 * y + 1 - 2 * c, dz = 2 * z + 1 - 2 * c;
                int ball = dx * dx + dy * dy + dz * dz <= 4 * rad * rad;
                int tunnel = dx * dx + dy * dy <= n * n / 16;            /* along z: shows the wall */
                int notch = x >= c && y < c && z < c + n / 8;           /* front top-right bite */
                int slab = z >= n - n / 8 && y >= n / 8;                /* a wall behind */
                vox[((size_t)z * (size_t)n + (size_t)y) * (size_t)n + (size_t)x] =
                    (uint8_t)(((ball && !tunnel && !notch) || slab) ? 1 : 0);
            }
}
