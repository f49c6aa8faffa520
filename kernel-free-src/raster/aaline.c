/* SPDX-License-Identifier: MIT */
/* fixel — antialiased lines (Xiaolin Wu) in fixed point, with exact integer
 * blending and exact clipping.
 *
 * Step k of the major axis puts the ideal line at minor offset k*inc / 2^32
 * (inc = minor/major in Q32.32, rounded to nearest): pixel q = floor of it
 * gets coverage 255 - f and pixel q + 1 gets f, f = the top 8 bits of the
 * fraction. Seeking to any k is one multiply, so a clipped line computes
 * exactly the coverages of the unclipped one.
 *
 * Naming: put_<format family>: blend one pixel of the colour with coverage a
 * (1..254; 0 is skipped, 255 is a plain store). */
#include "fixel/line.h"
#include "../base/fx_internal.h"

static inline uint32_t div255(uint32_t x) { return (x + 128 + ((x + 128) >> 8)) >> 8; }

/* Three 8-bit channels spread into 16-bit lanes of a 64-bit word, so one
 * multiply scales all of them; per lane s*a + d*(255-a) + 128 < 2^16, and
 * div255 (x + (x >> 8)) >> 8 is done on all lanes at once: exactly
 * fx_blend_over's per-channel rounding. */
#define LANES 0x000000FF00FF00FFull
#define HALF 0x0000008000800080ull
static inline uint64_t spread(uint32_t c)
{
    return (c & 0xFF00FFu) | ((uint64_t)(c & 0xFF00u) << 24);
}
static inline uint32_t gather(uint64_t t)
{
    return (uint32_t)(t & 0xFF00FFu) | (uint32_t)((t >> 24) & 0xFF00u);
}
static inline uint64_t mix(uint64_t s, uint64_t d, uint32_t a)
{
    uint64_t t = s * a + d * (255 - a) + HALF;
    return ((t + ((t >> 8) & LANES)) >> 8) & LANES;
}

/* 32-bit formats without alpha: the blend is per channel, so it runs on the
 * native value (channel order does not matter) and writes the X byte 0. */
static inline void put_x32(uint8_t *p, uint64_t s, uint32_t a)
{
    uint32_t *q = (uint32_t *)(void *)p;
    *q = gather(mix(s, spread(*q & 0xFFFFFFu), a));
}

/* 5-6-5: unpack by bit replication, blend the 8-bit channels, pack by
 * truncation (the surface rule). s holds the colour's channels in native
 * order (R, G, B lanes = the 565 fields high to low). */
static inline void put_565(uint8_t *p, uint64_t s, uint32_t a)
{
    uint16_t *q = (uint16_t *)(void *)p;
    uint32_t d = *q, r5 = d >> 11, g6 = (d >> 5) & 63, b5 = d & 31;
    uint32_t d8 = ((r5 << 3 | r5 >> 2) << 16) | ((g6 << 2 | g6 >> 4) << 8) | (b5 << 3 | b5 >> 2);
    uint32_t o = gather(mix(s, spread(d8), a));
    *q = (uint16_t)(((o >> 19) << 11) | (((o >> 10) & 63) << 5) | ((o >> 3) & 31));
}

typedef struct aa {
    const fx_ctx *c;
    int32_t ma0, mi0, ma_s, mi_s; /* start on the major/minor axis, directions */
    uint8_t ymajor;
    uint32_t major, minor;
    uint64_t inc;
    uint32_t alpha; /* colour alpha under OVER, else 255 */
} aa;

static void put_checked(const aa *L, int64_t ma, int64_t mi, uint32_t cov)
{
    const fx_ctx *c = L->c;
    if (!cov)
        return;
    int64_t x = L->ymajor ? mi : ma, y = L->ymajor ? ma : mi;
    if (x < c->clip.x0 || x >= c->clip.x1 || y < c->clip.y0 || y >= c->clip.y1)
        return;
    if (c->exterior && x >= c->exterior_rect.x0 && x < c->exterior_rect.x1 &&
        y >= c->exterior_rect.y0 && y < c->exterior_rect.y1)
        return;
    uint32_t a = L->alpha == 255 ? cov : div255(L->alpha * cov);
    uint32_t d = fx_surface_get_native(&c->surf, (int32_t)x, (int32_t)y);
    fx_surface_put_native(&c->surf, (int32_t)x, (int32_t)y,
                          fx_blend_over(c->surf.format, d, (c->color & 0xFFFFFFu) | a << 24));
}

static void steps_checked(const aa *L, uint32_t k0, uint32_t k1)
{
    for (uint32_t k = k0;; k++) {
        uint64_t off = (uint64_t)k * L->inc;
        int64_t q = (int64_t)(off >> 32);
        uint32_t f = (uint32_t)(off >> 24) & 0xFF;
        int64_t ma = L->ma0 + (int64_t)L->ma_s * k, mi = L->mi0 + L->mi_s * q;
        put_checked(L, ma, mi, 255 - f);
        put_checked(L, ma, mi + L->mi_s, f);
        if (k == k1)
            break;
    }
}

/* Steps [k0, k1] with both pixels of every pair inside the clip. */
static void steps_fast(const aa *L, uint32_t k0, uint32_t k1, unsigned bpp)
{
    const fx_ctx *c = L->c;
    uint64_t off = (uint64_t)k0 * L->inc;
    int64_t ma = L->ma0 + (int64_t)L->ma_s * k0, mi = L->mi0 + L->mi_s * (int64_t)(off >> 32);
    int32_t x = (int32_t)(L->ymajor ? mi : ma), y = (int32_t)(L->ymajor ? ma : mi);
    ptrdiff_t bytes = (ptrdiff_t)(bpp / 8);
    ptrdiff_t sx = bytes, sy = c->surf.stride;
    ptrdiff_t step_ma = L->ma_s * (L->ymajor ? sy : sx), step_mi = L->mi_s * (L->ymajor ? sx : sy);
    uint8_t *p = fx_row(&c->surf, y) + x * bytes;
    uint32_t frac = (uint32_t)off, inc = (uint32_t)L->inc, n = k1 - k0 + 1;
    if (L->inc >> 32)
        step_ma += step_mi;
    uint32_t nat = c->native;
    uint64_t s;
#define AA_WALK(PUT, STORE)                                 \
    for (;;) {                                              \
        uint32_t f = frac >> 24;                            \
        if (f == 0)                                         \
            STORE(p);                                       \
        else if (f == 255)                                  \
            STORE(p + step_mi);                             \
        else {                                              \
            PUT(p, s, 255 - f);                             \
            PUT(p + step_mi, s, f);                         \
        }                                                   \
        if (--n == 0)                                       \
            break;                                          \
        p += step_ma;                                       \
        uint32_t nf = frac + inc;                           \
        if (nf < frac)                                      \
            p += step_mi;                                   \
        frac = nf;                                          \
    }
#define STORE32(q) (*(uint32_t *)(void *)(q) = nat)
#define STORE16(q) (*(uint16_t *)(void *)(q) = (uint16_t)nat)
    if (bpp == 32) {
        s = spread(nat & 0xFFFFFFu);
        AA_WALK(put_x32, STORE32)
    } else {
        fx_color col = c->color;
        if (c->surf.format == FX_FMT_BGR565)
            col = (col & 0xFF00u) | ((col >> 16) & 0xFFu) | ((col & 0xFFu) << 16);
        s = spread(col & 0xFFFFFFu);
        AA_WALK(put_565, STORE16)
    }
#undef STORE32
#undef STORE16
#undef AA_WALK
}

/* Smallest k in [lo, hi + 1] with q(k) + add >= v (q is non-decreasing). */
static uint32_t first_q(const aa *L, uint32_t lo, uint32_t hi, int64_t add, int64_t v)
{
    uint64_t l = lo, h = (uint64_t)hi + 1;
    while (l < h) {
        uint64_t mid = l + (h - l) / 2;
        if ((int64_t)(((uint64_t)mid * L->inc) >> 32) + add >= v)
            h = mid;
        else
            l = mid + 1;
    }
    return (uint32_t)l;
}

void fx_aaline(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    if (fx_rect_empty(c->clip))
        return;
    aa L;
    int64_t dx = (int64_t)x1 - x0, dy = (int64_t)y1 - y0;
    uint32_t adx = (uint32_t)(dx < 0 ? -dx : dx), ady = (uint32_t)(dy < 0 ? -dy : dy);
    int32_t sx = dx > 0 ? 1 : dx < 0 ? -1 : 0, sy = dy > 0 ? 1 : dy < 0 ? -1 : 0;
    L.c = c;
    L.ymajor = ady > adx;
    L.major = L.ymajor ? ady : adx;
    L.minor = L.ymajor ? adx : ady;
    L.ma0 = L.ymajor ? y0 : x0;
    L.mi0 = L.ymajor ? x0 : y0;
    L.ma_s = L.ymajor ? sy : sx;
    L.mi_s = L.ymajor ? sx : sy;
    L.inc = L.major ? (((uint64_t)L.minor << 32) + L.major / 2) / L.major : 0;
    L.alpha = c->blend == FX_BLEND_OVER ? c->color >> 24 : 255;
    if (!L.alpha)
        return;

    /* Major axis: the steps whose column (row) is inside the clip. */
    int64_t ma_lo = L.ymajor ? c->clip.y0 : c->clip.x0, ma_hi = (L.ymajor ? c->clip.y1 : c->clip.x1) - 1;
    int64_t mi_lo = L.ymajor ? c->clip.x0 : c->clip.y0, mi_hi = (L.ymajor ? c->clip.x1 : c->clip.y1) - 1;
    int64_t a, b;
    if (L.ma_s >= 0) {
        a = ma_lo - L.ma0;
        b = ma_hi - L.ma0;
    } else {
        a = L.ma0 - ma_hi;
        b = L.ma0 - ma_lo;
    }
    if (L.ma_s == 0) { /* a single pixel */
        if (L.ma0 < ma_lo || L.ma0 > ma_hi)
            return;
        a = b = 0;
    }
    a = FX_MAX(a, 0);
    b = FX_MIN(b, (int64_t)L.major);
    if (a > b)
        return;
    uint32_t ka = (uint32_t)a, kb = (uint32_t)b;
    /* Minor axis, as offsets o from mi0 in the direction mi_s: visible o in [olo, ohi]. */
    int64_t olo, ohi;
    if (L.mi_s > 0) {
        olo = mi_lo - L.mi0;
        ohi = mi_hi - L.mi0;
    } else if (L.mi_s < 0) {
        olo = L.mi0 - mi_hi;
        ohi = L.mi0 - mi_lo;
    } else {
        if (L.mi0 < mi_lo || L.mi0 > mi_hi)
            return;
        olo = ohi = 0;
    }
    /* Pairs touching the clip: q + 1 >= olo and q <= ohi. */
    uint32_t ta = first_q(&L, ka, kb, 1, olo), tb_end = first_q(&L, ka, kb, 0, ohi + 1);
    if (ta >= tb_end)
        return;
    uint32_t tb = tb_end - 1;
    unsigned bpp = fx_format_get(c->surf.format)->bits_per_pixel;
    fx_format f = c->surf.format;
    int fast = !c->exterior && L.alpha == 255 &&
               (f == FX_FMT_XRGB8888 || f == FX_FMT_XBGR8888 || f == FX_FMT_RGB565 || f == FX_FMT_BGR565);
    if (!fast) {
        steps_checked(&L, ta, tb);
        return;
    }
    /* Pairs wholly inside: q >= olo and q + 1 <= ohi (a level line has no
     * second pixel: its coverage is always 0). */
    uint32_t ia = first_q(&L, ta, tb, 0, olo);
    uint32_t ib_end = first_q(&L, ta, tb, L.minor ? 1 : 0, ohi + 1);
    if (ia >= ib_end) {
        steps_checked(&L, ta, tb);
        return;
    }
    if (ta < ia)
        steps_checked(&L, ta, ia - 1);
    steps_fast(&L, ia, ib_end - 1, bpp);
    if (ib_end <= tb)
        steps_checked(&L, ib_end, tb);
}
