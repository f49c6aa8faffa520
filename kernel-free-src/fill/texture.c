/* SPDX-License-Identifier: MIT */
/* fixel — textures, procedural textures and gradients (see fixel/texture.h). */
#include "fixel/texture.h"
#include "../base/fx_internal.h"

/* ---- sampling ---- */

static int32_t wrap_index(int64_t i, int32_t n, int wrap)
{
    if (wrap == FX_TEX_CLAMP)
        return (int32_t)(i < 0 ? 0 : i >= n ? n - 1 : i);
    int64_t r = i % n;
    return (int32_t)(r < 0 ? r + n : r);
}

static fx_color texel(const fx_texture *tx, int32_t i, int32_t j)
{
    return fx_unpack(tx->img.format, fx_surface_get_native(&tx->img, i, j));
}

/* floor(s * n) for the unit square [0, 1) -> [0, n), wrapped or clamped. */
static int32_t lookup_index(fx16 s, int32_t n, int wrap)
{
    if (wrap == FX_TEX_CLAMP) {
        if (s < 0)
            return 0;
        if (s >= FX16_ONE)
            return n - 1;
    } else {
        s &= 0xFFFF;
    }
    return (int32_t)(((int64_t)s * n) >> 16);
}

fx_color fx_tex_lookup(const fx_texture *tx, fx16 s, fx16 t)
{
    return texel(tx, lookup_index(s, tx->img.w, tx->wrap), lookup_index(t, tx->img.h, tx->wrap));
}

void fx_tex_checker(const fx_surface *img, int32_t cell, fx_color c0, fx_color c1)
{
    if (cell < 1)
        cell = 1;
    uint32_t n0 = fx_pack(img->format, c0), n1 = fx_pack(img->format, c1);
    for (int32_t y = 0; y < img->h; y++)
        for (int32_t x = 0; x < img->w; x++)
            fx_surface_put_native(img, x, y, ((x / cell + y / cell) & 1) ? n1 : n0);
}

fx_color fx_tex_sample(const fx_texture *tx, fx16 s, fx16 t)
{
    if (tx->filter != FX_TEX_BILINEAR)
        return fx_tex_lookup(tx, s, t);
    int32_t w = tx->img.w, h = tx->img.h;
    if (tx->wrap == FX_TEX_CLAMP) {
        s = s < 0 ? 0 : s > FX16_ONE ? FX16_ONE : s;
        t = t < 0 ? 0 : t > FX16_ONE ? FX16_ONE : t;
    } else {
        s &= 0xFFFF;
        t &= 0xFFFF;
    }
    /* texel-space position of the sample relative to texel centres, Q16 */
    int64_t u = (int64_t)s * w - FX16_HALF, v = (int64_t)t * h - FX16_HALF;
    int64_t i0 = u >> 16, j0 = v >> 16;
    uint32_t fu = (uint32_t)(u >> 8) & 0xFF, fv = (uint32_t)(v >> 8) & 0xFF;
    int32_t ia = wrap_index(i0, w, tx->wrap), ib = wrap_index(i0 + 1, w, tx->wrap);
    int32_t ja = wrap_index(j0, h, tx->wrap), jb = wrap_index(j0 + 1, h, tx->wrap);
    fx_color c00 = texel(tx, ia, ja), c10 = texel(tx, ib, ja), c01 = texel(tx, ia, jb), c11 = texel(tx, ib, jb);
    uint32_t w00 = (256 - fu) * (256 - fv), w10 = fu * (256 - fv), w01 = (256 - fu) * fv, w11 = fu * fv;
    fx_color out = 0;
    for (int sh = 0; sh < 32; sh += 8) {
        uint32_t ch = ((c00 >> sh) & 0xFF) * w00 + ((c10 >> sh) & 0xFF) * w10 + ((c01 >> sh) & 0xFF) * w01 +
                      ((c11 >> sh) & 0xFF) * w11;
        out |= ((ch + 32768) >> 16) << sh;
    }
    return out;
}

/* ---- writing shaded pixels ---- */

static void put(const fx_ctx *c, int32_t x, int32_t y, fx_color col)
{
    if (c->exterior && x >= c->exterior_rect.x0 && x < c->exterior_rect.x1 && y >= c->exterior_rect.y0 &&
        y < c->exterior_rect.y1)
        return;
    uint32_t v = c->blend == FX_BLEND_OVER
                     ? fx_blend_over(c->surf.format, fx_surface_get_native(&c->surf, x, y), col)
                     : fx_pack(c->surf.format, col);
    fx_surface_put_native(&c->surf, x, y, v);
}

void fx_fill_tri_tex8(const fx_ctx *c, const fx8 *xy, const fx16 *st, const fx_texture *tx)
{
    int32_t attr[6] = {st[0], st[1], st[2], st[3], st[4], st[5]};
    for (int i = 0; i < 6; i++) /* fx_tri attributes are bounded by 2^30 */
        attr[i] = attr[i] > (1 << 30) - 1 ? (1 << 30) - 1 : attr[i] < -(1 << 30) + 1 ? -(1 << 30) + 1 : attr[i];
    fx_tri t;
    if (fx_tri_begin(&t, c->clip, xy, attr, 2) <= 0)
        return;
    fx_tri_span sp;
    while (fx_tri_next_span(&t, &sp)) {
        uint64_t s = fx_tri_attr_at(&t, 0, sp.x0, sp.y) + 0x80000000u, u = fx_tri_attr_at(&t, 1, sp.x0, sp.y) + 0x80000000u;
        for (int32_t x = sp.x0; x < sp.x1; x++) {
            put(c, x, sp.y, fx_tex_sample(tx, (fx16)((int64_t)s >> 32), (fx16)((int64_t)u >> 32)));
            s += t.gx[0];
            u += t.gx[1];
        }
    }
}

void fx_fill_tri_tex(const fx_ctx *c, const int32_t *xy, const fx16 *st, const fx_texture *tx)
{
    fx8 w[6];
    for (int i = 0; i < 6; i++) {
        if (xy[i] >= (1 << 22) || xy[i] <= -(1 << 22))
            return;
        w[i] = xy[i] * FX8_ONE;
    }
    fx_fill_tri_tex8(c, w, st, tx);
}

void fx_fill_poly_tex(const fx_ctx *c, const int32_t *xy, const fx16 *st, int32_t n, const fx_texture *tx)
{
    for (int32_t i = 1; i + 1 < n; i++) {
        int32_t v[6] = {xy[0], xy[1], xy[2 * i], xy[2 * i + 1], xy[2 * i + 2], xy[2 * i + 3]};
        fx16 q[6] = {st[0], st[1], st[2 * i], st[2 * i + 1], st[2 * i + 2], st[2 * i + 3]};
        fx_fill_tri_tex(c, v, q, tx);
    }
}

void fx_tex_shade(const void *map, int32_t y, int32_t x, int32_t n, fx_color *out)
{
    const fx_tex_map *m = map;
    for (int32_t k = 0; k < n; k++) {
        int64_t px = (int64_t)x + k;
        fx16 s = (fx16)(m->s0 + m->dsdx * px + (int64_t)m->dsdy * y);
        fx16 t = (fx16)(m->t0 + m->dtdx * px + (int64_t)m->dtdy * y);
        out[k] = fx_tex_sample(m->tex, s, t);
    }
}

/* ---- colour helpers ---- */

fx_color fx_color_lerp(fx_color a, fx_color b, fx16 w)
{
    int64_t ww = w < 0 ? 0 : w > FX16_ONE ? FX16_ONE : w;
    fx_color out = 0;
    for (int sh = 0; sh < 32; sh += 8) {
        int64_t ca = (a >> sh) & 0xFF, cb = (b >> sh) & 0xFF;
        out |= (uint32_t)((ca * (FX16_ONE - ww) + cb * ww + FX16_HALF) >> 16) << sh;
    }
    return out;
}

/* ---- procedural textures ---- */

static uint32_t hash2(int32_t ix, int32_t iy, uint32_t seed)
{
    uint32_t h = (uint32_t)ix * 0x27D4EB2Du ^ (uint32_t)iy * 0x165667B1u ^ seed * 0x9E3779B9u;
    h ^= h >> 15;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    h ^= h >> 16;
    return h;
}

static int64_t fade(int64_t f) /* 3f^2 - 2f^3 in Q16 */
{
    int64_t f2 = (f * f) >> 16;
    return (f2 * (3 * FX16_ONE - 2 * f)) >> 16;
}

fx16 fx_proc_noise(fx16 s, fx16 t, uint32_t seed)
{
    int32_t ix = s >> 16, iy = t >> 16;
    int64_t fx = fade(s & 0xFFFF), fy = fade(t & 0xFFFF);
    int64_t v00 = hash2(ix, iy, seed) >> 16, v10 = hash2(ix + 1, iy, seed) >> 16;
    int64_t v01 = hash2(ix, iy + 1, seed) >> 16, v11 = hash2(ix + 1, iy + 1, seed) >> 16;
    int64_t a = v00 + (((v10 - v00) * fx) >> 16), b = v01 + (((v11 - v01) * fx) >> 16);
    return (fx16)(a + (((b - a) * fy) >> 16));
}

fx16 fx_proc_turbulence(fx16 s, fx16 t, int octaves, uint32_t seed)
{
    if (octaves < 1)
        octaves = 1;
    if (octaves > 12)
        octaves = 12;
    int64_t sum = 0, norm = 0;
    for (int k = 0; k < octaves; k++) {
        fx16 n = fx_proc_noise((fx16)((uint32_t)s << k), (fx16)((uint32_t)t << k), seed + (uint32_t)k);
        int64_t a = 2 * (int64_t)n - FX16_ONE;
        sum += (a < 0 ? -a : a) >> k;
        norm += FX16_ONE >> k;
    }
    return (fx16)(sum * FX16_ONE / norm);
}

static int64_t radius(fx16 s, fx16 t) /* distance from (1/2, 1/2), Q16 */
{
    int64_t ds = (int64_t)s - FX16_HALF, dt = (int64_t)t - FX16_HALF;
    uint64_t d2 = (uint64_t)(ds * ds) + (uint64_t)(dt * dt);
    return fx_isqrt64(d2);
}

fx16 fx_proc_fakesphere(fx16 s, fx16 t)
{
    int64_t r = radius(s, t);
    if (r * 10 < 3 * (int64_t)FX16_ONE) /* r < 0.3 */
        return (fx16)(FX16_ONE - (r * 10 + 1) / 3);
    return 13107; /* 0.2 */
}

fx16 fx_proc_wood(fx16 s, fx16 t, uint32_t seed)
{
    int64_t r = radius(s, t);
    int64_t x = r * 8 + fx_proc_turbulence((fx16)((uint32_t)s << 2), (fx16)((uint32_t)t << 2), 4, seed) / 2;
    int64_t f = x & 0xFFFF; /* position within a ring */
    /* light early wood to dark late wood: a saw with a soft attack */
    return (fx16)(f < 0x3000 ? f * FX16_ONE / 0x3000 : FX16_ONE - (f - 0x3000) * FX16_ONE / (0x10000 - 0x3000));
}

fx16 fx_proc_marble(fx16 s, fx16 t, uint32_t seed)
{
    int64_t x = 4 * (int64_t)s +
                (int64_t)fx_proc_turbulence((fx16)((uint32_t)s << 2), (fx16)((uint32_t)t << 2), 5, seed);
    fx_angle a = (fx_angle)((uint64_t)x << 16); /* Q16 turns -> binary angle */
    return (fx16)(FX16_HALF + fx_sin(a) / 2);
}

fx16 fx_proc_eval(int kind, fx16 s, fx16 t, uint32_t seed)
{
    switch (kind) {
    case FX_PROC_FAKESPHERE: return fx_proc_fakesphere(s, t);
    case FX_PROC_NOISE: return fx_proc_noise(s, t, seed);
    case FX_PROC_TURBULENCE: return fx_proc_turbulence(s, t, 6, seed);
    case FX_PROC_WOOD: return fx_proc_wood(s, t, seed);
    case FX_PROC_MARBLE: return fx_proc_marble(s, t, seed);
    default: return 0;
    }
}

void fx_proc_shade(const void *map, int32_t y, int32_t x, int32_t n, fx_color *out)
{
    const fx_proc_map *m = map;
    int64_t size = m->size < 1 ? 1 : m->size;
    fx16 t = (fx16)((((int64_t)y - m->y0) * FX16_ONE) / size);
    for (int32_t k = 0; k < n; k++) {
        fx16 s = (fx16)((((int64_t)x + k - m->x0) * FX16_ONE) / size);
        out[k] = fx_color_lerp(m->c0, m->c1, fx_proc_eval(m->kind, s, t, m->seed));
    }
}

/* ---- gradients ---- */

fx_color fx_gradient_at(const fx_gradient *g, fx16 u)
{
    int32_t n = g->nstops < 1 ? 1 : g->nstops > FX_GRADIENT_MAX_STOPS ? FX_GRADIENT_MAX_STOPS : g->nstops;
    if (n == 1)
        return g->stops[0];
    u = u < 0 ? 0 : u > FX16_ONE ? FX16_ONE : u;
    int64_t pos = (int64_t)u * (n - 1);
    int32_t i = (int32_t)(pos >> 16);
    if (i >= n - 1)
        return g->stops[n - 1];
    return fx_color_lerp(g->stops[i], g->stops[i + 1], (fx16)(pos & 0xFFFF));
}

static fx16 ratio_q16(uint64_t num, uint64_t den) /* num/den in [0, 1], Q16, to nearest */
{
    if (num >= den)
        return FX16_ONE;
    while (den >= ((uint64_t)1 << 46)) {
        num >>= 1;
        den >>= 1;
    }
    return (fx16)(((num << 16) + den / 2) / den);
}

static fx16 gradient_param(const fx_gradient *g, int64_t x, int64_t y)
{
    int64_t dx = x - g->x0, dy = y - g->y0;
    if (g->radial) {
        uint64_t d2 = (uint64_t)(dx * dx) + (uint64_t)(dy * dy), r = g->r < 1 ? 1 : (uint64_t)g->r;
        if (d2 >= r * r)
            return FX16_ONE;
        /* d2 < r^2: distance in Q16 exactly floored when it fits */
        uint64_t dq = d2 < ((uint64_t)1 << 31) ? fx_isqrt64(d2 << 32) : (uint64_t)fx_isqrt64(d2) << 16;
        return ratio_q16(dq, r << 16);
    }
    int64_t ax = (int64_t)g->x1 - g->x0, ay = (int64_t)g->y1 - g->y0;
    int64_t num = dx * ax + dy * ay, den = ax * ax + ay * ay;
    if (den == 0 || num <= 0)
        return 0;
    return ratio_q16((uint64_t)num, (uint64_t)den);
}

void fx_gradient_shade(const void *gradient, int32_t y, int32_t x, int32_t n, fx_color *out)
{
    const fx_gradient *g = gradient;
    for (int32_t k = 0; k < n; k++)
        out[k] = fx_gradient_at(g, gradient_param(g, (int64_t)x + k, y));
}
