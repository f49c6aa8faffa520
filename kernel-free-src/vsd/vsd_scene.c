/* SPDX-License-Identifier: MIT */
/* fixel — the visible-surface test scene (fixel/vsd.h). Designed on a
 * 200 x 150 grid with depths 0..200 and scaled by the largest whole factor
 * that fits the screen (1 on a smaller one), so every vertex stays an integer and every quad
 * stays exactly planar. */
#include "vsd_int.h"
#include "fixel/fixed.h"

/* Add with the winding that faces the viewer (fixel/vsd.h). */
static int add_front(fx_vsd_scene *s, fx_vsd_vertex *v, int n, int32_t k, fx_color c)
{
    int64_t area = 0;
    for (int i = 0; i < n; i++) {
        v[i].x *= k;
        v[i].y *= k;
        v[i].z *= k;
    }
    for (int i = 0; i < n; i++)
        area += (int64_t)v[i].x * v[(i + 1) % n].y - (int64_t)v[(i + 1) % n].x * v[i].y;
    if (area > 0)
        for (int i = 0; i < n / 2; i++) {
            fx_vsd_vertex t = v[i];
            v[i] = v[n - 1 - i];
            v[n - 1 - i] = t;
        }
    return fx_vsd_add(s, v, n, c);
}

int fx_vsd_demo_scene(fx_vsd_scene *s, int32_t n)
{
    if (!s || n < 0)
        return -FX_EINVAL;
    int32_t k = s->w / 200 < s->h / 150 ? s->w / 200 : s->h / 150;
    if (k < 1)
        k = 1; /* a smaller screen shows the top-left part */
    if (k > 10)
        k = 10; /* depths up to 200 k stay within FX_VSD_COORD_MAX */
    int e;
    /* the floor, tilted: depth 150 - y / 5 */
    fx_vsd_vertex fl[4] = {{5, 5, 149}, {195, 5, 149}, {195, 145, 121}, {5, 145, 121}};
    /* three bars, each over the next: A (depth 50) over B, B (90 - y / 2)
     * over C, C (2 x / 5) over A */
    fx_vsd_vertex ba[4] = {{20, 30, 50}, {180, 30, 50}, {180, 50, 50}, {20, 50, 50}};
    fx_vsd_vertex bb[4] = {{140, 10, 85}, {160, 10, 85}, {160, 140, 20}, {140, 140, 20}};
    fx_vsd_vertex bc[4] = {{25, 15, 10}, {35, 5, 14}, {175, 125, 70}, {165, 135, 66}};
    /* two triangles passing through each other at x = 65 */
    fx_vsd_vertex t1[3] = {{20, 80, 20}, {20, 140, 20}, {110, 110, 110}};
    fx_vsd_vertex t2[3] = {{110, 85, 20}, {110, 145, 20}, {20, 115, 110}};
    if ((e = add_front(s, fl, 4, k, 0xFF404858u)) < 0 || (e = add_front(s, ba, 4, k, 0xFFE04040u)) < 0 ||
        (e = add_front(s, bb, 4, k, 0xFF40C040u)) < 0 || (e = add_front(s, bc, 4, k, 0xFF4070F0u)) < 0 ||
        (e = add_front(s, t1, 3, k, 0xFFF0C020u)) < 0 || (e = add_front(s, t2, 3, k, 0xFFC040C0u)) < 0)
        return e;
    uint32_t seed = 0x5eed1234u;
    for (int32_t i = 0; i < n; i++) {
        int32_t cx = 15 + (int32_t)(fx_rand32(&seed) % 170), cy = 15 + (int32_t)(fx_rand32(&seed) % 120);
        fx_vsd_vertex t[3];
        for (int j = 0; j < 3; j++) {
            t[j].x = cx - 12 + (int32_t)(fx_rand32(&seed) % 25);
            t[j].y = cy - 12 + (int32_t)(fx_rand32(&seed) % 25);
            t[j].z = 5 + (int32_t)(fx_rand32(&seed) % 140);
        }
        int64_t area = (int64_t)(t[1].x - t[0].x) * (t[2].y - t[0].y) -
                       (int64_t)(t[1].y - t[0].y) * (t[2].x - t[0].x);
        if (area == 0)
            continue; /* edge-on: nothing to see */
        uint32_t h = fx_rand32(&seed);
        fx_color col = 0xFF000000u | (0x60 + (h & 0x7F)) << 16 | (0x60 + ((h >> 8) & 0x7F)) << 8 |
                       (0x60 + ((h >> 16) & 0x7F));
        if ((e = add_front(s, t, 3, k, col)) < 0)
            return e;
    }
    return 0;
}
