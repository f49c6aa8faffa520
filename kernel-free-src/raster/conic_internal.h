/* SPDX-License-Identifier: MIT */
/* Helpers shared by circle.c and ellipse.c; not installed. */
#ifndef FIXEL_CONIC_INTERNAL_H
#define FIXEL_CONIC_INTERNAL_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fixed.h"
#include "../base/fx_internal.h"

/* Where the pixels go. Callers hand over only pixels inside c->clip; the
 * sink picks the cheapest correct write once per primitive. */
typedef struct conic_sink {
    const fx_ctx *c;
    int mode;       /* 0: plain store of c->native, 1: fx_plot (blend, exterior) */
    unsigned bytes; /* bytes per pixel for mode 0 stores; 0: fx_surface_put_native */
} conic_sink;

static inline void conic_sink_init(conic_sink *k, const fx_ctx *c)
{
    unsigned bpp = fx_format_get(c->surf.format)->bits_per_pixel;
    k->c = c;
    k->mode = (c->exterior || (c->blend == FX_BLEND_OVER && (c->color >> 24) != 255)) ? 1 : 0;
    k->bytes = (bpp == 32 || bpp == 16 || bpp == 8) ? bpp / 8 : 0;
}

static inline void conic_put(const conic_sink *k, int32_t x, int32_t y)
{
    const fx_ctx *c = k->c;
    if (k->mode) {
        fx_plot(c, x, y);
        return;
    }
    uint8_t *p = fx_row(&c->surf, y);
    switch (k->bytes) {
    case 4: ((uint32_t *)(void *)p)[x] = c->native; break;
    case 2: ((uint16_t *)(void *)p)[x] = (uint16_t)c->native; break;
    case 1: p[x] = (uint8_t)c->native; break;
    default: fx_surface_put_native(&c->surf, x, y, c->native); break;
    }
}

/* A plain span of 1, 2 or 4-byte pixels. Fixed-size copies of a pattern
 * block become single wide stores on every target (and are alias-safe),
 * several times faster than a store per pixel on wide discs. */
static inline void conic_fill(const fx_surface *s, unsigned bytes, int32_t y, int32_t x0, int32_t x1,
                              uint32_t v)
{
    uint8_t *p = fx_row(s, y) + (ptrdiff_t)x0 * bytes;
    size_t n = (size_t)(x1 - x0) * bytes;
    if (bytes == 1) {
        fx_memset(p, (int)(v & 0xFF), n);
        return;
    }
    uint32_t w = bytes == 4 ? v : ((v & 0xFFFFu) | (v << 16));
    uint32_t pat[8] = {w, w, w, w, w, w, w, w};
    for (; n >= 32; n -= 32, p += 32)
        fx_memcpy(p, pat, 32);
    for (; n >= 4; n -= 4, p += 4)
        fx_memcpy(p, pat, 4);
    if (n)
        fx_memcpy(p, pat, 2);
}

/* Span [x0, x1] (inclusive, 64-bit) on row y, clipped here. */
static inline void conic_span(const conic_sink *k, int64_t y, int64_t x0, int64_t x1)
{
    const fx_ctx *c = k->c;
    if (y < c->clip.y0 || y >= c->clip.y1)
        return;
    if (x0 < c->clip.x0)
        x0 = c->clip.x0;
    if (x1 > (int64_t)c->clip.x1 - 1)
        x1 = (int64_t)c->clip.x1 - 1;
    if (x0 > x1)
        return;
    if (k->mode)
        fx_hspan(c, (int32_t)y, (int32_t)x0, (int32_t)x1 + 1);
    else if (k->bytes)
        conic_fill(&c->surf, k->bytes, (int32_t)y, (int32_t)x0, (int32_t)x1 + 1, c->native);
    else
        fx_span_fill(&c->surf, (int32_t)y, (int32_t)x0, (int32_t)x1 + 1, c->native);
}

static inline int64_t conic_floor_div(int64_t n, int64_t d)
{
    int64_t q = n / d;
    return (q * d != n && ((n < 0) != (d < 0))) ? q - 1 : q;
}
static inline int64_t conic_ceil_div(int64_t n, int64_t d) { return -conic_floor_div(-n, d); }

/* Unsigned 128-bit values as two halves: enough for ellipse decisions with
 * semi-axes up to 2^31 (every term is below 2^127). */
typedef struct u128 {
    uint64_t hi, lo;
} u128;

static inline u128 u128_mul(uint64_t a, uint64_t b)
{
    u128 r;
    fx_umul64_wide(a, b, &r.hi, &r.lo);
    return r;
}
static inline u128 u128_add(u128 a, u128 b)
{
    u128 r = {a.hi + b.hi, a.lo + b.lo};
    r.hi += r.lo < a.lo;
    return r;
}
static inline u128 u128_sub(u128 a, u128 b) /* a >= b */
{
    u128 r = {a.hi - b.hi, a.lo - b.lo};
    r.hi -= a.lo < b.lo;
    return r;
}
static inline int u128_lt(u128 a, u128 b) { return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo); }
static inline int u128_zero(u128 a) { return !a.hi && !a.lo; }

/* floor(a / d) for d > 0, when the quotient fits in 64 bits (a.hi < d). */
static inline uint64_t u128_div64(u128 a, uint64_t d)
{
    uint64_t rem = a.hi, q = 0;
    for (int i = 63; i >= 0; i--) {
        uint64_t top = rem >> 63;
        rem = (rem << 1) | ((a.lo >> i) & 1);
        q <<= 1;
        if (top || rem >= d) {
            rem -= d;
            q |= 1;
        }
    }
    return q;
}

#endif
