/* SPDX-License-Identifier: MIT */
/* fixel — tensor-field glyphs, star glyphs and multi-part glyphs
 * (contracts in viz.h). */
#include "fixel/viz.h"
#include "fixel/circle.h"
#include "fixel/error.h"
#include "fixel/fill.h"
#include "fixel/line.h"
#include "../base/fx_internal.h"

static int64_t rdiv(int64_t n, int64_t d)
{
    return n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d);
}

static int64_t iabs64(int64_t v) { return v < 0 ? -v : v; }

/* (x, y) (not both 0) scaled to a unit vector in Q16. The components
 * may reach 2^33 or be a few units: the larger is first brought into
 * [2^29, 2^30] (halving moves the direction by under 2^-29, doubling is
 * exact), so fx_hypot's rounding to an integer costs under 2^-29. */
static void unit(int64_t x, int64_t y, fx16 *ux, fx16 *uy)
{
    while (iabs64(x) > (1 << 30) || iabs64(y) > (1 << 30)) {
        x = rdiv(x, 2);
        y = rdiv(y, 2);
    }
    while (iabs64(x) < (1 << 29) && iabs64(y) < (1 << 29)) {
        x *= 2;
        y *= 2;
    }
    uint32_t h = fx_hypot((int32_t)x, (int32_t)y);
    *ux = (fx16)rdiv(x * 65536, h);
    *uy = (fx16)rdiv(y * 65536, h);
}

int fx_eigen2_sym(int32_t a, int32_t b, int32_t c, fx_eigen2 *e)
{
    if (a < -FX_TENSOR_MAX || a > FX_TENSOR_MAX || b < -FX_TENSOR_MAX || b > FX_TENSOR_MAX ||
        c < -FX_TENSOR_MAX || c > FX_TENSOR_MAX)
        return -FX_ERANGE;
    int64_t d = (int64_t)a - c, b2 = 2 * (int64_t)b;
    /* d^2 + 4b^2 <= 2 * 2^60: fits unsigned 64 bits */
    uint64_t n = (uint64_t)(d * d) + (uint64_t)(b2 * b2);
    uint64_t s = fx_isqrt64(n);
    if (n - s * s > s) /* n > (s + 1/2)^2: nearer s + 1 */
        s++;
    int64_t D = (int64_t)s, tr = (int64_t)a + c;
    e->l1 = (int32_t)rdiv(tr + D, 2);
    e->l2 = (int32_t)rdiv(tr - D, 2);
    if (D == 0) {
        e->v1x = FX16_ONE;
        e->v1y = 0;
        e->v2x = 0;
        e->v2y = FX16_ONE;
        e->angle = 0;
        return 0;
    }
    /* rows of A - l I scaled by 2: (a - l, b) and (b, c - l); the larger of
     * d + D and D - d (both >= 0) keeps the vector far from zero */
    int64_t x1, y1, x2, y2;
    if (d >= 0) {
        x1 = d + D, y1 = b2;
        x2 = b2, y2 = -(d + D);
    } else {
        x1 = b2, y1 = D - d;
        x2 = d - D, y2 = b2;
    }
    unit(x1, y1, &e->v1x, &e->v1y);
    unit(x2, y2, &e->v2x, &e->v2y);
    if (e->v1y < 0 || (e->v1y == 0 && e->v1x < 0)) {
        e->v1x = -e->v1x;
        e->v1y = -e->v1y;
    }
    /* v2 a quarter turn counter-clockwise from v1, so the pair is right-handed */
    if ((int64_t)e->v1x * e->v2y - (int64_t)e->v1y * e->v2x < 0) {
        e->v2x = -e->v2x;
        e->v2y = -e->v2y;
    }
    /* exact on the axes, where CORDIC is a few units off */
    e->angle = e->v1y == 0 ? 0 : e->v1x == 0 ? FX_ANGLE_90 : fx_atan2(e->v1y, e->v1x);
    return 0;
}

static int32_t px8(int64_t v) { return fx_sat32((v + 128) >> 8); }

#define COS30_Q30 929887697 /* cos 30 degrees in Q2.30 */

/* Two barbs at +-30 degrees from the tip (tx, ty) back along -(ex, ey)
 * (unit Q16, screen axes), hl long (24.8). */
static void barbs(const fx_ctx *c, int64_t tx, int64_t ty, int64_t ex, int64_t ey, int64_t hl)
{
    int64_t ux = -((hl * ex) >> 16), uy = -((hl * ey) >> 16);
    for (int s = -1; s <= 1; s += 2) {
        int64_t hx = fx_mul64_shift(ux, COS30_Q30, 30) - s * (uy / 2);
        int64_t hy = s * (ux / 2) + fx_mul64_shift(uy, COS30_Q30, 30);
        fx_line(c, px8(tx), px8(ty), px8(tx + hx), px8(ty + hy));
    }
}

/* One principal axis: a line through the centre, r long each way along the
 * screen direction (ex, ey), with heads by the eigenvalue's sign. */
static void axis(const fx_ctx *c, int64_t cx, int64_t cy, int64_t ex, int64_t ey, int64_t r, int32_t l)
{
    if (r < 128)
        return;
    int64_t dx = (r * ex) >> 16, dy = (r * ey) >> 16;
    fx_line(c, px8(cx - dx), px8(cy - dy), px8(cx + dx), px8(cy + dy));
    if (l == 0)
        return;
    int64_t hl = r / 3;
    hl = hl < 2 * 256 ? 2 * 256 : hl > 6 * 256 ? 6 * 256 : hl;
    for (int end = -1; end <= 1; end += 2) {
        int64_t tx = cx + end * dx, ty = cy + end * dy;
        /* out along the axis at this end */
        int64_t ox = end * ex, oy = end * ey;
        if (l > 0)
            barbs(c, tx, ty, ox, oy, hl);
        else
            barbs(c, tx, ty, -ox, -oy, hl);
    }
}

#define GLYPH_N 32

void fx_tensor_glyph(const fx_ctx *c, fx8 cx, fx8 cy, const fx_eigen2 *e, int64_t lmax, int64_t rmax,
                     const fx_tensor_style *st)
{
    if (!c || !e || lmax <= 0 || rmax < 0 || rmax > ((int64_t)1 << 40))
        return;
    /* semi-axes in 24.8: |l| <= 2^31 and rmax <= 2^40 keep the product in 2^71:
     * divide first when it would not fit */
    int64_t l1 = iabs64(e->l1), l2 = iabs64(e->l2);
    int64_t r1 = fx_mul64_shift(rmax, ((int64_t)(l1 > lmax ? lmax : l1) << 30) / lmax, 30);
    int64_t r2 = fx_mul64_shift(rmax, ((int64_t)(l2 > lmax ? lmax : l2) << 30) / lmax, 30);
    int64_t rr = r1 > r2 ? r1 : r2;
    /* off the clip: nothing to draw (and the polygon stays within fx8) */
    if ((int64_t)cx + rr + 2048 < (int64_t)c->clip.x0 * 256 || (int64_t)cx - rr - 2048 > (int64_t)c->clip.x1 * 256 ||
        (int64_t)cy + rr + 2048 < (int64_t)c->clip.y0 * 256 || (int64_t)cy - rr - 2048 > (int64_t)c->clip.y1 * 256)
        return;
    /* screen directions: y runs down */
    int64_t e1x = e->v1x, e1y = -(int64_t)e->v1y, e2x = e->v2x, e2y = -(int64_t)e->v2y;
    if (r1 >= 128 || r2 >= 128) {
        fx8 xy[2 * GLYPH_N];
        int32_t pix[2 * GLYPH_N];
        for (int k = 0; k < GLYPH_N; k++) {
            fx_angle t = (fx_angle)((uint32_t)k << 27);
            int64_t co = fx_cos(t), si = fx_sin(t);
            int64_t a1 = (r1 * co) >> 16, a2 = (r2 * si) >> 16;
            int64_t x = cx + ((a1 * e1x + a2 * e2x) >> 16);
            int64_t y = cy + ((a1 * e1y + a2 * e2y) >> 16);
            xy[2 * k] = fx_sat32(x);
            xy[2 * k + 1] = fx_sat32(y);
            pix[2 * k] = px8(x);
            pix[2 * k + 1] = px8(y);
        }
        fx_ctx f = *c;
        if (st) {
            int s1 = (e->l1 > 0) - (e->l1 < 0), s2 = (e->l2 > 0) - (e->l2 < 0);
            fx_ctx_set_color(&f, s1 >= 0 && s2 >= 0 ? st->pos : s1 <= 0 && s2 <= 0 ? st->neg : st->mixed);
        }
        fx_fill_poly8(&f, xy, GLYPH_N, FX_FILL_EVENODD);
        for (int k = 0; k < GLYPH_N; k++) {
            int j = (k + 1) % GLYPH_N;
            fx_line(c, pix[2 * k], pix[2 * k + 1], pix[2 * j], pix[2 * j + 1]);
        }
    }
    axis(c, cx, cy, e1x, e1y, r1, e->l1);
    axis(c, cx, cy, e2x, e2y, r2, e->l2);
}

static int tgrid_ok(const fx_tgrid *g)
{
    return g && g->a && g->b && g->c && g->w >= 2 && g->h >= 2 && g->stride >= g->w;
}

/* Node position along an axis in 24.8: viz.c's node8 (so glyphs sit where
 * quiver's arrows do) while i (len - 1) 256 fits 63 bits, else rounded
 * to the pixel first. */
static int64_t node8(int32_t o, int64_t len, int32_t n, int32_t i)
{
    if (len <= ((int64_t)1 << 23))
        return (int64_t)o * 256 + rdiv((int64_t)i * (len - 1) * 256, n - 1);
    return ((int64_t)o + rdiv((int64_t)i * (len - 1), n - 1)) * 256;
}

/* Node spacing along an axis times step, 24.8, capped at 2^41 (glyphs
 * that large are all off any surface). */
static int64_t spacing8(int64_t len, int32_t n, int32_t step)
{
    int64_t one = len <= ((int64_t)1 << 23) ? rdiv((len - 1) * 256, n - 1) : rdiv(len - 1, n - 1) * 256;
    return one > (((int64_t)1 << 41) / step) ? (int64_t)1 << 41 : one * step;
}

int32_t fx_tensor_glyphs(const fx_ctx *c, fx_rect dest, const fx_tgrid *g, int32_t step,
                         const fx_tensor_style *st)
{
    if (!tgrid_ok(g) || fx_rect_empty(dest) || step < 1)
        return -FX_EINVAL;
    int64_t lmax = 0;
    for (int32_t j = 0; j < g->h; j += step)
        for (int32_t i = 0; i < g->w; i += step) {
            ptrdiff_t o = (ptrdiff_t)j * g->stride + i;
            fx_eigen2 e;
            if (fx_eigen2_sym(g->a[o], g->b[o], g->c[o], &e) < 0)
                return -FX_ERANGE;
            int64_t m = iabs64(e.l1) > iabs64(e.l2) ? iabs64(e.l1) : iabs64(e.l2);
            lmax = m > lmax ? m : lmax;
        }
    int64_t W = (int64_t)dest.x1 - dest.x0, H = (int64_t)dest.y1 - dest.y0;
    int64_t sx = spacing8(W, g->w, step), sy = spacing8(H, g->h, step);
    int64_t rmax = (sx < sy ? sx : sy) * 45 / 100;
    rmax = rmax > ((int64_t)1 << 40) ? (int64_t)1 << 40 : rmax;
    int32_t n = 0;
    for (int32_t j = 0; j < g->h; j += step)
        for (int32_t i = 0; i < g->w; i += step) {
            ptrdiff_t o = (ptrdiff_t)j * g->stride + i;
            fx_eigen2 e;
            fx_eigen2_sym(g->a[o], g->b[o], g->c[o], &e);
            int64_t x = node8(dest.x0, W, g->w, i), y = node8(dest.y0, H, g->h, j);
            n++;
            if (lmax == 0) {
                fx_plot(c, px8(x), px8(y));
                continue;
            }
            /* node positions reach 2^39 in 24.8: a glyph far off the clip is
             * skipped whole. It reaches rmax from its centre, and a head's
             * barbs up to 6 px (hl) beyond a tip; 8 px covers them and the
             * rounding to pixels, so a band of a frame skips only glyphs
             * that draw nothing in it (a 1 px margin lost barbs at band edges) */
            if (x < ((int64_t)c->clip.x0 - 8) * 256 - rmax || x > ((int64_t)c->clip.x1 + 8) * 256 + rmax ||
                y < ((int64_t)c->clip.y0 - 8) * 256 - rmax || y > ((int64_t)c->clip.y1 + 8) * 256 + rmax)
                continue;
            /* near the clip but with a radius past 2^23 px its centre does
             * not fit fx8: skipped rather than drawn round a wrapped centre */
            if (x < INT32_MIN || x > INT32_MAX || y < INT32_MIN || y > INT32_MAX)
                continue;
            fx_tensor_glyph(c, (fx8)x, (fx8)y, &e, lmax, rmax, st);
        }
    return n;
}

int fx_star_glyph(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r, const fx16 *vals, int32_t n,
                  fx_color outline)
{
    if (!c || !vals || n < 3 || n > 32 || r < 0)
        return -FX_EINVAL;
    int32_t xy[64];
    for (int32_t k = 0; k < n; k++) {
        int64_t v = vals[k] < 0 ? 0 : vals[k] > FX16_ONE ? FX16_ONE : vals[k];
        /* clockwise from straight up on screen: (sin t, -cos t) */
        fx_angle t = (fx_angle)(((uint64_t)k << 32) / (uint32_t)n);
        int64_t len = (int64_t)r * v; /* Q16 pixels */
        /* len reaches 2^47 for r near 2^31: the product takes 128 bits */
        xy[2 * k] = fx_sat32((int64_t)cx + fx_mul64_shift(len, fx_sin(t), 32));
        xy[2 * k + 1] = fx_sat32((int64_t)cy - fx_mul64_shift(len, fx_cos(t), 32));
    }
    fx_fill_poly(c, xy, n, FX_FILL_NONZERO);
    fx_ctx o = *c;
    fx_ctx_set_color(&o, outline);
    for (int32_t k = 0; k < n; k++) {
        int32_t j = (k + 1) % n;
        fx_line(&o, cx, cy, xy[2 * k], xy[2 * k + 1]);
        fx_line(&o, xy[2 * k], xy[2 * k + 1], xy[2 * j], xy[2 * j + 1]);
    }
    return 0;
}

void fx_multi_glyph(const fx_ctx *c, int32_t cx, int32_t cy, int32_t size, fx16 du, fx16 dv, fx16 t, fx16 bar,
                    fx_cmap m)
{
    if (!c || size < 4 || size > 4096)
        return;
    int64_t x0 = (int64_t)cx - size / 2, y1 = (int64_t)cy + size / 2;
    /* the bar: outline always, filled to its height */
    int32_t bw = size / 8 > 2 ? size / 8 : 2;
    int64_t bx = x0 + size - bw;
    int64_t b = bar < 0 ? 0 : bar > FX16_ONE ? FX16_ONE : bar;
    int32_t bh = (int32_t)rdiv(b * size, FX16_ONE);
    fx_rect_outline(c, fx_sat32(bx), fx_sat32(y1 - size), bw, size);
    fx_fill_rect(c, fx_sat32(bx), fx_sat32(y1 - bh), bw, bh);
    /* the disc */
    fx_ctx d = *c;
    uint32_t tt = t < 0 ? 0 : t > FX16_ONE ? FX16_ONE : (uint32_t)t;
    fx_ctx_set_color(&d, fx_cmap_color(m, tt));
    fx_disc(&d, cx, cy, size / 4);
    /* the arrow, cut at half the box */
    uint32_t len = fx_hypot(du, dv);
    if (len == 0)
        return;
    int64_t L = len > FX16_ONE ? FX16_ONE : len;
    int64_t half = (int64_t)size * 128; /* size / 2 in 24.8 */
    int64_t ex = rdiv((int64_t)du * 65536, len), ey = -rdiv((int64_t)dv * 65536, len);
    int64_t r = rdiv(half * L, FX16_ONE);
    int64_t cx8 = (int64_t)cx * 256, cy8 = (int64_t)cy * 256;
    int64_t tx = cx8 + ((r * ex) >> 16), ty = cy8 + ((r * ey) >> 16);
    fx_line(c, cx, cy, px8(tx), px8(ty));
    int64_t hl = r / 3 > 512 ? r / 3 : 512;
    barbs(c, tx, ty, ex, ey, hl);
}
