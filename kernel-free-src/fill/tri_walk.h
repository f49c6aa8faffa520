/* SPDX-License-Identifier: MIT */
/* fixel — the exact edge walkers and the triangle span stepper of fill.c,
 * shared with the GL rasterizer (kernel-free-src/gl), which steps spans
 * inline: its triangles are small (tens of pixels, a few pixels a row), so
 * a call per span cost as much as the span's pixels. Not installed. */
#ifndef FIXEL_TRI_WALK_H
#define FIXEL_TRI_WALK_H

#include "fixel/fill.h"
#include "../base/fx_wide.h"

static inline int64_t ceil_shift(int64_t v, unsigned s) { return (v + (((int64_t)1 << s) - 1)) >> s; }

/* ---- exact edge stepping ----
 * The edge (x0, y0) -> (x1, y1), y0 < y1, in vertex units with s fraction
 * bits, set up at pixel row y (y0 <= y << s < y1). x = ceil(xc / 2^s) and
 * e = x*D - N where D = dy << s and N = x0*dy + t*dx, t = (y << s) - y0. */
/* floor division with remainder for d > 0, on 32 bits when the operands
 * fit (a 64-bit divide costs several times more on common cores). */
static inline void floordivmod(int64_t n, int64_t d, int64_t *q, int64_t *r)
{
    int64_t qq, rr;
    if (n >= INT32_MIN && n <= INT32_MAX && d <= INT32_MAX) {
        int32_t n32 = (int32_t)n, d32 = (int32_t)d;
        qq = n32 / d32;
        rr = n32 % d32;
    } else {
        qq = n / d;
        rr = n % d;
    }
    if (rr < 0) {
        qq--;
        rr += d;
    }
    *q = qq;
    *r = rr;
}

static inline void edge_setup(fx_tri_edge *g, int64_t x0, int64_t y0, int64_t x1, int64_t y1,
                              unsigned s, int64_t y)
{
    int64_t dx = x1 - x0, dy = y1 - y0, t = y * ((int64_t)1 << s) - y0, qa, ra;
    int64_t adx = dx < 0 ? -dx : dx;
    if (t < ((int64_t)1 << 31) && adx < ((int64_t)1 << 31))
        floordivmod(t * dx, dy, &qa, &ra);
    else
        fx_w_floordivmod(fx_w_mul(t, dx), dy, &qa, &ra);
    int64_t m = x0 + qa;
    int64_t x = (m + (ra > 0) + (((int64_t)1 << s) - 1)) >> s;
    g->x = x;
    g->d = dy * ((int64_t)1 << s);
    g->e = dy * (x * ((int64_t)1 << s) - m) - ra;
    /* per-row step S = dx << s = qs*D + rs */
    int64_t q, r;
    floordivmod(dx, dy, &q, &r);
    g->qs = q;
    g->rs = r * ((int64_t)1 << s);
}

/* Branch-free: whether the error wraps is close to random from row to row
 * on a sloped edge, and the edges of a row do not depend on each other, so
 * a mask costs less than the mispredicted branches. */
static inline void edge_step(fx_tri_edge *g)
{
    int64_t e = g->e - g->rs, m = -(int64_t)(e < 0);
    g->e = e + (g->d & m);
    g->x += g->qs - m;
}

static inline int64_t clamp64(int64_t v, int32_t lo, int32_t hi) { return v < lo ? lo : v > hi ? hi : v; }

static inline int tri_next(fx_tri *t, fx_tri_span *s)
{
    while (t->y < t->yend) {
        int32_t y = t->y;
        if (y == t->ymid) {
            /* switch to the lower short edge; ymid == y happens once */
            edge_setup(&t->sht, t->vx[1], t->vy[1], t->vx[2], t->vy[2], 8, y);
            t->ymid = INT32_MIN;
        }
        /* selected by mask: compiled as a branch it was mispredicted on
         * about every other small triangle */
        int64_t m = -(int64_t)(t->long_left != 0), a = t->lng.x, b = t->sht.x;
        int64_t xl = (a & m) | (b & ~m), xr = (b & m) | (a & ~m);
        t->y = y + 1;
        edge_step(&t->lng);
        edge_step(&t->sht);
        xl = clamp64(xl, t->clip.x0, t->clip.x1);
        xr = clamp64(xr, t->clip.x0, t->clip.x1);
        if (xl < xr) {
            s->y = y;
            s->x0 = (int32_t)xl;
            s->x1 = (int32_t)xr;
            return 1;
        }
    }
    return 0;
}

#endif
