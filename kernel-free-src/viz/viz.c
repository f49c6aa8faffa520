/* SPDX-License-Identifier: MIT */
/* fixel — visualisation of integer grids (contracts in viz.h). */
#include "fixel/viz.h"
#include "fixel/error.h"
#include "fixel/line.h"
#include "../base/fx_internal.h"

static int grid_ok(const fx_grid *g)
{
    return g && g->v && g->w >= 2 && g->h >= 2 && g->stride >= g->w;
}

static int vgrid_ok(const fx_vgrid *g)
{
    return g && g->u && g->v && g->w >= 2 && g->h >= 2 && g->stride >= g->w;
}

void fx_grid_range(const fx_grid *g, int32_t *lo, int32_t *hi)
{
    int32_t a = INT32_MAX, b = INT32_MIN;
    for (int32_t j = 0; j < g->h; j++)
        for (int32_t i = 0; i < g->w; i++) {
            int32_t v = g->v[(ptrdiff_t)j * g->stride + i];
            a = v < a ? v : a;
            b = v > b ? v : b;
        }
    *lo = a;
    *hi = b;
}

/* 24.8 (sh = 8) or 16.16 (sh = 16) to the nearest pixel, ties up,
 * saturating: geometry reaching past int32 stays a (clipped) far point. */
static int32_t px_of(int64_t v, int sh)
{
    int64_t p = (v + ((int64_t)1 << (sh - 1))) >> sh;
    return fx_sat32(p);
}

/* Rounded (ties away from zero) n / d for d > 0. */
static int64_t rdiv(int64_t n, int64_t d)
{
    return n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d);
}

/* Pixel coordinate p (any integer, Q16.16 when q16) -> grid coordinate in
 * Q16.16 along an axis of n nodes spread over [o, o + len). */
static int64_t to_grid(int64_t p16, int32_t o, int64_t len, int32_t n)
{
    if (len < 2)
        return 0;
    return rdiv((p16 - (int64_t)o * 65536) * (n - 1), len - 1);
}

/* Bilinear sample at grid position (gx, gy) in Q16.16, clamped to the grid. */
static int64_t sample(const int32_t *v, int32_t w, int32_t h, int32_t stride, int64_t gx, int64_t gy)
{
    int64_t maxx = (int64_t)(w - 1) * 65536, maxy = (int64_t)(h - 1) * 65536;
    gx = gx < 0 ? 0 : gx > maxx ? maxx : gx;
    gy = gy < 0 ? 0 : gy > maxy ? maxy : gy;
    int32_t i = (int32_t)(gx >> 16), j = (int32_t)(gy >> 16);
    int64_t fx = gx & 0xFFFF, fy = gy & 0xFFFF;
    if (i == w - 1) {
        i--;
        fx = 65536;
    }
    if (j == h - 1) {
        j--;
        fy = 65536;
    }
    const int32_t *r0 = v + (ptrdiff_t)j * stride + i, *r1 = r0 + stride;
    int64_t top = (int64_t)r0[0] * (65536 - fx) + (int64_t)r0[1] * fx;
    int64_t bot = (int64_t)r1[0] * (65536 - fx) + (int64_t)r1[1] * fx;
    /* Q16 -> Q8 keeps the second product within 64 bits (|value| < 2^31) */
    int64_t t8 = rdiv(top, 256), b8 = rdiv(bot, 256);
    return rdiv(t8 * (65536 - fy) + b8 * fy, (int64_t)1 << 24);
}

int fx_heatmap(const fx_ctx *c, fx_rect dest, const fx_grid *g, int32_t lo, int32_t hi, fx_cmap m)
{
    if (!grid_ok(g) || fx_rect_empty(dest))
        return -FX_EINVAL;
    uint32_t lut[256];
    fx_color tab[256];
    fx_cmap_table(m, tab, 256);
    for (int i = 0; i < 256; i++)
        lut[i] = fx_pack(c->surf.format, tab[i]);
    fx_rect r = fx_rect_intersect(dest, c->clip);
    int64_t range = (int64_t)hi - lo;
    int64_t W = (int64_t)dest.x1 - dest.x0, H = (int64_t)dest.y1 - dest.y0;
    for (int32_t y = r.y0; y < r.y1; y++) {
        int64_t gy = to_grid((int64_t)y * 65536, dest.y0, H, g->h);
        for (int32_t x = r.x0; x < r.x1; x++) {
            int64_t gx = to_grid((int64_t)x * 65536, dest.x0, W, g->w);
            int64_t v = sample(g->v, g->w, g->h, g->stride, gx, gy);
            int64_t idx = range > 0 ? rdiv((v - lo) * 255, range) : 0;
            idx = idx < 0 ? 0 : idx > 255 ? 255 : idx;
            fx_surface_put_native(&c->surf, x, y, lut[idx]);
        }
    }
    return 0;
}

void fx_colorbar(const fx_ctx *c, fx_rect r, fx_cmap m, int ticks)
{
    int64_t w = (int64_t)r.x1 - r.x0, h = (int64_t)r.y1 - r.y0;
    if (w < 1 || h < 1 || w > INT32_MAX || h > INT32_MAX)
        return;
    int vertical = h > w;
    int32_t n = vertical ? h : w;
    fx_ctx cc = *c;
    /* Only the bands inside the clip are walked: a bar of 2^31 rows off a
     * small surface took a minute (issue #26). All positions in 64 bits. */
    int64_t k0, k1;
    if (vertical) { /* row r.y1 - 1 - k */
        k0 = (int64_t)r.y1 - c->clip.y1;
        k1 = (int64_t)r.y1 - 1 - c->clip.y0;
    } else { /* column r.x0 + k */
        k0 = (int64_t)c->clip.x0 - r.x0;
        k1 = (int64_t)c->clip.x1 - 1 - r.x0;
    }
    k0 = FX_MAX(k0, 0);
    k1 = FX_MIN(k1, (int64_t)n - 1);
    for (int64_t k = k0; k <= k1; k++) {
        /* t from 0 at the low end to 1 at the high end */
        uint32_t t = n > 1 ? (uint32_t)(((uint64_t)k * 65536 + (uint32_t)(n - 1) / 2) / (uint32_t)(n - 1)) : 0;
        fx_ctx_set_color(&cc, fx_cmap_color(m, t));
        if (vertical)
            fx_hspan(&cc, (int32_t)(r.y1 - 1 - k), r.x0, r.x1);
        else
            fx_fill_rect(&cc, (int32_t)(r.x0 + k), r.y0, 1, (int32_t)h);
    }
    fx_rect_outline(c, fx_sat32((int64_t)r.x0 - 1), fx_sat32((int64_t)r.y0 - 1), fx_sat32(w + 2), fx_sat32(h + 2));
    if (ticks < 2)
        return;
    for (int i = 0; i < ticks; i++) {
        int64_t off = rdiv((int64_t)i * (n - 1), ticks - 1);
        if (vertical) {
            int32_t y = fx_sat32((int64_t)r.y1 - 1 - off);
            fx_line(c, fx_sat32((int64_t)r.x1 + 1), y, fx_sat32((int64_t)r.x1 + 3), y);
        } else {
            int32_t x = fx_sat32((int64_t)r.x0 + off);
            fx_line(c, x, fx_sat32((int64_t)r.y1 + 1), x, fx_sat32((int64_t)r.y1 + 3));
        }
    }
}

/* Node position along an axis in 24.8. */
static int64_t node8(int32_t o, int64_t len, int32_t n, int32_t i)
{
    return (int64_t)o * 256 + rdiv((int64_t)i * (len - 1) * 256, n - 1);
}

typedef struct cell {
    int64_t x[4], y[4]; /* corners in 24.8: TL, TR, BR, BL */
    int64_t v[4];
} cell;

/* Crossing on the edge from corner a to corner b (canonical direction). */
static void cross(const cell *q, int a, int b, int64_t level, int32_t *px, int32_t *py)
{
    /* the fraction of the way, Q8.24 in [0, 1]: both factors < 2^33 */
    int64_t t = rdiv((level - q->v[a]) * ((int64_t)1 << 24), q->v[b] - q->v[a]);
    int64_t x = q->x[a] + fx_mul64_shift(q->x[b] - q->x[a], t, 24);
    int64_t y = q->y[a] + fx_mul64_shift(q->y[b] - q->y[a], t, 24);
    *px = px_of(x, 8);
    *py = px_of(y, 8);
}

/* Edges: 0 top (TL->TR), 1 right (TR->BR), 2 bottom (BL->BR), 3 left (TL->BL). */
static const uint8_t edge_ends[4][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}};

int32_t fx_contour(const fx_ctx *c, fx_rect dest, const fx_grid *g, int32_t level)
{
    if (!grid_ok(g) || fx_rect_empty(dest))
        return -FX_EINVAL;
    /* segments per case as edge pairs; 5 and 10 (saddles) are decided below */
    static const int8_t table[16][4] = {
        {-1, -1, -1, -1}, {3, 0, -1, -1}, {0, 1, -1, -1}, {3, 1, -1, -1},
        {1, 2, -1, -1},   {-1, -1, -1, -1}, {0, 2, -1, -1}, {3, 2, -1, -1},
        {2, 3, -1, -1},   {0, 2, -1, -1}, {-1, -1, -1, -1}, {1, 2, -1, -1},
        {1, 3, -1, -1},   {0, 1, -1, -1}, {3, 0, -1, -1}, {-1, -1, -1, -1},
    };
    int64_t W = (int64_t)dest.x1 - dest.x0, H = (int64_t)dest.y1 - dest.y0;
    int32_t segs = 0;
    for (int32_t j = 0; j + 1 < g->h; j++) {
        int64_t y0 = node8(dest.y0, H, g->h, j), y1 = node8(dest.y0, H, g->h, j + 1);
        if (y1 < ((int64_t)c->clip.y0 - 1) * 256 || y0 > ((int64_t)c->clip.y1 + 1) * 256)
            continue;
        for (int32_t i = 0; i + 1 < g->w; i++) {
            const int32_t *r0 = g->v + (ptrdiff_t)j * g->stride + i, *r1 = r0 + g->stride;
            cell q;
            q.v[0] = r0[0];
            q.v[1] = r0[1];
            q.v[2] = r1[1];
            q.v[3] = r1[0];
            int k = (q.v[0] >= level) | (q.v[1] >= level) << 1 | (q.v[2] >= level) << 2 |
                    (q.v[3] >= level) << 3;
            if (k == 0 || k == 15)
                continue;
            int64_t x0 = node8(dest.x0, W, g->w, i), x1 = node8(dest.x0, W, g->w, i + 1);
            q.x[0] = q.x[3] = x0;
            q.x[1] = q.x[2] = x1;
            q.y[0] = q.y[1] = y0;
            q.y[2] = q.y[3] = y1;
            int8_t e[4] = {table[k][0], table[k][1], table[k][2], table[k][3]};
            if (k == 5 || k == 10) {
                int centre_up = q.v[0] + q.v[1] + q.v[2] + q.v[3] >= 4 * (int64_t)level;
                /* the corners on the centre's side stay joined through it */
                int join02 = (k == 5) == centre_up;
                if (join02) {
                    e[0] = 0; e[1] = 1; e[2] = 2; e[3] = 3; /* cut off TR and BL */
                } else {
                    e[0] = 3; e[1] = 0; e[2] = 1; e[3] = 2; /* cut off TL and BR */
                }
            }
            for (int s = 0; s < 4 && e[s] >= 0; s += 2) {
                int32_t ax, ay, bx, by;
                cross(&q, edge_ends[e[s]][0], edge_ends[e[s]][1], level, &ax, &ay);
                cross(&q, edge_ends[e[s + 1]][0], edge_ends[e[s + 1]][1], level, &bx, &by);
                fx_line(c, ax, ay, bx, by);
                segs++;
            }
        }
    }
    return segs;
}

#define COS30_Q30 929887697 /* cos 30 degrees in Q2.30 */

int32_t fx_quiver(const fx_ctx *c, fx_rect dest, const fx_vgrid *g, int32_t step)
{
    if (!vgrid_ok(g) || fx_rect_empty(dest) || step < 1)
        return -FX_EINVAL;
    int64_t W = (int64_t)dest.x1 - dest.x0, H = (int64_t)dest.y1 - dest.y0;
    uint32_t maxmag = 0;
    for (int32_t j = 0; j < g->h; j += step)
        for (int32_t i = 0; i < g->w; i += step) {
            ptrdiff_t o = (ptrdiff_t)j * g->stride + i;
            uint32_t m = fx_hypot(g->u[o], g->v[o]);
            maxmag = m > maxmag ? m : maxmag;
        }
    /* node spacing in 24.8, the smaller axis */
    int64_t sx = rdiv((int64_t)(W - 1) * 256 * step, g->w - 1);
    int64_t sy = rdiv((int64_t)(H - 1) * 256 * step, g->h - 1);
    int64_t spacing = sx < sy ? sx : sy;
    int32_t arrows = 0;
    for (int32_t j = 0; j < g->h; j += step)
        for (int32_t i = 0; i < g->w; i += step) {
            ptrdiff_t o = (ptrdiff_t)j * g->stride + i;
            int64_t bx = node8(dest.x0, W, g->w, i), by = node8(dest.y0, H, g->h, j);
            int32_t px = px_of(bx, 8), py = px_of(by, 8);
            uint32_t m = fx_hypot(g->u[o], g->v[o]);
            arrows++;
            if (m == 0 || maxmag == 0) {
                fx_plot(c, px, py);
                continue;
            }
            /* unit direction on screen (v up) in Q32, length in 24.8; the
             * 128-bit products keep any int32 geometry in range */
            int64_t ex = ((int64_t)g->u[o] * ((int64_t)1 << 32)) / m;
            int64_t ey = -((int64_t)g->v[o] * ((int64_t)1 << 32)) / m;
            int64_t len = fx_mul64_shift(spacing * 9 / 10, ((int64_t)m << 32) / maxmag, 32);
            int64_t dx = fx_mul64_shift(len, ex, 32), dy = fx_mul64_shift(len, ey, 32);
            int64_t tx = bx + dx, ty = by + dy;
            fx_line(c, px, py, px_of(tx, 8), px_of(ty, 8));
            int64_t hl = len / 3 > 512 ? len / 3 : 512;
            /* back along the shaft, turned +-30 degrees */
            int64_t ux = -fx_mul64_shift(hl, ex, 32), uy = -fx_mul64_shift(hl, ey, 32);
            for (int s = -1; s <= 1; s += 2) {
                int64_t hx = fx_mul64_shift(ux, COS30_Q30, 30) - s * (uy / 2);
                int64_t hy = s * (ux / 2) + fx_mul64_shift(uy, COS30_Q30, 30);
                fx_line(c, px_of(tx, 8), px_of(ty, 8),
                        px_of(tx + hx, 8), px_of(ty + hy, 8));
            }
        }
    return arrows;
}

/* Screen-space step of length h (Q16.16 px) along the field at p (Q16.16
 * px); 0 when the field vanishes there. */
static int dir_at(const fx_vgrid *g, fx_rect d, int64_t px, int64_t py, int64_t h, int64_t *dx,
                  int64_t *dy)
{
    int64_t gx = to_grid(px, d.x0, (int64_t)d.x1 - d.x0, g->w),
            gy = to_grid(py, d.y0, (int64_t)d.y1 - d.y0, g->h);
    int64_t u = sample(g->u, g->w, g->h, g->stride, gx, gy);
    int64_t v = sample(g->v, g->w, g->h, g->stride, gx, gy);
    uint32_t m = fx_hypot((int32_t)u, (int32_t)v);
    if (m == 0)
        return 0;
    *dx = rdiv(u * h, m);
    *dy = rdiv(-v * h, m);
    return 1;
}

int32_t fx_streamline(const fx_ctx *c, fx_rect dest, const fx_vgrid *g, int32_t sx, int32_t sy,
                      fx16 h, int32_t max_steps)
{
    if (!vgrid_ok(g) || fx_rect_empty(dest) || h <= 0 || max_steps < 0)
        return -FX_EINVAL;
    int32_t steps = 0;
    const int64_t lox = (int64_t)dest.x0 * 65536, hix = (int64_t)(dest.x1 - 1) * 65536;
    const int64_t loy = (int64_t)dest.y0 * 65536, hiy = (int64_t)(dest.y1 - 1) * 65536;
    for (int dirn = 1; dirn >= -1; dirn -= 2) {
        int64_t x = (int64_t)sx * 65536, y = (int64_t)sy * 65536, hh = (int64_t)h * dirn;
        for (int32_t k = 0; k < max_steps; k++) {
            if (x < lox || x > hix || y < loy || y > hiy)
                break;
            int64_t k1x, k1y, k2x, k2y;
            if (!dir_at(g, dest, x, y, hh, &k1x, &k1y))
                break;
            if (!dir_at(g, dest, x + k1x / 2, y + k1y / 2, hh, &k2x, &k2y))
                break;
            int64_t nx = x + k2x, ny = y + k2y;
            fx_line(c, px_of(x, 16), px_of(y, 16),
                    px_of(nx, 16), px_of(ny, 16));
            x = nx;
            y = ny;
            steps++;
        }
    }
    return steps;
}
